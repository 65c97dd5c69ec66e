//! The LM-cut heuristic (Helmert and Domshlak, ICAPS 2009).
//!
//! In the delete relaxation with an artificial goal fact `G` (reached by a zero-cost
//! operator whose preconditions are the goal) and an artificial fact `I` true in every
//! state (the precondition of operators that have none), LM-cut repeats:
//!
//! 1. h^max of every fact, and for every operator its *supporter*: a precondition of
//!    highest h^max. Ties matter for the quality of the cuts: the first round takes the
//!    first such precondition in the operator's order; later rounds keep the supporter
//!    of the round before while it is still of highest cost. If `h^max(G) = 0`, stop.
//! 2. The *goal zone*: the facts from which `G` is reached through zero-cost operators,
//!    following supporters backwards. When a zero-cost operator has several preconditions
//!    of highest cost, its supporter becomes the first that no zero-cost operator achieves
//!    or that is already in the zone (as Fast Downward's goal-zone and border detection
//!    do), which keeps the zone, and the cuts, small.
//! 3. The *cut*: the operators whose supporter is reached from the state without entering
//!    the goal zone (following supporters forwards; the other effects of an operator that
//!    enters the goal zone are not reached) and that have an effect in the goal zone. It is a disjunctive action landmark; its cheapest cost `m` is added to `h` and
//!    subtracted from the cost of every operator in it.
//!
//! The sum is admissible (the cuts are landmarks with costs partitioned among them), not
//! necessarily consistent, and never below h^max. Step 1 after the first round is
//! incremental: only operators of the cut got cheaper, so only facts they reach can get
//! cheaper, and a decrease-only Dijkstra from their effects updates h^max and supporters.
//!
//! Cost per evaluation: O(rounds * (facts + preconditions + effects)), with a radix heap
//! over integer costs, round counters instead of clearing arrays, and no allocation once
//! the scratch buffers have grown.

use task::{Task, TaskError};

use crate::heuristic::Heuristic;
use crate::radix_heap::RadixHeap;

const INFINITE: u64 = u64::MAX;

/// The LM-cut heuristic; see the module documentation.
#[derive(Debug, Clone)]
pub struct LmCut {
    fact_offset: Vec<u32>,
    /// Index of the fact true in every state.
    fact_i: u32,
    /// Index of the artificial goal fact.
    fact_g: u32,
    /// Operator `o`'s preconditions: `pre[pre_start[o]..pre_start[o + 1]]` (never empty).
    pre_start: Vec<u32>,
    pre: Vec<u32>,
    eff_start: Vec<u32>,
    eff: Vec<u32>,
    base_cost: Vec<u64>,
    /// Operators with fact `f` as a precondition.
    pre_of_start: Vec<u32>,
    pre_of: Vec<u32>,
    /// Operators with fact `f` as an effect.
    ach_start: Vec<u32>,
    ach: Vec<u32>,
    // Scratch, reused across evaluations.
    cost: Vec<u64>,
    op_cost: Vec<u64>,
    supporter: Vec<u32>,
    unsatisfied: Vec<u32>,
    goal_zone: Vec<u32>,
    reached: Vec<u32>,
    in_cut: Vec<u32>,
    /// The round in which an operator's supporter was last updated, and its supporter at
    /// the start of that round's update.
    updated_in_round: Vec<u32>,
    round_supporter: Vec<u32>,
    round: u32,
    heap: RadixHeap,
    stack: Vec<u32>,
    frames: Vec<(u32, u32)>,
    cut: Vec<u32>,
}

/// `index[start[i]..start[i+1]]` lists, by counting sort of `(key, value)` pairs.
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

