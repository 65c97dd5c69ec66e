//! Ground truth: per frame and hand, what the simulated person was doing.
//!
//! The simulator knows its own noise-free state and intent: which phase of its script a
//! hand is in, which cube it goes for, when the grip closed. From the noise-free state it
//! computes the paper's hand-state variables by the paper's rules and thresholds (Table
//! 2) and the activity by the paper's rules (Table 1); the intent (phase, target) is
//! written beside them. This is the simulator's own code, independent of the grounding
//! stage it is there to check: it sees true positions, velocities and grips, where
//! grounding sees noisy frames.
//!
//! `actedOn` is the paper's geometric rule, not the intent: the nearest cube within
//! `acted_on_distance` of the palm that the hand moves towards, never the one in hand.
//! So a hand passing close by a cube on its way to another, heading for it, acts on it
//! for that moment, as the paper's rule says (and as grounding, which cannot know the
//! intent, sees it). Until the segmentation stage was measured against it, the truth
//! took only the scripted target; that made a rule no grounding from frames can follow
//! the reference, and most per-hand sequences differed by a passing Reach.

use std::io::{BufRead, Write};

use recording::{EntityId, Header};
use serde::{Deserialize, Serialize};

/// The `format` field of a ground-truth file.
pub const TRUTH_FORMAT_NAME: &str = "demoplan-truth";

/// The version of the ground-truth format.
pub const TRUTH_FORMAT_VERSION: u32 = 1;

/// The phase of the script a hand is in.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Phase {
    /// Resting (the idle hand, and the active hand before and after the task); small
    /// fidgets included.
    Rest,
    /// Moving towards a cube to grasp it (also the part of an aborted reach that heads
    /// for the wrong cube).
    Reach,
    /// Closing the hand on the cube, and resting while holding it before lifting.
    Grasp,
    /// Lifting and carrying the cube to above its place.
    Carry,
    /// The final descent onto the place.
    Approach,
    /// Opening the hand and letting the cube settle.
    Release,
    /// Moving away after releasing.
    Retreat,
}

impl Phase {
    /// Every phase, in script order.
    pub const ALL: [Phase; 7] = [
        Phase::Rest,
        Phase::Reach,
        Phase::Grasp,
        Phase::Carry,
        Phase::Approach,
        Phase::Release,
        Phase::Retreat,
    ];

    /// The name in files: `rest`, `reach`, ...
    pub fn name(self) -> &'static str {
        match self {
            Phase::Rest => "rest",
            Phase::Reach => "reach",
            Phase::Grasp => "grasp",
            Phase::Carry => "carry",
            Phase::Approach => "approach",
            Phase::Release => "release",
            Phase::Retreat => "retreat",
        }
    }
}

pub use recording::Activity;

/// One hand in one frame.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct HandTruth {
    /// The hand.
    pub hand: EntityId,
    /// The scripted phase.
    pub phase: Phase,
    /// The paper's activity, from the three variables below.
    pub activity: Activity,
    /// `handMove`: noise-free speed above the threshold.
    pub moving: bool,
    /// The noise-free speed (m/s).
    pub speed: f32,
    /// The cube the hand goes for in this phase (the cube to grasp; the cube to stack
    /// on), if any.
    pub target: Option<EntityId>,
    /// `actedOn`: the nearest cube (not the one in hand) that is close and that the hand
    /// moves towards; the target or not.
    pub acted_on: Option<EntityId>,
    /// `inHand`: the cube the closed hand holds.
    pub in_hand: Option<EntityId>,
}

/// Ground truth for one frame of the recording (same time, same order).
#[derive(Debug, Clone, PartialEq, Default)]
pub struct TruthFrame {
    /// The frame's time.
    pub time: f64,
    /// One entry per hand, in the order of the header's hands.
    pub hands: Vec<HandTruth>,
}

/// The first line of a ground-truth file.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct TruthHeader {
    /// `demoplan-truth`.
    pub format: String,
    /// 1.
    pub version: u32,
    /// The id of the recording this is the truth of.
    pub recording: String,
    /// The hands, by entity name.
    pub hands: Vec<String>,
    /// `handMove` threshold used (m/s).
    pub move_speed: f64,
    /// `actedOn` distance used (m).
    pub acted_on_distance: f64,
    /// `actedOn` least speed towards the target (m/s).
    pub toward_speed: f64,
}

#[derive(Serialize, Deserialize)]
struct HandLine<'a> {
    phase: Phase,
    activity: Activity,
    moving: bool,
    speed: f32,
    #[serde(borrow)]
    target: Option<&'a str>,
    #[serde(borrow)]
    acted_on: Option<&'a str>,
    #[serde(borrow)]
    in_hand: Option<&'a str>,
}

