//! The paper's state variables as facts over the entities of a recording, and states as
//! bit sets over the facts a scene can have.

use std::fmt;

use recording::{EntityId, EntityKind, Header};

/// The paper's state variables (its Table 2), in the order facts sort by.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Predicate {
    /// `handMove(h)`: the hand moves faster than the threshold.
    HandMove,
    /// `handOpen(h)`: the hand is open.
    HandOpen,
    /// `actedOn(h, c)`: the hand moves towards the object, close to it.
    ActedOn,
    /// `graspable(h, c)`: the object is within grasping distance of the palm.
    Graspable,
    /// `inHand(h, c)`: the hand holds the object.
    InHand,
    /// `inTouch(a, b)`: two things touch (unordered; written with `a` before `b`).
    InTouch,
    /// `onTop(a, b)`: `a` touches `b` and is above it.
    OnTop,
}

impl Predicate {
    /// Every predicate, in sort order.
    pub const ALL: [Predicate; 7] = [
        Predicate::HandMove,
        Predicate::HandOpen,
        Predicate::ActedOn,
        Predicate::Graspable,
        Predicate::InHand,
        Predicate::InTouch,
        Predicate::OnTop,
    ];

    /// The paper's name: `handMove`, `actedOn`, ...
    pub fn name(self) -> &'static str {
        match self {
            Predicate::HandMove => "handMove",
            Predicate::HandOpen => "handOpen",
            Predicate::ActedOn => "actedOn",
            Predicate::Graspable => "graspable",
            Predicate::InHand => "inHand",
            Predicate::InTouch => "inTouch",
            Predicate::OnTop => "onTop",
        }
    }

    /// Number of arguments (1 or 2).
    pub fn arity(self) -> usize {
        match self {
            Predicate::HandMove | Predicate::HandOpen => 1,
            _ => 2,
        }
    }
}

impl fmt::Display for Predicate {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

/// A ground fact: a predicate over entities of the recording. Facts sort by predicate,
/// then by their arguments' entity ids; `inTouch` is stored with the smaller id first.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct Fact {
    /// The predicate.
    pub predicate: Predicate,
    /// The arguments; for a unary predicate both are the hand.
    args: [EntityId; 2],
}

impl Fact {
    /// A unary fact.
    pub fn unary(predicate: Predicate, a: EntityId) -> Fact {
        Fact {
            predicate,
            args: [a, a],
        }
    }

    /// A binary fact (`inTouch` arguments are put in order).
    pub fn binary(predicate: Predicate, a: EntityId, b: EntityId) -> Fact {
        let args = if predicate == Predicate::InTouch && b < a {
            [b, a]
        } else {
            [a, b]
        };
        Fact { predicate, args }
    }

    /// The arguments: one or two entities.
    pub fn args(&self) -> &[EntityId] {
        &self.args[..self.predicate.arity()]
    }

    /// The first argument.
    pub fn first(&self) -> EntityId {
        self.args[0]
    }

    /// The second argument (the first again for a unary fact).
    pub fn second(&self) -> EntityId {
        self.args[1]
    }

    /// Renders with entity names: `inHand(right_hand, cube_1)`.
    pub fn display<'a>(&'a self, header: &'a Header) -> FactDisplay<'a> {
        FactDisplay { fact: self, header }
    }
}

/// A fact with entity names, from [`Fact::display`].
#[derive(Debug)]
pub struct FactDisplay<'a> {
    fact: &'a Fact,
    header: &'a Header,
}

impl fmt::Display for FactDisplay<'_> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}(", self.fact.predicate)?;
        for (i, id) in self.fact.args().iter().enumerate() {
            if i > 0 {
                f.write_str(", ")?;
            }
            match self.header.entities.get(id.index()) {
                Some(e) => f.write_str(&e.name)?,
                None => write!(f, "#{}", id.0)?,
            }
        }
        f.write_str(")")
    }
}

/// Index of a fact in a [`FactSpace`], and of its bit in a [`State`].
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct FactId(pub u32);

/// Marks "no bit" in the lookup tables.
const NONE: u32 = u32::MAX;

