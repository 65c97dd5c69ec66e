//! Lifted operators: what one demonstrated segment becomes, in a canonical form that is
//! the same for every segment that did the same thing to other objects.

use std::fmt;

use grounding::{Fact, FactSpace, Predicate};
use recording::{EntityId, EntityKind, Header};
use segment::{Activity, Segment};

use crate::cause::{self, OtherHands};
use crate::hash::stable_hash;

/// The type of an operator parameter. Types form the hierarchy `hand`, `thing`,
/// `cube - thing`, `table - thing`; every parameter has one of the leaf types (or `thing`
/// for scene entities that are neither cube nor table).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum ParamType {
    /// A hand.
    Hand,
    /// A cube.
    Cube,
    /// The table.
    Table,
    /// Any other thing of the scene.
    Thing,
}

impl ParamType {
    /// Every type, in parameter order.
    pub const ALL: [ParamType; 4] = [
        ParamType::Hand,
        ParamType::Cube,
        ParamType::Table,
        ParamType::Thing,
    ];

    /// The PDDL type name.
    pub fn name(self) -> &'static str {
        match self {
            ParamType::Hand => "hand",
            ParamType::Cube => "cube",
            ParamType::Table => "table",
            ParamType::Thing => "thing",
        }
    }

    /// The type with this name.
    pub fn from_name(name: &str) -> Option<ParamType> {
        ParamType::ALL.into_iter().find(|t| t.name() == name)
    }

    /// The type of a scene entity of this kind.
    pub fn of_kind(kind: EntityKind) -> ParamType {
        match kind {
            EntityKind::Hand => ParamType::Hand,
            EntityKind::Cube => ParamType::Cube,
            EntityKind::Table => ParamType::Table,
            EntityKind::Other => ParamType::Thing,
        }
    }

    /// The letter parameters of this type are named with: `?h`, `?c1`, `?t`, `?x1`.
    fn letter(self) -> char {
        match self {
            ParamType::Hand => 'h',
            ParamType::Cube => 'c',
            ParamType::Table => 't',
            ParamType::Thing => 'x',
        }
    }
}

/// A fact over parameters: a predicate and parameter indices (a unary fact repeats its
/// argument). `inTouch` is symmetric and always has the smaller index first.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct LiftedFact {
    /// The predicate.
    pub predicate: Predicate,
    /// Parameter indices.
    pub args: [u8; 2],
}

impl LiftedFact {
    /// A fact, with `inTouch` arguments put in order.
    pub fn new(predicate: Predicate, a: u8, b: u8) -> LiftedFact {
        let args = if predicate.arity() == 1 {
            [a, a]
        } else if predicate == Predicate::InTouch && b < a {
            [b, a]
        } else {
            [a, b]
        };
        LiftedFact { predicate, args }
    }

    /// The parameter indices (one or two).
    pub fn params(&self) -> &[u8] {
        &self.args[..self.predicate.arity()]
    }

    fn renamed(&self, to: &[u8]) -> LiftedFact {
        LiftedFact::new(
            self.predicate,
            to[self.args[0] as usize],
            to[self.args[1] as usize],
        )
    }
}

/// A lifted planning operator of one activity type: typed parameters, a precondition of
/// positive and negative facts, and effects that add and delete facts. Its fact lists are
/// sorted and, once built by [`Operator::new`], canonical: two operators equal up to
/// renaming of parameters are equal as values.
#[derive(Debug, Clone, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct Operator {
    /// The activity type.
    pub activity: Activity,
    /// Parameter types, in canonical order (grouped by type).
    pub params: Vec<ParamType>,
    /// Facts that must hold.
    pub pre_positive: Vec<LiftedFact>,
    /// Facts that must not hold.
    pub pre_negative: Vec<LiftedFact>,
    /// Facts that become true.
    pub add: Vec<LiftedFact>,
    /// Facts that become false.
    pub delete: Vec<LiftedFact>,
}

/// More permutations than this and canonicalisation orders same-typed parameters by a
/// signature instead of trying every order (no demonstrated segment comes near: an
/// operator over 8 cubes would need 40320 orders).
const MAX_PERMUTATIONS: usize = 40_320;

impl Operator {
    /// An operator in canonical form: parameters grouped by type, and within each type
    /// the order whose fact lists compare smallest.
    pub fn new(
        activity: Activity,
        params: Vec<ParamType>,
        pre_positive: Vec<LiftedFact>,
        pre_negative: Vec<LiftedFact>,
        add: Vec<LiftedFact>,
        delete: Vec<LiftedFact>,
    ) -> Operator {
        let raw = Operator {
            activity,
            params,
            pre_positive,
            pre_negative,
            add,
            delete,
        };
        raw.canonical()
    }