impl LmCut {
    /// LM-cut for `task` (costs as [`Task::cost`] gives them); fails if the task is not
    /// valid. O(size of the task).
    pub fn new(task: &Task) -> Result<LmCut, TaskError> {
        task.validate()?;
        let mut fact_offset = Vec::with_capacity(task.variables.len());
        let mut num_facts = 0u32;
        for v in &task.variables {
            fact_offset.push(num_facts);
            num_facts += v.domain_size();
        }
        let fact_i = num_facts;
        let fact_g = num_facts + 1;
        let facts = num_facts as usize + 2;
        let fact = |f: &task::Fact| fact_offset[f.var.index()] + f.value;
        let mut pre_start = vec![0u32];
        let mut pre = Vec::new();
        let mut eff_start = vec![0u32];
        let mut eff = Vec::new();
        let mut base_cost = Vec::new();
        for op in &task.operators {
            if op.preconditions.is_empty() {
                pre.push(fact_i);
            }
            pre.extend(op.preconditions.iter().map(fact));
            pre_start.push(pre.len() as u32);
            eff.extend(op.effects.iter().map(fact));
            eff_start.push(eff.len() as u32);
            base_cost.push(task.cost(op));
        }
        // The goal operator, last.
        if task.goal.is_empty() {
            pre.push(fact_i);
        }
        pre.extend(task.goal.iter().map(fact));
        pre_start.push(pre.len() as u32);
        eff.push(fact_g);
        eff_start.push(eff.len() as u32);
        base_cost.push(0);
        let ops = base_cost.len();
        let mut pre_pairs = Vec::with_capacity(pre.len());
        let mut eff_pairs = Vec::with_capacity(eff.len());
        for o in 0..ops {
            for &f in &pre[pre_start[o] as usize..pre_start[o + 1] as usize] {
                pre_pairs.push((f, o as u32));
            }
            for &f in &eff[eff_start[o] as usize..eff_start[o + 1] as usize] {
                eff_pairs.push((f, o as u32));
            }
        }
        let (pre_of_start, pre_of) = group_by(facts, &pre_pairs);
        let (ach_start, ach) = group_by(facts, &eff_pairs);
        Ok(LmCut {
            fact_offset,
            fact_i,
            fact_g,
            pre_start,
            pre,
            eff_start,
            eff,
            base_cost,
            pre_of_start,
            pre_of,
            ach_start,
            ach,
            cost: vec![INFINITE; facts],
            op_cost: vec![0; ops],
            supporter: vec![0; ops],
            unsatisfied: vec![0; ops],
            goal_zone: vec![0; facts],
            reached: vec![0; facts],
            in_cut: vec![0; ops],
            updated_in_round: vec![0; ops],
            round_supporter: vec![0; ops],
            round: 0,
            heap: RadixHeap::new(),
            stack: Vec::new(),
            frames: Vec::new(),
            cut: Vec::new(),
        })
    }

    #[inline]
    fn pres(&self, op: usize) -> std::ops::Range<usize> {
        self.pre_start[op] as usize..self.pre_start[op + 1] as usize
    }

    #[inline]
    fn effs(&self, op: usize) -> std::ops::Range<usize> {
        self.eff_start[op] as usize..self.eff_start[op + 1] as usize
    }

    /// The first precondition (in the operator's order) of highest cost.
    #[inline]
    fn best_supporter(&self, op: usize) -> u32 {
        let mut best = u32::MAX;
        let mut best_cost = 0;
        for &p in &self.pre[self.pres(op)] {
            let c = self.cost[p as usize];
            if best == u32::MAX || c > best_cost {
                best = p;
                best_cost = c;
            }
        }
        best
    }

    /// After the supporter of `op` got cheaper: the supporter the operator had when this
    /// round's update began stays while it is of highest cost, otherwise the first
    /// precondition of highest cost takes over. Remembering the round's starting supporter
    /// makes the result depend only on the updated costs, not on the order in which the
    /// update visits the preconditions.
    #[inline]
    fn updated_supporter(&mut self, op: usize) -> u32 {
        if self.updated_in_round[op] != self.round {
            self.updated_in_round[op] = self.round;
            self.round_supporter[op] = self.supporter[op];
        }
        let pres = self.pres(op);
        let max = self.pre[pres.clone()]
            .iter()
            .map(|&p| self.cost[p as usize])
            .max()
            .unwrap_or(0);
        let previous = self.round_supporter[op];
        if self.cost[previous as usize] == max {
            return previous;
        }
        self.pre[pres]
            .iter()
            .copied()
            .find(|&p| self.cost[p as usize] == max)
            .unwrap_or(previous)
    }

    /// Relaxes the effects of `op` with value `value`.
    #[inline]
    fn relax_effects(&mut self, op: usize, value: u64) {
        for i in self.effs(op) {
            let e = self.eff[i] as usize;
            if value < self.cost[e] {
                self.cost[e] = value;
                self.heap.push(value, e as u32);
            }
        }
    }

    /// h^max from scratch, with supporters.
    fn first_exploration(&mut self, state: &[u32]) {
        self.cost.fill(INFINITE);
        self.heap.clear();
        for o in 0..self.op_cost.len() {
            self.op_cost[o] = self.base_cost[o];
            self.unsatisfied[o] = self.pre_start[o + 1] - self.pre_start[o];
        }
        for (var, &value) in state.iter().enumerate() {
            let f = (self.fact_offset[var] + value) as usize;
            self.cost[f] = 0;
            self.heap.push(0, f as u32);
        }
        self.cost[self.fact_i as usize] = 0;
        self.heap.push(0, self.fact_i);
        while let Some((c, f)) = self.heap.pop() {
            if c > self.cost[f as usize] {
                continue;
            }
            let (start, end) = (
                self.pre_of_start[f as usize] as usize,
                self.pre_of_start[f as usize + 1] as usize,
            );
            for i in start..end {
                let o = self.pre_of[i] as usize;
                self.unsatisfied[o] -= 1;
                if self.unsatisfied[o] == 0 {
                    let s = self.best_supporter(o);
                    self.supporter[o] = s;
                    let value = self.op_cost[o] + self.cost[s as usize];
                    self.relax_effects(o, value);
                }
            }
        }
    }

