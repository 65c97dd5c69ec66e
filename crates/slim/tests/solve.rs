//! Algorithm 1 on a library whose priority-1 domain cannot reach the goal: the loop
//! rejects that level before search and widens to priority 2, which plans.

#![allow(clippy::unwrap_used, clippy::expect_used)]

use std::time::Duration;

use learn::{paper_goal_tower, problem, tower_goal, DomainOptions, Scene};
use slim::{solve, Backend, LevelResult, Outcome, RunLimits, Solved};

mod common;

use common::widening_library as fixture;

/// Algorithm 1 on the widening library for `problem`, with LM-cut and a minute per
/// level, each level's run handed to `seen`.
fn widen(problem: &pddl::Problem, seen: impl FnMut(&LevelResult)) -> Solved {
    let backend = Backend::Demoplan(search::parse_search("astar(lmcut())").unwrap().into());
    let limits = RunLimits::time(Duration::from_secs(60));
    solve(
        &fixture(),
        DomainOptions::default(),
        problem,
        &backend,
        limits,
        seen,
    )
}

#[test]
fn widening_finds_the_plan_on_the_second_level() {
    let scene = Scene::cubes_on_table(4);
    let tower = paper_goal_tower(2);
    let p = problem("goal", "demoplan", &scene, &tower_goal(&scene, &tower));
    let mut seen = Vec::new();
    let solved = widen(&p, |l| seen.push((l.prio, l.run.outcome)));
    assert_eq!(
        seen,
        [(1, Outcome::RelaxedUnreachable), (2, Outcome::Solved)]
    );
    let level = solved.plan_level().unwrap();
    assert_eq!(level.operators, 3);
    // Take and put each of cube_2, cube_3: 4 actions; costs ceil(100 * (1 - 6/6)) = 0
    // for take and ceil(100 * (1 - 1/5)) = 80 for the put onto a cube.
    assert_eq!(level.run.plan.len(), 4);
    assert_eq!(level.run.cost, Some(160));
    assert!(!solved.any_limit());
    assert!(solved.cumulative >= level.run.total_time);
}

#[test]
fn exhausting_every_level_reports_each() {
    let scene = Scene::cubes_on_table(3);
    // Holding cube_1 while it stands on the table: each fact is reachable on its own
    // (so the relaxation alone rejects no level), but taking a cube lifts it off the
    // table and putting it down empties the hand. Priority 1 is searched to the end; on
    // priority 2 the translator's invariants already prove the two goal facts mutually
    // exclusive ("where cube_1 is": on one thing or in one hand), so it is rejected
    // before search, as the relaxation rejects a level.
    let goal = vec![
        (
            grounding::Predicate::InHand,
            vec!["left_hand".to_string(), "cube_1".to_string()],
        ),
        (
            grounding::Predicate::OnTop,
            vec!["cube_1".to_string(), "table".to_string()],
        ),
    ];
    let p = problem("impossible", "demoplan", &scene, &goal);
    let solved = widen(&p, |_| {});
    assert!(solved.plan_level().is_none());
    let outcomes: Vec<Outcome> = solved.levels.iter().map(|l| l.run.outcome).collect();
    assert_eq!(outcomes, [Outcome::Unsolvable, Outcome::RelaxedUnreachable]);
}
