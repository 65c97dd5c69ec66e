//! The LM-cut heuristic (Helmert and Domshlak, ICAPS 2009).
//!
//! In the delete relaxation with an artificial goal fact `G` (reached by a zero-cost
//! operator whose preconditions are the goal) and an artificial fact `I` true in every
//! state (the precondition of operators that have none), LM-cut repeats:
//!
//! 1. h^max of every fact, and for every operator its *supporter*: the precondition of
//!    highest h^max (ties: lowest fact index). If `h^max(G) = 0`, stop.
//! 2. The *goal zone*: the facts from which `G` is reached through zero-cost operators,
//!    following supporters backwards.
//! 3. The *cut*: the operators whose supporter is reached from the state without entering
//!    the goal zone (following supporters forwards) and that have an effect in the goal
//!    zone. It is a disjunctive action landmark; its cheapest cost `m` is added to `h` and
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
    round: u32,
    heap: RadixHeap,
    stack: Vec<u32>,
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
            round: 0,
            heap: RadixHeap::new(),
            stack: Vec::new(),
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

    /// The precondition of highest cost, lowest index on ties.
    #[inline]
    fn best_supporter(&self, op: usize) -> u32 {
        let mut best = u32::MAX;
        let mut best_cost = 0;
        for &p in &self.pre[self.pres(op)] {
            let c = self.cost[p as usize];
            if best == u32::MAX || c > best_cost || (c == best_cost && p < best) {
                best = p;
                best_cost = c;
            }
        }
        best
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
                    let s = self.best_supporter(o);
                    self.supporter[o] = s;
                    let value = self.op_cost[o] + self.cost[s as usize];
                    self.relax_effects(o, value);
                }
            }
        }
    }

    /// Marks the goal zone with the current round.
    fn mark_goal_zone(&mut self) {
        self.stack.clear();
        self.goal_zone[self.fact_g as usize] = self.round;
        self.stack.push(self.fact_g);
        while let Some(f) = self.stack.pop() {
            let (start, end) = (
                self.ach_start[f as usize] as usize,
                self.ach_start[f as usize + 1] as usize,
            );
            for i in start..end {
                let o = self.ach[i] as usize;
                if self.op_cost[o] == 0 && self.unsatisfied[o] == 0 {
                    let s = self.supporter[o];
                    if self.goal_zone[s as usize] != self.round {
                        self.goal_zone[s as usize] = self.round;
                        self.stack.push(s);
                    }
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
                for k in self.effs(o) {
                    let e = self.eff[k];
                    if self.goal_zone[e as usize] == self.round {
                        if self.in_cut[o] != self.round {
                            self.in_cut[o] = self.round;
                            self.cut.push(o as u32);
                        }
                    } else if self.reached[e as usize] != self.round {
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
