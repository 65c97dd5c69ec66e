//! Segmentation and classification of demonstrations (the paper's Table 1), decision
//! trees as data, a C4.5 learner, and ARFF import of symbolic hand-state tables.
//!
//! A [`Segmenter`] takes grounded frames ([`grounding::GroundedFrame`]: per hand its
//! [`grounding::HandFacts`], and the state) and cuts each hand's time where its tuple
//! (handMove, actedOn is an object, inHand is an object) changes; a segment shorter than
//! the minimum duration merges into a neighbour. Each [`Segment`] has its hand, start,
//! end, [`Activity`], the objects in hand and acted on, and two states: the facts at the
//! last frame before it and at its last frame.
//!
//! Classification is an [`ActivityTree`]: a [`DecisionTree`] over hand [`Feature`]s whose
//! default is the paper's Table 1 ([`ActivityTree::table_one`]); trees print as Weka's
//! J48 prints them and are stored as JSON. [`C45`] learns one from a [`Dataset`] of
//! labelled cases. [`read_arff`] reads Weka ARFF tables, and
//! [`ArffTable::hand_frames`] reads one as the hand-state frames of the activity
//! recognisers this work builds on; [`ArffReader`] and [`HandTable`] read the same a row
//! at a time, for tables of any length. [`evaluate`] measures segments against labels.
//!
//! ```
//! use grounding::{GroundingConfig, Grounder};
//! use segment::{Activity, ActivityTree, Segmenter};
//!
//! let text = std::fs::read_to_string(concat!(
//!     env!("CARGO_MANIFEST_DIR"),
//!     "/../../docs/examples/two-cubes.jsonl"
//! ))?;
//! let recording = recording::Recording::read(text.as_bytes())?;
//! // The example has 2 frames a second: no minimum duration.
//! let config = GroundingConfig::from_toml("min_duration = 0.0")?;
//! let mut grounder = Grounder::new(&recording.header, &config);
//! let hands = grounder.space().hands().to_vec();
//! let mut segmenter = Segmenter::new(&hands, ActivityTree::table_one(), 0.0);
//! for frame in &recording.frames {
//!     grounder.push(frame, &mut |g| segmenter.push_grounded(g));
//! }
//! grounder.finish(&mut |g| segmenter.push_grounded(g));
//! let activities: Vec<Activity> = segmenter.finish().iter().map(|s| s.activity).collect();
//! assert!(activities.contains(&Activity::Put));
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```
//!
//! The crate does no I/O and never prints.

mod arff;
mod c45;
mod check;
pub mod evaluate;
mod labels;
mod segmenter;
mod tree;

pub use arff::{
    dataset, is_arff_file, is_arff_text, is_hand_state, read_arff, ArffAttribute, ArffError,
    ArffKind, ArffReader, ArffRow, ArffTable, ArffWarning, FrameActivities, HandFrames, HandTable,
    HandTableFrames, LabelledFrame, TableSegments, UnknownLabels, WEKA_DUMMY_STRING,
};
pub use c45::{add_errors, Case, Dataset, C45};
pub use check::{learn_activity_tree, Confusion, LearnedTree};
pub use labels::{LabelMap, LabelMapError, UnknownLabel};
pub use segmenter::{Segment, Segmenter};
pub use tree::{
    Activity, ActivityTree, Attribute, DecisionTree, Feature, Node, TreeError, TREE_FORMAT,
};
