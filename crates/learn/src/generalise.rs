//! Generalised operators (issue 39): the demonstrated operators of one activity type
//! whose effects are equal up to renaming of the parameters that occur in them, merged
//! into one operator that keeps only the precondition facts all of them share.
//!
//! A demonstrated operator's precondition holds every fact, positive or negative, about
//! every object the segment involved, so two segments that did the same thing to their
//! cubes but found the scene around them a little different are two operators. A
//! generalised operator answers that:
//!
//! - the members of a group are the operators of one type whose effects (the parameters
//!   that occur in the add and delete lists, and those lists) are equal up to renaming
//!   ([`effect_key`]);
//! - the merged operator keeps the effect parameters and the parameters of the
//!   precondition facts every member shares under a renaming that aligns its effects
//!   with the others'; its precondition is those shared facts, positive and negative;
//! - its count is the sum of the members' counts, its provenance their union (the
//!   library does that part: [`crate::Library`]).
//!
//! So each member's precondition, renamed, contains the merged one: the merged operator
//! is applicable in every start state a member was demonstrated in, with the same
//! effects ([`covers`] checks this, and the tests check it on random operators and on
//! learned libraries).
//!
//! The merge is a function of the set of members alone: groups are keyed by canonical
//! forms, members are taken in canonical order, and the first member is intersected
//! with each of the others in turn, each time under the alignment (a bijection of effect
//! parameters that maps effects onto effects, extended to other parameters of the same
//! type or to none) that keeps the most facts, ties broken by the first in enumeration
//! order (targets by index, "none" last). Learning order therefore never changes a
//! generalised library.

use std::collections::BTreeMap;

use crate::operator::{LiftedFact, Operator, ParamType};

/// The form of a library's operators: as demonstrated, or generalised.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord, Default)]
pub enum OperatorForm {
    /// One operator per demonstrated precondition (the paper's; the default).
    #[default]
    Specific,
    /// The demonstrated operators merged by effects ([`generalise`]).
    Generalised,
}

impl OperatorForm {
    /// Both forms, the default first.
    pub const ALL: [OperatorForm; 2] = [OperatorForm::Specific, OperatorForm::Generalised];

    /// `specific` or `generalised`, as library files name them.
    pub fn name(self) -> &'static str {
        match self {
            OperatorForm::Specific => "specific",
            OperatorForm::Generalised => "generalised",
        }
    }

    /// The form of a [`name`](Self::name).
    pub fn from_name(name: &str) -> Option<OperatorForm> {
        OperatorForm::ALL.into_iter().find(|f| f.name() == name)
    }
}

/// `learn --generalise`, declared here (with the `clap` feature) beside the form it
/// chooses.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
#[cfg_attr(feature = "clap", derive(clap::Args))]
pub struct FormArgs {
    /// For a new library: merge operators of one type whose effects are equal up to
    /// renaming into one, with the precondition facts all share and the sum of their
    /// counts (off: the paper's operators). Into a library of specific operators: exit 36.
    /// See docs/operators.md.
    #[cfg_attr(feature = "clap", arg(long))]
    pub generalise: bool,
}

impl FormArgs {
    /// The form asked for: generalised with `--generalise`, else the library's own.
    pub fn form(&self) -> Option<OperatorForm> {
        self.generalise.then_some(OperatorForm::Generalised)
    }
}

/// The effects of an operator up to renaming: the operator of its effect parameters with
/// its add and delete lists only, in canonical form. Two operators of one type whose
/// keys are equal are merged by [`generalise`].
pub fn effect_key(op: &Operator) -> Operator {
    let used = effect_params(op);
    let mut to = vec![u8::MAX; op.params.len()];
    let mut params = Vec::with_capacity(used.len());
    for (new, &old) in used.iter().enumerate() {
        to[old as usize] = new as u8;
        params.push(op.params[old as usize]);
    }
    let map = |facts: &[LiftedFact]| -> Vec<LiftedFact> {
        let mut v: Vec<LiftedFact> = facts.iter().map(|f| rename(f, &to)).collect();
        v.sort_unstable();
        v.dedup();
        v
    };
    Operator::new(
        op.activity,
        params,
        Vec::new(),
        Vec::new(),
        map(&op.add),
        map(&op.delete),
    )
}

