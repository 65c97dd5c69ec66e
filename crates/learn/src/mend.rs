//! Mending activities whose effects contradict their class ([`crate::breaches`]):
//! relabelled by what their effects mean, joined with a neighbour, or dropped as noise
//! (docs/operators.md, "Activities that mean what they say").
//!
//! Why activities breach their class, found on simulated and real recordings:
//! - the segmenter merges a segment shorter than the minimum duration into a neighbour,
//!   and the neighbour takes its end state: an Idle that absorbed a short grasp ends
//!   holding a cube, a Reach that absorbed the closing hand adds `inHand`;
//! - a hand that passes close to a cube on its way back to rest is, for a moment,
//!   acting on it (Table 1's Reach) but ends at nothing;
//! - a Stack whose hand hovers above the tower before the descent is split in two, the
//!   first part still holding the cube;
//! - grasps known only from geometry flicker where the tracker loses the hand.
//!
//! The rules, one activity at a time, in order:
//! - a Stack that ends still holding its cube is completed by the hand's next activity
//!   when that one lets the cube go (a Stack or Put, or a Take in which the hand rests on
//!   the tower and opens): the two join, with the class the landing means;
//! - any other breach: the activity gets the class its effects mean ([`meaning_of`]):
//!   Take when it ends holding a cube it did not hold, Put when it ends still carrying
//!   one, Stack or Put when it let a cube come to rest on a cube or the table, Reach when it ends acting on or next to a cube,
//!   Idle when it changed nothing in the scene;
//! - effects no class means (a cube set down by a hand that never held it) are noise:
//!   the activity is dropped.
//!
//! Then the activities are grouped again as the library's grouping says (a relabelled
//! activity may join its neighbour of the same class, or settle the one before it), and
//! an activity that still breaches its class is dropped. A Put may end still holding its
//! cube: the paper's chain Reach, Take, Put, Stack carries the cube with the Put.

use std::collections::BTreeMap;

use grounding::{Fact, FactSpace, Predicate, State};
use recording::EntityId;
use segment::{Activity, Segment};

use crate::cause::{changes, OtherHands};
use crate::meaning::{breaches, holding, Breach};
use crate::pipeline::{activities, union_objects, Grouping};

/// What mending did, per breach: activities mended (relabelled or joined) and dropped.
#[derive(Debug, Clone, Default, PartialEq, Eq)]
pub struct MendCounts {
    /// Mended activities per breach.
    pub mended: BTreeMap<Breach, u64>,
    /// Dropped activities per breach.
    pub dropped: BTreeMap<Breach, u64>,
}

impl MendCounts {
    /// Activities mended, over every breach.
    pub fn mended_total(&self) -> u64 {
        (self.mended.values()).fold(0u64, |sum, n| sum.saturating_add(*n))
    }

    /// Activities dropped, over every breach.
    pub fn dropped_total(&self) -> u64 {
        (self.dropped.values()).fold(0u64, |sum, n| sum.saturating_add(*n))
    }

    /// Adds another's counts.
    pub fn add(&mut self, other: &MendCounts) {
        for (mine, theirs) in [
            (&mut self.mended, &other.mended),
            (&mut self.dropped, &other.dropped),
        ] {
            for (b, n) in theirs {
                let count = mine.entry(*b).or_default();
                *count = count.saturating_add(*n);
            }
        }
    }

    /// The line `demoplan learn` prints: `mended 3 activities (stack keeps its cube 3),
    /// dropped 0; 2 changes no hand caused`.
    pub fn line(&self, uncaused: u64) -> String {
        let per = |m: &BTreeMap<Breach, u64>| {
            let parts: Vec<String> = m.iter().map(|(b, n)| format!("{} {n}", b.name())).collect();
            if parts.is_empty() {
                String::new()
            } else {
                format!(" ({})", parts.join(", "))
            }
        };
        format!(
            "mended {} activities{}, dropped {}{}; {uncaused} changes no hand caused\n",
            self.mended_total(),
            per(&self.mended),
            self.dropped_total(),
            per(&self.dropped),
        )
    }
}

fn holds(state: &State, space: &FactSpace, fact: Fact) -> bool {
    space.id(&fact).is_some_and(|id| state.contains(id))
}

