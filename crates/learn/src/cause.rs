//! Which hand caused which change: an activity's operator holds only the changes its own
//! hand caused (issue 39).
//!
//! Between the state an activity starts from and its last frame, anything in the scene
//! may change: the other hand stacks a cube, a cube tips over, the tracker jitters. An
//! operator that took in every change over the objects it touches would, as soon as the
//! table is among them, take in every cube that left or landed on the table anywhere. So
//! each changed fact is given to a cause, one fact at a time and by rules that look at no
//! other changed fact (the result does not depend on the order of the facts):
//!
//! 1. a fact about a hand belongs to that hand;
//! 2. a fact between two things (`inTouch`, `onTop`) changes because one of them moved,
//!    the upper one (which lands on or leaves the other): it belongs to the activity whose
//!    hand held that thing during the activity (or in the state it starts from), else to
//!    another hand that held it meanwhile, else to the activity whose hand acted on it (a
//!    push), else to another hand that acted on it meanwhile; when no hand did any of
//!    that to the upper thing, the same order over either thing decides;
//! 3. anything else no hand caused: a cube tipping over, tracker noise.
//!
//! The table and other fixed things are never held or acted on, so nothing reaches
//! another object through them: the table is a place, not a link.

use grounding::{Fact, FactSpace, Predicate, State};
use recording::EntityId;
use segment::Segment;

/// What the other hands did while an activity ran: the objects they held or acted on in
/// their activities that overlap it in time. Sorted sets.
#[derive(Debug, Clone, Default, PartialEq, Eq)]
pub struct OtherHands {
    /// Objects another hand held.
    pub held: Vec<EntityId>,
    /// Objects another hand acted on.
    pub acted: Vec<EntityId>,
}

impl OtherHands {
    /// The other hands' activities among `all` that overlap `activity` in time (its span
    /// and the frame before it, which its start state is).
    pub fn during(activity: &Segment, all: &[Segment], space: &FactSpace) -> OtherHands {
        let mut others = OtherHands::default();
        for other in all.iter().filter(|o| o.hand != activity.hand) {
            if other.start > activity.end || other.end < activity.start {
                continue;
            }
            others.held.extend(held(other, space));
            others.acted.extend_from_slice(&other.acted);
        }
        for set in [&mut others.held, &mut others.acted] {
            set.sort_unstable();
            set.dedup();
        }
        others
    }
}

/// The objects an activity's hand held: at some frame of it, or in the state it starts
/// from (a hand that lets go at once still moved what it held). Sorted.
pub fn held(activity: &Segment, space: &FactSpace) -> Vec<EntityId> {
    let mut held = activity.held.clone();
    for &o in space.objects() {
        let in_hand = Fact::binary(Predicate::InHand, activity.hand, o);
        if space
            .id(&in_hand)
            .is_some_and(|id| activity.start_state.contains(id))
        {
            held.push(o);
        }
    }
    held.sort_unstable();
    held.dedup();
    held
}

/// Who caused a changed fact, as seen from one activity.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Cause {
    /// The activity's own hand.
    Own,
    /// Another hand (its own activity has the change).
    Other,
    /// No hand.
    Nobody,
}

/// What one activity sees change, split by cause. Each list is sorted.
#[derive(Debug, Clone, Default, PartialEq, Eq)]
pub struct Changes {
    /// Changes its own hand caused: the operator's effects.
    pub own: Vec<Fact>,
    /// Changes another hand caused.
    pub other: Vec<Fact>,
    /// Changes no hand caused.
    pub nobody: Vec<Fact>,
}

/// What an activity's hand did, for [`cause`]: the objects it held ([`held`]) and acted
/// on ([`Segment::acted`]), sorted.
#[derive(Debug, Clone, Copy)]
pub struct OwnHand<'a> {
    /// The hand.
    pub hand: EntityId,
    /// Objects it held.
    pub held: &'a [EntityId],
    /// Objects it acted on.
    pub acted: &'a [EntityId],
}

