//! Plans and replaying them.

use task::{OpId, Task, TaskError};

/// A sequence of operators from the initial state to a goal state.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Plan {
    /// The operators, in order.
    pub operators: Vec<OpId>,
    /// The sum of their costs as [`Task::cost`] gives them.
    pub cost: u64,
}

impl Plan {
    /// The plan made of `operators`, with its cost computed from `task` (saturating; an
    /// operator outside the task counts 0).
    pub fn new(task: &Task, operators: Vec<OpId>) -> Plan {
        let cost = operators
            .iter()
            .filter_map(|op| task.operators.get(op.index()))
            .fold(0u64, |sum, op| sum.saturating_add(task.cost(op)));
        Plan { operators, cost }
    }

    /// The number of steps.
    pub fn len(&self) -> usize {
        self.operators.len()
    }

    /// True for the empty plan (the initial state is a goal state).
    pub fn is_empty(&self) -> bool {
        self.operators.is_empty()
    }
}

/// Why a plan cannot be replayed.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum ReplayError {
    /// The task itself is invalid.
    #[error("invalid task: {0}")]
    InvalidTask(#[from] TaskError),
    /// A step names an operator the task does not have.
    #[error("step {step}: the task has no operator {}", op.0)]
    UnknownOperator {
        /// The step, from 0.
        step: usize,
        /// The operator.
        op: OpId,
    },
    /// A step's preconditions do not hold.
    #[error("step {step}: operator `{name}` is not applicable")]
    NotApplicable {
        /// The step, from 0.
        step: usize,
        /// The operator.
        op: OpId,
        /// Its name.
        name: String,
    },
}

/// Applies `plan` to the initial state of `task`, checking each step's preconditions,
/// and returns the final state (one value per variable). Whether that state is a goal
/// state is for the caller to ask ([`Task::is_goal`]). O(task size + plan length * op
/// size).
pub fn replay(task: &Task, plan: &[OpId]) -> Result<Vec<u32>, ReplayError> {
    task.validate()?;
    let mut state = task.initial_state.clone();
    for (step, &op) in plan.iter().enumerate() {
        let operator = task
            .operators
            .get(op.index())
            .ok_or(ReplayError::UnknownOperator { step, op })?;
        if !task.is_applicable(operator, &state) {
            return Err(ReplayError::NotApplicable {
                step,
                op,
                name: operator.name.clone(),
            });
        }
        for f in &operator.effects {
            state[f.var.index()] = f.value;
        }
    }
    Ok(state)
}

#[cfg(test)]
mod tests {
    use super::*;
    use task::{Fact, Operator, VarId, Variable};

    fn task() -> Task {
        Task {
            variables: vec![Variable::binary("a"), Variable::binary("b")],
            mutexes: vec![],
            initial_state: vec![1, 1],
            goal: vec![Fact::new(VarId(1), 0)],
            operators: vec![
                Operator {
                    name: "make-a".into(),
                    preconditions: vec![],
                    effects: vec![Fact::new(VarId(0), 0)],
                    cost: 3,
                },
                Operator {
                    name: "a-to-b".into(),
                    preconditions: vec![Fact::new(VarId(0), 0)],
                    effects: vec![Fact::new(VarId(0), 1), Fact::new(VarId(1), 0)],
                    cost: 0,
                },
            ],
            use_costs: true,
        }
    }

    #[test]
    fn replays_and_reports_the_failing_step() {
        let t = task();
        let plan = Plan::new(&t, vec![OpId(0), OpId(1)]);
        assert_eq!(plan.cost, 3);
        assert_eq!(plan.len(), 2);
        assert!(!plan.is_empty());
        let end = replay(&t, &plan.operators).unwrap();
        assert_eq!(end, vec![1, 0]);
        assert!(t.is_goal(&end));
        assert_eq!(
            replay(&t, &[OpId(0), OpId(1), OpId(1)]),
            Err(ReplayError::NotApplicable {
                step: 2,
                op: OpId(1),
                name: "a-to-b".into()
            })
        );
        let err = replay(&t, &[OpId(7)]).unwrap_err();
        assert_eq!(err.to_string(), "step 0: the task has no operator 7");
        assert_eq!(replay(&t, &[]).unwrap(), vec![1, 1]);
    }
}
