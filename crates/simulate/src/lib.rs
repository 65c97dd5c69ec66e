//! Simulated VR demonstrations of people stacking cubes, in demoplan's recording format,
//! with ground truth.
//!
//! The paper's recordings (people stacking 5 cm cubes in Virtual Reality) are not public;
//! this crate makes realistic stand-ins, deterministic per seed. A scene is a table with
//! cubes and two hands. Each [`Participant`] has a style drawn from [`SimParams`]: speed,
//! handedness, grip levels, and how often they rest the hand after grasping (the paper's
//! `Put` against `Put2`). A demonstration is a script of minimum-jerk movements (reach,
//! grasp, carry, approach, release, retreat) with pauses, aborted reaches, regrasps and
//! an idle hand that drifts and fidgets; movements aim at where things really are when
//! they start. Rendering steps the noise-free world (grips close and open with first-order
//! dynamics, a grab system attaches the cube when the grip closes near it, released cubes
//! drop onto what is below) and writes what a tracker reports: poses with a few
//! millimetres of slowly varying error and jitter, noisy velocities and grips, dropped
//! frames and timestamp jitter.
//!
//! Beside each frame the simulator gives its ground truth ([`TruthFrame`]): per hand the
//! scripted [`Phase`] and target (its intent), the paper's hand-state variables computed
//! by the paper's rules from the noise-free state, and the [`Activity`] of the paper's
//! Table 1.
//!
//! ```
//! let params = simulate::SimParams::default();
//! let study = simulate::study(&params, 7, 1, 1)?;
//! let demo = &study.demonstrations[0];
//! let mut activities = std::collections::BTreeSet::new();
//! for (frame, truth) in demo.frames() {
//!     assert_eq!(frame.states.len(), demo.header().entities.len());
//!     activities.extend(truth.hands.iter().map(|h| h.activity));
//! }
//! assert!(activities.contains(&simulate::Activity::Reach));
//! # Ok::<(), simulate::ParamError>(())
//! ```

mod manifest;
mod motion;
mod params;
mod render;
mod rng;
mod script;
mod study;
mod style;
mod truth;

pub use manifest::{
    manifest, truth_path, write_study, written_listing, WriteStudyError, Written, MANIFEST,
};
pub use params::{Interval, ParamError, SimParams};
pub use render::Frames;
pub use rng::Rng;
pub use study::{session, study, Demonstration, Participant, Placement, Side, Study, Target};
pub use style::Style;
pub use truth::{
    read_truth, Activity, HandTruth, Phase, TruthError, TruthFrame, TruthHeader, TruthWriter,
    TRUTH_FORMAT_NAME, TRUTH_FORMAT_VERSION,
};

/// The seed of the embedded default study, the one later stages reproduce the paper with.
pub const DEFAULT_SEED: u64 = 7;

/// Participants in the paper's study.
pub const DEFAULT_PARTICIPANTS: u32 = 3;

/// Demonstrations per participant in the paper's study.
pub const DEFAULT_PER_PARTICIPANT: u32 = 4;

/// The embedded default: the paper's 3 participants times 4 demonstrations, seed 7,
/// default parameters.
pub fn default_study() -> Study {
    // The defaults are valid (a unit test checks it), so this cannot fail; fall back to
    // an empty study rather than panic.
    study(
        &SimParams::default(),
        DEFAULT_SEED,
        DEFAULT_PARTICIPANTS,
        DEFAULT_PER_PARTICIPANT,
    )
    .unwrap_or_else(|_| Study {
        seed: DEFAULT_SEED,
        params: SimParams::default(),
        participants: Vec::new(),
        demonstrations: Vec::new(),
    })
}

impl Iterator for Frames<'_> {
    type Item = (recording::Frame, TruthFrame);

    fn next(&mut self) -> Option<Self::Item> {
        let mut frame = recording::Frame::default();
        let mut truth = TruthFrame::default();
        self.next_into(&mut frame, &mut truth)
            .then_some((frame, truth))
    }
}
