//! What an activity's class means for its effects (the paper's Table 1 read as effects),
//! and the activities whose effects say otherwise.
//!
//! In grounded facts, for the activity's own hand `h`:
//! - Idle adds no `inHand`, `onTop` or `inTouch`, and ends acting on no cube it did not
//!   act on at its start;
//! - Reach ends with `actedOn(h, c)` or `graspable(h, c)` of a cube and adds no `inHand`;
//! - Take ends with `inHand(h, c)`;
//! - Stack ends with the cube it held no longer `inHand` and `onTop` the table or a cube;
//!   Put ends so too, or still holding its cube: the paper's own chain Reach, Take, Put,
//!   Stack carries the cube with the Put (its Put and Put2 both hold the cube at the
//!   end; docs/operators.md).

use grounding::{Fact, FactSpace, Predicate, State};
use recording::EntityId;
use segment::{Activity, Segment};

/// How an activity's effects contradict its class. Written in library files by
/// [`Breach::name`].
#[derive(
    Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord, serde::Serialize, serde::Deserialize,
)]
#[serde(rename_all = "kebab-case")]
pub enum Breach {
    /// An Idle whose hand's changes add `inHand`, `onTop` or `inTouch`.
    IdleChangesThings,
    /// An Idle that ends acting on a cube it did not act on (Table 1's Idle acts on
    /// nothing: the end of a Reach merged into it).
    IdleActsOn,
    /// A Reach that ends acting on no cube and with none graspable.
    ReachEndsAtNothing,
    /// A Reach that adds `inHand`.
    ReachGrasps,
    /// A Take that ends holding nothing.
    TakeEndsEmpty,
    /// A Stack that ends still holding the cube it held.
    PlacementKeepsCube,
    /// A cube that leaves its support before its hand is seen to hold it (a grasp known
    /// from geometry is seen once the cube moves with the hand): the lift-off is moved to
    /// the activity that holds it. Not a breach of a class: counted by mending.
    LiftBeforeGrasp,
    /// A cube that lands while its hand is still seen to hold it (the release from
    /// geometry is seen once the hand moves off): the landing is moved to the activity
    /// that lets it go. Counted by mending.
    LandingBeforeRelease,
    /// A Put or Stack whose cube ends on nothing (not on the table, not on a cube).
    PlacementLeavesCubeUnsupported,
}

impl Breach {
    /// Every breach, in order.
    pub const ALL: [Breach; 9] = [
        Breach::IdleChangesThings,
        Breach::IdleActsOn,
        Breach::ReachEndsAtNothing,
        Breach::ReachGrasps,
        Breach::TakeEndsEmpty,
        Breach::PlacementKeepsCube,
        Breach::PlacementLeavesCubeUnsupported,
        Breach::LiftBeforeGrasp,
        Breach::LandingBeforeRelease,
    ];

    /// Whether mending answers it ([`crate::mend`]). A Reach that ends at nothing (a hand
    /// passing close to a cube) and a Take that ends empty (a cube taken again and set
    /// down where it was) are what Table 1 calls those motions even without noise: they
    /// are counted, not mended, and their operators change nothing in the scene.
    pub fn is_mended(self) -> bool {
        !matches!(self, Breach::ReachEndsAtNothing | Breach::TakeEndsEmpty)
    }

    /// A short name for reports.
    pub fn name(self) -> &'static str {
        match self {
            Breach::IdleChangesThings => "idle-changes-things",
            Breach::IdleActsOn => "idle-acts-on",
            Breach::ReachEndsAtNothing => "reach-ends-at-nothing",
            Breach::ReachGrasps => "reach-grasps",
            Breach::TakeEndsEmpty => "take-ends-empty",
            Breach::PlacementKeepsCube => "placement-keeps-cube",
            Breach::PlacementLeavesCubeUnsupported => "placement-leaves-cube-unsupported",
            Breach::LiftBeforeGrasp => "lift-before-grasp",
            Breach::LandingBeforeRelease => "landing-before-release",
        }
    }
}

fn holds(state: &State, space: &FactSpace, fact: Fact) -> bool {
    space.id(&fact).is_some_and(|id| state.contains(id))
}

/// The objects `hand` holds in `state`.
pub fn holding(state: &State, space: &FactSpace, hand: EntityId) -> Vec<EntityId> {
    (space.objects().iter().copied())
        .filter(|&o| holds(state, space, Fact::binary(Predicate::InHand, hand, o)))
        .collect()
}

/// Whether `cube` stands on something (the table, a cube) in `state`.
fn supported(state: &State, space: &FactSpace, cube: EntityId) -> bool {
    (space.things().iter().copied())
        .any(|t| t != cube && holds(state, space, Fact::binary(Predicate::OnTop, cube, t)))
}

/// Whether the states say where things rest: some thing stands on another. A hand-state
/// table (ARFF) has no geometry, and its states never do.
fn has_geometry(start: &State, end: &State, space: &FactSpace) -> bool {
    [start, end]
        .iter()
        .any(|s| s.facts(space).any(|f| f.predicate == Predicate::OnTop))
}

/// The breaches of an activity whose own hand caused `own` (its effects, from
/// [`crate::changes`]), first the one that decides how it is mended.
pub fn breaches(activity: &Segment, own: &[Fact], space: &FactSpace) -> Vec<Breach> {
    let hand = activity.hand;
    let end = &activity.end_state;
    let start = &activity.start_state;
    let added = |p: Predicate| {
        own.iter()
            .any(|f| f.predicate == p && !holds(start, space, *f))
    };
    let mut out = Vec::new();
    match activity.activity {
        Activity::Idle => {
            if added(Predicate::InHand) || added(Predicate::OnTop) || added(Predicate::InTouch) {
                out.push(Breach::IdleChangesThings);
            }
            let acts_at_end = space
                .objects()
                .iter()
                .any(|&o| holds(end, space, Fact::binary(Predicate::ActedOn, hand, o)));
            if added(Predicate::ActedOn) && acts_at_end {
                out.push(Breach::IdleActsOn);
            }
        }
        Activity::Reach => {
            if added(Predicate::InHand) {
                out.push(Breach::ReachGrasps);
            }
            let near = space.objects().iter().any(|&o| {
                holds(end, space, Fact::binary(Predicate::ActedOn, hand, o))
                    || holds(end, space, Fact::binary(Predicate::Graspable, hand, o))
            });
            if !near {
                out.push(Breach::ReachEndsAtNothing);
            }
        }
        Activity::Take => {
            if holding(end, space, hand).is_empty() {
                out.push(Breach::TakeEndsEmpty);
            }
        }
        Activity::Put | Activity::Stack => {
            let mut cubes = activity.held.clone();
            cubes.extend(holding(start, space, hand));
            cubes.sort_unstable();
            cubes.dedup();
            let still = holding(end, space, hand);
            // A Put may carry its cube on: the paper's chain is Reach, Take, Put, Stack.
            let keeps = cubes.iter().any(|c| still.contains(c));
            if keeps && activity.activity == Activity::Stack {
                out.push(Breach::PlacementKeepsCube);
            } else if has_geometry(start, end, space)
                && (cubes.iter()).any(|&c| !still.contains(&c) && !supported(end, space, c))
            {
                out.push(Breach::PlacementLeavesCubeUnsupported);
            }
        }
    }
    out
}