/// The generalised operators of `operators`: each with the indices (into `operators`)
/// of the members it merges, in the order of their effect keys. Deterministic: the same
/// set of operators, in any order, gives the same operators (the members' indices
/// follow the input's order).
///
/// Complexity: per group of `k` members, `k - 1` alignments, each an enumeration of
/// the bijections between effect parameters and the injections of the other parameters
/// (bounded by [`ALIGNMENT_BUDGET`] leaves; demonstrated operators have a handful of
/// parameters).
pub fn generalise(operators: &[Operator]) -> Vec<(Operator, Vec<usize>)> {
    let mut groups: BTreeMap<Operator, Vec<usize>> = BTreeMap::new();
    for (i, op) in operators.iter().enumerate() {
        groups.entry(effect_key(op)).or_default().push(i);
    }
    groups
        .into_values()
        .map(|mut members| {
            // Canonical order of the members, whatever the input's order.
            members.sort_by(|&a, &b| operators[a].cmp(&operators[b]).then(a.cmp(&b)));
            let ops: Vec<&Operator> = members.iter().map(|&i| &operators[i]).collect();
            let merged = merge(&ops);
            members.sort_unstable();
            (merged, members)
        })
        .collect()
}

/// The most complete alignments tried per member; past it, the best found so far is
/// taken (still deterministic).
pub const ALIGNMENT_BUDGET: usize = 100_000;

/// The merge of operators with equal effect keys, the first taken as the reference.
fn merge(ops: &[&Operator]) -> Operator {
    let Some((first, rest)) = ops.split_first() else {
        unreachable!("a group has at least one member");
    };
    let reference = *first;
    let effects = effect_params(reference);
    let mut positive = reference.pre_positive.clone();
    let mut negative = reference.pre_negative.clone();
    for &member in rest {
        let (p, n) = shared(reference, &effects, &positive, &negative, member);
        positive = p;
        negative = n;
    }
    // Keep the effect parameters and those of the shared facts, in the reference's order.
    let mut keep = vec![false; reference.params.len()];
    for &p in &effects {
        keep[p as usize] = true;
    }
    for f in positive.iter().chain(&negative) {
        for &a in f.params() {
            keep[a as usize] = true;
        }
    }
    let mut to = vec![u8::MAX; reference.params.len()];
    let mut params = Vec::new();
    for (old, &kept) in keep.iter().enumerate() {
        if kept {
            to[old] = params.len() as u8;
            params.push(reference.params[old]);
        }
    }
    let map = |facts: &[LiftedFact]| -> Vec<LiftedFact> {
        let mut v: Vec<LiftedFact> = facts.iter().map(|f| rename(f, &to)).collect();
        v.sort_unstable();
        v.dedup();
        v
    };
    Operator::new(
        reference.activity,
        params,
        map(&positive),
        map(&negative),
        map(&reference.add),
        map(&reference.delete),
    )
}

/// The facts of `positive` and `negative` (over the reference's parameters) that
/// `member` shares under the best alignment.
fn shared(
    reference: &Operator,
    effects: &[u8],
    positive: &[LiftedFact],
    negative: &[LiftedFact],
    member: &Operator,
) -> (Vec<LiftedFact>, Vec<LiftedFact>) {
    let member_effects = effect_params(member);
    // Parameters of the reference still in a fact and not in its effects.
    let mut others: Vec<u8> = positive
        .iter()
        .chain(negative)
        .flat_map(|f| f.params().to_vec())
        .filter(|p| !effects.contains(p))
        .collect();
    others.sort_unstable();
    others.dedup();
    let member_others: Vec<u8> = (0..member.params.len() as u8)
        .filter(|p| !member_effects.contains(p))
        .collect();
    let mut search = Alignment {
        reference,
        member,
        positive,
        negative,
        effects,
        member_effects: &member_effects,
        others: &others,
        member_others: &member_others,
        map: vec![None; reference.params.len()],
        used: vec![false; member.params.len()],
        best: None,
        leaves: 0,
    };
    search.effects_from(0);
    let Some((_, map)) = search.best else {
        // Equal effect keys always align; nothing shared if they somehow do not.
        return (Vec::new(), Vec::new());
    };
    let keep = |facts: &[LiftedFact], theirs: &[LiftedFact]| -> Vec<LiftedFact> {
        facts
            .iter()
            .filter(|f| mapped(f, &map).is_some_and(|g| theirs.binary_search(&g).is_ok()))
            .copied()
            .collect()
    };
    (
        keep(positive, &member.pre_positive),
        keep(negative, &member.pre_negative),
    )
}

