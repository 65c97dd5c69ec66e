//! Grounding and segmentation of a recording, the one copy of that pipeline: frames from
//! a reader (a file of any length, streamed) or from memory (simulated demonstrations,
//! tests) go through the `Grounder` into the `Segmenter`.

use std::convert::Infallible;
use std::io::BufRead;

use grounding::{FactSpace, GroundedFrame, Grounder, GroundingConfig};
use recording::{Frame, Header};
use segment::{Activity, ActivityTree, Segment, Segmenter, TableSegments};

use crate::domain::Scene;
use crate::hash::StableHasher;
use crate::library::{Added, Library, RecordingInfo};

/// A recording grounded and segmented.
#[derive(Debug, Clone)]
pub struct Segmented {
    /// The recording's header (for an ARFF table, the one its objects make).
    pub header: Header,
    /// The facts of its scene.
    pub space: FactSpace,
    /// Its segments, in the order they ended.
    pub segments: Vec<Segment>,
    /// Number of frames.
    pub frames: u64,
    /// Seconds from the first frame to the last.
    pub duration: f64,
}

impl Segmented {
    /// An ARFF hand-state table's segments, with the header its objects make.
    pub fn from_table(header: Header, table: TableSegments) -> Segmented {
        Segmented {
            header,
            space: table.space,
            segments: table.segments,
            frames: table.frames,
            duration: table.duration,
        }
    }
}

/// What a caller sees while a recording is segmented: every frame read with the grounder
/// after it (its signals, for the timeline), and every grounded frame when it is final.
pub trait Observer {
    /// A frame was read and pushed into the grounder.
    fn frame(&mut self, _frame: &Frame, _grounder: &Grounder) {}
    /// A frame left the grounder, final.
    fn grounded(&mut self, _frame: &GroundedFrame<'_>) {}
}

/// Sees nothing.
impl Observer for () {}

/// Keeps the grounded state of one frame (`wanted`, 0-based): a scene taken from a
/// recording.
#[derive(Debug, Clone)]
pub struct StateAt {
    /// The frame wanted.
    pub wanted: u64,
    /// Its state, once grounded.
    pub state: Option<grounding::State>,
}

impl Observer for StateAt {
    fn grounded(&mut self, g: &GroundedFrame<'_>) {
        if g.index == self.wanted {
            self.state = Some(g.state.clone());
        }
    }
}

/// The scene of frame `wanted` (0-based) of a recording, grounded with `config`
/// ([`Scene::from_state`]), and how many frames the recording has: no scene when it has
/// fewer. The recording is read to its end (and segmented with Table 1), so a damaged
/// line after the frame is still an error.
pub fn scene_at_frame<R: BufRead>(
    reader: &mut recording::Reader<R>,
    config: &GroundingConfig,
    wanted: u64,
) -> Result<(Option<Scene>, u64), recording::ReadError> {
    let mut at = StateAt {
        wanted,
        state: None,
    };
    let segmented = segment_reader(reader, config, &ActivityTree::table_one(), &mut at)?;
    let scene =
        (at.state).map(|state| Scene::from_state(&segmented.header, &segmented.space, &state));
    Ok((scene, segmented.frames))
}

/// Keeps every grounded frame's hand facts, to be joined with per-frame labels such as
/// the simulator's truth ([`HandsGrounded::labelled`]).
#[derive(Debug, Clone, Default)]
pub struct HandsGrounded {
    /// Per grounded frame: its index and the facts of each hand.
    pub frames: Vec<(u64, Vec<grounding::HandFacts>)>,
}

impl HandsGrounded {
    /// Each hand of each frame with its label: `labels` per frame index, per hand
    /// (frames without labels are left out).
    pub fn labelled<'a>(
        &'a self,
        labels: &'a [Vec<Activity>],
    ) -> impl Iterator<Item = (grounding::HandFacts, Activity)> + 'a {
        self.frames.iter().flat_map(move |(index, hands)| {
            let frame_labels = usize::try_from(*index)
                .ok()
                .and_then(|i| labels.get(i))
                .map_or(&[][..], Vec::as_slice);
            hands.iter().copied().zip(frame_labels.iter().copied())
        })
    }
}

