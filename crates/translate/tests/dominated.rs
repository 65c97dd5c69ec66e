//! Property: removing dominated operators keeps the optimal cost (and solvability).
//!
//! Random small finite-domain tasks get `put2`-style variants of some of their operators
//! (the same effects, one more precondition, a cost no lower), as learned domains have
//! them; uniform-cost search over the explicit state space (the oracle) must find the
//! same optimal cost before and after the removal, and every variant must go.

#![allow(clippy::unwrap_used, clippy::expect_used)] // tests fail loudly by design

use proptest::prelude::*;
use task::testing::optimal_cost;
use task::{Fact, Operator, Task, VarId, Variable};

/// A partial assignment: per variable, maybe a value.
fn facts(values: &[Option<u32>]) -> Vec<Fact> {
    values
        .iter()
        .enumerate()
        .filter_map(|(v, x)| x.map(|x| Fact::new(VarId(v as u32), x)))
        .collect()
}

/// A random task over 2-5 ternary variables with 1-10 operators, and a list of variants to
/// add: (operator, variable, value, extra cost).
fn task_and_variants() -> impl Strategy<Value = (Task, Vec<(usize, usize, u32, u64)>)> {
    (2usize..=5).prop_flat_map(|n| {
        let partial = move |density| {
            proptest::collection::vec(proptest::option::weighted(density, 0u32..3), n)
        };
        let op = (partial(0.4), partial(0.5), 0u64..=3);
        (
            proptest::collection::vec(op, 1..=10),
            proptest::collection::vec(0u32..3, n),
            partial(0.5),
            any::<bool>(),
            proptest::collection::vec(
                (any::<prop::sample::Index>(), 0..n, 0u32..3, 0u64..=2),
                0..=6,
            ),
        )
            .prop_map(move |(ops, initial_state, goal, use_costs, variants)| {
                let mut operators: Vec<Operator> = ops
                    .into_iter()
                    .enumerate()
                    .map(|(i, (pre, eff, cost))| Operator {
                        name: format!("op{i}"),
                        preconditions: facts(&pre),
                        effects: facts(&eff),
                        cost,
                    })
                    .collect();
                // An operator without effects is not a task's operator.
                for (i, op) in operators.iter_mut().enumerate() {
                    if op.effects.is_empty() {
                        op.effects.push(Fact::new(VarId((i % n) as u32), 0));
                    }
                }
                let count = operators.len();
                let task = Task {
                    variables: (0..n)
                        .map(|i| Variable {
                            name: format!("var{i}"),
                            value_names: (0..3).map(|x| format!("v{x}")).collect(),
                        })
                        .collect(),
                    mutexes: vec![],
                    initial_state,
                    goal: facts(&goal),
                    operators,
                    use_costs,
                };
                let variants = variants
                    .into_iter()
                    .map(|(i, var, value, extra)| (i.index(count), var, value, extra))
                    .collect();
                (task, variants)
            })
    })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(1000))]

    #[test]
    fn removing_dominated_operators_keeps_the_optimal_cost((mut task, variants) in task_and_variants()) {
        let mut added = 0;
        for (i, var, value, extra) in variants {
            let base = task.operators[i].clone();
            if base.preconditions.iter().any(|f| f.var.index() == var) {
                continue;
            }
            let mut variant = base.clone();
            variant.name = format!("{}-variant{added}", base.name);
            variant.preconditions.push(Fact::new(VarId(var as u32), value));
            variant.preconditions.sort_by_key(|f| f.var);
            variant.cost += extra;
            task.operators.push(variant);
            added += 1;
        }
        prop_assert!(task.validate().is_ok());
        let expected = optimal_cost(&task);
        let mut pruned = task.clone();
        let removed = translate::remove_dominated_operators(&mut pruned, &mut || false);
        prop_assert_eq!(removed, task.operators.len() - pruned.operators.len());
        prop_assert!(removed >= added, "{} removed, {} variants added", removed, added);
        prop_assert!(pruned.operators.iter().all(|o| !o.name.contains("-variant")));
        prop_assert_eq!(optimal_cost(&pruned), expected);
        // What stays is dominated by nothing: removing again removes nothing.
        prop_assert_eq!(translate::remove_dominated_operators(&mut pruned, &mut || false), 0);
    }
}