/// The search for the alignment of a member with the reference that keeps most facts.
struct Alignment<'a> {
    reference: &'a Operator,
    member: &'a Operator,
    positive: &'a [LiftedFact],
    negative: &'a [LiftedFact],
    effects: &'a [u8],
    member_effects: &'a [u8],
    others: &'a [u8],
    member_others: &'a [u8],
    /// Reference parameter -> member parameter, so far.
    map: Vec<Option<u8>>,
    /// Member parameters taken.
    used: Vec<bool>,
    /// The best score and map found.
    best: Option<(usize, Vec<Option<u8>>)>,
    leaves: usize,
}

impl Alignment<'_> {
    /// Maps the reference's effect parameters from the `i`-th on, bijectively onto the
    /// member's, then checks that the effects map onto the member's.
    fn effects_from(&mut self, i: usize) {
        if self.leaves >= ALIGNMENT_BUDGET {
            return;
        }
        let Some(&p) = self.effects.get(i) else {
            let same = |mine: &[LiftedFact], theirs: &[LiftedFact]| {
                let mut v: Vec<LiftedFact> =
                    mine.iter().filter_map(|f| mapped(f, &self.map)).collect();
                v.sort_unstable();
                v.dedup();
                v == theirs
            };
            if same(&self.reference.add, &self.member.add)
                && same(&self.reference.delete, &self.member.delete)
            {
                self.others_from(0);
            }
            return;
        };
        for &q in self.member_effects {
            if !self.used[q as usize]
                && self.member.params[q as usize] == self.reference.params[p as usize]
            {
                self.assign(p, Some(q));
                self.effects_from(i + 1);
                self.assign(p, None);
            }
        }
    }

    /// Maps the reference's other parameters from the `i`-th on, each to an unused
    /// member parameter of its type outside the effects, or to none.
    fn others_from(&mut self, i: usize) {
        if self.leaves >= ALIGNMENT_BUDGET {
            return;
        }
        let Some(&p) = self.others.get(i) else {
            self.leaves += 1;
            let score = self.score();
            if self.best.as_ref().is_none_or(|(b, _)| score > *b) {
                self.best = Some((score, self.map.clone()));
            }
            return;
        };
        let ty: ParamType = self.reference.params[p as usize];
        for &q in self.member_others {
            if !self.used[q as usize] && self.member.params[q as usize] == ty {
                self.assign(p, Some(q));
                self.others_from(i + 1);
                self.assign(p, None);
            }
        }
        self.others_from(i + 1);
    }

    fn assign(&mut self, p: u8, q: Option<u8>) {
        if let Some(old) = self.map[p as usize] {
            self.used[old as usize] = false;
        }
        self.map[p as usize] = q;
        if let Some(q) = q {
            self.used[q as usize] = true;
        }
    }

    fn score(&self) -> usize {
        let count = |mine: &[LiftedFact], theirs: &[LiftedFact]| {
            mine.iter()
                .filter(|f| mapped(f, &self.map).is_some_and(|g| theirs.binary_search(&g).is_ok()))
                .count()
        };
        count(self.positive, &self.member.pre_positive)
            + count(self.negative, &self.member.pre_negative)
    }
}

