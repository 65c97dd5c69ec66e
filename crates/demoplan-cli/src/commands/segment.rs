//! `demoplan segment FILE...`: ground recordings (or read ARFF hand-state tables), cut
//! each hand's frames into segments and classify them; print a table or JSON.

use std::fmt::Write as _;
use std::path::{Path, PathBuf};

use grounding::{FactSpace, State};
use recording::{EntityId, Header};
use segment::{Segment, Segmenter};
use serde_json::{json, Value};

use crate::commands::demo_input::{self, Segmented};
use crate::diagnostic::Failure;
use crate::exit::ExitCode;

/// The command line of `segment`.
#[derive(Debug)]
pub struct SegmentArgs {
    pub files: Vec<PathBuf>,
    pub json: bool,
    pub config: Option<PathBuf>,
    pub tree: Option<PathBuf>,
}

pub fn run(args: SegmentArgs) -> Result<ExitCode, Failure> {
    let config = demo_input::config(args.config.as_deref())?;
    let tree = demo_input::activity_tree(args.tree.as_deref())?;
    let mut text = String::new();
    let mut files = Vec::new();
    for (i, path) in args.files.iter().enumerate() {
        let segmented = if demo_input::is_arff(path) {
            let frames = demo_input::hand_frames(path)?;
            let space = FactSpace::new(&frames.header);
            let mut segmenter = Segmenter::new(&[EntityId(0)], tree.clone(), config.min_duration);
            let empty = State::default();
            for f in &frames.frames {
                segmenter.push(f.time, &[f.hand], &empty);
            }
            let duration = match (frames.frames.first(), frames.frames.last()) {
                (Some(a), Some(b)) => b.time - a.time,
                _ => 0.0,
            };
            Segmented {
                space,
                frames: frames.frames.len() as u64,
                duration,
                header: frames.header,
                segments: segmenter.finish(),
            }
        } else {
            demo_input::segment_recording(path, &config, &tree, |_, _| {}, |_| {})?
        };
        if args.json {
            files.push(to_json(path, &segmented));
        } else {
            if i > 0 {
                text.push('\n');
            }
            table(&mut text, path, &segmented);
        }
    }
    if args.json {
        let doc = json!({ "files": files });
        text = serde_json::to_string_pretty(&doc).unwrap_or_default();
        text.push('\n');
    }
    print!("{text}");
    Ok(ExitCode::SUCCESS)
}

fn name(header: &Header, id: Option<EntityId>) -> String {
    id.and_then(|id| header.entities.get(id.index()))
        .map_or_else(|| "-".to_string(), |e| e.name.clone())
}

fn table(out: &mut String, path: &Path, s: &Segmented) {
    let hands = s.space.hands().len();
    let _ = writeln!(
        out,
        "{}: {} segment{}, {} hand{}, {} frames, {:.2} s",
        path.display(),
        s.segments.len(),
        if s.segments.len() == 1 { "" } else { "s" },
        hands,
        if hands == 1 { "" } else { "s" },
        s.frames,
        s.duration
    );
    let width = s
        .segments
        .iter()
        .map(|g| name(&s.header, Some(g.hand)).len())
        .max()
        .unwrap_or(4)
        .max(4);
    let _ = writeln!(
        out,
        "{:<width$}  {:>8}  {:>8}  {:<8}  {:<10}  acted on",
        "hand", "start", "end", "activity", "in hand"
    );
    for g in &s.segments {
        let _ = writeln!(
            out,
            "{:<width$}  {:>8.3}  {:>8.3}  {:<8}  {:<10}  {}",
            name(&s.header, Some(g.hand)),
            g.start,
            g.end,
            g.activity.name(),
            name(&s.header, g.in_hand),
            name(&s.header, g.acted_on),
        );
    }
}

fn facts(space: &FactSpace, header: &Header, state: &State) -> Value {
    Value::Array(
        state
            .facts(space)
            .map(|f| Value::String(f.display(header).to_string()))
            .collect(),
    )
}

fn segment_json(s: &Segmented, g: &Segment) -> Value {
    let object = |id: Option<EntityId>| match id {
        Some(_) => Value::String(name(&s.header, id)),
        None => Value::Null,
    };
    json!({
        "hand": name(&s.header, Some(g.hand)),
        "start": g.start,
        "end": g.end,
        "frames": g.frames,
        "activity": g.activity.name(),
        "moving": g.moving,
        "in_hand": object(g.in_hand),
        "acted_on": object(g.acted_on),
        "start_state": facts(&s.space, &s.header, &g.start_state),
        "end_state": facts(&s.space, &s.header, &g.end_state),
    })
}

fn to_json(path: &Path, s: &Segmented) -> Value {
    json!({
        "file": path.display().to_string(),
        "recording": s.header.id,
        "frames": s.frames,
        "duration": s.duration,
        "hands": s.space.hands().iter().map(|&h| name(&s.header, Some(h))).collect::<Vec<_>>(),
        "segments": s.segments.iter().map(|g| segment_json(s, g)).collect::<Vec<_>>(),
    })
}
