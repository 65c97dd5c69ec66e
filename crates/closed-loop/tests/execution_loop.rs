//! The execution loop on hand-written libraries whose cheapest plans the cube world
//! cannot execute: an Idle operator that adds `inHand` (a copy of taking a cube from the
//! table, typed Idle, so its gripper never closes).

#![allow(clippy::unwrap_used, clippy::expect_used)]

use std::time::Duration;

use closed_loop::{solve, Check, Execution, Solved, Verdict, NO_EXECUTABLE_PLAN};
use learn::{paper_goal_tower, problem, tower_goal, DomainOptions, Library, Scene};
use slim::{Backend, ExitCode, Outcome, RunLimits};

fn library(name: &str) -> Library {
    let path = format!("{}/tests/fixtures/{name}", env!("CARGO_MANIFEST_DIR"));
    Library::from_json(&std::fs::read_to_string(path).unwrap()).unwrap()
}

/// The paper's goal 1 (a tower of 2) on 3 cubes with one hand.
fn goal_one() -> pddl::Problem {
    let scene = Scene::cubes_on_table(3);
    let tower = paper_goal_tower(1);
    problem("goal", "demoplan", &scene, &tower_goal(&scene, &tower))
}

fn run(library: &Library, execution: Execution) -> (Solved, Vec<(usize, Outcome)>) {
    let backend = Backend::Demoplan(search::parse_search("astar(lmcut())").unwrap().into());
    let limits = RunLimits::time(Duration::from_secs(60));
    let mut seen = Vec::new();
    let solved = solve(
        library,
        DomainOptions::default(),
        &goal_one(),
        &backend,
        limits,
        execution,
        |a| seen.push((a.level.prio, a.level.run.outcome)),
    )
    .unwrap();
    (solved, seen)
}

fn actions(plan: &[pddl::Step]) -> Vec<&str> {
    plan.iter().map(|s| s.action.as_str()).collect()
}

#[test]
fn a_failing_operator_is_set_aside_and_the_same_level_plans_again() {
    let lib = library("broken-idle-library.json");
    let (solved, seen) = run(&lib, Execution::On);
    // Priority 1 twice: the plan with the broken idle, then without it.
    assert_eq!(seen, [(1, Outcome::Solved), (1, Outcome::Solved)]);
    let first = &solved.attempts[0];
    assert!(
        actions(&first.level.run.plan).contains(&"idle"),
        "{first:?}"
    );
    let Check::StepFailed(aside) = &first.check else {
        panic!("{:?}", first.check)
    };
    assert_eq!(aside.name, "idle");
    assert_eq!(aside.prio, 1);
    assert_eq!(aside.step, 1);
    assert!(
        aside.action.starts_with("(idle left_hand cube_"),
        "{aside:?}"
    );
    assert!(aside
        .promised
        .iter()
        .any(|f| f.starts_with("(inhand left_hand cube_")));
    assert!(
        aside.found.iter().all(|f| !f.starts_with("(inhand")),
        "{aside:?}"
    );
    assert!(aside.why.starts_with("expected (inhand"), "{}", aside.why);
    // The same level without it: take and put, which the cube world executes.
    let second = &solved.attempts[1];
    assert_eq!(second.level.operators, first.level.operators - 1);
    assert_eq!(second.check, Check::Executed);
    assert_eq!(actions(&second.level.run.plan), ["take", "put"]);
    let Verdict::Plan(plan) = solved.verdict() else {
        panic!("{solved:?}")
    };
    assert!(std::ptr::eq(plan, second));
    assert_eq!(solved.exit_code(), ExitCode::SUCCESS);
    assert_eq!(solved.replans(), 1);
    assert_eq!(solved.set_aside().len(), 1);
    assert!(solved.execution_time > Duration::ZERO);
    assert!(solved.cumulative >= solved.execution_time);
    let note = closed_loop::attempt_note(first).unwrap();
    assert!(note.contains("FAILED: expected (inhand"), "{note}");
    assert!(note.contains("set aside idle"), "{note}");
}

#[test]
fn without_execution_the_loop_is_algorithm_one() {
    let lib = library("broken-idle-library.json");
    let (solved, _) = run(&lib, Execution::Off);
    let backend = Backend::Demoplan(search::parse_search("astar(lmcut())").unwrap().into());
    let plain = slim::solve(
        &lib,
        DomainOptions::default(),
        &goal_one(),
        &backend,
        RunLimits::time(Duration::from_secs(60)),
        |_| {},
    );
    assert_eq!(solved.attempts.len(), plain.levels.len());
    let Verdict::Plan(plan) = solved.verdict() else {
        panic!("{solved:?}")
    };
    let level = plain.plan_level().unwrap();
    assert_eq!(plan.level.run.plan, level.run.plan);
    assert_eq!(plan.level.prio, level.prio);
    assert_eq!(plan.check, Check::NotRun);
    // The unexecutable plan, as Algorithm 1 alone gives it.
    assert!(actions(&level.run.plan).contains(&"idle"));
    assert_eq!(solved.replans(), 0);
    assert_eq!(solved.execution_time, Duration::ZERO);
}

#[test]
fn when_no_plan_executes_the_answer_lists_what_was_set_aside() {
    let lib = library("no-executable-library.json");
    let (solved, seen) = run(&lib, Execution::On);
    // The plan with the idle fails; without it, nothing can pick a cube up.
    assert_eq!(
        seen,
        [(1, Outcome::Solved), (1, Outcome::RelaxedUnreachable)]
    );
    assert!(matches!(solved.verdict(), Verdict::NoExecutablePlan));
    assert_eq!(solved.exit_code(), NO_EXECUTABLE_PLAN);
    assert!(solved.plan().is_none());
    let names: Vec<&str> = solved.set_aside().iter().map(|s| s.name.as_str()).collect();
    assert_eq!(names, ["idle"]);
    let text = solved.no_executable_plan_text();
    assert!(text.starts_with("No executable plan"), "{text}");
    assert!(text.contains("  idle (operator "), "{text}");
    // Without execution the same library gives the unexecutable plan.
    let (off, _) = run(&lib, Execution::Off);
    assert_eq!(off.exit_code(), ExitCode::SUCCESS);
}

#[test]
fn a_scene_the_cube_world_cannot_lay_out_is_an_input_error_before_planning() {
    let lib = library("broken-idle-library.json");
    let text = "(define (problem p) (:domain demoplan)
        (:objects left_hand - hand cube_1 cube_2 - cube table - table)
        (:init (handopen left_hand) (ontop cube_1 cube_2) (ontop cube_2 cube_1))
        (:goal (ontop cube_1 table)))";
    let problem = pddl::parse_problem(text).unwrap();
    let backend = Backend::Demoplan(search::parse_search("astar(blind())").unwrap().into());
    let mut planned = 0;
    let e = solve(
        &lib,
        DomainOptions::default(),
        &problem,
        &backend,
        RunLimits::default(),
        Execution::On,
        |_| planned += 1,
    )
    .unwrap_err();
    assert!(matches!(e, closed_loop::LoopError::Scene(_)), "{e:?}");
    assert_eq!(e.exit_code(), ExitCode::INPUT_ERROR);
    assert!(e.to_string().contains("--no-execute"), "{e}");
    assert_eq!(planned, 0);
}