    /// Whether the operator changes nothing.
    pub fn has_effects(&self) -> bool {
        !self.add.is_empty() || !self.delete.is_empty()
    }

    /// The parameter names: `?h`, `?c1`, `?c2`, `?t`, ... (a type with a single parameter
    /// other than cube has no number).
    pub fn param_names(&self) -> Vec<String> {
        let mut names = Vec::with_capacity(self.params.len());
        for (i, &t) in self.params.iter().enumerate() {
            let same = self.params.iter().filter(|&&u| u == t).count();
            let nth = self.params[..i].iter().filter(|&&u| u == t).count() + 1;
            if same == 1 && t != ParamType::Cube {
                names.push(format!("?{}", t.letter()));
            } else {
                names.push(format!("?{}{nth}", t.letter()));
            }
        }
        names
    }

    /// The canonical text: the activity, typed parameters and the four fact lists. Equal
    /// operators have equal texts; the library's ids hash it.
    pub fn canonical_text(&self) -> String {
        let names = self.param_names();
        let mut s = format!("{}(", self.activity.name());
        for (i, (n, t)) in names.iter().zip(&self.params).enumerate() {
            if i > 0 {
                s.push_str(", ");
            }
            s.push_str(&format!("{n} - {}", t.name()));
        }
        s.push(')');
        for (label, facts) in [
            ("pre", &self.pre_positive),
            ("not", &self.pre_negative),
            ("add", &self.add),
            ("del", &self.delete),
        ] {
            s.push_str(&format!(" {label}: ["));
            for (i, f) in facts.iter().enumerate() {
                if i > 0 {
                    s.push_str(", ");
                }
                s.push_str(&fact_text(f, &names));
            }
            s.push(']');
        }
        s
    }

    /// The stable id: 16 hex digits of a hash of the canonical text.
    pub fn id(&self) -> String {
        format!("{:016x}", stable_hash(self.canonical_text().as_bytes()))
    }

    fn renamed(&self, to: &[u8]) -> Operator {
        let map = |facts: &[LiftedFact]| {
            let mut v: Vec<LiftedFact> = facts.iter().map(|f| f.renamed(to)).collect();
            v.sort_unstable();
            v.dedup();
            v
        };
        let mut params = vec![ParamType::Hand; self.params.len()];
        for (old, &new) in to.iter().enumerate() {
            params[new as usize] = self.params[old];
        }
        Operator {
            activity: self.activity,
            params,
            pre_positive: map(&self.pre_positive),
            pre_negative: map(&self.pre_negative),
            add: map(&self.add),
            delete: map(&self.delete),
        }
    }

    fn key(&self) -> (&[LiftedFact], &[LiftedFact], &[LiftedFact], &[LiftedFact]) {
        (
            &self.pre_positive,
            &self.pre_negative,
            &self.add,
            &self.delete,
        )
    }

    /// The canonical form: parameters grouped by type (hand, cube, table, thing), and
    /// within a type the order that makes the fact lists smallest.
    fn canonical(&self) -> Operator {
        let n = self.params.len();
        // Parameters of each type, in their current order.
        let groups: Vec<Vec<u8>> = ParamType::ALL
            .iter()
            .map(|&t| {
                (0..n as u8)
                    .filter(|&i| self.params[i as usize] == t)
                    .collect()
            })
            .filter(|g: &Vec<u8>| !g.is_empty())
            .collect();
        let total: usize = groups
            .iter()
            .map(|g| (1..=g.len()).product::<usize>())
            .try_fold(1usize, |acc, p| acc.checked_mul(p))
            .unwrap_or(usize::MAX);
        if total > MAX_PERMUTATIONS {
            return self.by_signature(&groups);
        }
        // Try every combination of orders within the groups; `to[old] = new`.
        let mut best: Option<Operator> = None;
        let mut orders: Vec<Vec<u8>> = groups.clone();
        let mut to = vec![0u8; n];
        loop {
            let mut next = 0u8;
            for order in &orders {
                for &old in order {
                    to[old as usize] = next;
                    next += 1;
                }
            }
            let candidate = self.renamed(&to);
            if best.as_ref().is_none_or(|b| candidate.key() < b.key()) {
                best = Some(candidate);
            }
            // Advance the orders like an odometer of next permutations.
            let mut advanced = false;
            for (order, group) in orders.iter_mut().zip(&groups) {
                if next_permutation(order) {
                    advanced = true;
                    break;
                }
                // This group has wrapped: back to its first order, carry to the next.
                order.clone_from(group);
            }
            if !advanced {
                break;
            }
        }
        best.unwrap_or_else(|| self.clone())
    }