    /// Updates h^max after the operators of the cut got cheaper: costs only decrease.
    fn second_exploration(&mut self) {
        self.heap.clear();
        for k in 0..self.cut.len() {
            let o = self.cut[k] as usize;
            let value = self.op_cost[o] + self.cost[self.supporter[o] as usize];
            self.relax_effects(o, value);
        }
        while let Some((c, f)) = self.heap.pop() {
            if c > self.cost[f as usize] {
                continue;
            }
            let (start, end) = (
                self.pre_of_start[f as usize] as usize,
                self.pre_of_start[f as usize + 1] as usize,
            );
            for i in start..end {
                let o = self.pre_of[i] as usize;
                // Only an operator whose most expensive precondition got cheaper changes.
                if self.unsatisfied[o] == 0 && self.supporter[o] == f {
                    let s = self.updated_supporter(o);
                    self.supporter[o] = s;
                    let value = self.op_cost[o] + self.cost[s as usize];
                    self.relax_effects(o, value);
                }
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
            .all(|&o| self.op_cost[o as usize] != 0)
    }

    /// Among the preconditions of a zero-cost operator that tie with its supporter, prefers
    /// the first that no zero-cost operator achieves (the border of the goal zone) or that
    /// is already in the goal zone: the zone then grows less through zero-cost chains, and
    /// the cuts stay small.
    fn break_supporter_ties(&mut self, op: usize) {
        let target = self.cost[self.supporter[op] as usize];
        for i in self.pres(op) {
            let p = self.pre[i];
            if self.cost[p as usize] != target {
                continue;
            }
            if self.has_no_zero_cost_achiever(p) || self.goal_zone[p as usize] == self.round {
                self.supporter[op] = p;
                return;
            }
        }
    }

    /// Marks the goal zone with the current round: depth first from the goal fact through
    /// the supporters of zero-cost achievers, with an explicit stack of (fact, next
    /// achiever) frames so deep zones cannot overflow the call stack.
    fn mark_goal_zone(&mut self) {
        self.frames.clear();
        self.goal_zone[self.fact_g as usize] = self.round;
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
            if self.op_cost[o] == 0 && self.unsatisfied[o] == 0 {
                self.break_supporter_ties(o);
                let s = self.supporter[o];
                if self.goal_zone[s as usize] != self.round {
                    self.goal_zone[s as usize] = self.round;
                    self.frames.push((s, self.ach_start[s as usize]));
                }
            }
        }
    }

    /// Collects the cut: from the state, along supporters, up to the goal zone.
    fn find_cut(&mut self, state: &[u32]) {
        self.cut.clear();
        self.stack.clear();
        for (var, &value) in state.iter().enumerate() {
            let f = self.fact_offset[var] + value;
            self.reached[f as usize] = self.round;
            self.stack.push(f);
        }
        self.reached[self.fact_i as usize] = self.round;
        self.stack.push(self.fact_i);
        while let Some(f) = self.stack.pop() {
            let (start, end) = (
                self.pre_of_start[f as usize] as usize,
                self.pre_of_start[f as usize + 1] as usize,
            );
            for i in start..end {
                let o = self.pre_of[i] as usize;
                if self.unsatisfied[o] != 0 || self.supporter[o] != f {
                    continue;
                }
                let enters_goal_zone = self
                    .effs(o)
                    .any(|k| self.goal_zone[self.eff[k] as usize] == self.round);
                if enters_goal_zone {
                    // A cut operator; its other effects lie beyond the cut.
                    if self.in_cut[o] != self.round {
                        self.in_cut[o] = self.round;
                        self.cut.push(o as u32);
                    }
                    continue;
                }
                for k in self.effs(o) {
                    let e = self.eff[k];
                    if self.reached[e as usize] != self.round {
                        self.reached[e as usize] = self.round;
                        self.stack.push(e);
                    }
                }
            }
        }
    }

    fn next_round(&mut self) {
        if self.round == u32::MAX {
            // Counters wrap after four billion rounds: start the stamps afresh.
            self.goal_zone.fill(0);
            self.reached.fill(0);
            self.in_cut.fill(0);
            self.updated_in_round.fill(0);
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
        if self.cost[self.fact_g as usize] == INFINITE {
            return None;
        }
        let mut h: u64 = 0;
        while self.cost[self.fact_g as usize] != 0 {
            self.next_round();
            self.mark_goal_zone();
            self.find_cut(state);
            let Some(m) = self.cut.iter().map(|&o| self.op_cost[o as usize]).min() else {
                // Cannot happen while h^max(G) > 0; stop rather than loop.
                break;
            };
            if m == 0 {
                break;
            }
            h = h.saturating_add(m);
            for k in 0..self.cut.len() {
                let o = self.cut[k] as usize;
                self.op_cost[o] -= m;
            }
            self.second_exploration();
        }
        Some(h)
    }
}