impl Observer for HandsGrounded {
    fn grounded(&mut self, g: &GroundedFrame<'_>) {
        self.frames.push((g.index, g.hands.to_vec()));
    }
}

/// Grounds and segments frames drawn by `next` (which fills the frame and says whether
/// there was one) of a recording with this header: the pipeline both [`segment_reader`]
/// and [`segment_frames`] run. Memory is bounded by the grounder's window and the
/// segments, whatever the number of frames.
pub fn segment_with<E>(
    header: &Header,
    mut next: impl FnMut(&mut Frame) -> Result<bool, E>,
    config: &GroundingConfig,
    tree: &ActivityTree,
    observer: &mut dyn Observer,
) -> Result<Segmented, E> {
    let mut grounder = Grounder::new(header, config);
    let hands = grounder.space().hands().to_vec();
    let mut segmenter = Segmenter::new(&hands, tree.clone(), config.min_duration);
    let mut frame = Frame::default();
    let (mut frames, mut first, mut last) = (0u64, None, 0.0);
    while next(&mut frame)? {
        frames += 1;
        first.get_or_insert(frame.time);
        last = frame.time;
        grounder.push(&frame, &mut |g| {
            segmenter.push_grounded(g);
            observer.grounded(g);
        });
        observer.frame(&frame, &grounder);
    }
    grounder.finish(&mut |g| {
        segmenter.push_grounded(g);
        observer.grounded(g);
    });
    Ok(Segmented {
        header: header.clone(),
        space: grounder.space().clone(),
        segments: segmenter.finish(),
        frames,
        duration: last - first.unwrap_or(last),
    })
}

/// Grounds and segments a recording read a frame at a time (its header already read).
pub fn segment_reader<R: BufRead>(
    reader: &mut recording::Reader<R>,
    config: &GroundingConfig,
    tree: &ActivityTree,
    observer: &mut dyn Observer,
) -> Result<Segmented, recording::ReadError> {
    let header = reader.header().clone();
    segment_with(&header, |f| reader.read_frame(f), config, tree, observer)
}

/// Grounds and segments frames of a recording with this header, held in memory.
pub fn segment_frames(
    header: &Header,
    frames: impl IntoIterator<Item = Frame>,
    config: &GroundingConfig,
    tree: &ActivityTree,
) -> Segmented {
    let mut frames = frames.into_iter();
    let next =
        |f: &mut Frame| -> Result<bool, Infallible> { Ok(frames.next().map(|x| *f = x).is_some()) };
    match segment_with(header, next, config, tree, &mut ()) {
        Ok(segmented) => segmented,
        Err(never) => match never {},
    }
}

/// How a hand's segments are grouped into the activities that become operators.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
pub enum Grouping {
    /// Maximal runs of consecutive segments with the same class. Segments end wherever a
    /// hand's tuple changes, so a hand that stops and starts again while idle gives several
    /// Idle segments; the paper counts them as one Idle activity (its 115 activities from
    /// 12 demonstrations), and one operator should describe the whole activity.
    Runs,
    /// Runs, and an Idle run right after another activity of the same hand is that
    /// activity's settling: the activity ends where the Idle does. The hand that reached
    /// a cube comes to rest beside it; the stacked cube drops the last millimetres onto
    /// the one below as the hand opens. The paper maps each hand activity to "all the
    /// respectively caused environment changes", and its five-operator domain chains
    /// reach, take, put and stack directly (20 actions for the five cubes of its fifth
    /// goal); with Idle apart, the cube's landing and the release are Idle operators
    /// split by incidental hand state, and no tower is reachable from the most frequent
    /// operators (see docs/operators.md). Idle runs that start a hand's recording or
    /// follow nothing but Idle stay Idle activities.
    #[default]
    Settled,
}

impl Grouping {
    /// Both groupings, the default first.
    pub const ALL: [Grouping; 2] = [Grouping::Settled, Grouping::Runs];