/// Every fact a scene can have, numbered in sort order, with lookup tables from
/// entities to fact ids. Built once per recording from its header.
///
/// Hands are the entities of kind `hand`; *objects* (what a hand can act on, grasp and
/// hold) are the other entities without a fixed pose that are not a table; *things*
/// (what can touch and stand on each other) are all entities but hands.
#[derive(Debug, Clone)]
pub struct FactSpace {
    facts: Vec<Fact>,
    words: usize,
    hands: Vec<EntityId>,
    objects: Vec<EntityId>,
    things: Vec<EntityId>,
    /// Per hand (index into `hands`): the id of `handMove`, `handOpen`; and the first id of
    /// its `actedOn`, `graspable`, `inHand` runs (one per object).
    hand_move: Vec<u32>,
    hand_open: Vec<u32>,
    acted_on: Vec<u32>,
    graspable: Vec<u32>,
    in_hand: Vec<u32>,
    /// Per pair of things (index into `things`, row-major): `inTouch` (both orders) and
    /// `onTop` (ordered) ids.
    in_touch: Vec<u32>,
    on_top: Vec<u32>,
    /// Per entity: its index among hands, objects, things (or `NONE`).
    hand_index: Vec<u32>,
    object_index: Vec<u32>,
    thing_index: Vec<u32>,
}

impl FactSpace {
    /// The facts of a recording's scene.
    pub fn new(header: &Header) -> FactSpace {
        let n = header.entities.len();
        let hands: Vec<EntityId> = header.ids_of(EntityKind::Hand).collect();
        let objects: Vec<EntityId> = header
            .ids()
            .filter(|&id| {
                let e = header.entity(id);
                e.kind != EntityKind::Hand && e.kind != EntityKind::Table && e.fixed.is_none()
            })
            .collect();
        let things: Vec<EntityId> = header
            .ids()
            .filter(|&id| header.entity(id).kind != EntityKind::Hand)
            .collect();
        let movable = |id: EntityId| objects.contains(&id);
        let index = |list: &[EntityId]| {
            let mut v = vec![NONE; n];
            for (i, id) in list.iter().enumerate() {
                v[id.index()] = i as u32;
            }
            v
        };
        let mut facts = Vec::new();
        let mut push = |f: Fact| {
            facts.push(f);
            (facts.len() - 1) as u32
        };
        let hand_move = hands
            .iter()
            .map(|&h| push(Fact::unary(Predicate::HandMove, h)))
            .collect();
        let hand_open = hands
            .iter()
            .map(|&h| push(Fact::unary(Predicate::HandOpen, h)))
            .collect();
        let mut per_object = |p: Predicate| -> Vec<u32> {
            hands
                .iter()
                .map(|&h| {
                    let first = facts.len() as u32;
                    for &o in &objects {
                        facts.push(Fact::binary(p, h, o));
                    }
                    first
                })
                .collect()
        };
        let acted_on = per_object(Predicate::ActedOn);
        let graspable = per_object(Predicate::Graspable);
        let in_hand = per_object(Predicate::InHand);
        let t = things.len();
        let mut in_touch = vec![NONE; t * t];
        for i in 0..t {
            for j in i + 1..t {
                let id = facts.len() as u32;
                facts.push(Fact::binary(Predicate::InTouch, things[i], things[j]));
                in_touch[i * t + j] = id;
                in_touch[j * t + i] = id;
            }
        }
        let mut on_top = vec![NONE; t * t];
        for i in 0..t {
            if !movable(things[i]) {
                continue;
            }
            for j in 0..t {
                if i != j {
                    on_top[i * t + j] = facts.len() as u32;
                    facts.push(Fact::binary(Predicate::OnTop, things[i], things[j]));
                }
            }
        }
        debug_assert!(facts.windows(2).all(|w| w[0] < w[1]));
        FactSpace {
            words: facts.len().div_ceil(64).max(1),
            facts,
            hand_index: index(&hands),
            object_index: index(&objects),
            thing_index: index(&things),
            hands,
            objects,
            things,
            hand_move,
            hand_open,
            acted_on,
            graspable,
            in_hand,
            in_touch,
            on_top,
        }
    }

    /// Number of facts.
    pub fn len(&self) -> usize {
        self.facts.len()
    }

    /// Whether the scene has no fact at all.
    pub fn is_empty(&self) -> bool {
        self.facts.is_empty()
    }

    /// Words of 64 bits in a [`State`] of this space.
    pub fn words(&self) -> usize {
        self.words
    }

    /// The fact with this id.
    pub fn fact(&self, id: FactId) -> Option<Fact> {
        self.facts.get(id.0 as usize).copied()
    }

    /// Every fact, in sort order (the id is the position).
    pub fn facts(&self) -> &[Fact] {
        &self.facts
    }

    /// The id of a fact, if the scene can have it.
    pub fn id(&self, fact: &Fact) -> Option<FactId> {
        self.facts
            .binary_search(fact)
            .ok()
            .map(|i| FactId(i as u32))
    }

    /// The hands, in entity order.
    pub fn hands(&self) -> &[EntityId] {
        &self.hands
    }

    /// The objects hands act on, grasp and hold, in entity order.
    pub fn objects(&self) -> &[EntityId] {
        &self.objects
    }

