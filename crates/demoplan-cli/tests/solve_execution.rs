//! `demoplan solve` with execution in the loop (issue 39): the operator of a failing step
//! is set aside and the level searched again, `--no-execute` gives Algorithm 1's plan,
//! "no executable plan" exits 45 with nothing written, a scene the cube world cannot lay
//! out is an input error before any planning.

#![allow(clippy::unwrap_used, clippy::expect_used)]

use std::path::{Path, PathBuf};

mod common;
use common::{demoplan, exits, stdout_text, succeeds, tempdir, transcript, workspace};

fn library(name: &str) -> PathBuf {
    workspace()
        .join("crates/closed-loop/tests/fixtures")
        .join(name)
}

/// The paper's goal 1 on three cubes, written into `dir`.
fn goal(dir: &Path) -> PathBuf {
    let goal = dir.join("goal.pddl");
    succeeds(
        demoplan()
            .args(["problem", "--paper-goal", "1", "--cubes", "3", "-o"])
            .arg(&goal),
    );
    goal
}

fn plan_actions(plan: &Path) -> Vec<String> {
    std::fs::read_to_string(plan)
        .unwrap()
        .lines()
        .filter(|l| l.starts_with('('))
        .map(|l| l[1..].split(' ').next().unwrap().to_string())
        .collect()
}

#[test]
fn a_failing_step_sets_its_operator_aside_and_the_level_plans_again() {
    let dir = tempdir("set-aside");
    let goal = goal(&dir);
    let plan = dir.join("plan");
    let out = succeeds(
        demoplan()
            .arg("solve")
            .arg(library("broken-idle-library.json"))
            .arg(&goal)
            .arg("--plan-file")
            .arg(&plan),
    );
    let log = stdout_text(&out);
    let rows: Vec<&str> = log.lines().filter(|l| l.starts_with("    1 ")).collect();
    assert_eq!(rows.len(), 2, "{log}");
    assert!(
        log.contains("      step 1 (idle left_hand cube_2 table): FAILED: expected (inhand left_hand cube_2)"),
        "{log}"
    );
    assert!(log.contains("set aside idle (operator "), "{log}");
    assert!(
        log.contains("searching priority 1 again without it"),
        "{log}"
    );
    assert!(log.contains("executed in the cube world"), "{log}");
    assert!(log.contains("; executing plans: "), "{log}");
    assert!(log.contains(" 1 replan(s)\n"), "{log}");
    assert!(
        log.contains("Solution found at priority 1 (2 operators): 2 step(s)"),
        "{log}"
    );
    assert_eq!(plan_actions(&plan), ["take", "put"]);
    // The plan written executes.
    let domain = dir.join("domain.pddl");
    succeeds(
        demoplan()
            .arg("domain")
            .arg(library("broken-idle-library.json"))
            .args(["--prio", "2", "-o"])
            .arg(&domain),
    );
    succeeds(demoplan().arg("execute").arg(&domain).arg(&goal).arg(&plan));
}

#[test]
fn no_execute_gives_algorithm_ones_plan_and_output() {
    let dir = tempdir("no-execute");
    let goal = goal(&dir);
    let plan = dir.join("plan");
    let out = succeeds(
        demoplan()
            .arg("solve")
            .arg(library("broken-idle-library.json"))
            .arg(&goal)
            .arg("--no-execute")
            .arg("--plan-file")
            .arg(&plan),
    );
    let log = stdout_text(&out);
    assert_eq!(plan_actions(&plan), ["idle", "put"]);
    // The table, the cumulative line and the solution, as before execution was in the
    // loop: nothing about execution.
    let lines: Vec<&str> = log.lines().collect();
    assert_eq!(lines.len(), 4, "{log}");
    assert!(lines[1].starts_with("    1         3  solved "), "{log}");
    assert!(lines[2].starts_with("Cumulative time over 1 level(s), failed ones included: "));
    assert!(lines[2].ends_with(" s"), "{log}");
    assert!(lines[3].starts_with("Solution found at priority 1 (3 operators): 2 step(s), cost 20;"));
}

#[test]
fn no_executable_plan_exits_45_lists_what_was_set_aside_and_writes_nothing() {
    let dir = tempdir("none-executes");
    let goal = goal(&dir);
    let plan = dir.join("plan");
    let out = exits(
        45,
        demoplan()
            .arg("solve")
            .arg(library("no-executable-library.json"))
            .arg(&goal)
            .arg("--plan-file")
            .arg(&plan),
    );
    let log = stdout_text(&out);
    assert!(
        log.contains("No executable plan: the cube world executed none of the 1 plan(s) found (exit 45).\nSet aside for this problem:\n  idle (operator "),
        "{log}"
    );
    assert!(
        log.contains("priority 1, step 1 (idle left_hand cube_2 table): expected (inhand"),
        "{log}"
    );
    assert!(!plan.exists(), "{}", transcript(&out));
}

#[test]
fn a_scene_the_cube_world_cannot_lay_out_is_an_input_error_and_no_execute_plans_it() {
    let dir = tempdir("scene");
    // A tower standing on a cube that stands on it: no layout.
    let problem = dir.join("cycle.pddl");
    std::fs::write(
        &problem,
        "(define (problem cycle) (:domain demoplan)
           (:objects left_hand - hand cube_1 cube_2 - cube table - table)
           (:init (handopen left_hand) (ontop cube_1 cube_2) (ontop cube_2 cube_1))
           (:goal (not (handopen left_hand))))\n",
    )
    .unwrap();
    let plan = dir.join("plan");
    let mut solve = demoplan();
    solve
        .arg("solve")
        .arg(library("broken-idle-library.json"))
        .arg(&problem)
        .arg("--plan-file")
        .arg(&plan);
    let out = exits(31, &mut solve);
    let err = common::stderr_text(&out);
    assert!(
        err.contains("cycle.pddl: the cube world cannot lay out this problem"),
        "{err}"
    );
    assert!(err.contains("--no-execute"), "{err}");
    assert_eq!(stdout_text(&out).lines().count(), 1, "{}", transcript(&out));
    assert!(!plan.exists());
    exits(11, solve.arg("--no-execute"));
}
