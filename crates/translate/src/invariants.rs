//! Invariant synthesis: lifted mutex groups, checked against the ground actions.
//!
//! An invariant candidate is a set of *parts*, each a predicate with some argument
//! positions bound to the invariant's parameters and at most one position counted. It
//! claims: for every binding of the parameters, at most one matching atom is true. This is
//! the candidate space of Helmert's invariant synthesis ("Concise finite-domain
//! representations for PDDL planning tasks", AIJ 2009); unlike that algorithm, which proves
//! candidates on the lifted schemas, this module checks them on the reachable ground
//! actions, which is exact for the task at hand and needs no unification:
//!
//! - the initial state has at most one true atom per parameter binding;
//! - every ground action that adds an atom of a group either requires that atom already,
//!   or deletes another atom of the same group that its precondition requires, and it
//!   never adds two atoms of one group;
//! - except actions whose precondition holds two atoms of one group: in a state where
//!   the candidate holds they never apply (by induction over the reachable states), and
//!   relaxed grounding does keep such actions.
//!
//! A candidate that fails the second test on some action is refined by adding a part for
//! a required-and-deleted atom of that action that would balance the add; refinement is a
//! breadth-first search over candidates, bounded by [`MAX_CANDIDATES`].
//!
//! Complexity: per candidate, linear in the effects of the actions that add one of its
//! predicates.

use std::collections::VecDeque;

use rustc_hash::{FxHashMap, FxHashSet};

use crate::ground::{AtomId, Grounding};
use crate::model::{Model, PredId};

/// Candidates examined at most; past that, the invariants found so far are used.
pub(crate) const MAX_CANDIDATES: usize = 5_000;

/// A predicate in an invariant: `fixed[j]` is the argument position of invariant
/// parameter `j`; the one remaining position, if any, is counted.
#[derive(Debug, Clone, PartialEq, Eq, Hash, PartialOrd, Ord)]
struct Part {
    pred: PredId,
    fixed: Vec<u8>,
}

#[derive(Debug, Clone, PartialEq, Eq, Hash)]
struct Candidate {
    parts: Vec<Part>,
}

/// A ground mutex group: atoms of which at most one is true in any reachable state.
pub(crate) type Group = Vec<AtomId>;

struct Checker<'g> {
    g: &'g Grounding,
    /// Actions by the predicates they add.
    adders: Vec<Vec<u32>>,
    /// Whether an action's required atom is in its precondition: `pre` is sorted.
    stamp: Vec<u32>,
    round: u32,
}

fn key_of(g: &Grounding, part: &Part, atom: AtomId) -> Vec<u32> {
    let args = g.atoms.args(atom);
    part.fixed.iter().map(|&p| args[p as usize]).collect()
}

/// The parts of `c` that match `atom`'s predicate.
fn parts_for<'c>(c: &'c Candidate, g: &Grounding, atom: AtomId) -> impl Iterator<Item = &'c Part> {
    let pred = g.atoms.pred(atom);
    c.parts.iter().filter(move |p| p.pred == pred)
}

enum Verdict {
    Invariant,
    /// Unbalanced add: the action, and the group key that grew.
    Unbalanced {
        action: u32,
        key: Vec<u32>,
    },
    Invalid,
}

impl Checker<'_> {
    fn check(&mut self, c: &Candidate) -> Verdict {
        let g = self.g;
        // Initial state: at most one atom per key.
        let mut keys: FxHashMap<Vec<u32>, AtomId> = FxHashMap::default();
        for &a in &g.init {
            for part in parts_for(c, g, a) {
                if *keys.entry(key_of(g, part, a)).or_insert(a) != a {
                    return Verdict::Invalid;
                }
            }
        }
        self.round += 1;
        let preds: FxHashSet<PredId> = c.parts.iter().map(|p| p.pred).collect();
        let mut preds: Vec<PredId> = preds.into_iter().collect();
        preds.sort_unstable();
        for pred in preds {
            for &act in &self.adders[pred.0 as usize] {
                if self.stamp[act as usize] == self.round {
                    continue;
                }
                self.stamp[act as usize] = self.round;
                let action = &g.actions[act as usize];
                if requires_two_of_a_group(g, c, &action.pre) {
                    // Never applicable in a state where the candidate holds: by
                    // induction over reachable states it cannot break the candidate.
                    continue;
                }
                let mut added: Vec<(Vec<u32>, AtomId)> = Vec::new();
                for &a in &action.add {
                    for part in parts_for(c, g, a) {
                        added.push((key_of(g, part, a), a));
                    }
                }
                added.sort_unstable();
                added.dedup();
                for w in added.windows(2) {
                    if w[0].0 == w[1].0 {
                        return Verdict::Invalid; // two atoms of one group become true
                    }
                }
                for (key, a) in added {
                    if action.pre.binary_search(&a).is_ok() {
                        continue;
                    }
                    let balanced = action.del.iter().any(|&d| {
                        d != a
                            && action.pre.binary_search(&d).is_ok()
                            && parts_for(c, g, d).any(|part| key_of(g, part, d) == key)
                    });
                    if !balanced {
                        return Verdict::Unbalanced { action: act, key };
                    }
                }
            }
        }
        Verdict::Invariant
    }
}

