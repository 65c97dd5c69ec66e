//! The h^max heuristic.

use std::cmp::Reverse;
use std::collections::BinaryHeap;

use task::{Task, TaskError};

use crate::heuristic::Heuristic;

const INFINITE: u64 = u64::MAX;

/// The h^max heuristic (Bonet and Geffner): in the delete relaxation, the cost of a fact
/// is 0 if it holds in the state and otherwise the cheapest over its achievers of the
/// operator's cost plus the *most* expensive of its preconditions; h^max is the most
/// expensive goal fact, `None` if some goal fact is unreachable even when deletes are
/// ignored (then the state is a true dead end).
///
/// Admissible and consistent. Each evaluation is a Dijkstra-like exploration over facts
/// with a precondition counter per operator, stopping once every goal fact is settled:
/// O((facts + preconditions + effects) * log(facts)) time and no allocation once the
/// scratch buffers have grown. Operators without preconditions are applied at the start.
#[derive(Debug, Clone)]
pub struct HMax {
    /// First fact id of each variable: fact `var = value` is `fact_offset[var] + value`.
    fact_offset: Vec<u32>,
    op_cost: Vec<u64>,
    op_num_pre: Vec<u32>,
    /// Effects of operator `o`: `op_effects[op_effect_start[o]..op_effect_start[o + 1]]`.
    op_effect_start: Vec<u32>,
    op_effects: Vec<u32>,
    /// Operators with fact `f` as precondition: `pre_of[pre_of_start[f]..pre_of_start[f + 1]]`.
    pre_of_start: Vec<u32>,
    pre_of: Vec<u32>,
    /// Operators without preconditions.
    unconditional: Vec<u32>,
    is_goal: Vec<bool>,
    num_goals: u32,
    // Scratch, reused across evaluations.
    fact_cost: Vec<u64>,
    unsatisfied: Vec<u32>,
    queue: BinaryHeap<Reverse<(u64, u32)>>,
}

impl HMax {
    /// h^max for `task` (costs as [`Task::cost`] gives them); fails if the task is not
    /// valid. O(size of the task).
    pub fn new(task: &Task) -> Result<HMax, TaskError> {
        task.validate()?;
        let (fact_offset, num_facts) = crate::heuristic::fact_offsets(task);
        let fact = |f: &task::Fact| fact_offset[f.var.index()] + f.value;

        let mut op_cost = Vec::with_capacity(task.operators.len());
        let mut op_num_pre = Vec::with_capacity(task.operators.len());
        let mut op_effect_start = vec![0u32];
        let mut op_effects = Vec::new();
        let mut unconditional = Vec::new();
        let mut pre_count = vec![0u32; num_facts as usize + 1];
        for (i, op) in task.operators.iter().enumerate() {
            op_cost.push(task.cost(op));
            op_num_pre.push(op.preconditions.len() as u32);
            if op.preconditions.is_empty() {
                unconditional.push(i as u32);
            }
            for f in &op.preconditions {
                pre_count[fact(f) as usize + 1] += 1;
            }
            op_effects.extend(op.effects.iter().map(fact));
            op_effect_start.push(op_effects.len() as u32);
        }
        // Counting sort of (fact, operator) pairs by fact.
        for f in 0..num_facts as usize {
            pre_count[f + 1] += pre_count[f];
        }
        let pre_of_start = pre_count.clone();
        let mut next = pre_count;
        let mut pre_of = vec![0u32; *pre_of_start.last().unwrap_or(&0) as usize];
        for (i, op) in task.operators.iter().enumerate() {
            for f in &op.preconditions {
                let slot = &mut next[fact(f) as usize];
                pre_of[*slot as usize] = i as u32;
                *slot += 1;
            }
        }
        let mut is_goal = vec![false; num_facts as usize];
        for f in &task.goal {
            is_goal[fact(f) as usize] = true;
        }
        Ok(HMax {
            fact_offset,
            op_cost,
            op_num_pre,
            op_effect_start,
            op_effects,
            pre_of_start,
            pre_of,
            unconditional,
            is_goal,
            num_goals: task.goal.len() as u32,
            fact_cost: vec![INFINITE; num_facts as usize],
            unsatisfied: vec![0; task.operators.len()],
            queue: BinaryHeap::new(),
        })
    }

    #[inline]
    fn reach(&mut self, fact: u32, cost: u64) {
        let slot = &mut self.fact_cost[fact as usize];
        if cost < *slot {
            *slot = cost;
            self.queue.push(Reverse((cost, fact)));
        }
    }

    #[inline]
    fn apply(&mut self, op: usize, base: u64) {
        let cost = base.saturating_add(self.op_cost[op]);
        let (start, end) = (
            self.op_effect_start[op] as usize,
            self.op_effect_start[op + 1] as usize,
        );
        for i in start..end {
            let fact = self.op_effects[i];
            self.reach(fact, cost);
        }
    }
}

impl Heuristic for HMax {
    fn name(&self) -> &str {
        "hmax"
    }