/// The class an activity's effects mean (see the module documentation), or `None` when
/// no class means them. `own` are the changes its hand caused.
pub fn meaning_of(activity: &Segment, own: &[Fact], space: &FactSpace) -> Option<Activity> {
    let hand = activity.hand;
    let (start, end) = (&activity.start_state, &activity.end_state);
    let added = |f: &Fact| !holds(start, space, *f) && holds(end, space, *f);
    let held_before = holding(start, space, hand);
    let held_after = holding(end, space, hand);
    if held_after.iter().any(|c| !held_before.contains(c)) {
        return Some(Activity::Take);
    }
    if !held_after.is_empty() {
        // Still carrying what it held: the paper's Put, a carry.
        return Some(Activity::Put);
    }
    let mut moved: Vec<EntityId> = activity.held.clone();
    moved.extend(&held_before);
    let landed = own
        .iter()
        .find(|f| f.predicate == Predicate::OnTop && added(f) && moved.contains(&f.first()));
    if let Some(f) = landed {
        let on_cube = space.objects().contains(&f.second());
        return Some(if on_cube {
            Activity::Stack
        } else {
            Activity::Put
        });
    }
    let things_changed = own
        .iter()
        .any(|f| matches!(f.predicate, Predicate::OnTop | Predicate::InTouch) && added(f));
    if things_changed {
        return None;
    }
    let near = space.objects().iter().any(|&o| {
        holds(end, space, Fact::binary(Predicate::ActedOn, hand, o))
            || holds(end, space, Fact::binary(Predicate::Graspable, hand, o))
    });
    let acts_newly = space.objects().iter().any(|&o| {
        let f = Fact::binary(Predicate::ActedOn, hand, o);
        !holds(start, space, f) && holds(end, space, f)
    });
    // An Idle that ends near a cube is a hand at rest beside it; one that came to act on
    // a cube is the end of a Reach.
    let reached = if activity.activity == Activity::Idle {
        acts_newly
    } else {
        near
    };
    if reached && held_after.is_empty() {
        return Some(Activity::Reach);
    }
    Some(Activity::Idle)
}

fn own_changes(activity: &Segment, all: &[Segment], space: &FactSpace) -> Vec<Fact> {
    let others = OtherHands::during(activity, all, space);
    changes(
        activity,
        &activity.start_state,
        &activity.end_state,
        &others,
        space,
    )
    .own
}

/// Joins `later` into `earlier`: one activity over both spans, with the later one's class.
fn join(earlier: &Segment, later: &Segment) -> Segment {
    let mut joined = later.clone();
    joined.start = earlier.start;
    joined.frames += earlier.frames;
    joined.start_state = earlier.start_state.clone();
    union_objects(&mut joined, earlier);
    joined
}

/// The activities of a recording (from [`activities`], sorted by hand, then time)
/// mended, and what was done. Under [`Grouping::Runs`] nothing is mended: there the Idle
/// after a Stack is the cube landing, an Idle that changes things by design.
pub fn mend(
    grouped: &[Segment],
    grouping: Grouping,
    space: &FactSpace,
) -> (Vec<Segment>, MendCounts) {
    if grouping == Grouping::Runs {
        return (grouped.to_vec(), MendCounts::default());
    }
    let mut aligned = grouped.to_vec();
    let mut counts = align_with_hold(&mut aligned, space);
    let (mended, more) = mend_pass(&aligned, space);
    counts.add(&more);
    regroup(mended, grouping, space, counts)
}

/// Whether `f` relates `cube` to what it stands on or touches, `cube` being the upper.
fn rests(f: &Fact, cube: EntityId) -> bool {
    match f.predicate {
        Predicate::OnTop => f.first() == cube,
        Predicate::InTouch => f.args().contains(&cube),
        _ => false,
    }
}

/// Sets `facts` in a state to `on`.
fn set_facts(state: &mut State, facts: &[Fact], on: bool, space: &FactSpace) {
    let mut these = space.empty_state();
    for f in facts {
        if let Some(id) = space.id(f) {
            these.insert(id);
        }
    }
    *state = if on {
        let mut union = state.clone();
        for id in these.ids() {
            union.insert(id);
        }
        union
    } else {
        state.difference(&these)
    };
}

