//! The LM-cut heuristic (Helmert and Domshlak, ICAPS 2009).
//!
//! In the delete relaxation with an artificial goal fact `G` (reached by a zero-cost
//! operator whose preconditions are the goal) and an artificial fact `I` true in every
//! state (the precondition of operators that have none), LM-cut repeats:
//!
//! 1. h^max of every fact, and for every operator its *supporter*: a precondition of
//!    highest h^max. Ties matter for the quality of the cuts: the first round takes the
//!    precondition the exploration reaches last (its queue keeps a stack per cost, as Fast
//!    Downward's bucket queue does); in later rounds an operator whose supporter got
//!    cheaper keeps its supporter while that is still of highest cost, else takes the
//!    first of highest cost in the operator's tie-breaking order (`tie_breaking_order`);
//!    it keeps the supporter it has now (see `SupporterRule`), the operators of a fact
//!    visited in operator order as Fast Downward does. If `h^max(G) = 0`, stop.
//! 2. The *goal zone*: the facts from which `G` is reached through zero-cost operators,
//!    following supporters backwards. When a zero-cost operator has several preconditions
//!    of highest cost, its supporter becomes the first that no zero-cost operator achieves
//!    or that is already in the zone (as Fast Downward's goal-zone and border detection
//!    do), which keeps the zone, and the cuts, small.
//! 3. The *cut*: the operators whose supporter is reached from the state without entering
//!    the goal zone (following supporters forwards; the other effects of an operator that
//!    enters the goal zone are not reached) and that have an effect in the goal zone. It is a
//!    disjunctive action landmark; its cheapest cost `m` is added to `h` and subtracted
//!    from the cost of every operator in it.
//!
//! The sum is admissible (the cuts are landmarks with costs partitioned among them), not
//! necessarily consistent, and never below h^max. Step 1 after the first round is
//! incremental: only operators of the cut got cheaper, so only facts they reach can get
//! cheaper, and a decrease-only Dijkstra from their effects updates h^max and supporters.
//!
//! Cost per evaluation: O(rounds * (facts + preconditions + effects)), with a queue of a
//! bucket per small cost and a radix heap above (`radix_heap.rs`), round counters instead
//! of clearing arrays, and no allocation once the scratch buffers have grown.

use task::{Task, TaskError};

use crate::heuristic::Heuristic;
use crate::radix_heap::RadixHeap;

const INFINITE: u64 = u64::MAX;
/// The end of an intrusive list.
const NONE: u32 = u32::MAX;

/// Which supporter an operator keeps when its supporter got cheaper in the incremental
/// h^max update of a later round (if the kept one is no longer of highest h^max, the
/// operator takes the first precondition of highest h^max instead).
///
/// Ties decide which landmarks LM-cut finds, so the rule changes values, not
/// admissibility. Expansions of `astar(lmcut())` against Fast Downward's on the 78
/// instances of `bench/lists/fd-lmcut-1s.txt`, median of demoplan / FD's "until last
/// jump": 1.005 with `KeepCurrent`, 1.037 with `KeepRoundStart` (elevators p14: 16,078
/// with `KeepRoundStart`, 13,849 with `KeepCurrent`, FD 14,947; satellite p09: 386, 344,
/// FD 344).
///
/// Only `KeepCurrent` is ever used; `KeepRoundStart` exists for the tests alone, whose
/// from-scratch oracle (`oracle.rs`) can state it.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
enum SupporterRule {
    /// The supporter it has now, which an earlier update in the same round may have set:
    /// Fast Downward's rule. The result depends on the order of the updates.
    #[default]
    KeepCurrent,
    /// The supporter it had when the round's update began: the result depends only on
    /// the updated costs, so a reference that recomputes h^max from scratch in every round
    /// can state it (the tests' oracle does).
    #[cfg(test)]
    KeepRoundStart,
}

/// An operator of the relaxed task: static data and per-evaluation state side by side, so
/// that the inner loops touch one cache line per operator.
#[derive(Debug, Clone, Copy, Default)]
struct RelaxedOp {
    /// Cost in the current round (the base cost minus the cuts it was in).
    cost: u64,
    base_cost: u64,
    /// A precondition of highest h^max, once all preconditions are reached.
    supporter: u32,
    /// Neighbours in the list of operators with the same supporter ([`NONE`] at the ends).
    supported_prev: u32,
    supported_next: u32,
    /// Preconditions not yet reached in the first exploration.
    unsatisfied: u32,
    /// Preconditions: `pre[pre_start..pre_start + num_pre]` (never empty).
    pre_start: u32,
    num_pre: u32,
    /// Effects: `eff[eff_start..eff_end]`.
    eff_start: u32,
    eff_end: u32,
    /// The last round in whose goal zone one of its effects lies (marked while the zone is
    /// marked, so the cut search tests one field instead of every effect).
    enters_zone: u32,
    /// For the tests' rule: the round in which its supporter was last updated, and its
    /// supporter when that round's update began.
    #[cfg(test)]
    updated_in_round: u32,
    #[cfg(test)]
    round_supporter: u32,
}