/// Whether `general` applies wherever `specific` was demonstrated, with its effects: a
/// renaming of `general`'s parameters into `specific`'s (injective, types kept) maps its
/// add and delete lists onto `specific`'s and its precondition facts, positive and
/// negative, into `specific`'s. Then `specific`'s start state, under its own binding,
/// satisfies `general`'s precondition.
///
/// An exhaustive search over injections (exponential in the parameters; for tests and
/// checks of small operators).
pub fn covers(general: &Operator, specific: &Operator) -> bool {
    if general.activity != specific.activity {
        return false;
    }
    let mut map = vec![None; general.params.len()];
    let mut used = vec![false; specific.params.len()];
    covers_from(general, specific, 0, &mut map, &mut used)
}

fn covers_from(
    general: &Operator,
    specific: &Operator,
    i: usize,
    map: &mut Vec<Option<u8>>,
    used: &mut Vec<bool>,
) -> bool {
    if i == general.params.len() {
        let image = |facts: &[LiftedFact]| -> Vec<LiftedFact> {
            let mut v: Vec<LiftedFact> = facts.iter().filter_map(|f| mapped(f, map)).collect();
            v.sort_unstable();
            v.dedup();
            v
        };
        let within = |mine: &[LiftedFact], theirs: &[LiftedFact]| {
            image(mine).iter().all(|f| theirs.contains(f))
        };
        return image(&general.add) == specific.add
            && image(&general.delete) == specific.delete
            && within(&general.pre_positive, &specific.pre_positive)
            && within(&general.pre_negative, &specific.pre_negative);
    }
    for q in 0..specific.params.len() {
        if !used[q] && specific.params[q] == general.params[i] {
            used[q] = true;
            map[i] = Some(q as u8);
            if covers_from(general, specific, i + 1, map, used) {
                return true;
            }
            used[q] = false;
            map[i] = None;
        }
    }
    false
}

/// The parameters that occur in an operator's effects, ascending.
fn effect_params(op: &Operator) -> Vec<u8> {
    let mut v: Vec<u8> = op
        .add
        .iter()
        .chain(&op.delete)
        .flat_map(|f| f.params().to_vec())
        .collect();
    v.sort_unstable();
    v.dedup();
    v
}

/// A fact renamed by a total map (`to[old] = new`).
fn rename(f: &LiftedFact, to: &[u8]) -> LiftedFact {
    LiftedFact::new(f.predicate, to[f.args[0] as usize], to[f.args[1] as usize])
}

/// A fact renamed by a partial map; `None` when one of its parameters has no image.
fn mapped(f: &LiftedFact, map: &[Option<u8>]) -> Option<LiftedFact> {
    let a = map[f.args[0] as usize]?;
    let b = map[f.args[1] as usize]?;
    Some(LiftedFact::new(f.predicate, a, b))
}

#[cfg(test)]
mod tests {
    use super::*;
    use grounding::Predicate;
    use proptest::prelude::*;
    use segment::Activity;

    fn f(p: Predicate, a: u8, b: u8) -> LiftedFact {
        LiftedFact::new(p, a, b)
    }

    /// Stack `?c1` (held) onto `?c2`, with a third cube `?c3` somewhere.
    fn stack(extra_pos: Vec<LiftedFact>, extra_neg: Vec<LiftedFact>) -> Operator {
        let mut pos = vec![f(Predicate::InHand, 0, 1), f(Predicate::ActedOn, 0, 2)];
        pos.extend(extra_pos);
        let mut neg = vec![f(Predicate::OnTop, 1, 2), f(Predicate::HandOpen, 0, 0)];
        neg.extend(extra_neg);
        Operator::new(
            Activity::Stack,
            vec![
                ParamType::Hand,
                ParamType::Cube,
                ParamType::Cube,
                ParamType::Cube,
            ],
            pos,
            neg,
            vec![f(Predicate::OnTop, 1, 2), f(Predicate::HandOpen, 0, 0)],
            vec![f(Predicate::InHand, 0, 1)],
        )
    }