/// A cube leaves its support when a hand grasps it and lands when the hand lets it go;
/// where grasps are known from geometry alone, the hold is seen late (the cube must move
/// with the hand first) and let go late (the hand must move off). Between two activities
/// of a hand, such a change seen before the hold changes belongs with it: the cube's
/// lift-off that an activity not holding it shows, when the hand's next activity holds
/// it, moves to that one; the landing that an activity still holding its cube shows, when
/// the next one lets the cube go, moves to that one. Moving a change is moving the
/// boundary state between the two. Counted as [`Breach::LiftBeforeGrasp`] and
/// [`Breach::LandingBeforeRelease`].
fn align_with_hold(activities: &mut [Segment], space: &FactSpace) -> MendCounts {
    let mut counts = MendCounts::default();
    for i in 1..activities.len() {
        let (before, after) = activities.split_at_mut(i);
        let (x, y) = (&mut before[i - 1], &mut after[0]);
        if x.hand != y.hand {
            continue;
        }
        let (start, end) = (x.start_state.clone(), x.end_state.clone());
        let holds_at = |state: &State, c: EntityId| holding(state, space, x.hand).contains(&c);
        let changed = |gone: bool| -> Vec<Fact> {
            let (from, to) = if gone { (&start, &end) } else { (&end, &start) };
            from.difference(to).facts(space).collect()
        };
        // Lift-off before the grasp is seen.
        for &c in &y.held {
            if x.held.contains(&c) || holds_at(&start, c) {
                continue;
            }
            let lifted: Vec<Fact> = changed(true).into_iter().filter(|f| rests(f, c)).collect();
            if !lifted.is_empty() {
                set_facts(&mut x.end_state, &lifted, true, space);
                set_facts(&mut y.start_state, &lifted, true, space);
                *counts.mended.entry(Breach::LiftBeforeGrasp).or_default() += 1;
            }
        }
        // Landing before the release is seen.
        for c in holding(&end, space, x.hand) {
            if holds_at(&y.end_state, c) {
                continue;
            }
            let landed: Vec<Fact> = changed(false).into_iter().filter(|f| rests(f, c)).collect();
            if !landed.is_empty() {
                set_facts(&mut x.end_state, &landed, false, space);
                set_facts(&mut y.start_state, &landed, false, space);
                *counts
                    .mended
                    .entry(Breach::LandingBeforeRelease)
                    .or_default() += 1;
            }
        }
    }
    counts
}

/// One pass of the rules over `grouped`, without regrouping.
fn mend_pass(grouped: &[Segment], space: &FactSpace) -> (Vec<Segment>, MendCounts) {
    let mut counts = MendCounts::default();
    let mut out: Vec<Segment> = Vec::with_capacity(grouped.len());
    let mut pending: Option<Segment> = None;
    let mut i = 0;
    while i < grouped.len() || pending.is_some() {
        let a = match pending.take() {
            Some(a) => a,
            None => {
                let a = grouped[i].clone();
                i += 1;
                a
            }
        };
        let own = own_changes(&a, grouped, space);
        let Some(&breach) = breaches(&a, &own, space).iter().find(|b| b.is_mended()) else {
            out.push(a);
            continue;
        };
        let next = grouped.get(i).filter(|n| n.hand == a.hand);
        if breach == Breach::PlacementKeepsCube {
            // The hand's next activity that lets the cube go completes the placement: a
            // Stack or Put, or a Take in which the hand rests on the tower and opens.
            let kept = holding(&a.end_state, space, a.hand);
            let completes = |n: &&Segment| {
                let still = holding(&n.end_state, space, n.hand);
                n.activity != Activity::Idle && kept.iter().any(|c| !still.contains(c))
            };
            if let Some(n) = next.filter(completes) {
                let mut joined = join(&a, n);
                let own = own_changes(&joined, grouped, space);
                joined.activity = match meaning_of(&joined, &own, space) {
                    Some(class @ (Activity::Put | Activity::Stack)) => class,
                    _ => a.activity,
                };
                pending = Some(joined);
                i += 1;
                *counts.mended.entry(breach).or_default() += 1;
                continue;
            }
        }
        match meaning_of(&a, &own, space) {
            Some(class) if class != a.activity => {
                let mut relabelled = a;
                relabelled.activity = class;
                out.push(relabelled);
                *counts.mended.entry(breach).or_default() += 1;
            }
            _ => *counts.dropped.entry(breach).or_default() += 1,
        }
    }
    (out, counts)
}

