//! Segmentation of simulated demonstrations measured against the simulator's ground
//! truth; shared by `tests/simulated.rs` and the examples `accuracy` and `diagnose`.

#![allow(dead_code)]

use grounding::{Grounder, GroundingConfig, HandFacts};
use recording::Frame;
use segment::evaluate::{
    agreement, frame_activities, segment_sequence, sequence, sequence_matches,
};
use segment::{Activity, ActivityTree, Segment, Segmenter};
use simulate::{Demonstration, TruthFrame};

/// Frames closer than this to a boundary of the truth are not counted (s).
pub const IGNORE: f64 = 0.1;

/// One demonstration's result.
#[derive(Debug, Clone)]
pub struct Measured {
    pub id: String,
    /// Frames (of both hands) that agree, and that were counted.
    pub agree: usize,
    pub counted: usize,
    /// Per hand: whether the sequence of activities equals the truth's, where runs of the
    /// truth that lie wholly within `IGNORE` of their boundaries may be left out ...
    pub sequence_equal: Vec<bool>,
    /// ... with the truth's runs shorter than the minimum duration merged as segments
    /// are ...
    pub merged_equal: Vec<bool>,
    /// ... and with every run of the truth, however short.
    pub strict_equal: Vec<bool>,
    /// Per hand: (segmented, truth) sequences, for messages.
    pub sequences: Vec<(Vec<Activity>, Vec<Activity>)>,
}

impl Measured {
    pub fn agreement(&self) -> f64 {
        self.agree as f64 / self.counted.max(1) as f64
    }

    pub fn all_sequences_equal(&self) -> bool {
        self.sequence_equal.iter().all(|&x| x)
    }
}

/// Renders, grounds and segments a demonstration.
pub fn run(
    demo: &Demonstration,
    config: &GroundingConfig,
    tree: &ActivityTree,
) -> (Vec<Frame>, Vec<TruthFrame>, Vec<Segment>) {
    let (frames, truth): (Vec<Frame>, Vec<TruthFrame>) = demo.frames().unzip();
    let mut grounder = Grounder::new(demo.header(), config);
    let hands = grounder.space().hands().to_vec();
    let mut segmenter = Segmenter::new(&hands, tree.clone(), config.min_duration);
    for f in &frames {
        grounder.push(f, &mut |g| segmenter.push_grounded(g));
    }
    grounder.finish(&mut |g| segmenter.push_grounded(g));
    (frames, truth, segmenter.finish())
}

pub fn measure(demo: &Demonstration, config: &GroundingConfig, tree: &ActivityTree) -> Measured {
    let (frames, truth, segments) = run(demo, config, tree);
    let times: Vec<f64> = frames.iter().map(|f| f.time).collect();
    let mut m = Measured {
        id: demo.id.clone(),
        agree: 0,
        counted: 0,
        sequence_equal: Vec::new(),
        merged_equal: Vec::new(),
        strict_equal: Vec::new(),
        sequences: Vec::new(),
    };
    let nh = truth.first().map_or(0, |t| t.hands.len());
    for h in 0..nh {
        let hand = truth[0].hands[h].hand;
        let labels: Vec<Activity> = truth.iter().map(|t| t.hands[h].activity).collect();
        let predicted = frame_activities(&segments, hand, &times);
        let (a, c) = agreement(&times, &predicted, &labels, IGNORE);
        m.agree += a;
        m.counted += c;
        let ours = segment_sequence(&segments, hand);
        let theirs = sequence(&times, &labels, config.min_duration);
        m.sequence_equal
            .push(sequence_matches(&times, &labels, &ours, IGNORE));
        m.merged_equal.push(ours == theirs);
        m.strict_equal.push(ours == sequence(&times, &labels, 0.0));
        m.sequences.push((ours, theirs));
    }
    m
}

/// Every grounded hand frame of a demonstration with the truth's activity.
pub fn labelled_frames(
    demo: &Demonstration,
    config: &GroundingConfig,
) -> Vec<(HandFacts, Activity)> {
    let (frames, truth): (Vec<Frame>, Vec<TruthFrame>) = demo.frames().unzip();
    let mut grounder = Grounder::new(demo.header(), config);
    let mut out = Vec::new();
    let mut take = |g: &grounding::GroundedFrame<'_>| {
        if let Some(t) = truth.get(g.index as usize) {
            for (h, th) in g.hands.iter().zip(&t.hands) {
                out.push((*h, th.activity));
            }
        }
    };
    for f in &frames {
        grounder.push(f, &mut take);
    }
    grounder.finish(&mut take);
    out
}

/// The command line of the examples that measure simulated studies: `FIRST_SEED COUNT
/// [PARTICIPANTS PER_PARTICIPANT [GROUNDING.toml]]`, defaults 1, `default_count`, 3
/// and 4 (the paper's study shape) and the default grounding.
pub struct StudyArgs {
    pub seeds: std::ops::Range<u64>,
    pub participants: u32,
    pub per_participant: u32,
    pub config: GroundingConfig,
}

impl StudyArgs {
    pub fn from_env(default_count: u64) -> Result<StudyArgs, Box<dyn std::error::Error>> {
        let args: Vec<String> = std::env::args().collect();
        let first: u64 = args.get(1).map_or(Ok(1), |s| s.parse())?;
        let count: u64 = args.get(2).map_or(Ok(default_count), |s| s.parse())?;
        let participants: u32 = args.get(3).map_or(Ok(3), |s| s.parse())?;
        let per_participant: u32 = args.get(4).map_or(Ok(4), |s| s.parse())?;
        let config = match args.get(5) {
            Some(path) => GroundingConfig::from_toml(&std::fs::read_to_string(path)?)?,
            None => GroundingConfig::default(),
        };
        Ok(StudyArgs {
            seeds: first..first + count,
            participants,
            per_participant,
            config,
        })
    }
}