    /// Everything but hands, in entity order.
    pub fn things(&self) -> &[EntityId] {
        &self.things
    }

    /// A state with no fact.
    pub fn empty_state(&self) -> State {
        State {
            words: vec![0; self.words],
        }
    }

    /// The facts all of whose arguments are among `entities`, as a mask to
    /// [`State::restrict`] states with.
    pub fn mask(&self, entities: &[EntityId]) -> State {
        let mut mask = self.empty_state();
        for (i, f) in self.facts.iter().enumerate() {
            if f.args().iter().all(|a| entities.contains(a)) {
                mask.words[i / 64] |= 1 << (i % 64);
            }
        }
        mask
    }

    /// The position of a hand in [`FactSpace::hands`].
    pub fn hand_index(&self, id: EntityId) -> Option<usize> {
        lookup(&self.hand_index, id)
    }

    /// The position of an object in [`FactSpace::objects`].
    pub fn object_index(&self, id: EntityId) -> Option<usize> {
        lookup(&self.object_index, id)
    }

    /// The position of a thing in [`FactSpace::things`].
    pub fn thing_index(&self, id: EntityId) -> Option<usize> {
        lookup(&self.thing_index, id)
    }

    pub(crate) fn hand_move_bit(&self, hand: usize) -> u32 {
        self.hand_move[hand]
    }

    pub(crate) fn hand_open_bit(&self, hand: usize) -> u32 {
        self.hand_open[hand]
    }

    pub(crate) fn acted_on_bit(&self, hand: usize, object: usize) -> u32 {
        self.acted_on[hand] + object as u32
    }

    pub(crate) fn graspable_bit(&self, hand: usize, object: usize) -> u32 {
        self.graspable[hand] + object as u32
    }

    pub(crate) fn in_hand_bit(&self, hand: usize, object: usize) -> u32 {
        self.in_hand[hand] + object as u32
    }

    /// `inTouch` of two things (indices into `things`), `NONE` for a thing and itself.
    pub(crate) fn in_touch_bit(&self, a: usize, b: usize) -> u32 {
        self.in_touch[a * self.things.len() + b]
    }

    /// `onTop(a, b)` (indices into `things`), `NONE` when `a` cannot be on top.
    pub(crate) fn on_top_bit(&self, a: usize, b: usize) -> u32 {
        self.on_top[a * self.things.len() + b]
    }

    /// The object a hand acts on in a state, if any.
    pub fn acted_on(&self, state: &State, hand: usize) -> Option<EntityId> {
        self.first_object(state, self.acted_on[hand])
    }

    /// The object a hand holds in a state, if any.
    pub fn in_hand(&self, state: &State, hand: usize) -> Option<EntityId> {
        self.first_object(state, self.in_hand[hand])
    }

    fn first_object(&self, state: &State, first: u32) -> Option<EntityId> {
        (0..self.objects.len())
            .find(|&o| state.contains_bit(first + o as u32))
            .map(|o| self.objects[o])
    }
}

fn lookup(table: &[u32], id: EntityId) -> Option<usize> {
    table
        .get(id.index())
        .copied()
        .filter(|&i| i != NONE)
        .map(|i| i as usize)
}

pub(crate) const NO_BIT: u32 = NONE;

/// A set of facts of one [`FactSpace`]: one bit per fact, so that comparing two states,
/// taking their difference or restricting one to some objects is a few word operations.
/// Iterating gives the facts in sort order.
#[derive(Debug, Clone, PartialEq, Eq, Hash, PartialOrd, Ord, Default)]
pub struct State {
    words: Vec<u64>,
}

impl State {
    /// A state from its words (bit `i` of word `w` is fact `64 w + i`).
    pub fn from_words(words: Vec<u64>) -> State {
        State { words }
    }

    /// The words.
    pub fn words(&self) -> &[u64] {
        &self.words
    }

    pub(crate) fn words_mut(&mut self) -> &mut [u64] {
        &mut self.words
    }

    /// Whether the fact with this id holds.
    pub fn contains(&self, id: FactId) -> bool {
        self.contains_bit(id.0)
    }

    pub(crate) fn contains_bit(&self, bit: u32) -> bool {
        self.words
            .get((bit / 64) as usize)
            .is_some_and(|w| w & (1 << (bit % 64)) != 0)
    }

    /// Adds a fact.
    pub fn insert(&mut self, id: FactId) {
        let w = (id.0 / 64) as usize;
        if w >= self.words.len() {
            self.words.resize(w + 1, 0);
        }
        self.words[w] |= 1 << (id.0 % 64);
    }

