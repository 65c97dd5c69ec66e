//! A plan `demoplan reproduce` found on the calibrated simulator's default library (seed
//! 7, A* with LM-cut, goal 2, the priority-6 domain): `stack11` puts the held cube down and
//! ends with the hand still moving and out of reach of the cube it was at (its effects
//! delete `graspable`). The cube world used to offer only a 3 cm rise for a moving end,
//! which stays within `graspable`'s 10 cm, so step 7 failed although the tower was built.
//! Every step must now execute, and the goal hold.

#![allow(clippy::unwrap_used, clippy::expect_used)]

#[test]
fn a_stack_that_ends_moving_away_from_the_cube_executes() {
    let d = pddl::parse_domain(include_str!("fixtures/seed7-calibrated-prio-6.pddl")).unwrap();
    let p = pddl::parse_problem(include_str!("fixtures/goal-2.pddl")).unwrap();
    let plan = pddl::parse_plan(include_str!("fixtures/lmcut-seed7-prio-6-goal-2.plan")).unwrap();
    assert!(validate::validate(&d, &p, &plan).unwrap().is_valid());
    let report = cubeworld::execute(&d, &p, &plan.steps).unwrap();
    let failed: Vec<String> = report
        .steps
        .iter()
        .filter(|s| !s.failed.is_empty())
        .map(|s| format!("{} {} {:?}", s.index, s.action_text(), s.failed))
        .collect();
    assert!(report.success(), "{failed:?} goal {:?}", report.goal);
    assert_eq!(report.first_failure(), None);
}
