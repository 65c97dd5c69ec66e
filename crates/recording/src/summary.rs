//! A recording summarised for people (`demoplan inspect`): duration, nominal and
//! measured frame rate, gaps, entities, which optional fields are present, contacts.
//! Gathered a frame at a time, so a recording of any length is summarised in memory
//! bounded by its entities.

use std::collections::BTreeSet;
use std::fmt::Write as _;

use crate::model::{EntityKind, Frame, Header};

/// An interval longer than this many nominal frame periods is a gap.
pub const GAP: f64 = 1.5;

/// What one entity showed over the recording.
#[derive(Debug, Default, Clone)]
struct EntityStats {
    observed: u64,
    velocity: u64,
    grip_min: f32,
    grip_max: f32,
    holding: u64,
    held: BTreeSet<u32>,
}

/// What a recording holds, gathered a frame at a time ([`Summary::observe`]) and
/// rendered for people ([`Summary::render`]): `demoplan inspect`.
#[derive(Debug, Clone)]
pub struct Summary {
    header: Header,
    frames: u64,
    first: f64,
    last: f64,
    min_dt: f64,
    max_dt: f64,
    gaps: u64,
    longest_gap: (f64, f64),
    entities: Vec<EntityStats>,
    contact_frames: u64,
    pairs: BTreeSet<(u32, u32)>,
}

fn line(out: &mut String, key: &str, value: impl std::fmt::Display) {
    let _ = writeln!(out, "{key:<14} {value}");
}

fn ms(seconds: f64) -> String {
    format!("{:.1} ms", seconds * 1000.0)
}

impl Summary {
    /// Nothing seen yet of a recording with this header.
    pub fn new(header: &Header) -> Summary {
        Summary {
            header: header.clone(),
            frames: 0,
            first: 0.0,
            last: 0.0,
            min_dt: f64::INFINITY,
            max_dt: 0.0,
            gaps: 0,
            longest_gap: (0.0, 0.0),
            entities: vec![
                EntityStats {
                    grip_min: f32::INFINITY,
                    grip_max: f32::NEG_INFINITY,
                    ..EntityStats::default()
                };
                header.entities.len()
            ],
            contact_frames: 0,
            pairs: BTreeSet::new(),
        }
    }

    /// Counts one more frame (frames in the order read).
    pub fn observe(&mut self, frame: &Frame) {
        let s = self;
        let period = 1.0 / s.header.frame_rate;
        if s.frames == 0 {
            s.first = frame.time;
        } else {
            let dt = frame.time - s.last;
            s.min_dt = s.min_dt.min(dt);
            s.max_dt = s.max_dt.max(dt);
            if dt > GAP * period {
                s.gaps += 1;
                if dt > s.longest_gap.0 {
                    s.longest_gap = (dt, s.last);
                }
            }
        }
        s.last = frame.time;
        s.frames += 1;
        for (e, state) in s.entities.iter_mut().zip(&frame.states) {
            let Some(state) = state else { continue };
            e.observed += 1;
            e.velocity += u64::from(state.velocity.is_some());
            if let Some(g) = state.grip {
                e.grip_min = e.grip_min.min(g);
                e.grip_max = e.grip_max.max(g);
            }
            if let Some(h) = state.holding {
                e.holding += 1;
                e.held.insert(h.0);
            }
        }
        if !frame.contacts.is_empty() {
            s.contact_frames += 1;
            for c in &frame.contacts {
                s.pairs.insert((c.a.0.min(c.b.0), c.a.0.max(c.b.0)));
            }
        }
    }

    /// Frames seen.
    pub fn frames(&self) -> u64 {
        self.frames
    }

    /// The summary as text: the recording's fields, timing, gaps, entity kinds, fields
    /// present, contacts, then a table of the entities. `source` says where it was read.
    pub fn render(&self, source: &str) -> String {
        let mut out = String::new();
        render(&mut out, source, &self.header, self);
        out
    }
}

