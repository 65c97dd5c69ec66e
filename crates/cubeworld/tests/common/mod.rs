//! What the cube world's test binaries share.

#![allow(clippy::unwrap_used)] // tests fail loudly by design

use learn::{paper_goal_tower, problem, tower_goal, Scene};

/// The paper's goal `goal` (a tower of `goal + 1` cubes) over six cubes on the table, as
/// `demoplan problem --paper-goal` writes it, parsed.
pub fn paper_problem(goal: usize) -> pddl::Problem {
    let scene = Scene::cubes_on_table(6);
    let tower = paper_goal_tower(goal);
    let text = problem(
        &format!("paper-goal-{goal}"),
        "demoplan",
        &scene,
        &tower_goal(&scene, &tower),
    )
    .to_string();
    pddl::parse_problem(&text).unwrap()
}