/// Whether the precondition holds two different atoms of one group of `c` (same key).
/// Grounding is relaxed, so it keeps actions such as freecell's move of a card onto the
/// card it already stands on (`on(c, a)` and `clear(a)` required, both in the group
/// "what is on a"); in a state where the candidate holds, such an action never applies.
fn requires_two_of_a_group(g: &Grounding, c: &Candidate, pre: &[AtomId]) -> bool {
    // Most actions require at most one atom of a candidate: decide those without
    // allocating the keys (this runs per action and candidate).
    if pre
        .iter()
        .filter(|&&a| parts_for(c, g, a).next().is_some())
        .count()
        < 2
    {
        return false;
    }
    let mut keys: Vec<(Vec<u32>, AtomId)> = Vec::new();
    for &a in pre {
        for part in parts_for(c, g, a) {
            keys.push((key_of(g, part, a), a));
        }
    }
    if keys.len() < 2 {
        return false;
    }
    keys.sort_unstable();
    keys.dedup();
    keys.windows(2).any(|w| w[0].0 == w[1].0)
}

/// The parts for `atom` whose key equals `key`: invariant parameter `j` goes to a
/// position holding `key[j]`, and at most one position is left counted.
fn balancing_parts(g: &Grounding, atom: AtomId, key: &[u32]) -> Vec<Part> {
    let args = g.atoms.args(atom);
    if args.len() != key.len() && args.len() != key.len() + 1 {
        return Vec::new();
    }
    let mut out = Vec::new();
    let mut fixed = Vec::new();
    fn assign(
        args: &[u32],
        key: &[u32],
        j: usize,
        fixed: &mut Vec<u8>,
        pred: PredId,
        out: &mut Vec<Part>,
    ) {
        if j == key.len() {
            out.push(Part {
                pred,
                fixed: fixed.clone(),
            });
            return;
        }
        for (pos, &a) in args.iter().enumerate() {
            if a == key[j] && !fixed.contains(&(pos as u8)) {
                fixed.push(pos as u8);
                assign(args, key, j + 1, fixed, pred, out);
                fixed.pop();
            }
        }
    }
    assign(args, key, 0, &mut fixed, g.atoms.pred(atom), &mut out);
    out
}

/// Synthesises invariants and returns their ground mutex groups (each sorted, size >= 2,
/// deduplicated, in a deterministic order).
pub(crate) fn mutex_groups(model: &Model, g: &Grounding) -> Vec<Group> {
    let mut adders: Vec<Vec<u32>> = vec![Vec::new(); model.predicates.len()];
    for (i, a) in g.actions.iter().enumerate() {
        let mut preds: Vec<PredId> = a.add.iter().map(|&x| g.atoms.pred(x)).collect();
        preds.sort_unstable();
        preds.dedup();
        for p in preds {
            adders[p.0 as usize].push(i as u32);
        }
    }
    let mut checker = Checker {
        g,
        adders,
        stamp: vec![0; g.actions.len()],
        round: 0,
    };

    // Arities of fluent predicates, from any atom (predicates without atoms cannot matter).
    let mut arity: FxHashMap<PredId, usize> = FxHashMap::default();
    for a in 0..g.atoms.len() as AtomId {
        if g.fluent[a as usize] {
            arity
                .entry(g.atoms.pred(a))
                .or_insert_with(|| g.atoms.args(a).len());
        }
    }
    let mut preds: Vec<(PredId, usize)> = arity.into_iter().collect();
    preds.sort_unstable();
    let mut queue: VecDeque<Candidate> = VecDeque::new();
    let mut seen: FxHashSet<Candidate> = FxHashSet::default();
    for &(pred, n) in &preds {
        // No counted position, or each position counted in turn.
        let all: Vec<u8> = (0..n as u8).collect();
        let mut starts = vec![Part {
            pred,
            fixed: all.clone(),
        }];
        for counted in 0..n as u8 {
            starts.push(Part {
                pred,
                fixed: all.iter().copied().filter(|&p| p != counted).collect(),
            });
        }
        for part in starts {
            let c = Candidate { parts: vec![part] };
            if seen.insert(c.clone()) {
                queue.push_back(c);
            }
        }
    }
    let mut invariants = Vec::new();
    let mut examined = 0;
    while let Some(c) = queue.pop_front() {
        examined += 1;
        if examined > MAX_CANDIDATES {
            break;
        }
        let verdict = checker.check(&c);
        match verdict {
            Verdict::Invariant => invariants.push(c),
            Verdict::Invalid => {}
            Verdict::Unbalanced { action, key } => {
                let act = &g.actions[action as usize];
                for &d in &act.del {
                    if act.pre.binary_search(&d).is_err() || !g.fluent[d as usize] {
                        continue;
                    }
                    for part in balancing_parts(g, d, &key) {
                        if c.parts.contains(&part) {
                            continue;
                        }
                        let mut parts = c.parts.clone();
                        parts.push(part);
                        parts.sort_unstable();
                        let refined = Candidate { parts };
                        if seen.insert(refined.clone()) {
                            queue.push_back(refined);
                        }
                    }
                }
            }
        }
    }

    // Ground groups: every reachable fluent atom joins the group of its key, per invariant.
    let mut groups: Vec<Group> = Vec::new();
    let mut group_set: FxHashSet<Group> = FxHashSet::default();
    for inv in &invariants {
        let mut by_key: FxHashMap<Vec<u32>, Vec<AtomId>> = FxHashMap::default();
        for a in 0..g.atoms.len() as AtomId {
            if !g.fluent[a as usize] {
                continue;
            }
            for part in parts_for(inv, g, a) {
                by_key.entry(key_of(g, part, a)).or_default().push(a);
            }
        }
        let mut keyed: Vec<(Vec<u32>, Vec<AtomId>)> = by_key.into_iter().collect();
        keyed.sort_unstable();
        for (_, mut atoms) in keyed {
            atoms.sort_unstable();
            atoms.dedup();
            if atoms.len() >= 2 && group_set.insert(atoms.clone()) {
                groups.push(atoms);
            }
        }
    }
    groups
}