/// The things whose motion changes a fact between two things: the upper one, which lands
/// on or leaves the lower (`onTop`'s first argument; for `inTouch`, the one on top of the
/// other in `start` or `end`, else both).
fn movers(fact: &Fact, start: &State, end: &State, space: &FactSpace) -> Vec<EntityId> {
    let (a, b) = (fact.first(), fact.second());
    let on = |x, y| {
        let f = Fact::binary(Predicate::OnTop, x, y);
        space
            .id(&f)
            .is_some_and(|id| start.contains(id) || end.contains(id))
    };
    match fact.predicate {
        Predicate::OnTop => vec![a],
        _ if on(a, b) && !on(b, a) => vec![a],
        _ if on(b, a) && !on(a, b) => vec![b],
        _ => vec![a, b],
    }
}

/// The cause of one changed fact, by the rules of the module documentation, looking at
/// the fact and the two states only. Between two things, the hands that held (then
/// acted on) the thing that moved ([`movers`]) come first, then those of either thing.
pub fn cause(
    fact: &Fact,
    own: OwnHand<'_>,
    others: &OtherHands,
    (start, end): (&State, &State),
    space: &FactSpace,
) -> Cause {
    let is_hand = |e: &EntityId| space.hand_index(*e).is_some();
    if fact.args().contains(&own.hand) {
        return Cause::Own;
    }
    if fact.args().iter().any(is_hand) {
        return Cause::Other;
    }
    let order: [(&[EntityId], Cause); 4] = [
        (own.held, Cause::Own),
        (&others.held, Cause::Other),
        (own.acted, Cause::Own),
        (&others.acted, Cause::Other),
    ];
    for things in [movers(fact, start, end, space), fact.args().to_vec()] {
        for (set, cause) in order {
            if things.iter().any(|t| set.binary_search(t).is_ok()) {
                return cause;
            }
        }
    }
    Cause::Nobody
}

/// Every fact that differs between `start` and `end`, split by [`cause`].
pub fn changes(
    activity: &Segment,
    start: &State,
    end: &State,
    others: &OtherHands,
    space: &FactSpace,
) -> Changes {
    let held = held(activity, space);
    let mut out = Changes::default();
    let (gone, come) = (start.difference(end), end.difference(start));
    for f in gone.facts(space).chain(come.facts(space)) {
        let own = OwnHand {
            hand: activity.hand,
            held: &held,
            acted: &activity.acted,
        };
        match cause(&f, own, others, (start, end), space) {
            Cause::Own => out.own.push(f),
            Cause::Other => out.other.push(f),
            Cause::Nobody => out.nobody.push(f),
        }
    }
    for list in [&mut out.own, &mut out.other, &mut out.nobody] {
        list.sort_unstable();
    }
    out
}

#[cfg(test)]
pub(crate) mod tests {
    use super::*;
    use crate::operator::lift;
    use proptest::prelude::*;
    use recording::{Entity, EntityKind, Header, Pose, Vec3};
    use segment::Activity;

    pub(crate) const LEFT: EntityId = EntityId(0);
    pub(crate) const RIGHT: EntityId = EntityId(1);

    /// Two hands, `cubes` cubes (entities 2..), the table last.
    pub(crate) fn scene(cubes: usize) -> Header {
        let e = |name: String, kind: EntityKind, fixed: bool| Entity {
            name,
            kind,
            size: Vec3::new(0.05, 0.05, 0.05),
            fixed: fixed.then(Pose::default),
        };
        let mut entities = vec![
            e("left_hand".into(), EntityKind::Hand, false),
            e("right_hand".into(), EntityKind::Hand, false),
        ];
        entities.extend((0..cubes).map(|i| e(format!("cube_{}", i + 1), EntityKind::Cube, false)));
        entities.push(e("table".into(), EntityKind::Table, true));
        Header {
            id: "t".into(),
            participant: "p".into(),
            task: "t".into(),
            frame_rate: 90.0,
            entities,
            meta: Default::default(),
        }
    }

    pub(crate) fn state(space: &FactSpace, facts: &[Fact]) -> State {
        let mut s = space.empty_state();
        for f in facts {
            s.insert(space.id(f).expect("a fact of the scene"));
        }
        s
    }

    pub(crate) fn on(a: u32, b: u32) -> [Fact; 2] {
        [
            Fact::binary(Predicate::OnTop, EntityId(a), EntityId(b)),
            Fact::binary(Predicate::InTouch, EntityId(a), EntityId(b)),
        ]
    }