fn render(out: &mut String, source: &str, h: &Header, s: &Summary) {
    line(out, "recording", format!("{} ({source})", h.id));
    line(
        out,
        "format",
        format!("{} {}", crate::FORMAT_NAME, crate::FORMAT_VERSION),
    );
    line(out, "participant", &h.participant);
    line(out, "task", &h.task);
    if !h.meta.is_empty() {
        let meta: Vec<String> = h.meta.iter().map(|(k, v)| format!("{k}={v}")).collect();
        line(out, "meta", meta.join(", "));
    }
    line(out, "frames", s.frames);
    let duration = s.last - s.first;
    if s.frames == 0 {
        line(out, "duration", "no frames");
    } else {
        line(
            out,
            "duration",
            format!("{duration:.3} s ({:.3} s to {:.3} s)", s.first, s.last),
        );
    }
    let measured = if s.frames > 1 && duration > 0.0 {
        format!(", {:.1} Hz measured", (s.frames - 1) as f64 / duration)
    } else {
        String::new()
    };
    line(
        out,
        "frame rate",
        format!("{} Hz nominal{measured}", h.frame_rate),
    );
    if s.frames > 1 {
        line(
            out,
            "intervals",
            format!("{} to {}", ms(s.min_dt), ms(s.max_dt)),
        );
        line(
            out,
            "gaps",
            if s.gaps == 0 {
                format!("none (no interval over {GAP} nominal periods)")
            } else {
                format!(
                    "{} interval{} over {GAP} nominal periods; longest {} after {:.3} s",
                    s.gaps,
                    if s.gaps == 1 { "" } else { "s" },
                    ms(s.longest_gap.0),
                    s.longest_gap.1
                )
            },
        );
    }
    let kinds: Vec<String> = EntityKind::ALL
        .iter()
        .filter_map(|&k| {
            let n = h.ids_of(k).count();
            (n > 0).then(|| format!("{n} {}", plural(k, n)))
        })
        .collect();
    line(
        out,
        "entities",
        format!("{} ({})", h.entities.len(), kinds.join(", ")),
    );
    let fields = fields_present(h, s);
    line(out, "fields", fields);
    line(
        out,
        "contacts",
        if s.contact_frames == 0 {
            "none reported".to_string()
        } else {
            format!(
                "in {} of {} frames; {} distinct pair{}",
                s.contact_frames,
                s.frames,
                s.pairs.len(),
                if s.pairs.len() == 1 { "" } else { "s" }
            )
        },
    );
    out.push('\n');
    let name_width = h
        .entities
        .iter()
        .map(|e| e.name.len())
        .max()
        .unwrap_or(0)
        .max(6);
    let _ = writeln!(
        out,
        "{:<name_width$}  {:<5}  {:<20}  {:<11}  {:<8}  {:<12}  holding",
        "entity", "kind", "size (m)", "observed", "velocity", "grip"
    );
    for (e, st) in h.entities.iter().zip(&s.entities) {
        let size = format!("{} x {} x {}", e.size.x, e.size.y, e.size.z);
        if e.fixed.is_some() {
            let _ = writeln!(
                out,
                "{:<name_width$}  {:<5}  {:<20}  fixed (pose in the header)",
                e.name,
                e.kind.name(),
                size
            );
            continue;
        }
        let grip = if st.grip_min.is_finite() {
            format!("{:.2} to {:.2}", st.grip_min, st.grip_max)
        } else {
            "-".into()
        };
        let holding = if st.holding == 0 {
            if e.kind == EntityKind::Hand {
                "never".to_string()
            } else {
                "-".to_string()
            }
        } else {
            let names: Vec<&str> = st
                .held
                .iter()
                .filter_map(|&i| h.entities.get(i as usize).map(|e| e.name.as_str()))
                .collect();
            format!("{} frames ({})", st.holding, names.join(", "))
        };
        let _ = writeln!(
            out,
            "{:<name_width$}  {:<5}  {:<20}  {:<11}  {:<8}  {:<12}  {}",
            e.name,
            e.kind.name(),
            size,
            format!("{}/{}", st.observed, s.frames),
            st.velocity,
            grip,
            holding
        );
    }
}