/// A fact of the relaxed task.
#[derive(Debug, Clone, Copy)]
struct RelaxedFact {
    /// h^max.
    cost: u64,
    /// The round in which it was last marked in the goal zone.
    goal_zone: u32,
    /// The round in which it was last reached by the cut search.
    reached: u32,
    /// First of the operators this fact supports (a doubly linked list through
    /// `RelaxedOp::supported_next`), so the explorations visit only those operators
    /// instead of every operator the fact is a precondition of.
    supported: u32,
    /// Last of them. The list is in operator order (see [`link`]).
    supported_last: u32,
}

/// The LM-cut heuristic; see the module documentation.
#[derive(Debug, Clone)]
pub struct LmCut {
    fact_offset: Vec<u32>,
    /// Index of the fact true in every state.
    fact_i: u32,
    /// Index of the artificial goal fact.
    fact_g: u32,
    ops: Vec<RelaxedOp>,
    facts: Vec<RelaxedFact>,
    rule: SupporterRule,
    pre: Vec<u32>,
    eff: Vec<u32>,
    /// Operators with fact `f` as a precondition: `pre_of[pre_of_start[f]..pre_of_start[f + 1]]`.
    pre_of_start: Vec<u32>,
    pre_of: Vec<u32>,
    /// Operators with fact `f` as an effect, likewise.
    ach_start: Vec<u32>,
    ach: Vec<u32>,
    // Scratch, reused across evaluations.
    round: u32,
    heap: RadixHeap,
    /// The cut search's stack, one place per fact.
    stack: Vec<u32>,
    frames: Vec<(u32, u32)>,
    /// The cut: `cut[..cut_len]`, one place per operator.
    cut: Vec<u32>,
    cut_len: usize,
    /// The values of the cut's operators, computed before any is relaxed.
    cut_values: Vec<u64>,
    /// The lists of supported operators that may be out of operator order.
    unsorted: Unsorted,
}

/// `values[start[k]..start[k + 1]]` lists, by counting sort of `(key, value)` pairs.
fn group_by(keys: usize, pairs: &[(u32, u32)]) -> (Vec<u32>, Vec<u32>) {
    let mut start = vec![0u32; keys + 1];
    for &(k, _) in pairs {
        start[k as usize + 1] += 1;
    }
    for k in 0..keys {
        start[k + 1] += start[k];
    }
    let mut next = start.clone();
    let mut values = vec![0u32; pairs.len()];
    for &(k, v) in pairs {
        values[next[k as usize] as usize] = v;
        next[k as usize] += 1;
    }
    (start, values)
}

/// The first fact of `pres` whose h^max equals `cost`.
#[inline]
fn first_with_cost(pres: &[u32], facts: &[RelaxedFact], cost: u64) -> Option<u32> {
    pres.iter()
        .copied()
        .find(|&p| facts[p as usize].cost == cost)
}

/// An operator's preconditions in the order LM-cut breaks ties in (the first of highest
/// h^max becomes the supporter): those on variables the operator does not change, then
/// those on variables it changes, each by `rank` (see [`Task::atom_order_ranks`]).
///
/// Ties decide which landmarks LM-cut finds. This is the order in which Fast Downward's
/// search reads the preconditions from its translator's file (prevail conditions, then
/// the others, each sorted by the variable numbering before the causal-graph
/// reordering), so both planners mostly find the same landmarks on the same task (the
/// rest of Fast Downward's ties, such as its queue's order, are not reproduced).
/// Expansions with this order / with preconditions by ascending variable index (Fast
/// Downward in brackets): satellite p09 386 / 582 (344), p07 2,004 / 4,341 (2,004),
/// freecell 3-3 62 / 108 (44).
pub fn tie_breaking_order<'a>(
    op: &'a task::Operator,
    rank: &[u32],
) -> impl Iterator<Item = &'a task::Fact> {
    let changes = |f: &task::Fact| op.effects.iter().any(|e| e.var == f.var);
    let mut order: Vec<(bool, u32, &task::Fact)> = op
        .preconditions
        .iter()
        .map(|f| (changes(f), rank[f.var.index()], f))
        .collect();
    order.sort_by_key(|&(changed, rank, _)| (changed, rank));
    order.into_iter().map(|(_, _, f)| f)
}