    pub(crate) fn activity(
        hand: EntityId,
        class: Activity,
        held: &[u32],
        acted: &[u32],
        start: State,
        end: State,
    ) -> Segment {
        Segment {
            hand,
            start: 0.0,
            end: 1.0,
            frames: 90,
            activity: class,
            moving: true,
            acted_on: acted.last().map(|&e| EntityId(e)),
            in_hand: None,
            held: held.iter().map(|&e| EntityId(e)).collect(),
            acted: acted.iter().map(|&e| EntityId(e)).collect(),
            start_state: start,
            end_state: end,
        }
    }

    /// Issue 39: while the right hand reaches for cube 3, the left hand puts cube 1 (which
    /// left the table) onto cube 2. The Reach holds none of it: the table is no link.
    #[test]
    fn a_reach_takes_in_nothing_the_other_hand_stacks() {
        let header = scene(3);
        let space = FactSpace::new(&header);
        let table = 5;
        let mut before = vec![];
        before.extend(on(2, table));
        before.extend(on(3, table));
        before.extend(on(4, table));
        before.push(Fact::binary(Predicate::InHand, LEFT, EntityId(2)));
        let mut after = vec![];
        after.extend(on(2, 3));
        after.extend(on(3, table));
        after.extend(on(4, table));
        after.push(Fact::binary(Predicate::ActedOn, RIGHT, EntityId(4)));
        let (start, end) = (state(&space, &before), state(&space, &after));
        let reach = activity(
            RIGHT,
            Activity::Reach,
            &[],
            &[4],
            start.clone(),
            end.clone(),
        );
        let stack = activity(LEFT, Activity::Stack, &[2], &[3], start, end);
        let all = [stack.clone(), reach.clone()];
        let lifted = lift(
            &reach,
            &OtherHands::during(&reach, &all, &space),
            &space,
            &header,
        );
        let text = lifted.operator.canonical_text();
        assert_eq!(
            text,
            "Reach(?h - hand, ?c1 - cube) pre: [] not: [handMove(?h), handOpen(?h), \
             actedOn(?h, ?c1), graspable(?h, ?c1), inHand(?h, ?c1)] add: [actedOn(?h, ?c1)] \
             del: []"
        );
        assert!(lifted.uncaused.is_empty());
        // The Stack has the stacking, and what the left hand let go of; not the reach.
        let lifted = lift(
            &stack,
            &OtherHands::during(&stack, &all, &space),
            &space,
            &header,
        );
        let op = &lifted.operator;
        let names = op.param_names();
        let adds: Vec<String> = op.add.iter().map(|f| crate::fact_text(f, &names)).collect();
        let dels: Vec<String> = op
            .delete
            .iter()
            .map(|f| crate::fact_text(f, &names))
            .collect();
        assert_eq!(adds, ["inTouch(?c1, ?c2)", "onTop(?c1, ?c2)"]);
        assert_eq!(
            dels,
            ["inHand(?h, ?c1)", "inTouch(?c1, ?t)", "onTop(?c1, ?t)"]
        );
    }

    /// The right hand still rests on the cube it just stacked when the left hand sets its
    /// cube on top: the landing is the left hand's, whose cube moved.
    #[test]
    fn a_landing_belongs_to_the_hand_that_held_the_upper_cube() {
        let header = scene(2);
        let space = FactSpace::new(&header);
        let table = 4;
        let mut before = on(2, table).to_vec();
        before.push(Fact::binary(Predicate::InHand, RIGHT, EntityId(2)));
        before.push(Fact::binary(Predicate::InHand, LEFT, EntityId(3)));
        let mut after = on(2, table).to_vec();
        after.extend(on(3, 2));
        let (start, end) = (state(&space, &before), state(&space, &after));
        let rest = activity(RIGHT, Activity::Take, &[2], &[], start.clone(), end.clone());
        let stack = activity(LEFT, Activity::Stack, &[3], &[2], start, end);
        let all = [stack.clone(), rest.clone()];
        let own = |a: &Segment| {
            let others = OtherHands::during(a, &all, &space);
            changes(a, &a.start_state, &a.end_state, &others, &space).own
        };
        let landing = on(3, 2);
        assert!(own(&rest).iter().all(|f| !landing.contains(f)));
        assert!(landing.iter().all(|f| own(&stack).contains(f)));
    }