/// Groups mended activities again and drops those that still breach their class.
fn regroup(
    mended: Vec<Segment>,
    grouping: Grouping,
    space: &FactSpace,
    mut counts: MendCounts,
) -> (Vec<Segment>, MendCounts) {
    let grouped = activities(&mended, grouping);
    let mut out = Vec::with_capacity(grouped.len());
    for a in &grouped {
        let own = own_changes(a, &grouped, space);
        match breaches(a, &own, space).iter().find(|b| b.is_mended()) {
            Some(&breach) => *counts.dropped.entry(breach).or_default() += 1,
            None => out.push(a.clone()),
        }
    }
    (out, counts)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::cause::tests::{activity, on, scene, state, LEFT};

    fn classes(mended: &[Segment]) -> Vec<Activity> {
        mended.iter().map(|a| a.activity).collect()
    }

    /// The case: an Idle from the start whose end state holds a cube (a short
    /// grasp merged into it) is the Take it ends with.
    #[test]
    fn an_idle_that_grasps_is_a_take() {
        let header = scene(2);
        let space = FactSpace::new(&header);
        let grasp = Fact::binary(Predicate::InHand, LEFT, EntityId(2));
        let start = state(&space, &on(2, 4));
        let mut end_facts = on(2, 4).to_vec();
        end_facts.push(grasp);
        let idle = activity(
            LEFT,
            Activity::Idle,
            &[2],
            &[],
            start,
            state(&space, &end_facts),
        );
        let (mended, counts) = mend(&[idle], Grouping::Settled, &space);
        assert_eq!(classes(&mended), [Activity::Take]);
        assert_eq!(counts.mended.get(&Breach::IdleChangesThings), Some(&1));
        assert_eq!(counts.dropped_total(), 0);
    }

    /// A Stack whose hand hovers, still holding the cube, then sets it down: one Stack.
    #[test]
    fn a_stack_that_keeps_its_cube_joins_the_placement_after_it() {
        let header = scene(2);
        let space = FactSpace::new(&header);
        let held = Fact::binary(Predicate::InHand, LEFT, EntityId(2));
        let (mut carrying, mut stacked) = (on(3, 4).to_vec(), on(3, 4).to_vec());
        carrying.push(held);
        stacked.extend(on(2, 3));
        let hover = activity(
            LEFT,
            Activity::Stack,
            &[2],
            &[3],
            state(&space, &carrying),
            state(&space, &carrying),
        );
        let mut descent = activity(
            LEFT,
            Activity::Stack,
            &[2],
            &[3],
            state(&space, &carrying),
            state(&space, &stacked),
        );
        (descent.start, descent.end) = (1.0, 2.0);
        let (mended, counts) = mend(&[hover, descent], Grouping::Settled, &space);
        assert_eq!(classes(&mended), [Activity::Stack]);
        assert_eq!((mended[0].start, mended[0].end), (0.0, 2.0));
        assert_eq!(counts.mended.get(&Breach::PlacementKeepsCube), Some(&1));
    }

    /// A cube that comes to rest on another while the hand idles, held by no hand: noise.
    #[test]
    fn an_idle_that_sets_down_a_cube_it_never_held_is_dropped() {
        let header = scene(2);
        let space = FactSpace::new(&header);
        let idle = activity(
            LEFT,
            Activity::Idle,
            &[],
            &[2],
            state(&space, &on(2, 4)),
            state(&space, &on(2, 3)),
        );
        let (mended, counts) = mend(std::slice::from_ref(&idle), Grouping::Settled, &space);
        assert!(mended.is_empty());
        assert_eq!(counts.dropped.get(&Breach::IdleChangesThings), Some(&1));
        // Under `runs`, nothing is mended.
        let (kept, counts) = mend(&[idle], Grouping::Runs, &space);
        assert_eq!(kept.len(), 1);
        assert_eq!(counts, MendCounts::default());
    }
}