/// Makes `fact` the supporter of operator `o`, at the end of `fact`'s list; returns false
/// if that put the list out of operator order.
///
/// Fast Downward visits the operators a fact supports in operator order (its
/// `precondition_of`, filtered by supporter), in the cut search and in the incremental
/// update, and that order decides which supporter the update keeps, and so LM-cut's
/// values. The first exploration links each fact's operators in ascending order, so its
/// lists are in order; an operator that changes supporter later may not be, and the list
/// is sorted when it is next visited ([`sort_supported`]). Cheaper than the alternatives
/// measured: iterating the preconditions' operators as Fast Downward does cost about a
/// fifth more time per evaluation (logistics, blocks, sokoban), and inserting each
/// operator in its place half again as much on freecell, whose lists are long.
#[inline]
fn link(ops: &mut [RelaxedOp], facts: &mut [RelaxedFact], o: u32, fact: u32) -> bool {
    let last = facts[fact as usize].supported_last;
    if last == NONE {
        facts[fact as usize].supported = o;
    } else {
        ops[last as usize].supported_next = o;
    }
    facts[fact as usize].supported_last = o;
    let op = &mut ops[o as usize];
    op.supporter = fact;
    op.supported_prev = last;
    op.supported_next = NONE;
    last == NONE || last < o
}

/// Puts `fact`'s list of supported operators in operator order, through `scratch`.
#[cold]
fn sort_supported(
    ops: &mut [RelaxedOp],
    facts: &mut [RelaxedFact],
    fact: u32,
    scratch: &mut Vec<u32>,
) {
    scratch.clear();
    let mut next = facts[fact as usize].supported;
    while next != NONE {
        scratch.push(next);
        next = ops[next as usize].supported_next;
    }
    scratch.sort_unstable();
    let mut prev = NONE;
    for &o in scratch.iter() {
        ops[o as usize].supported_prev = prev;
        if prev == NONE {
            facts[fact as usize].supported = o;
        } else {
            ops[prev as usize].supported_next = o;
        }
        prev = o;
    }
    if prev != NONE {
        ops[prev as usize].supported_next = NONE;
    }
    facts[fact as usize].supported_last = prev;
}

/// Takes operator `o` out of its supporter's list.
#[inline]
fn unlink(ops: &mut [RelaxedOp], facts: &mut [RelaxedFact], o: u32) {
    let RelaxedOp {
        supporter,
        supported_prev: prev,
        supported_next: next,
        ..
    } = ops[o as usize];
    if prev == NONE {
        facts[supporter as usize].supported = next;
    } else {
        ops[prev as usize].supported_next = next;
    }
    if next == NONE {
        facts[supporter as usize].supported_last = prev;
    } else {
        ops[next as usize].supported_prev = prev;
    }
}

/// Changes the supporter of operator `o` to `fact`, and records in `unsorted` a list that
/// this put out of operator order.
#[inline]
fn relink(
    ops: &mut [RelaxedOp],
    facts: &mut [RelaxedFact],
    unsorted: &mut Unsorted,
    o: u32,
    fact: u32,
) {
    if ops[o as usize].supporter != fact {
        unlink(ops, facts, o);
        if !link(ops, facts, o, fact) {
            unsorted.mark(fact);
        }
    }
}

/// The facts whose lists of supported operators may be out of operator order.
#[derive(Debug, Clone, Default)]
struct Unsorted {
    /// Per fact.
    flag: Vec<bool>,
    /// The facts flagged, in the order flagged (a fact sorted since may still be listed).
    facts: Vec<u32>,
    /// Scratch for sorting a list.
    scratch: Vec<u32>,
}

impl Unsorted {
    #[inline]
    fn mark(&mut self, fact: u32) {
        if !std::mem::replace(&mut self.flag[fact as usize], true) {
            self.facts.push(fact);
        }
    }

    /// Sorts `fact`'s list if it is flagged.
    #[inline]
    fn sort(&mut self, ops: &mut [RelaxedOp], facts: &mut [RelaxedFact], fact: u32) {
        if std::mem::take(&mut self.flag[fact as usize]) {
            sort_supported(ops, facts, fact, &mut self.scratch);
        }
    }