    #[test]
    fn operators_with_equal_effects_merge_keeping_shared_facts() {
        // The third cube stands on the target cube's left in one, on the held cube's
        // right in the other: incidental facts, not shared under any alignment.
        let one = stack(
            vec![f(Predicate::InTouch, 2, 3)],
            vec![f(Predicate::OnTop, 3, 2)],
        );
        let two = stack(
            vec![f(Predicate::OnTop, 3, 1)],
            vec![f(Predicate::OnTop, 3, 2)],
        );
        let merged = generalise(&[one.clone(), two.clone()]);
        assert_eq!(merged.len(), 1);
        let (op, members) = &merged[0];
        assert_eq!(members, &vec![0, 1]);
        // The third cube stays, through the one fact both share: nothing on the target.
        assert_eq!(
            op.canonical_text(),
            "Stack(?h - hand, ?c1 - cube, ?c2 - cube, ?c3 - cube) pre: [actedOn(?h, ?c1), \
             inHand(?h, ?c2)] not: [handOpen(?h), onTop(?c2, ?c1), onTop(?c3, ?c1)] \
             add: [handOpen(?h), onTop(?c2, ?c1)] del: [inHand(?h, ?c2)]"
        );
        assert!(covers(op, &one) && covers(op, &two));
        // Learning order does not matter.
        assert_eq!(generalise(&[two, one])[0].0, *op);
    }

    #[test]
    fn parameters_of_no_shared_fact_are_dropped() {
        let one = stack(vec![f(Predicate::InTouch, 2, 3)], vec![]);
        let two = stack(vec![f(Predicate::OnTop, 3, 1)], vec![]);
        let merged = generalise(&[one, two]);
        assert_eq!(merged[0].0.params.len(), 3, "{}", merged[0].0);
    }

    #[test]
    fn different_effects_stay_apart() {
        let one = stack(vec![], vec![]);
        let mut put = one.clone();
        put.add = vec![f(Predicate::OnTop, 2, 1)];
        let put = Operator::new(
            put.activity,
            put.params,
            put.pre_positive,
            put.pre_negative,
            put.add,
            put.delete,
        );
        assert_eq!(generalise(&[one.clone(), put.clone()]).len(), 2);
        // Same effects, other type: apart too.
        let mut other = one.clone();
        other.activity = Activity::Put;
        assert_eq!(generalise(&[one, other]).len(), 2);
    }

    #[test]
    fn a_single_operator_is_its_own_generalisation() {
        let one = stack(
            vec![f(Predicate::InTouch, 2, 3)],
            vec![f(Predicate::OnTop, 3, 2)],
        );
        assert_eq!(generalise(std::slice::from_ref(&one)), vec![(one, vec![0])]);
    }

    #[test]
    fn symmetric_effects_align_by_the_facts_they_keep() {
        // Both cubes released at once: effects symmetric in ?c1 and ?c2. One member has
        // a cube on the table and touching it, the other has the other cube so and the
        // first touching the table as well: the alignment that swaps the cubes keeps
        // two facts, the identity one, and the swap is chosen.
        let op = |pos: Vec<LiftedFact>| {
            Operator::new(
                Activity::Put,
                vec![
                    ParamType::Hand,
                    ParamType::Cube,
                    ParamType::Cube,
                    ParamType::Table,
                ],
                pos,
                vec![],
                vec![f(Predicate::HandOpen, 0, 0)],
                vec![f(Predicate::InHand, 0, 1), f(Predicate::InHand, 0, 2)],
            )
        };
        let one = op(vec![f(Predicate::OnTop, 1, 3), f(Predicate::InTouch, 1, 3)]);
        let two = op(vec![
            f(Predicate::OnTop, 2, 3),
            f(Predicate::InTouch, 2, 3),
            f(Predicate::InTouch, 1, 3),
        ]);
        assert_ne!(one, two);
        for ops in [[one.clone(), two.clone()], [two.clone(), one.clone()]] {
            let merged = generalise(&ops);
            assert_eq!(merged.len(), 1);
            assert_eq!(merged[0].0, one);
        }
    }

