//! The operator library, the paper's core idea: every demonstrated segment becomes a
//! lifted planning operator, operators equal up to renaming of parameters are merged
//! with a count, the count becomes an action cost, and domains are built from the most
//! frequent operators first.
//!
//! - [`lift`] turns a [`segment::Segment`] into an [`Operator`]: its objects are the
//!   segment's hand, the object in hand, the object acted on and the arguments of the
//!   facts that change; the precondition is every fact over them (positive or negative)
//!   in the state the segment starts from, the effects what differs at its last frame.
//! - [`Library`] merges and counts operators, remembers their provenance and the
//!   recordings (by content hash, never counted twice), names operators by rank (`put`,
//!   `put2`, ...) and costs them with `ceil(lambda * (1 - count / type_count))`. Its
//!   JSON form is versioned and deterministic: the same recordings give the same bytes
//!   in any learning order.
//! - [`generalise()`] merges the operators of one type whose effects are equal up to
//!   renaming into one that keeps only their shared precondition facts: a library of
//!   [`OperatorForm::Generalised`] operators (`learn --generalise`) counts and ranks
//!   those, computed from the demonstrated ones it keeps.
//! - [`operator_subset`] and [`levels`] are the paper's `OperatorSubset` and the levels
//!   of its Algorithm 1; [`domain`] and [`problem`] write PDDL through the `pddl` crate.
//!
//! - [`segment_reader`] is the pipeline from frames to segments (grounding, then
//!   segmentation), the one every command runs; [`timeline`] draws its result.
//!
//! ```
//! use learn::{cost, Library};
//! assert_eq!(cost(100, 1, 3), 67); // ceil(100 * (1 - 1/3))
//! assert!(Library::default().is_empty());
//! ```

mod cards;
mod cause;
mod domain;
mod files;
mod generalise;
mod hash;
mod inputs;
mod library;
mod listing;
mod lock;
mod meaning;
mod mend;
mod operator;
mod pipeline;
mod scoring;
mod timeline;
mod update;

pub use cards::{cards_markdown, cards_text, domain_text, levels_table, summary_table};
pub use cause::{cause, changes, held, Cause, Changes, OtherHands, OwnHand};
pub use domain::{
    action, chosen_domain, domain, domain_name, levels, operator_subset, paper_goal_tower,
    pddl_predicate, per_type, problem, tower_goal, DomainChoice, DomainOptions, EmptyDomain, Level,
    Scene, Tower, TowerError, DEFAULT_CUBES, DEFAULT_HANDS,
};
pub use files::{
    arff_reader, hand_table, labelled_frames, learn_tree, nominal_dataset, read_truth,
    segment_arff, segment_path, FileError, Labelled, TreeError, ARFF_FRAME_RATE,
};
pub use generalise::{covers, effect_key, generalise, FormArgs, OperatorForm, ALIGNMENT_BUDGET};
pub use hash::{stable_hash, StableHasher};
pub use inputs::{content_hash, learning_inputs, Batch, Inputs, InputsError};
pub use library::{
    cost, display_name, Added, Entry, Library, LibraryError, Provenance, Ranked, RecordingInfo,
    DEFAULT_LAMBDA, FORMAT_NAME, FORMAT_VERSION,
};
pub use lock::{lock_path, resolve_target, LockError, Waiting, WriteLock};
pub use meaning::{breaches, holding, Breach};
pub use mend::{meaning_of, mend, MendCounts};
pub use operator::{fact_text, lift, lift_all, Lifted, LiftedFact, Operator, ParamType};
pub use pipeline::{
    activities, add_frames, recording_hash, scene_at_frame, segment_frames, segment_reader,
    segment_with, Grouping, HandsGrounded, Observer, Segmented, StateAt,
};
pub use scoring::{truth_activities, truth_classes, truth_hand_facts};
pub use timeline::{activity_color, timeline, Signals};
pub use update::{LibraryFileError, Update, UpdateError, Updated};