    /// Sorts every flagged list.
    fn sort_all(&mut self, ops: &mut [RelaxedOp], facts: &mut [RelaxedFact]) {
        while let Some(fact) = self.facts.pop() {
            self.sort(ops, facts, fact);
        }
    }

    /// Forgets every flag (the lists were rebuilt).
    fn clear(&mut self) {
        while let Some(fact) = self.facts.pop() {
            self.flag[fact as usize] = false;
        }
    }
}

/// Recomputes an operator whose supporter got cheaper (or that got cheaper itself): its
/// value is its cost plus its most expensive precondition; its supporter stays the one
/// `rule` keeps while that is of highest cost, otherwise becomes the first precondition of
/// highest cost. Relaxes its effects.
#[allow(clippy::too_many_arguments)] // The split borrows of `LmCut` the update needs.
fn update_operator(
    ops: &mut [RelaxedOp],
    facts: &mut [RelaxedFact],
    unsorted: &mut Unsorted,
    pre: &[u32],
    eff: &[u32],
    heap: &mut RadixHeap,
    rule: SupporterRule,
    round: u32,
    o: u32,
) {
    #[cfg(not(test))]
    let _ = round;
    #[cfg(test)]
    {
        let op = &mut ops[o as usize];
        if op.updated_in_round != round {
            op.updated_in_round = round;
            op.round_supporter = op.supporter;
        }
    }
    let op = ops[o as usize];
    let pres = &pre[op.pre_start as usize..(op.pre_start + op.num_pre) as usize];
    let Some(max) = pres.iter().map(|&p| facts[p as usize].cost).max() else {
        return;
    };
    let previous = match rule {
        SupporterRule::KeepCurrent => op.supporter,
        #[cfg(test)]
        SupporterRule::KeepRoundStart => op.round_supporter,
    };
    let supporter = if facts[previous as usize].cost == max {
        previous
    } else {
        first_with_cost(pres, facts, max).unwrap_or(previous)
    };
    relink(ops, facts, unsorted, o, supporter);
    relax_effects(
        &eff[op.eff_start as usize..op.eff_end as usize],
        op.cost.saturating_add(max),
        facts,
        heap,
    );
}

/// Lowers the h^max of the effects to `value` where that is cheaper, queueing them.
#[inline]
fn relax_effects(effects: &[u32], value: u64, facts: &mut [RelaxedFact], heap: &mut RadixHeap) {
    for &e in effects {
        let fact = &mut facts[e as usize];
        if value < fact.cost {
            fact.cost = value;
            heap.push(value, e);
        }
    }
}

impl LmCut {
    /// LM-cut for `task` (costs as [`Task::cost`] gives them), with Fast Downward's
    /// supporter rule; fails if the task is not valid. O(size of the task).
    pub fn new(task: &Task) -> Result<LmCut, TaskError> {
        LmCut::with_supporter_rule(task, SupporterRule::KeepCurrent)
    }