    fn any_fact(params: &[ParamType]) -> impl Strategy<Value = Option<LiftedFact>> {
        let params = params.to_vec();
        let n = params.len() as u8;
        (0..Predicate::ALL.len(), 0..n, 0..n).prop_map(move |(p, a, b)| {
            let predicate = Predicate::ALL[p];
            let hand_first = matches!(
                predicate,
                Predicate::HandMove
                    | Predicate::HandOpen
                    | Predicate::ActedOn
                    | Predicate::Graspable
                    | Predicate::InHand
            );
            let is_hand = |i: u8| params[i as usize] == ParamType::Hand;
            let ok = if predicate.arity() == 1 {
                is_hand(a)
            } else if hand_first {
                is_hand(a) && !is_hand(b)
            } else {
                !is_hand(a) && !is_hand(b) && a != b
            };
            ok.then(|| LiftedFact::new(predicate, a, b))
        })
    }

    /// Random operators over one hand, up to 3 cubes and a table, effects drawn from a
    /// few shapes so that groups form.
    fn any_operator() -> impl Strategy<Value = Operator> {
        (1usize..=3, 0usize..3).prop_flat_map(|(cubes, shape)| {
            let mut params = vec![ParamType::Hand];
            params.extend(std::iter::repeat_n(ParamType::Cube, cubes));
            params.push(ParamType::Table);
            let table = cubes as u8 + 1;
            let facts = proptest::collection::vec(any_fact(&params), 0..12);
            let negs = proptest::collection::vec(any_fact(&params), 0..12);
            (Just(params), facts, negs).prop_map(move |(params, pos, neg)| {
                let (add, delete) = match shape {
                    0 => (vec![f(Predicate::OnTop, 1, table)], vec![]),
                    1 => (
                        vec![f(Predicate::HandOpen, 0, 0)],
                        vec![f(Predicate::InHand, 0, 1)],
                    ),
                    _ => (vec![f(Predicate::ActedOn, 0, 1)], vec![]),
                };
                let mut pos: Vec<LiftedFact> = pos.into_iter().flatten().collect();
                pos.sort_unstable();
                pos.dedup();
                let mut neg: Vec<LiftedFact> = neg
                    .into_iter()
                    .flatten()
                    .filter(|g| pos.binary_search(g).is_err())
                    .collect();
                neg.sort_unstable();
                neg.dedup();
                Operator::new(Activity::Put, params, pos, neg, add, delete)
            })
        })
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(200))]

        /// Every member is covered by its generalised operator (it applies in the
        /// member's start state with the member's effects), members of one group have
        /// equal effect keys and no two groups do, the counts add up, and the result does
        /// not depend on the order of the operators.
        #[test]
        fn generalised_operators_cover_their_members(
            ops in proptest::collection::vec(any_operator(), 1..8)
        ) {
            let merged = generalise(&ops);
            let mut seen = vec![0usize; ops.len()];
            let mut keys = Vec::new();
            for (op, members) in &merged {
                prop_assert!(!members.is_empty());
                let key = effect_key(&ops[members[0]]);
                prop_assert_eq!(&effect_key(op), &key);
                keys.push(key.clone());
                for &m in members {
                    seen[m] += 1;
                    prop_assert_eq!(&effect_key(&ops[m]), &key);
                    prop_assert!(covers(op, &ops[m]), "{} does not cover {}", op, ops[m]);
                }
            }
            prop_assert!(seen.iter().all(|&s| s == 1));
            keys.sort();
            keys.dedup();
            prop_assert_eq!(keys.len(), merged.len());
            let mut reversed = ops.clone();
            reversed.reverse();
            let again: Vec<Operator> = generalise(&reversed).into_iter().map(|(o, _)| o).collect();
            let first: Vec<Operator> = merged.into_iter().map(|(o, _)| o).collect();
            prop_assert_eq!(again, first);
        }
    }
}
