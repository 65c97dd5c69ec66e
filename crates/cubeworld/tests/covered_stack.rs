//! A plan `demoplan reproduce` found (A* with iPDB, goal 5, the priority-4 domain) that
//! is valid in PDDL but cannot be carried out: step 18 (`stack4 left_hand cube_3 cube_1`)
//! puts cube_3, with cube_4, cube_5 and cube_6 on it, onto cube_1 and lets go, while the
//! learned operators keep `(ontop cube_3 cube_2)` from step 16; no later step moves
//! cube_3 again, so step 21 (`stack2 left_hand cube_2 cube_1`) would have to put cube_2
//! where cube_3 stands. The cube world must report that step (with the hand and cube it
//! would have to move through each other) and the goal's missing `(ontop cube_3 cube_2)`,
//! and must not move a held cube through the tower on the way (which used to knock cube_6
//! off cube_5). With cube_1 clear, the same `stack2` executes.

#![allow(clippy::unwrap_used, clippy::expect_used)]

const DOMAIN: &str = include_str!("fixtures/prio-4.pddl");

fn run(problem: &str, plan: &str) -> cubeworld::ExecutionReport {
    let d = pddl::parse_domain(DOMAIN).unwrap();
    let p = pddl::parse_problem(problem).unwrap();
    let plan = pddl::parse_plan(plan).unwrap();
    let valid = validate::validate(&d, &p, &plan).unwrap();
    assert!(valid.is_valid());
    cubeworld::execute(&d, &p, &plan.steps).unwrap()
}

fn describe(report: &cubeworld::ExecutionReport) -> String {
    let mut s = String::new();
    for step in &report.steps {
        s.push_str(&format!(
            "{} {} {:?} {:?} {:?}\n",
            step.index,
            step.action_text(),
            step.failed,
            step.collisions,
            step.grounded
        ));
    }
    s.push_str(&format!("goal {:?}\n", report.goal));
    s
}

#[test]
fn a_stack_onto_a_covered_cube_fails_at_that_step_without_moving_cubes_through_others() {
    let report = run(
        include_str!("fixtures/goal-5.pddl"),
        include_str!("fixtures/ipdb-prio-4-goal-5.plan"),
    );
    let text = describe(&report);
    assert!(!report.success(), "{text}");
    assert_eq!(report.steps.len(), 21);
    assert_eq!(report.first_failure(), Some(20), "{text}");
    for step in &report.steps[..20] {
        assert!(step.collisions.is_empty(), "{text}");
    }
    let last = &report.steps[20];
    assert_eq!(last.action_text(), "(stack2 left_hand cube_2 cube_1)");
    assert!(
        last.failed
            .iter()
            .any(|f| f.expected && f.fact == "(ontop cube_2 cube_1)"),
        "{text}"
    );
    assert!(!last.collisions.is_empty(), "{text}");
    let missing = &report.goal.unsatisfied;
    assert!(
        missing.contains(&"(ontop cube_3 cube_2)".to_string()),
        "{text}"
    );
    // The tower on cube_1 stays whole.
    for fact in [
        "(ontop cube_4 cube_3)",
        "(ontop cube_5 cube_4)",
        "(ontop cube_6 cube_5)",
    ] {
        assert!(!missing.contains(&fact.to_string()), "{text}");
    }
}

#[test]
fn the_same_stack_onto_a_clear_cube_executes() {
    let report = run(
        include_str!("fixtures/stack2-clear.pddl"),
        include_str!("fixtures/stack2-clear.plan"),
    );
    assert!(report.success(), "{}", describe(&report));
    assert!(report.steps.iter().all(|s| s.collisions.is_empty()));
}