    /// LM-cut for `task` with the given supporter rule; see [`LmCut::new`].
    fn with_supporter_rule(task: &Task, rule: SupporterRule) -> Result<LmCut, TaskError> {
        task.validate()?;
        let (fact_offset, num_facts) = crate::heuristic::fact_offsets(task);
        let fact_i = num_facts;
        let fact_g = num_facts + 1;
        let num_facts = num_facts as usize + 2;
        let fact = |f: &task::Fact| fact_offset[f.var.index()] + f.value;
        let mut ops = Vec::with_capacity(task.operators.len() + 1);
        let mut pre = Vec::new();
        let mut eff = Vec::new();
        let mut add = |pres: Vec<u32>, effs: Vec<u32>, cost: u64| {
            let pres = if pres.is_empty() { vec![fact_i] } else { pres };
            ops.push(RelaxedOp {
                base_cost: cost,
                pre_start: pre.len() as u32,
                num_pre: pres.len() as u32,
                eff_start: eff.len() as u32,
                eff_end: (eff.len() + effs.len()) as u32,
                ..RelaxedOp::default()
            });
            pre.extend(pres);
            eff.extend(effs);
        };
        let rank = task.atom_order_ranks();
        for op in &task.operators {
            add(
                tie_breaking_order(op, &rank).map(fact).collect(),
                op.effects.iter().map(fact).collect(),
                task.cost(op),
            );
        }
        // The goal operator, last.
        add(task.goal.iter().map(fact).collect(), vec![fact_g], 0);
        let mut pre_pairs = Vec::with_capacity(pre.len());
        let mut eff_pairs = Vec::with_capacity(eff.len());
        for (o, op) in ops.iter().enumerate() {
            let start = op.pre_start as usize;
            for &f in &pre[start..start + op.num_pre as usize] {
                pre_pairs.push((f, o as u32));
            }
            for &f in &eff[op.eff_start as usize..op.eff_end as usize] {
                eff_pairs.push((f, o as u32));
            }
        }
        let (pre_of_start, pre_of) = group_by(num_facts, &pre_pairs);
        let (ach_start, ach) = group_by(num_facts, &eff_pairs);
        let num_ops = ops.len();
        Ok(LmCut {
            fact_offset,
            fact_i,
            fact_g,
            ops,
            rule,
            facts: vec![
                RelaxedFact {
                    cost: INFINITE,
                    goal_zone: 0,
                    reached: 0,
                    supported: NONE,
                    supported_last: NONE,
                };
                num_facts
            ],
            pre,
            eff,
            pre_of_start,
            pre_of,
            ach_start,
            ach,
            round: 0,
            heap: RadixHeap::new(),
            stack: vec![0; num_facts],
            frames: Vec::new(),
            cut: vec![0; num_ops],
            cut_len: 0,
            cut_values: vec![0; num_ops],
            unsorted: Unsorted {
                flag: vec![false; num_facts],
                ..Unsorted::default()
            },
        })
    }

    /// h^max from scratch, with supporters: the precondition reached last. The radix
    /// heap hands out the facts of one cost last in, first out, like Fast Downward's
    /// bucket queue; with its ties this is closer to Fast Downward's values than the first
    /// precondition of highest cost (pegsol p20: 50,755 expansions against 80,785; Fast
    /// Downward 54,091).
    fn first_exploration(&mut self, state: &[u32]) {
        let LmCut {
            ops,
            facts,
            eff,
            pre_of_start,
            pre_of,
            heap,
            ..
        } = self;
        for f in facts.iter_mut() {
            f.cost = INFINITE;
            f.supported = NONE;
            f.supported_last = NONE;
        }
        self.unsorted.clear();
        for op in ops.iter_mut() {
            op.cost = op.base_cost;
            op.unsatisfied = op.num_pre;
        }
        heap.clear();
        for (var, &value) in state.iter().enumerate() {
            let f = self.fact_offset[var] + value;
            facts[f as usize].cost = 0;
            heap.push(0, f);
        }
        facts[self.fact_i as usize].cost = 0;
        heap.push(0, self.fact_i);
        while let Some((c, f)) = heap.pop() {
            if c > facts[f as usize].cost {
                continue;
            }
            for &o in
                &pre_of[pre_of_start[f as usize] as usize..pre_of_start[f as usize + 1] as usize]
            {
                let op = &mut ops[o as usize];
                op.unsatisfied -= 1;
                if op.unsatisfied == 0 {
                    // Every precondition is reached at a cost of at most `c`, `f` at `c`:
                    // `f`, the one reached last, is a precondition of highest cost.
                    let op = *op;
                    let in_order = link(ops, facts, o, f);
                    debug_assert!(in_order, "operators are linked in ascending order here");
                    relax_effects(
                        &eff[op.eff_start as usize..op.eff_end as usize],
                        op.cost + c,
                        facts,
                        heap,
                    );
                }
            }
        }
    }

    /// Updates h^max after the operators of the cut got cheaper: costs only decrease.
    ///
    /// An operator whose supporter got cheaper is updated (`update_operator`), its
    /// supporter chosen by the [`SupporterRule`]. The operators of a fact are updated in
    /// operator order (its list of supported operators, sorted first if an earlier change
    /// of supporter put it out of order: see [`link`]), the facts in the order the heap
    /// hands them out.
    fn second_exploration(&mut self) {
        let round = self.round;
        let rule = self.rule;
        let LmCut {
            ops,
            facts,
            pre,
            eff,
            heap,
            cut,
            cut_len,
            cut_values,
            unsorted,
            ..
        } = self;
        heap.clear();
        // The cut's operators got cheaper: each is valued by its supporter, which is its
        // most expensive precondition until an effect is relaxed, so all are valued before
        // any effect is (relaxing one cut operator's effects can lower another's
        // supporter below its other preconditions, and valuing that one by its supporter
        // then would undercount h^max). Fast Downward queues them the same way.
        for (&o, value) in cut[..*cut_len].iter().zip(cut_values.iter_mut()) {
            let op = ops[o as usize];
            *value = op.cost.saturating_add(facts[op.supporter as usize].cost);
        }
        for (&o, &value) in cut[..*cut_len].iter().zip(cut_values.iter()) {
            let op = ops[o as usize];
            relax_effects(
                &eff[op.eff_start as usize..op.eff_end as usize],
                value,
                facts,
                heap,
            );
        }
        while let Some((c, f)) = heap.pop() {
            if c > facts[f as usize].cost {
                continue;
            }
            // Only an operator whose most expensive precondition got cheaper changes.
            unsorted.sort(ops, facts, f);
            let mut next = facts[f as usize].supported;
            while next != NONE {
                let o = next;
                next = ops[o as usize].supported_next;
                update_operator(ops, facts, unsorted, pre, eff, heap, rule, round, o);
            }
        }
    }