    /// Number of facts that hold.
    pub fn len(&self) -> usize {
        self.words.iter().map(|w| w.count_ones() as usize).sum()
    }

    /// Whether no fact holds.
    pub fn is_empty(&self) -> bool {
        self.words.iter().all(|&w| w == 0)
    }

    /// The ids of the facts that hold, in order.
    pub fn ids(&self) -> impl Iterator<Item = FactId> + '_ {
        self.words.iter().enumerate().flat_map(|(w, &word)| {
            let mut rest = word;
            std::iter::from_fn(move || {
                if rest == 0 {
                    return None;
                }
                let bit = rest.trailing_zeros();
                rest &= rest - 1;
                Some(FactId(w as u32 * 64 + bit))
            })
        })
    }

    /// The facts that hold, in sort order.
    pub fn facts<'a>(&'a self, space: &'a FactSpace) -> impl Iterator<Item = Fact> + 'a {
        self.ids().filter_map(|id| space.fact(id))
    }

    /// The facts of this state that are also in `mask` (e.g. [`FactSpace::mask`]).
    pub fn restrict(&self, mask: &State) -> State {
        State {
            words: self
                .words
                .iter()
                .zip(mask.words.iter().chain(std::iter::repeat(&0)))
                .map(|(a, b)| a & b)
                .collect(),
        }
    }

    /// The facts of this state that are not in `other`.
    pub fn difference(&self, other: &State) -> State {
        State {
            words: self
                .words
                .iter()
                .zip(other.words.iter().chain(std::iter::repeat(&0)))
                .map(|(a, b)| a & !b)
                .collect(),
        }
    }

    /// Copies another state's facts into this one, keeping the allocation.
    pub fn copy_from(&mut self, other: &State) {
        self.words.clear();
        self.words.extend_from_slice(&other.words);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use recording::{Entity, Pose, Vec3};

    pub(crate) fn scene() -> Header {
        let e = |name: &str, kind: EntityKind, fixed: bool| Entity {
            name: name.into(),
            kind,
            size: Vec3::new(0.05, 0.05, 0.05),
            fixed: fixed.then(Pose::default),
        };
        Header {
            id: "t".into(),
            participant: "p".into(),
            task: "t".into(),
            frame_rate: 90.0,
            entities: vec![
                e("left_hand", EntityKind::Hand, false),
                e("right_hand", EntityKind::Hand, false),
                e("cube_a", EntityKind::Cube, false),
                e("cube_b", EntityKind::Cube, false),
                e("table", EntityKind::Table, true),
            ],
            meta: Default::default(),
        }
    }

    #[test]
    fn facts_are_numbered_in_sort_order_and_found_again() {
        let h = scene();
        let space = FactSpace::new(&h);
        // 2 handMove, 2 handOpen, 3 x 2 x 2 hand-object, 3 inTouch, 2 x 2 onTop.
        assert_eq!(space.len(), 2 + 2 + 12 + 3 + 4);
        for (i, f) in space.facts().iter().enumerate() {
            assert_eq!(space.id(f), Some(FactId(i as u32)));
        }
        let f = Fact::binary(Predicate::InTouch, EntityId(4), EntityId(2));
        assert_eq!(f.args(), &[EntityId(2), EntityId(4)]);
        assert_eq!(f.display(&h).to_string(), "inTouch(cube_a, table)");
        assert_eq!(
            Fact::unary(Predicate::HandMove, EntityId(1))
                .display(&h)
                .to_string(),
            "handMove(right_hand)"
        );
    }

    #[test]
    fn states_compare_restrict_and_list_their_facts_in_order() {
        let h = scene();
        let space = FactSpace::new(&h);
        let id = |f: Fact| space.id(&f).unwrap_or(FactId(0));
        let mut s = space.empty_state();
        s.insert(id(Fact::binary(Predicate::OnTop, EntityId(2), EntityId(3))));
        s.insert(id(Fact::unary(Predicate::HandOpen, EntityId(1))));
        s.insert(id(Fact::binary(
            Predicate::InHand,
            EntityId(0),
            EntityId(2),
        )));
        let names: Vec<String> = s.facts(&space).map(|f| f.display(&h).to_string()).collect();
        assert_eq!(
            names,
            [
                "handOpen(right_hand)",
                "inHand(left_hand, cube_a)",
                "onTop(cube_a, cube_b)"
            ]
        );
        let mask = space.mask(&[EntityId(0), EntityId(2)]);
        let r = s.restrict(&mask);
        assert_eq!(r.len(), 1);
        assert_eq!(s.difference(&r).len(), 2);
        assert_eq!(space.in_hand(&s, 0), Some(EntityId(2)));
        assert_eq!(space.acted_on(&s, 0), None);
    }
}
