//! A segmented recording as people and scripts read it (`demoplan segment`): a table of
//! segments, or JSON with each segment's start and end states, written a segment at a
//! time so that memory follows the segments, not the text of all of them.

use std::fmt::Write as _;
use std::io::{self, Write};

use grounding::State;
use recording::EntityId;
use segment::Segment;
use serde_json::{json, Value};

use crate::pipeline::Segmented;

impl Segmented {
    /// An entity's name, `-` for none.
    fn name(&self, id: Option<EntityId>) -> String {
        id.and_then(|id| self.header.entities.get(id.index()))
            .map_or_else(|| "-".to_string(), |e| e.name.clone())
    }

    fn facts(&self, state: &State) -> Value {
        Value::Array(
            state
                .facts(&self.space)
                .map(|f| Value::String(f.display(&self.header).to_string()))
                .collect(),
        )
    }

    /// The segments as a table headed by a line about the recording read from `source`:
    /// hand, start, end, activity, object in hand, object acted on.
    pub fn table(&self, source: &str) -> String {
        let mut out = String::new();
        let (segments, hands) = (self.segments.len(), self.space.hands().len());
        let _ = writeln!(
            out,
            "{source}: {segments} segment{}, {hands} hand{}, {} frames, {:.2} s",
            if segments == 1 { "" } else { "s" },
            if hands == 1 { "" } else { "s" },
            self.frames,
            self.duration
        );
        let width = self
            .segments
            .iter()
            .map(|g| self.name(Some(g.hand)).len())
            .max()
            .unwrap_or(4)
            .max(4);
        let _ = writeln!(
            out,
            "{:<width$}  {:>8}  {:>8}  {:<8}  {:<10}  acted on",
            "hand", "start", "end", "activity", "in hand"
        );
        for g in &self.segments {
            let _ = writeln!(
                out,
                "{:<width$}  {:>8.3}  {:>8.3}  {:<8}  {:<10}  {}",
                self.name(Some(g.hand)),
                g.start,
                g.end,
                g.activity.name(),
                self.name(g.in_hand),
                self.name(g.acted_on),
            );
        }
        out
    }

    fn segment_json(&self, g: &Segment) -> Value {
        let object = |id: Option<EntityId>| id.map_or(Value::Null, |_| self.name(id).into());
        json!({
            "hand": self.name(Some(g.hand)),
            "start": g.start,
            "end": g.end,
            "frames": g.frames,
            "activity": g.activity.name(),
            "moving": g.moving,
            "in_hand": object(g.in_hand),
            "acted_on": object(g.acted_on),
            "start_state": self.facts(&g.start_state),
            "end_state": self.facts(&g.end_state),
        })
    }

    /// Writes the recording read from `source` as one entry of a JSON document's
    /// `files` array (indented as it sits there), a segment at a time: what
    /// `serde_json::to_string_pretty` would print for it, keys sorted, `segments` last.
    pub fn write_json(&self, out: &mut dyn Write, source: &str) -> io::Result<()> {
        let hands: Vec<String> = self
            .space
            .hands()
            .iter()
            .map(|&h| self.name(Some(h)))
            .collect();
        let head = json!({
            "file": source,
            "recording": self.header.id,
            "frames": self.frames,
            "duration": self.duration,
            "hands": hands,
        });
        let head = serde_json::to_string_pretty(&head).map_err(io::Error::other)?;
        // Everything but the closing brace, then the segments.
        let open = head.strip_suffix("\n}").unwrap_or(&head);
        out.write_all(b"    ")?;
        write_nested(out, open, 4)?;
        if self.segments.is_empty() {
            return out.write_all(b",\n      \"segments\": []\n    }");
        }
        out.write_all(b",\n      \"segments\": [")?;
        for (i, g) in self.segments.iter().enumerate() {
            out.write_all(if i > 0 { b",\n        " } else { b"\n        " })?;
            let text =
                serde_json::to_string_pretty(&self.segment_json(g)).map_err(io::Error::other)?;
            write_nested(out, &text, 8)?;
        }
        out.write_all(b"\n      ]\n    }")
    }
}

/// Writes `text` (pretty JSON, no raw newlines inside strings) indented by `indent`
/// spaces from its second line on, as it sits nested in the whole document.
fn write_nested(out: &mut dyn Write, text: &str, indent: usize) -> io::Result<()> {
    let pad = " ".repeat(indent);
    let mut nested = String::with_capacity(text.len() + 64);
    for (i, line) in text.lines().enumerate() {
        if i > 0 {
            nested.push('\n');
            nested.push_str(&pad);
        }
        nested.push_str(line);
    }
    out.write_all(nested.as_bytes())
}