    /// The name in library files and on the command line: `settled`, `runs`.
    pub fn name(self) -> &'static str {
        match self {
            Grouping::Runs => "runs",
            Grouping::Settled => "settled",
        }
    }

    /// The grouping with this name.
    pub fn from_name(name: &str) -> Option<Grouping> {
        Grouping::ALL.into_iter().find(|g| g.name() == name)
    }
}

/// `learn --activities`: the groupings by [`Grouping::name`], the default first, each
/// with its line of `--help`.
#[cfg(feature = "clap")]
impl clap::ValueEnum for Grouping {
    fn value_variants<'a>() -> &'a [Self] {
        &Grouping::ALL
    }

    fn to_possible_value(&self) -> Option<clap::builder::PossibleValue> {
        let help = match self {
            Grouping::Settled => "An activity ends where the Idle right after it ends",
            Grouping::Runs => {
                "Runs of one class; the Idle after an activity is an activity of its own"
            }
        };
        Some(clap::builder::PossibleValue::new(self.name()).help(help))
    }
}

/// The activities of a recording, grouped as `grouping` says; each is one segment (start
/// state of its first piece; end, end state, objects and tuple of its last). Sorted by
/// hand, then time.
pub fn activities(segments: &[Segment], grouping: Grouping) -> Vec<Segment> {
    let mut sorted: Vec<&Segment> = segments.iter().collect();
    sorted.sort_by(|a, b| a.hand.cmp(&b.hand).then(a.start.total_cmp(&b.start)));
    let mut out: Vec<Segment> = Vec::with_capacity(sorted.len());
    for s in sorted {
        match out.last_mut() {
            Some(last) if last.hand == s.hand && last.activity == s.activity => {
                last.end = s.end;
                last.frames += s.frames;
                last.moving = s.moving;
                last.acted_on = s.acted_on;
                last.in_hand = s.in_hand;
                union_objects(last, s);
                last.end_state = s.end_state.clone();
            }
            // Every piece of an Idle run after another activity is taken in: the
            // activity's class stays, so the run's next piece matches here again.
            Some(last)
                if grouping == Grouping::Settled
                    && last.hand == s.hand
                    && s.activity == Activity::Idle
                    && last.activity != Activity::Idle =>
            {
                // The settling: the activity keeps its class, objects and tuple, and
                // ends with the Idle's end state.
                last.end = s.end;
                last.frames += s.frames;
                union_objects(last, s);
                last.end_state = s.end_state.clone();
            }
            _ => out.push(s.clone()),
        }
    }
    out
}

/// Takes in the objects another piece of an activity held and acted on.
pub(crate) fn union_objects(activity: &mut Segment, piece: &Segment) {
    for (set, more) in [
        (&mut activity.held, &piece.held),
        (&mut activity.acted, &piece.acted),
    ] {
        set.extend_from_slice(more);
        set.sort_unstable();
        set.dedup();
    }
}

/// The content hash (16 hex digits) of a recording with these frames as demoplan's
/// writer writes it: the hash `demoplan learn` gives the file.
pub fn recording_hash(header: &Header, frames: &[Frame]) -> String {
    let mut hasher = StableHasher::new();
    if let Ok(mut writer) = recording::Writer::new(&mut hasher, header) {
        for f in frames {
            if writer.write_frame(f).is_err() {
                break;
            }
        }
        let _ = writer.finish();
    }
    format!("{:016x}", hasher.finish())
}

/// Grounds, segments and learns a recording held in memory (a simulated demonstration),
/// as `demoplan learn` does a file; `source` says where it came from.
pub fn add_frames(
    library: &mut Library,
    header: &Header,
    frames: Vec<Frame>,
    config: &GroundingConfig,
    tree: &ActivityTree,
    source: &str,
) -> Added {
    let hash = recording_hash(header, &frames);
    let segmented = segment_frames(header, frames, config, tree);
    library.add_recording(
        RecordingInfo {
            hash,
            id: header.id.clone(),
            participant: header.participant.clone(),
            source: source.to_string(),
            frames: segmented.frames,
            segments: 0,
            ..Default::default()
        },
        header,
        &segmented.space,
        &segmented.segments,
    )
}
