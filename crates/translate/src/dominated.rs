//! Dominated operators (issue 25 item 4): of two operators with the same effect
//! assignments, the one whose preconditions (prevail conditions included) contain the
//! other's and whose cost is not lower is never needed in an optimal plan: wherever it
//! applies, the other applies too, reaches the same state, and costs no more. Learned
//! domains are full of them: `put2`-style variants of an operator with extra incidental
//! preconditions and a higher cost.
//!
//! Removing them keeps every optimal plan's cost (a plan using a dominated operator stays
//! a plan, as cheap or cheaper, with its dominator instead), and so the optimal cost and
//! solvability. Off by default in the translator, so that its output stays Fast
//! Downward's.

use rustc_hash::FxHashMap;
use task::{Fact, Task};

/// Removes from `task` every operator another dominates, keeping the order of the rest;
/// of operators equal in preconditions, effects and cost the first stays. Returns how many
/// went. `stop` is asked between groups of operators with the same effects; when it says
/// yes the removal ends early, having removed only dominated operators (the task stays
/// correct, with fewer removals).
///
/// Domination, with `pre` the preconditions and `c` the cost (as [`Task::cost`] counts
/// it): `b` dominates `a` when `eff(a) = eff(b)`, `pre(b) ⊆ pre(a)`, `c(b) <= c(a)`,
/// and, if all three are equalities, `b` comes first. This is a strict partial order, so
/// every removed operator has a dominator that stays. O(sum over effect groups of k² ·
/// preconditions), k the group's size.
pub fn remove_dominated_operators(task: &mut Task, stop: &mut dyn FnMut() -> bool) -> usize {
    let mut groups: FxHashMap<&[Fact], Vec<usize>> = FxHashMap::default();
    for (i, op) in task.operators.iter().enumerate() {
        groups.entry(op.effects.as_slice()).or_default().push(i);
    }
    let mut groups: Vec<Vec<usize>> = groups.into_values().filter(|g| g.len() > 1).collect();
    groups.sort_unstable(); // Deterministic: by the first operator of each group.
    let mut dominated = vec![false; task.operators.len()];
    for group in &groups {
        if stop() {
            break;
        }
        for &a in group {
            let op_a = &task.operators[a];
            let cost_a = task.cost(op_a);
            dominated[a] = group.iter().any(|&b| {
                if b == a {
                    return false;
                }
                let op_b = &task.operators[b];
                let cost_b = task.cost(op_b);
                cost_b <= cost_a
                    && is_subset(&op_b.preconditions, &op_a.preconditions)
                    && (b < a
                        || cost_b < cost_a
                        || op_b.preconditions.len() < op_a.preconditions.len())
            });
        }
    }
    let removed = dominated.iter().filter(|&&d| d).count();
    if removed > 0 {
        let mut index = 0;
        task.operators.retain(|_| {
            let keep = !dominated[index];
            index += 1;
            keep
        });
    }
    removed
}

/// Whether every fact of `small` is in `large`; both sorted by variable, at most one fact
/// per variable (as a [`Task`]'s preconditions are).
fn is_subset(small: &[Fact], large: &[Fact]) -> bool {
    let mut rest = large.iter();
    small.iter().all(|f| {
        rest.by_ref()
            .find(|g| g.var >= f.var)
            .is_some_and(|g| g == f)
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use task::testing::op;
    use task::{Operator, VarId, Variable};

    fn task(operators: Vec<Operator>) -> Task {
        Task {
            variables: (0..3).map(|i| Variable::binary(&format!("v{i}"))).collect(),
            mutexes: vec![],
            initial_state: vec![0, 0, 0],
            goal: vec![Fact::new(VarId(0), 1)],
            operators,
            use_costs: true,
        }
    }

    fn names_after(mut t: Task) -> (usize, Vec<String>) {
        let removed = remove_dominated_operators(&mut t, &mut || false);
        (removed, t.operators.into_iter().map(|o| o.name).collect())
    }

    #[test]
    fn a_variant_with_extra_preconditions_and_no_lower_cost_goes() {
        let t = task(vec![
            op("put2", &[(0, 0), (1, 1)], &[(0, 1)], 2),
            op("put", &[(0, 0)], &[(0, 1)], 1),
            // Cheaper with more preconditions: not dominated.
            op("put-cheap", &[(0, 0), (2, 1)], &[(0, 1)], 0),
            // Other effects: not compared.
            op("other", &[(0, 0), (1, 1)], &[(0, 1), (2, 1)], 5),
        ]);
        assert_eq!(
            names_after(t),
            (1, vec!["put".into(), "put-cheap".into(), "other".into()])
        );
    }

    #[test]
    fn equal_operators_keep_the_first_and_equal_costs_keep_the_smaller_precondition() {
        let t = task(vec![
            op("b", &[(0, 0), (1, 0)], &[(0, 1)], 1),
            op("a1", &[(0, 0)], &[(0, 1)], 1),
            op("a2", &[(0, 0)], &[(0, 1)], 1),
        ]);
        assert_eq!(names_after(t), (2, vec!["a1".into()]));
    }

    #[test]
    fn without_action_costs_every_operator_costs_one() {
        let mut t = task(vec![
            op("many", &[(0, 0), (1, 0)], &[(0, 1)], 0),
            op("few", &[(0, 0)], &[(0, 1)], 9),
        ]);
        t.use_costs = false;
        assert_eq!(names_after(t), (1, vec!["few".into()]));
    }

    #[test]
    fn subsets_are_by_fact_not_by_variable() {
        assert!(is_subset(&[], &[Fact::new(VarId(0), 1)]));
        let f = |v, x| Fact::new(VarId(v), x);
        assert!(is_subset(&[f(1, 0)], &[f(0, 1), f(1, 0), f(2, 0)]));
        assert!(!is_subset(&[f(1, 1)], &[f(0, 1), f(1, 0), f(2, 0)]));
        assert!(!is_subset(&[f(3, 0)], &[f(0, 1)]));
        assert!(!is_subset(&[f(0, 1), f(2, 0)], &[f(0, 1)]));
    }

    #[test]
    fn stopping_early_removes_nothing_wrongly() {
        let mut t = task(vec![
            op("put2", &[(0, 0), (1, 1)], &[(0, 1)], 2),
            op("put", &[(0, 0)], &[(0, 1)], 1),
        ]);
        assert_eq!(remove_dominated_operators(&mut t, &mut || true), 0);
        assert_eq!(t.operators.len(), 2);
    }
}
