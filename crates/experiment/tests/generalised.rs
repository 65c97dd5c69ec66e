//! Domains from a generalised library (issue 39) still plan and execute: the default
//! simulated study, learned with generalised operators, gives a priority-1 domain that
//! plans the paper's goals (towers of 2 to 6 cubes, one hand) optimally, and every plan
//! executes in the cube world.

#![allow(clippy::unwrap_used, clippy::expect_used)]

use std::time::Duration;

use experiment::{Cell, Conditions, Known, Lab, LevelChoice, Planner};
use slim::Outcome;

#[test]
fn the_generalised_priority_one_domain_plans_towers_that_execute() {
    let mut lab = Lab::new(simulate::SimParams::default(), None, None, None);
    for goal in 1..=5 {
        let conditions = Conditions {
            generalised: true,
            ..Conditions::paper_goal(simulate::DEFAULT_SEED, goal, 1)
        };
        let cell = Cell {
            conditions,
            level: LevelChoice::Prio(1),
            planner: Planner::Lmcut,
            time_limit: Duration::from_secs(60),
            repeat: 0,
        };
        let record = lab.run(&cell, &Known::new()).unwrap();
        assert_eq!(record.outcome, Outcome::Solved, "goal {goal}: {record:?}");
        assert_eq!(record.prio, 1);
        assert!(record.length.is_some_and(|n| n >= goal), "{record:?}");
        assert_eq!(
            record.executed,
            Some(true),
            "goal {goal}: the plan fails in the cube world: {:?}",
            record.plan
        );
    }
    // The library behind it is generalised: its file says so.
    let study = simulate::default_study();
    let library = experiment::learn_study_as(
        &study,
        learn::Grouping::Settled,
        learn::OperatorForm::Generalised,
    );
    assert_eq!(library.form(), learn::OperatorForm::Generalised);
    assert!(library.len() < library.specific_entries().count());
}