    /// True if no operator of cost 0 (in this round) achieves `fact`.
    #[inline]
    fn has_no_zero_cost_achiever(&self, fact: u32) -> bool {
        let (start, end) = (
            self.ach_start[fact as usize] as usize,
            self.ach_start[fact as usize + 1] as usize,
        );
        self.ach[start..end]
            .iter()
            .all(|&o| self.ops[o as usize].cost != 0)
    }

    /// Among the preconditions of a zero-cost operator that tie with its supporter, prefers
    /// the first that no zero-cost operator achieves (the border of the goal zone) or that
    /// is already in the goal zone: the zone then grows less through zero-cost chains, and
    /// the cuts stay small.
    fn break_supporter_ties(&mut self, o: usize) {
        let op = self.ops[o];
        let target = self.facts[op.supporter as usize].cost;
        for i in op.pre_start..op.pre_start + op.num_pre {
            let p = self.pre[i as usize];
            let fact = self.facts[p as usize];
            if fact.cost != target {
                continue;
            }
            if fact.goal_zone == self.round || self.has_no_zero_cost_achiever(p) {
                relink(
                    &mut self.ops,
                    &mut self.facts,
                    &mut self.unsorted,
                    o as u32,
                    p,
                );
                return;
            }
        }
    }

    /// Marks the goal zone with the current round: depth first from the goal fact through
    /// the supporters of zero-cost achievers, with an explicit stack of (fact, next
    /// achiever) frames so deep zones cannot overflow the call stack.
    fn mark_goal_zone(&mut self) {
        self.frames.clear();
        self.facts[self.fact_g as usize].goal_zone = self.round;
        self.frames
            .push((self.fact_g, self.ach_start[self.fact_g as usize]));
        while let Some(&(f, cursor)) = self.frames.last() {
            if cursor == self.ach_start[f as usize + 1] {
                self.frames.pop();
                continue;
            }
            if let Some(top) = self.frames.last_mut() {
                top.1 += 1;
            }
            let o = self.ach[cursor as usize] as usize;
            self.ops[o].enters_zone = self.round;
            if self.ops[o].cost == 0 && self.ops[o].unsatisfied == 0 {
                self.break_supporter_ties(o);
                let s = self.ops[o].supporter;
                if self.facts[s as usize].goal_zone != self.round {
                    self.facts[s as usize].goal_zone = self.round;
                    self.frames.push((s, self.ach_start[s as usize]));
                }
            }
        }
    }

    /// Collects the cut: from the state, along supporters, up to the goal zone.
    ///
    /// The hottest loop of LM-cut (over half of its time). It works on slices and on a
    /// stack and a cut of fixed size (each fact is pushed, and each operator put in the
    /// cut, at most once per round), so the loop calls nothing that could grow a vector:
    /// otherwise the compiler must assume the call may change the other arrays and
    /// reloads their addresses and lengths from memory at every step.
    fn find_cut(&mut self, state: &[u32]) {
        self.unsorted.sort_all(&mut self.ops, &mut self.facts);
        let round = self.round;
        let ops = &self.ops[..];
        let facts = &mut self.facts[..];
        let eff = &self.eff[..];
        let stack = &mut self.stack[..];
        let cut = &mut self.cut[..];
        let mut top = 0;
        let mut cut_len = 0;
        facts[self.fact_i as usize].reached = round;
        stack[top] = self.fact_i;
        top += 1;
        for (&offset, &value) in self.fact_offset.iter().zip(state) {
            let f = offset + value;
            facts[f as usize].reached = round;
            stack[top] = f;
            top += 1;
        }
        while top > 0 {
            top -= 1;
            let f = stack[top];
            let mut next = facts[f as usize].supported;
            while next != NONE {
                let o = next;
                let op = &ops[o as usize];
                next = op.supported_next;
                if op.enters_zone == round {
                    // A cut operator; its other effects lie beyond the cut. It is met
                    // once: only through its supporter, which is pushed once.
                    cut[cut_len] = o;
                    cut_len += 1;
                    continue;
                }
                for &e in &eff[op.eff_start as usize..op.eff_end as usize] {
                    let fact = &mut facts[e as usize];
                    if fact.reached != round {
                        fact.reached = round;
                        stack[top] = e;
                        top += 1;
                    }
                }
            }
        }
        self.cut_len = cut_len;
    }