    /// Orders same-typed parameters by how they occur in the fact lists (a fallback for
    /// operators with too many parameters to try every order; equal operators still get
    /// equal forms unless two parameters share a signature).
    fn by_signature(&self, groups: &[Vec<u8>]) -> Operator {
        let signature = |p: u8| {
            let mut sig: Vec<(usize, Predicate, usize)> = Vec::new();
            for (list, facts) in [
                &self.pre_positive,
                &self.pre_negative,
                &self.add,
                &self.delete,
            ]
            .iter()
            .enumerate()
            {
                for f in facts.iter() {
                    for (pos, &a) in f.params().iter().enumerate() {
                        if a == p {
                            sig.push((list, f.predicate, pos));
                        }
                    }
                }
            }
            sig.sort_unstable();
            sig
        };
        let mut to = vec![0u8; self.params.len()];
        let mut next = 0u8;
        for group in groups {
            let mut g = group.clone();
            g.sort_by_key(|&p| signature(p));
            for old in g {
                to[old as usize] = next;
                next += 1;
            }
        }
        self.renamed(&to)
    }
}

/// Rearranges `v` into the next permutation in lexicographic order; false (and `v`
/// unchanged) when it is the last.
fn next_permutation(v: &mut [u8]) -> bool {
    if v.len() < 2 {
        return false;
    }
    let mut i = v.len() - 1;
    while i > 0 && v[i - 1] >= v[i] {
        i -= 1;
    }
    if i == 0 {
        return false;
    }
    let mut j = v.len() - 1;
    while v[j] <= v[i - 1] {
        j -= 1;
    }
    v.swap(i - 1, j);
    v[i..].reverse();
    true
}

/// `inHand(?h, ?c1)`.
pub fn fact_text(f: &LiftedFact, names: &[String]) -> String {
    let args: Vec<&str> = f
        .params()
        .iter()
        .map(|&a| names.get(a as usize).map(String::as_str).unwrap_or("?"))
        .collect();
    format!("{}({})", f.predicate.name(), args.join(", "))
}

impl fmt::Display for Operator {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.canonical_text())
    }
}

/// An activity lifted: its operator, and what changed meanwhile that no hand caused.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Lifted {
    /// The operator.
    pub operator: Operator,
    /// Changes seen during the activity that no hand caused (a cube tipping over,
    /// tracker noise): in no operator.
    pub uncaused: Vec<Fact>,
}

/// The operator an activity demonstrates, holding only the changes its own hand caused
/// ([`crate::cause`]); `others` is what the other hands did meanwhile
/// ([`OtherHands::during`]).
///
/// Its objects: the activity's hand, the object in hand and the object acted on at its
/// last frame, and the arguments of the changes its hand caused (putting a cube down
/// changes `onTop(cube, table)`, so the table is one). The precondition is every fact
/// over those objects, positive when it holds in the start state and negative when not;
/// the effects are the changes its hand caused. Changes over those objects that another
/// hand caused, or none, are in no effect.
pub fn lift(activity: &Segment, others: &OtherHands, space: &FactSpace, header: &Header) -> Lifted {
    let start = &activity.start_state;
    let end = &activity.end_state;
    let changes = cause::changes(activity, start, end, others, space);
    let mut involved: Vec<EntityId> = vec![activity.hand];
    involved.extend(activity.in_hand);
    involved.extend(activity.acted_on);
    for f in &changes.own {
        involved.extend_from_slice(f.args());
    }
    involved.sort_unstable_by_key(|&e| {
        (
            ParamType::of_kind(header_kind(header, e).unwrap_or(EntityKind::Other)),
            e,
        )
    });
    involved.dedup();
    let index_of = |e: EntityId| involved.iter().position(|&x| x == e).unwrap_or(0) as u8;
    let lifted = |f: &Fact| LiftedFact::new(f.predicate, index_of(f.first()), index_of(f.second()));
    let mask = space.mask(&involved);
    let before = start.restrict(&mask);
    let (mut add, mut delete) = (Vec::new(), Vec::new());
    for f in &changes.own {
        let holds_before = space.id(f).is_some_and(|id| before.contains(id));
        if holds_before {
            delete.push(lifted(f));
        } else {
            add.push(lifted(f));
        }
    }
    let params = involved
        .iter()
        .map(|&e| ParamType::of_kind(header_kind(header, e).unwrap_or(EntityKind::Other)))
        .collect();
    let operator = Operator::new(
        activity.activity,
        params,
        before.facts(space).map(|f| lifted(&f)).collect(),
        mask.difference(&before)
            .facts(space)
            .map(|f| lifted(&f))
            .collect(),
        add,
        delete,
    );
    Lifted {
        operator,
        uncaused: changes.nobody,
    }
}