fn plural(k: EntityKind, n: usize) -> String {
    if n == 1 {
        k.name().to_string()
    } else {
        format!("{}s", k.name())
    }
}

/// Which optional fields appear, and for which entities: `pos rot (every observed
/// entity), vel (2 hands), grip (2 hands), holding (1 hand)`.
fn fields_present(h: &Header, s: &Summary) -> String {
    let moving: Vec<usize> = (0..h.entities.len())
        .filter(|&i| h.entities[i].fixed.is_none())
        .collect();
    let missing: u64 = moving
        .iter()
        .map(|&i| s.frames - s.entities[i].observed)
        .sum();
    let mut parts = vec![if missing == 0 {
        "pos rot (every entity in every frame)".to_string()
    } else {
        format!(
            "pos rot ({missing} entity state{} missing: tracking lost)",
            if missing == 1 { "" } else { "s" }
        )
    }];
    let count = |f: &dyn Fn(&EntityStats) -> bool| -> Vec<&str> {
        moving
            .iter()
            .filter(|&&i| f(&s.entities[i]))
            .map(|&i| h.entities[i].name.as_str())
            .collect()
    };
    for (name, with) in [
        ("vel", count(&|e| e.velocity > 0)),
        ("grip", count(&|e| e.grip_min.is_finite())),
        ("holding", count(&|e| e.holding > 0)),
    ] {
        if !with.is_empty() {
            parts.push(format!("{name} ({})", with.join(", ")));
        }
    }
    parts.join(", ")
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::{Entity, EntityState, Vec3};

    fn header() -> Header {
        Header {
            id: "demo".into(),
            participant: "p01".into(),
            task: "stack".into(),
            frame_rate: 10.0,
            entities: vec![
                Entity {
                    name: "right_hand".into(),
                    kind: EntityKind::Hand,
                    size: Vec3::new(0.1, 0.1, 0.1),
                    fixed: None,
                },
                Entity {
                    name: "cube_a".into(),
                    kind: EntityKind::Cube,
                    size: Vec3::new(0.05, 0.05, 0.05),
                    fixed: None,
                },
            ],
            meta: Default::default(),
        }
    }

    fn value<'a>(text: &'a str, key: &str) -> &'a str {
        text.lines()
            .find(|l| l.starts_with(key))
            .map_or("", |l| l[14..].trim())
    }

    #[test]
    fn gaps_grips_and_missing_states_are_counted() {
        let h = header();
        let mut summary = Summary::new(&h);
        for (i, t) in [0.0, 0.1, 0.2, 0.5].into_iter().enumerate() {
            let mut frame = Frame::empty(t, 2);
            frame.states[0] = Some(EntityState {
                grip: Some(0.2 * i as f32),
                ..Default::default()
            });
            if i != 2 {
                frame.states[1] = Some(EntityState::default());
            }
            summary.observe(&frame);
        }
        let text = summary.render("demo.jsonl");
        assert_eq!(summary.frames(), 4);
        assert_eq!(value(&text, "recording"), "demo (demo.jsonl)");
        assert_eq!(value(&text, "duration"), "0.500 s (0.000 s to 0.500 s)");
        assert_eq!(value(&text, "frame rate"), "10 Hz nominal, 6.0 Hz measured");
        assert_eq!(
            value(&text, "gaps"),
            "1 interval over 1.5 nominal periods; longest 300.0 ms after 0.200 s"
        );
        assert_eq!(value(&text, "entities"), "2 (1 hand, 1 cube)");
        assert!(
            value(&text, "fields").starts_with("pos rot (1 entity state missing"),
            "{text}"
        );
        let hand = text
            .lines()
            .find(|l| l.starts_with("right_hand"))
            .unwrap_or("");
        assert!(
            hand.contains("4/4") && hand.contains("0.00 to 0.60"),
            "{hand}"
        );
    }

    #[test]
    fn a_recording_without_frames_says_so() {
        let text = Summary::new(&header()).render("empty.jsonl");
        assert_eq!(value(&text, "duration"), "no frames");
        assert!(!text.contains("intervals"), "{text}");
    }
}