#[derive(Serialize, Deserialize)]
struct FrameLine<'a> {
    t: f64,
    #[serde(borrow)]
    hands: std::collections::BTreeMap<&'a str, HandLine<'a>>,
}

/// Writes a ground-truth file: the header line, then one line per frame.
#[derive(Debug)]
pub struct TruthWriter<W: Write> {
    out: W,
    names: Vec<String>,
}

impl<W: Write> TruthWriter<W> {
    /// Writes the header line. `recording` gives the entity names.
    pub fn new(mut out: W, header: &TruthHeader, recording: &Header) -> std::io::Result<Self> {
        serde_json::to_writer(&mut out, header)?;
        out.write_all(b"\n")?;
        Ok(TruthWriter {
            out,
            names: recording.entities.iter().map(|e| e.name.clone()).collect(),
        })
    }

    /// Writes one frame's truth.
    pub fn write(&mut self, frame: &TruthFrame) -> std::io::Result<()> {
        let names = &self.names;
        let name =
            |id: Option<EntityId>| id.and_then(|id| names.get(id.index()).map(String::as_str));
        let hands = frame
            .hands
            .iter()
            .map(|h| {
                (
                    name(Some(h.hand)).unwrap_or("?"),
                    HandLine {
                        phase: h.phase,
                        activity: h.activity,
                        moving: h.moving,
                        speed: h.speed,
                        target: name(h.target),
                        acted_on: name(h.acted_on),
                        in_hand: name(h.in_hand),
                    },
                )
            })
            .collect();
        let line = FrameLine {
            t: frame.time,
            hands,
        };
        serde_json::to_writer(&mut self.out, &line)?;
        self.out.write_all(b"\n")
    }

    /// Flushes and returns the output.
    pub fn finish(mut self) -> std::io::Result<W> {
        self.out.flush()?;
        Ok(self.out)
    }
}

/// A malformed ground-truth file.
#[derive(Debug, thiserror::Error)]
#[error("line {line}: {message}")]
pub struct TruthError {
    /// 1-based line.
    pub line: u64,
    /// What is wrong.
    pub message: String,
}

/// Reads a whole ground-truth file; `recording` resolves the entity names.
pub fn read_truth<R: BufRead>(
    input: R,
    recording: &Header,
) -> Result<(TruthHeader, Vec<TruthFrame>), TruthError> {
    let mut lines = input.lines();
    let err = |line: u64, message: String| TruthError { line, message };
    let first = lines
        .next()
        .ok_or_else(|| err(1, "empty file".into()))?
        .map_err(|e| err(1, e.to_string()))?;
    let header: TruthHeader =
        serde_json::from_str(&first).map_err(|e| err(1, format!("header: {e}")))?;
    if header.format != TRUTH_FORMAT_NAME || header.version != TRUTH_FORMAT_VERSION {
        return Err(err(
            1,
            format!(
                "not a ground-truth file of version {TRUTH_FORMAT_VERSION} (format `{}`, version {})",
                header.format, header.version
            ),
        ));
    }
    let mut frames = Vec::new();
    for (i, line) in lines.enumerate() {
        let n = i as u64 + 2;
        let text = line.map_err(|e| err(n, e.to_string()))?;
        if text.trim().is_empty() {
            continue;
        }
        let parsed: FrameLine<'_> =
            serde_json::from_str(&text).map_err(|e| err(n, e.to_string()))?;
        let find = |name: Option<&str>| -> Result<Option<EntityId>, TruthError> {
            name.map(|s| {
                recording
                    .find(s)
                    .ok_or_else(|| err(n, format!("unknown entity `{s}`")))
            })
            .transpose()
        };
        let mut hands = Vec::with_capacity(header.hands.len());
        for hand_name in &header.hands {
            let h = parsed
                .hands
                .get(hand_name.as_str())
                .ok_or_else(|| err(n, format!("no entry for hand `{hand_name}`")))?;
            hands.push(HandTruth {
                hand: find(Some(hand_name))?.unwrap_or(EntityId(0)),
                phase: h.phase,
                activity: h.activity,
                moving: h.moving,
                speed: h.speed,
                target: find(h.target)?,
                acted_on: find(h.acted_on)?,
                in_hand: find(h.in_hand)?,
            });
        }
        frames.push(TruthFrame {
            time: parsed.t,
            hands,
        });
    }
    Ok((header, frames))
}