/// A recording's activities lifted, in their order, with the changes no hand caused
/// counted once: along the first hand's activities (which cover the recording), a change
/// that neither that activity's hand nor another hand meanwhile caused.
pub fn lift_all(
    activities: &[Segment],
    space: &FactSpace,
    header: &Header,
) -> (Vec<Operator>, u64) {
    let first_hand = activities.iter().map(|a| a.hand).min();
    let mut operators = Vec::with_capacity(activities.len());
    let mut uncaused = 0u64;
    for activity in activities {
        let others = OtherHands::during(activity, activities, space);
        let lifted = lift(activity, &others, space, header);
        if Some(activity.hand) == first_hand {
            uncaused = uncaused.saturating_add(lifted.uncaused.len() as u64);
        }
        operators.push(lifted.operator);
    }
    (operators, uncaused)
}

fn header_kind(header: &Header, e: EntityId) -> Option<EntityKind> {
    header.entities.get(e.index()).map(|x| x.kind)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn f(p: Predicate, a: u8, b: u8) -> LiftedFact {
        LiftedFact::new(p, a, b)
    }

    #[test]
    fn operators_equal_up_to_renaming_have_one_form() {
        // Stack c_a onto c_b, once with the cubes as parameters 1, 2 and once as 2, 1.
        let one = Operator::new(
            Activity::Stack,
            vec![ParamType::Hand, ParamType::Cube, ParamType::Cube],
            vec![f(Predicate::InHand, 0, 1), f(Predicate::ActedOn, 0, 2)],
            vec![f(Predicate::OnTop, 1, 2)],
            vec![f(Predicate::OnTop, 1, 2), f(Predicate::InTouch, 2, 1)],
            vec![],
        );
        let two = Operator::new(
            Activity::Stack,
            vec![ParamType::Cube, ParamType::Hand, ParamType::Cube],
            vec![f(Predicate::InHand, 1, 2), f(Predicate::ActedOn, 1, 0)],
            vec![f(Predicate::OnTop, 2, 0)],
            vec![f(Predicate::OnTop, 2, 0), f(Predicate::InTouch, 0, 2)],
            vec![],
        );
        assert_eq!(one, two);
        assert_eq!(one.id(), two.id());
        assert_eq!(one.params[0], ParamType::Hand);
    }

    #[test]
    fn different_roles_are_different_operators() {
        let base = |held: u8, aimed: u8| {
            Operator::new(
                Activity::Stack,
                vec![ParamType::Hand, ParamType::Cube, ParamType::Cube],
                vec![
                    f(Predicate::InHand, 0, held),
                    f(Predicate::ActedOn, 0, aimed),
                ],
                vec![],
                vec![f(Predicate::OnTop, held, aimed)],
                vec![],
            )
        };
        // Renaming: the same.
        assert_eq!(base(1, 2), base(2, 1));
        // The held cube ends on itself: a different operator (and not a valid one, but
        // canonicalisation must not merge it).
        assert_ne!(base(1, 2), base(1, 1));
    }

    #[test]
    fn canonical_text_names_parameters_by_type() {
        let op = Operator::new(
            Activity::Put,
            vec![ParamType::Table, ParamType::Cube, ParamType::Hand],
            vec![f(Predicate::InHand, 2, 1)],
            vec![f(Predicate::OnTop, 1, 0)],
            vec![f(Predicate::OnTop, 1, 0)],
            vec![f(Predicate::HandMove, 2, 2)],
        );
        assert_eq!(
            op.canonical_text(),
            "Put(?h - hand, ?c1 - cube, ?t - table) pre: [inHand(?h, ?c1)] not: [onTop(?c1, ?t)] \
             add: [onTop(?c1, ?t)] del: [handMove(?h)]"
        );
    }

    #[test]
    fn next_permutation_visits_every_order() {
        let mut v = vec![0u8, 1, 2, 3];
        let mut count = 1;
        while next_permutation(&mut v) {
            count += 1;
        }
        assert_eq!(count, 24);
    }
}