    fn next_round(&mut self) {
        if self.round == u32::MAX {
            // Counters wrap after four billion rounds: start the stamps afresh.
            for f in &mut self.facts {
                f.goal_zone = 0;
                f.reached = 0;
            }
            for op in &mut self.ops {
                op.enters_zone = 0;
                #[cfg(test)]
                {
                    op.updated_in_round = 0;
                }
            }
            self.round = 0;
        }
        self.round += 1;
    }
}

impl Heuristic for LmCut {
    fn name(&self) -> &str {
        "lmcut"
    }

    fn evaluate(&mut self, state: &[u32]) -> Option<u64> {
        self.first_exploration(state);
        let goal = self.fact_g as usize;
        if self.facts[goal].cost == INFINITE {
            return None;
        }
        let mut h: u64 = 0;
        while self.facts[goal].cost != 0 {
            self.next_round();
            self.mark_goal_zone();
            self.find_cut(state);
            let Some(m) = self.cut[..self.cut_len]
                .iter()
                .map(|&o| self.ops[o as usize].cost)
                .min()
            else {
                // Cannot happen while h^max(G) > 0; stop rather than loop.
                break;
            };
            if m == 0 {
                break;
            }
            h = h.saturating_add(m);
            for &o in &self.cut[..self.cut_len] {
                self.ops[o as usize].cost -= m;
            }
            self.second_exploration();
        }
        Some(h)
    }
}