    fn evaluate(&mut self, state: &[u32]) -> Option<u64> {
        if self.num_goals == 0 {
            return Some(0);
        }
        self.fact_cost.fill(INFINITE);
        self.unsatisfied.copy_from_slice(&self.op_num_pre);
        self.queue.clear();
        for (var, &value) in state.iter().enumerate() {
            let fact = self.fact_offset[var] + value;
            self.reach(fact, 0);
        }
        for i in 0..self.unconditional.len() {
            let op = self.unconditional[i] as usize;
            self.apply(op, 0);
        }
        let mut goals_left = self.num_goals;
        while let Some(Reverse((cost, fact))) = self.queue.pop() {
            if cost > self.fact_cost[fact as usize] {
                continue; // A stale entry: the fact was settled more cheaply.
            }
            if self.is_goal[fact as usize] {
                goals_left -= 1;
                if goals_left == 0 {
                    // Facts settle in order of cost, so this is the most expensive goal.
                    return Some(cost);
                }
            }
            let (start, end) = (
                self.pre_of_start[fact as usize] as usize,
                self.pre_of_start[fact as usize + 1] as usize,
            );
            for i in start..end {
                let op = self.pre_of[i] as usize;
                self.unsatisfied[op] -= 1;
                if self.unsatisfied[op] == 0 {
                    // The last precondition settled is the most expensive one.
                    self.apply(op, cost);
                }
            }
        }
        None
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::test_tasks::op;
    use task::{Fact, VarId, Variable};

    /// Variables a, b, c, d binary (value 0 = true); goal c and d.
    /// make-a (no pre, 2) -> a; a-to-b (a, 3) -> b; ab-to-c (a b, 1) -> c;
    /// cheap-c (d, 10) -> c; make-d (a, 4) -> d.
    fn task() -> Task {
        Task {
            variables: ["a", "b", "c", "d"]
                .iter()
                .map(|n| Variable::binary(n))
                .collect(),
            mutexes: vec![],
            initial_state: vec![1, 1, 1, 1],
            goal: vec![Fact::new(VarId(2), 0), Fact::new(VarId(3), 0)],
            operators: vec![
                op("make-a", &[], &[(0, 0)], 2),
                op("a-to-b", &[(0, 0)], &[(1, 0)], 3),
                op("ab-to-c", &[(0, 0), (1, 0)], &[(2, 0)], 1),
                op("cheap-c", &[(3, 0)], &[(2, 0)], 10),
                op("make-d", &[(0, 0)], &[(3, 0)], 4),
            ],
            use_costs: true,
        }
    }

    #[test]
    fn hand_made_task() {
        let mut h = HMax::new(&task()).unwrap();
        assert_eq!(h.name(), "hmax");
        // a = 2, b = 5, c = max(2, 5) + 1 = 6, d = 2 + 4 = 6: h = 6.
        assert_eq!(h.evaluate(&[1, 1, 1, 1]), Some(6));
        // With a true: b = 3, c = 4, d = 4.
        assert_eq!(h.evaluate(&[0, 1, 1, 1]), Some(4));
        // With a, b true: c = 1, d = 4.
        assert_eq!(h.evaluate(&[0, 0, 1, 1]), Some(4));
        // With c, d true: the goal.
        assert_eq!(h.evaluate(&[1, 1, 0, 0]), Some(0));
        // Only d missing, and a true.
        assert_eq!(h.evaluate(&[0, 1, 0, 1]), Some(4));
        // Repeated evaluations give the same answers (scratch is reset).
        assert_eq!(h.evaluate(&[1, 1, 1, 1]), Some(6));
    }

    #[test]
    fn unit_costs_and_dead_ends() {
        let mut t = task();
        t.use_costs = false;
        let mut h = HMax::new(&t).unwrap();
        // a = 1, b = 2, c = 3, d = 2.
        assert_eq!(h.evaluate(&[1, 1, 1, 1]), Some(3));
        // Without make-a nothing but the state is reachable.
        t.operators.remove(0);
        let mut h = HMax::new(&t).unwrap();
        assert_eq!(h.evaluate(&[1, 1, 1, 1]), None);
        assert_eq!(h.evaluate(&[1, 1, 1, 0]), Some(1)); // cheap-c costs 1 without costs.
                                                        // An empty goal costs nothing.
        t.goal.clear();
        assert_eq!(HMax::new(&t).unwrap().evaluate(&[1, 1, 1, 1]), Some(0));
    }

    #[test]
    fn zero_costs() {
        let mut t = task();
        for o in &mut t.operators {
            o.cost = 0;
        }
        let mut h = HMax::new(&t).unwrap();
        assert_eq!(h.evaluate(&[1, 1, 1, 1]), Some(0));
    }

    #[test]
    fn invalid_task_is_an_error() {
        let mut t = task();
        t.goal.push(Fact::new(VarId(9), 0));
        assert!(HMax::new(&t).is_err());
    }
}
