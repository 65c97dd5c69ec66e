//! Properties of the whole pipeline over many simulated studies, rather than one seed's
//! numbers: for every seed of a range, the library learned from a study of the paper's
//! shape (3 participants x 4 demonstrations) lets Algorithm 1 (`slim::solve`) plan each of
//! the paper's goals 1 to 3 at some level, and every plan found executes in the cube world.
//!
//! The 100-seed distributions of the library's size belong to the calibration script
//! (`cargo run --release -p learn --example calibrate`), not to `cargo test`.

#![allow(clippy::unwrap_used, clippy::expect_used)]

use recording::Activity;
use std::time::Duration;

use grounding::GroundingConfig;
use learn::{DomainOptions, Library};
use segment::ActivityTree;

mod common;
use common::paper_problem;

/// Seeds tried: 20 studies; on each, the paper's goals 1 to 3 (towers of 2 to 4 cubes)
/// with LM-cut. Goals 4 and 5 take from seconds to minutes each on priority 1 in the test
/// profile, too long for CI over 20 seeds; `crates/slim/examples/priority_one.rs` plans
/// all five over 100 seeds with the release build.
const SEEDS: std::ops::RangeInclusive<u64> = 1..=20;
const GOALS: std::ops::RangeInclusive<usize> = 1..=3;

/// A level's limit. Generous: it is a guard against a search that never ends, not a
/// measure of speed (a level that hits it counts as not planned and fails the test).
const LEVEL_LIMIT: Duration = Duration::from_secs(120);

fn library(seed: u64) -> Library {
    let study = simulate::study(&simulate::SimParams::default(), seed, 3, 4).unwrap();
    let config = GroundingConfig::default();
    let tree = ActivityTree::table_one();
    let mut library = Library::default();
    for demo in &study.demonstrations {
        let frames = demo.frames().map(|(f, _)| f).collect();
        learn::add_frames(&mut library, demo.header(), frames, &config, &tree, "");
    }
    library
}

#[test]
fn every_seed_plans_every_paper_goal_and_every_plan_executes() {
    let backend = slim::Backend::Demoplan(search::parse_search("astar(lmcut())").unwrap().into());
    let mut planned = 0;
    for seed in SEEDS {
        let library = library(seed);
        // Every type of the paper's Table 1 is demonstrated, so priority 1 has a domain.
        for a in Activity::OPERATOR_ORDER {
            assert!(library.type_count(a) > 0, "seed {seed}: no {a} activity");
        }
        for goal in GOALS {
            let p = paper_problem(goal);
            let solved = slim::solve(
                &library,
                DomainOptions::default(),
                &p,
                &backend,
                slim::RunLimits::time(LEVEL_LIMIT),
                |_| {},
            );
            let level = solved.plan_level().unwrap_or_else(|| {
                let tried: Vec<String> = solved
                    .levels
                    .iter()
                    .map(|l| format!("prio {}: {:?}", l.prio, l.run.outcome))
                    .collect();
                panic!("seed {seed}, goal {goal}: no plan at any level ({tried:?})")
            });
            // Each extra cube of the tower needs at least a reach, a grasp and a put.
            assert!(
                level.run.plan.len() >= 3 * goal,
                "seed {seed}, goal {goal}: {} actions",
                level.run.plan.len()
            );
            let report = cubeworld::execute(&level.domain, &p, &level.run.plan).unwrap();
            assert!(
                report.success(),
                "seed {seed}, goal {goal}, prio {}: the plan {:?} does not execute: step {:?}, goal {:?}",
                level.prio,
                level.run.plan,
                report.steps.iter().find(|s| !s.failed.is_empty()).map(|s| s.action_text()),
                report.goal
            );
            planned += 1;
        }
    }
    assert_eq!(planned, SEEDS.count() * GOALS.count());
}