#[cfg(test)]
mod oracle;

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;
    use task::{Fact, Operator, VarId, Variable};

    /// Every state of `task` (mixed radix over the domains).
    fn all_states(task: &Task) -> Vec<Vec<u32>> {
        let mut states = vec![vec![]];
        for v in &task.variables {
            states = states
                .into_iter()
                .flat_map(|s| {
                    (0..v.domain_size()).map(move |x| {
                        let mut s = s.clone();
                        s.push(x);
                        s
                    })
                })
                .collect();
        }
        states
    }

    proptest! {
        /// The incremental rounds (heap, supporter lists, goal zone, cut) against the
        /// oracle that recomputes h^max from scratch every round, in every state of small
        /// random tasks. The oracle states the round-start rule; Fast Downward's rule,
        /// the one `LmCut::new` takes, shares every line but the choice of the supporter
        /// kept (its admissibility and dominance over h^max are `tests/properties.rs`').
        #[test]
        fn the_round_start_rule_equals_the_oracle(task in crate::test_tasks::tasks()) {
            let mut lmcut = LmCut::with_supporter_rule(&task, SupporterRule::KeepRoundStart)
                .map_err(|e| TestCaseError::fail(e.to_string()))?;
            for state in all_states(&task) {
                prop_assert_eq!(
                    lmcut.evaluate(&state),
                    oracle::reference_lmcut(&task, &state),
                    "in {:?}",
                    state
                );
            }
        }
    }

    fn variable(values: &[&str]) -> Variable {
        Variable {
            name: "v".into(),
            value_names: values.iter().map(|s| s.to_string()).collect(),
        }
    }

    /// The operators a fact supports, front to back, and back to front through the
    /// `supported_prev` links.
    fn supported_list(lmcut: &LmCut, fact: u32) -> Vec<u32> {
        let mut forwards = vec![];
        let mut next = lmcut.facts[fact as usize].supported;
        while next != NONE {
            forwards.push(next);
            next = lmcut.ops[next as usize].supported_next;
        }
        let mut backwards = vec![];
        let mut prev = lmcut.facts[fact as usize].supported_last;
        while prev != NONE {
            backwards.insert(0, prev);
            prev = lmcut.ops[prev as usize].supported_prev;
        }
        assert_eq!(
            forwards, backwards,
            "the two directions of the list disagree"
        );
        forwards
    }

    /// Fast Downward visits the operators a fact supports in operator order: the first
    /// exploration builds the lists in that order, an operator that changes supporter
    /// joins at the end and flags the list if that breaks the order, and sorting the
    /// flagged lists (before every visit) restores it, whichever operator moved.
    #[test]
    fn supported_lists_are_visited_in_operator_order() {
        let f = |v: u32, x: u32| Fact::new(VarId(v), x);
        let op = |name: &str, effect: Fact| Operator {
            name: name.into(),
            preconditions: vec![f(0, 0)],
            effects: vec![effect],
            cost: 1,
        };
        let task = Task {
            variables: (0..4).map(|_| variable(&["a", "b"])).collect(),
            mutexes: vec![],
            initial_state: vec![0; 4],
            goal: vec![f(1, 1), f(2, 1), f(3, 1)],
            operators: vec![op("o0", f(1, 1)), op("o1", f(2, 1)), op("o2", f(3, 1))],
            use_costs: false,
        };
        let mut lmcut = LmCut::new(&task).unwrap();
        lmcut.first_exploration(&task.initial_state);
        let supporter = lmcut.fact_offset[0];
        let elsewhere = lmcut.fact_i;
        assert_eq!(supported_list(&lmcut, supporter), vec![0, 1, 2]);
        assert!(lmcut.unsorted.facts.is_empty());
        let relink = |lmcut: &mut LmCut, o: u32, fact: u32| {
            relink(
                &mut lmcut.ops,
                &mut lmcut.facts,
                &mut lmcut.unsorted,
                o,
                fact,
            );
        };
        for o in [0, 1, 2] {
            relink(&mut lmcut, o, elsewhere);
            let rest: Vec<u32> = [0, 1, 2].into_iter().filter(|&x| x != o).collect();
            assert_eq!(supported_list(&lmcut, supporter), rest);
            assert_eq!(supported_list(&lmcut, elsewhere), vec![o]);
            relink(&mut lmcut, o, supporter);
            // At the end: in order only if it is the last operator.
            assert_eq!(lmcut.unsorted.flag[supporter as usize], o != 2);
            lmcut.unsorted.sort_all(&mut lmcut.ops, &mut lmcut.facts);
            assert_eq!(supported_list(&lmcut, supporter), vec![0, 1, 2]);
            assert_eq!(supported_list(&lmcut, elsewhere), vec![]);
        }
        for o in [2, 0, 1] {
            relink(&mut lmcut, o, elsewhere);
        }
        assert_eq!(supported_list(&lmcut, elsewhere), vec![2, 0, 1]);
        lmcut.unsorted.sort_all(&mut lmcut.ops, &mut lmcut.facts);
        assert_eq!(supported_list(&lmcut, elsewhere), vec![0, 1, 2]);
        assert_eq!(supported_list(&lmcut, supporter), vec![]);
    }

    #[test]
    fn variables_rank_by_their_sorted_atoms() {
        let task = Task {
            variables: vec![
                variable(&["Atom on(b, a)", "Atom on(a, b)", "<none of those>"]),
                variable(&["Atom clear(a)", "NegatedAtom clear(a)"]),
                variable(&["x", "y"]),
                variable(&["Atom on(a, a)", "Atom on(c, b)"]),
                variable(&["Atom handempty()", "NegatedAtom handempty()"]),
            ],
            mutexes: vec![],
            initial_state: vec![0; 5],
            goal: vec![],
            operators: vec![],
            use_costs: false,
        };
        // Without atom names first, then clear(a) < handempty() < [on(a, a), on(c, b)]
        // < [on(a, b), on(b, a)]: lists compare atom by atom.
        assert_eq!(task.atom_order_ranks(), vec![4, 1, 0, 3, 2]);
    }

    #[test]
    fn ties_go_to_unchanged_variables_first_then_by_rank() {
        let f = |v: u32| Fact::new(VarId(v), 0);
        let op = Operator {
            name: "o".into(),
            preconditions: vec![f(0), f(1), f(2), f(3)],
            effects: vec![Fact::new(VarId(1), 1), Fact::new(VarId(2), 1)],
            cost: 1,
        };
        let rank = [3, 0, 2, 1];
        let order: Vec<u32> = tie_breaking_order(&op, &rank).map(|f| f.var.0).collect();
        assert_eq!(order, vec![3, 0, 1, 2]);
    }
}
