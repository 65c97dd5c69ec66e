//! The heuristic interface and the blind heuristic.

use task::{Fact, Task};

use crate::cpdbs::PdbStatistics;
use crate::scp::ScpStatistics;

/// An estimate of the cost from a state to the goal.
///
/// The search calls [`evaluate`](Self::evaluate) once per newly registered state, with
/// the state unpacked (one value per variable, in the order of [`Task::variables`]) and
/// caches the value. For A* to return optimal plans the estimate must be *admissible*
/// (never above the true cost); it need not be *consistent*, since the search reopens
/// states reached again more cheaply. `None` says the goal cannot be reached from the
/// state (a dead end), which must be true: the search prunes such states.
///
/// Implementations keep their scratch buffers between calls, which is why the receiver
/// is `&mut self`.
pub trait Heuristic {
    /// The name used in logs, as in the search string: `blind`, `hmax`.
    fn name(&self) -> &str;

    /// The estimate for `state`, or `None` if the state is a dead end.
    fn evaluate(&mut self, state: &[u32]) -> Option<u64>;

    /// For pattern-database heuristics (`pdb`, `ipdb`, `cpdbs`): what building them did
    /// (patterns, sizes, the hill climbing), for logs. `None` for the others.
    fn pdb_statistics(&self) -> Option<&PdbStatistics> {
        None
    }

    /// For saturated cost partitioning (`scp`, `scp_online`): what building it did and,
    /// online, what the search added (orders). `None` for the others.
    fn scp_statistics(&self) -> Option<&ScpStatistics> {
        None
    }

    /// What building the heuristic did, as log lines in Fast Downward's (or Scorpion's)
    /// words, one per line without a final newline; printed before the search. `None`
    /// for heuristics that build nothing worth reporting.
    fn construction_log(&self) -> Option<String> {
        self.pdb_statistics().map(ToString::to_string)
    }
}

impl<H: Heuristic + ?Sized> Heuristic for Box<H> {
    fn name(&self) -> &str {
        (**self).name()
    }

    fn evaluate(&mut self, state: &[u32]) -> Option<u64> {
        (**self).evaluate(state)
    }

    fn pdb_statistics(&self) -> Option<&PdbStatistics> {
        (**self).pdb_statistics()
    }

    fn scp_statistics(&self) -> Option<&ScpStatistics> {
        (**self).scp_statistics()
    }

    fn construction_log(&self) -> Option<String> {
        (**self).construction_log()
    }
}

/// The blind heuristic: 0 on goal states, otherwise the cheapest operator cost (0 if the
/// task has no operators). Admissible and consistent; O(goal facts) per state.
#[derive(Debug, Clone)]
pub struct Blind {
    goal: Vec<Fact>,
    min_cost: u64,
}

impl Blind {
    /// The blind heuristic for `task` (costs as [`Task::cost`] gives them).
    pub fn new(task: &Task) -> Blind {
        let min_cost = task
            .operators
            .iter()
            .map(|op| task.cost(op))
            .min()
            .unwrap_or(0);
        Blind {
            goal: task.goal.clone(),
            min_cost,
        }
    }
}

impl Heuristic for Blind {
    fn name(&self) -> &str {
        "blind"
    }

    #[inline]
    fn evaluate(&mut self, state: &[u32]) -> Option<u64> {
        let goal = self
            .goal
            .iter()
            .all(|f| state.get(f.var.index()) == Some(&f.value));
        Some(if goal { 0 } else { self.min_cost })
    }
}

/// The facts of `task` numbered densely, variable by variable, as the relaxed
/// explorations number them: fact `var = value` is `offsets[var] + value`. Returns the
/// offsets and the number of facts. O(variables).
pub(crate) fn fact_offsets(task: &Task) -> (Vec<u32>, u32) {
    let mut offsets = Vec::with_capacity(task.variables.len());
    let mut facts = 0u32;
    for v in &task.variables {
        offsets.push(facts);
        facts += v.domain_size();
    }
    (offsets, facts)
}

#[cfg(test)]
mod tests {
    use super::*;
    use task::{Operator, VarId, Variable};

    #[test]
    fn blind_is_zero_on_goals_and_min_cost_elsewhere() {
        let op = |cost| Operator {
            name: "o".into(),
            preconditions: vec![],
            effects: vec![Fact::new(VarId(0), 0)],
            cost,
        };
        let mut task = Task {
            variables: vec![Variable::binary("a")],
            mutexes: vec![],
            initial_state: vec![1],
            goal: vec![Fact::new(VarId(0), 0)],
            operators: vec![op(5), op(3), op(7)],
            use_costs: true,
        };
        let mut blind = Blind::new(&task);
        assert_eq!(blind.name(), "blind");
        assert_eq!(blind.evaluate(&[0]), Some(0));
        assert_eq!(blind.evaluate(&[1]), Some(3));
        task.use_costs = false;
        assert_eq!(Blind::new(&task).evaluate(&[1]), Some(1));
        task.operators.clear();
        assert_eq!(Blind::new(&task).evaluate(&[1]), Some(0));
    }
}