    /// A cube that tips off the table's edge while no hand is near is nobody's change.
    #[test]
    fn a_change_no_hand_caused_is_in_no_operator() {
        let header = scene(2);
        let space = FactSpace::new(&header);
        let table = 4;
        let start = state(&space, &on(2, table));
        let end = state(&space, &[]);
        let idle = activity(LEFT, Activity::Idle, &[], &[], start, end);
        let lifted = lift(&idle, &OtherHands::default(), &space, &header);
        assert!(!lifted.operator.has_effects());
        assert_eq!(lifted.uncaused.len(), 2);
        let (_, uncaused) = crate::lift_all(&[idle], &space, &header);
        assert_eq!(uncaused, 2);
    }

    /// A random activity of the left hand in a scene of `n` cubes: start and end states,
    /// the objects it held and acted on, and what the right hand held meanwhile.
    /// Cubes, start and end facts (one flag per fact), held, acted on, the other's held.
    type Case = (usize, Vec<bool>, Vec<bool>, Vec<u8>, Vec<u8>, Vec<u8>);

    fn random_case() -> impl Strategy<Value = Case> {
        (2usize..5).prop_flat_map(|n| {
            let facts = FactSpace::new(&scene(n)).len();
            (
                Just(n),
                prop::collection::vec(any::<bool>(), facts),
                prop::collection::vec(any::<bool>(), facts),
                prop::collection::vec(0u8..n as u8, 0..2),
                prop::collection::vec(0u8..n as u8, 0..2),
                prop::collection::vec(0u8..n as u8, 0..2),
            )
        })
    }

    proptest! {
        /// The operator does not depend on the order of the changed facts: renaming the
        /// cubes (which reorders every fact about them) gives the same operator.
        #[test]
        fn renaming_the_cubes_gives_the_same_operator(
            (n, start_bits, end_bits, held, acted, other_held) in random_case(),
            seed in any::<u64>(),
        ) {
            let header = scene(n);
            let space = FactSpace::new(&header);
            let pick = |bits: &[bool]| -> Vec<Fact> {
                space.facts().iter().zip(bits).filter(|(_, &b)| b).map(|(f, _)| *f).collect()
            };
            let (start, end) = (pick(&start_bits), pick(&end_bits));
            // A permutation of the cubes, from the seed.
            let mut order: Vec<u32> = (0..n as u32).collect();
            let mut s = seed;
            for i in (1..order.len()).rev() {
                s = s.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
                order.swap(i, (s >> 33) as usize % (i + 1));
            }
            let rename = |e: EntityId| {
                if (2..2 + n as u32).contains(&e.0) { EntityId(2 + order[e.0 as usize - 2]) } else { e }
            };
            let rename_fact = |f: &Fact| match f.args() {
                [a] => Fact::unary(f.predicate, rename(*a)),
                [a, b] => Fact::binary(f.predicate, rename(*a), rename(*b)),
                _ => *f,
            };
            let cubes = |v: &[u8]| -> Vec<u32> { v.iter().map(|&c| 2 + u32::from(c)).collect() };
            let renamed_cubes = |v: &[u8]| -> Vec<u32> {
                v.iter().map(|&c| 2 + order[usize::from(c)]).collect()
            };
            let sorted = |v: Vec<u32>| { let mut v = v; v.sort_unstable(); v.dedup(); v };
            let make = |start: &[Fact], end: &[Fact], held: Vec<u32>, acted: Vec<u32>, other: Vec<u32>| {
                let a = activity(LEFT, Activity::Put, &held, &acted, state(&space, start), state(&space, end));
                let others = OtherHands {
                    held: other.iter().map(|&e| EntityId(e)).collect(),
                    acted: vec![],
                };
                lift(&a, &others, &space, &header)
            };
            let one = make(&start, &end, sorted(cubes(&held)), sorted(cubes(&acted)), sorted(cubes(&other_held)));
            let start2: Vec<Fact> = start.iter().map(rename_fact).collect();
            let end2: Vec<Fact> = end.iter().map(rename_fact).collect();
            let two = make(
                &start2,
                &end2,
                sorted(renamed_cubes(&held)),
                sorted(renamed_cubes(&acted)),
                sorted(renamed_cubes(&other_held)),
            );
            prop_assert_eq!(one.operator, two.operator);
            prop_assert_eq!(one.uncaused.len(), two.uncaused.len());
        }
    }
}
