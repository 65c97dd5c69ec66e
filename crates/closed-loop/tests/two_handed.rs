//! Issue 39's acceptance on simulated people who behave like real ones (the simulator's
//! `two-handed` style: both hands at once, grasps from geometry alone, dropped frames,
//! recordings cut mid-motion): what is learned means what it says, and Algorithm 1's
//! plans execute in the cube world.

#![allow(clippy::unwrap_used, clippy::expect_used)]

use std::time::Duration;

use closed_loop::{solve, Execution, Verdict};
use grounding::{GroundingConfig, Predicate};
use learn::{problem, tower_goal, DomainOptions, Grouping, Library, Scene};
use segment::{Activity, ActivityTree};
use slim::{Backend, RunLimits};

/// Seeds of the two-handed studies learned here (3 participants x 4 demonstrations).
const SEEDS: [u64; 2] = [1, 2];

struct Learned {
    library: Library,
    activities: u64,
    agreeing: u64,
    dropped: u64,
}

/// A two-handed study learned, with its activities scored against the simulator's truth
/// (`learn::truth_activities`: the noise-free hand facts through the same segmenter and
/// grouping).
fn learned(seed: u64) -> Learned {
    let params = simulate::Style::TwoHanded.params();
    let study = simulate::study(&params, seed, 3, 4).unwrap();
    let (config, tree) = (GroundingConfig::default(), ActivityTree::table_one());
    let mut library = Library::default();
    let (mut activities, mut agreeing, mut dropped) = (0, 0, 0);
    for demo in &study.demonstrations {
        let (frames, truth): (Vec<_>, Vec<_>) = demo.frames().unzip();
        let seg = learn::segment_frames(demo.header(), frames.clone(), &config, &tree);
        let grouped = learn::activities(&seg.segments, Grouping::Settled);
        let (mended, counts) = learn::mend(&grouped, Grouping::Settled, &seg.space);
        let truth_frames = learn::truth_hand_facts(&truth);
        let hands = seg.space.hands().to_vec();
        let truth = learn::truth_activities(
            &hands,
            truth_frames,
            &tree,
            config.min_duration,
            Grouping::Settled,
        );
        let classes = learn::truth_classes(&mended, &truth);
        activities += mended.len() as u64 + counts.dropped_total();
        dropped += counts.dropped_total();
        agreeing += (mended.iter().zip(&classes))
            .filter(|(a, t)| Some(a.activity) == **t)
            .count() as u64;
        learn::add_frames(&mut library, demo.header(), frames, &config, &tree, "");
    }
    Learned {
        library,
        activities,
        agreeing,
        dropped,
    }
}

#[test]
fn two_handed_activities_mean_their_class_and_agree_with_the_truth() {
    for seed in SEEDS {
        let l = learned(seed);
        for e in l.library.entries() {
            let op = &e.operator;
            let adds = |p| op.add.iter().any(|f| f.predicate == p);
            if op.activity == Activity::Idle {
                let changes_things =
                    adds(Predicate::InHand) || adds(Predicate::OnTop) || adds(Predicate::InTouch);
                assert!(!changes_things, "seed {seed}: {}", op.canonical_text());
            }
        }
        let share = |n: u64| n as f64 / l.activities as f64;
        assert!(
            share(l.agreeing) >= 0.95,
            "seed {seed}: {} of {} activities agree with the truth",
            l.agreeing,
            l.activities
        );
        assert!(
            share(l.dropped) < 0.05,
            "seed {seed}: {} dropped",
            l.dropped
        );
    }
}

/// Towers of 2 to 6 cubes, with one hand and with two: Algorithm 1 finds a plan with
/// execution off and on; with execution on it executes in the cube world, and with
/// execution off too, except one hand's tower of 6. There the optimal plan may reach
/// every cube before taking the first, and a lifted Reach over its own cube cannot say
/// that the hand leaves the others: a known limit of the operators (docs/operators.md),
/// which the loop answers by setting that Reach aside.
#[test]
fn two_handed_libraries_give_plans_the_cube_world_executes() {
    let backend = Backend::Demoplan(search::parse_search("astar(lmcut())").unwrap().into());
    for seed in SEEDS {
        let library = learned(seed).library;
        for hands in [1, 2] {
            for height in 2..=6 {
                let scene = Scene::with_hands(6, hands);
                let tower: Vec<String> = (1..=height).map(|i| format!("cube_{i}")).collect();
                let task = problem("tower", "demoplan", &scene, &tower_goal(&scene, &tower));
                let limits = RunLimits::time(Duration::from_secs(60));
                let what = format!("seed {seed}, {hands} hand(s), tower of {height}");
                for execution in [Execution::Off, Execution::On] {
                    let solved = solve(
                        &library,
                        DomainOptions::default(),
                        &task,
                        &backend,
                        limits,
                        execution,
                        |_| {},
                    )
                    .unwrap();
                    let Verdict::Plan(attempt) = solved.verdict() else {
                        panic!("{what}, {execution:?}: no plan ({:?})", solved.exit_code());
                    };
                    if execution == Execution::On || hands == 2 || height <= 5 {
                        let report = cubeworld::execute(
                            &attempt.level.domain,
                            &task,
                            &attempt.level.run.plan,
                        )
                        .unwrap();
                        assert!(report.success(), "{what}, {execution:?}: {}", report.text());
                    }
                }
            }
        }
    }
}
