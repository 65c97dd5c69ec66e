//! Property: h² keeps the optimal cost and solvability, alone and followed by dominated
//! operator removal, on random finite-domain tasks (`task::testing::tasks`, the search
//! crate's generator) against uniform-cost search over the explicit state space; and the
//! mutexes it adds hold in every state reachable in the pruned task.

#![allow(clippy::unwrap_used, clippy::expect_used)] // tests fail loudly by design

use std::collections::HashSet;

use proptest::prelude::*;
use task::testing::{optimal_cost, tasks};
use task::Task;
use translate::{h2_mutexes, H2Outcome};

/// The pruned task's optimal cost (`None`: unsolvable), and the task.
fn after_h2(task: &Task) -> (Option<u64>, Option<Task>) {
    let mut pruned = task.clone();
    match h2_mutexes(&mut pruned, &task::Limits::default()) {
        H2Outcome::Pruned(_) => (optimal_cost(&pruned), Some(pruned)),
        H2Outcome::Unsolvable(_) => (None, None),
        H2Outcome::Stopped(limit) => panic!("{limit} without limits"),
    }
}

/// The states reachable from the initial state.
fn reachable_states(task: &Task) -> HashSet<Vec<u32>> {
    let mut seen = HashSet::from([task.initial_state.clone()]);
    let mut stack = vec![task.initial_state.clone()];
    while let Some(s) = stack.pop() {
        for op in task.operators.iter().filter(|o| task.is_applicable(o, &s)) {
            let mut t = s.clone();
            for e in &op.effects {
                t[e.var.index()] = e.value;
            }
            if seen.insert(t.clone()) {
                stack.push(t);
            }
        }
    }
    seen
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(1000))]

    #[test]
    fn h2_keeps_the_optimal_cost_and_its_mutexes_hold(task in tasks()) {
        let expected = optimal_cost(&task);
        let (found, pruned) = after_h2(&task);
        prop_assert_eq!(found, expected);
        if let Some(pruned) = pruned {
            prop_assert!(pruned.validate().is_ok());
            prop_assert!(pruned.operators.len() <= task.operators.len());
            for state in reachable_states(&pruned) {
                for group in &pruned.mutexes {
                    let true_facts = group.iter().filter(|f| state[f.var.index()] == f.value).count();
                    prop_assert!(true_facts <= 1, "{:?} breaks mutex {:?}", state, group);
                }
            }
            // Both options, in the translator's order: h², then dominated operators.
            let mut both = pruned.clone();
            translate::remove_dominated_operators(&mut both, &mut || false);
            prop_assert_eq!(optimal_cost(&both), expected);
            // h² again finds nothing more to remove.
            let mut again = pruned.clone();
            let H2Outcome::Pruned(stats) = h2_mutexes(&mut again, &task::Limits::default()) else {
                panic!("h2 twice");
            };
            prop_assert_eq!((stats.operators_removed, stats.facts_removed), (0, 0));
        }
    }
}
