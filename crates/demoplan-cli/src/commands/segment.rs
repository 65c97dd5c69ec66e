//! `demoplan segment FILE...`: ground recordings (or read ARFF hand-state tables), cut
//! each hand's frames into segments and classify them; print a table or JSON.

use std::fmt::Write as _;
use std::io::Write;
use std::path::{Path, PathBuf};

use grounding::{FactSpace, State};
use recording::{EntityId, Header};
use segment::Segment;
use serde_json::{json, Value};

use crate::commands::demo_input::{self, Segmented};
use crate::diagnostic::Failure;
use crate::exit::ExitCode;
use crate::output;

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
    // Each file is printed as soon as it is segmented, and JSON one segment at a time:
    // memory follows one file's segments, not the text of all of them (an hour's
    // recording has thousands of segments, each with two fact lists).
    let mut out = std::io::BufWriter::new(std::io::stdout().lock());
    if args.json {
        write_out(&mut out, "{\n  \"files\": [")?;
    }
    for (i, path) in args.files.iter().enumerate() {
        let segmented = if demo_input::is_arff(path) {
            demo_input::segment_arff(path, &tree, config.min_duration)?
        } else {
            demo_input::segment_recording(path, &config, &tree, |_, _| {}, |_| {})?
        };
        if args.json {
            write_out(&mut out, if i > 0 { ",\n" } else { "\n" })?;
            write_file_json(&mut out, path, &segmented)?;
        } else {
            let mut text = String::new();
            if i > 0 {
                text.push('\n');
            }
            table(&mut text, path, &segmented);
            write_out(&mut out, &text)?;
        }
    }
    if args.json {
        let end = if args.files.is_empty() {
            "]\n}\n"
        } else {
            "\n  ]\n}\n"
        };
        write_out(&mut out, end)?;
    }
    out.flush()
        .map_err(|e| output::stdout_failure(&e))
        .map(|()| ExitCode::SUCCESS)
}

fn write_out(out: &mut impl Write, text: &str) -> Result<(), Failure> {
    output::print(out, text)
}

/// Writes `text` (pretty JSON, no raw newlines inside strings) indented by `indent`
/// spaces from its second line on, as it sits nested in the whole document.
fn write_nested(out: &mut impl Write, text: &str, indent: usize) -> Result<(), Failure> {
    let pad = " ".repeat(indent);
    let mut nested = String::with_capacity(text.len() + 64);
    for (i, line) in text.lines().enumerate() {
        if i > 0 {
            nested.push('\n');
            nested.push_str(&pad);
        }
        nested.push_str(line);
    }
    write_out(out, &nested)
}

/// One entry of `files`: what `serde_json::to_string_pretty` would print for it inside
/// the document, written a segment at a time. Its keys are in serde_json's order
/// (sorted), so `segments` comes last.
fn write_file_json(out: &mut impl Write, path: &Path, s: &Segmented) -> Result<(), Failure> {
    let head = json!({
        "file": path.display().to_string(),
        "recording": s.header.id,
        "frames": s.frames,
        "duration": s.duration,
        "hands": s.space.hands().iter().map(|&h| name(&s.header, Some(h))).collect::<Vec<_>>(),
    });
    let head = serde_json::to_string_pretty(&head).unwrap_or_default();
    // Everything but the closing brace, then the segments.
    let open = head.strip_suffix("\n}").unwrap_or(&head);
    write_out(out, "    ")?;
    write_nested(out, open, 4)?;
    if s.segments.is_empty() {
        return write_out(out, ",\n      \"segments\": []\n    }");
    }
    write_out(out, ",\n      \"segments\": [")?;
    for (i, g) in s.segments.iter().enumerate() {
        write_out(out, if i > 0 { ",\n        " } else { "\n        " })?;
        let text = serde_json::to_string_pretty(&segment_json(s, g)).unwrap_or_default();
        write_nested(out, &text, 8)?;
    }
    write_out(out, "\n      ]\n    }")
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
