//! Memory limits per run (issue 23): a run that reaches its memory limit has the outcome
//! `MemoryLimit`, in every level of Algorithm 1, and the limit is the run's own: what
//! the process held before the run started is not charged to it.

#![allow(clippy::unwrap_used, clippy::expect_used)]

use std::sync::atomic::{AtomicU64, Ordering};
use std::time::Duration;

use learn::{paper_goal_tower, problem, tower_goal, DomainOptions, Scene};
use slim::{solve, Backend, MemoryProbe, Outcome, RunLimits};

mod common;

use common::widening_library as fixture;

fn goal_problem() -> pddl::Problem {
    let scene = Scene::cubes_on_table(4);
    let tower = paper_goal_tower(2);
    problem("goal", "demoplan", &scene, &tower_goal(&scene, &tower))
}

fn lmcut() -> Backend {
    Backend::Demoplan(search::parse_search("astar(lmcut())").unwrap().into())
}

/// Algorithm 1 with LM-cut on the widening library and the paper's goal 1, under `limits`.
fn solve_goal(limits: RunLimits) -> slim::Solved {
    solve(
        &fixture(),
        DomainOptions::default(),
        &goal_problem(),
        &lmcut(),
        limits,
        |_| {},
    )
}

fn nothing() {}

/// A process that already holds a terabyte when the run starts, and allocates nothing
/// more (as far as the probe says).
fn a_terabyte() -> u64 {
    1 << 40
}

/// A heap that grows by a gibibyte every time it is read: the first check a run makes
/// after its start finds it over a limit of less.
fn growing() -> u64 {
    static HEAP: AtomicU64 = AtomicU64::new(0);
    HEAP.fetch_add(1 << 30, Ordering::Relaxed)
}

#[test]
fn the_heap_held_before_a_run_is_not_charged_to_it() {
    let limits = RunLimits {
        time: Some(Duration::from_secs(60)),
        memory_bytes: Some(16 << 20),
        memory: Some(MemoryProbe {
            in_use: a_terabyte,
            reset: nothing,
            peak: a_terabyte,
        }),
    };
    let solved = solve_goal(limits);
    let outcomes: Vec<&Outcome> = solved.levels.iter().map(|l| &l.run.outcome).collect();
    assert_eq!(
        outcomes,
        [&Outcome::RelaxedUnreachable, &Outcome::Solved],
        "a limit of 16 MiB on top of the terabyte held before the run"
    );
    // The limit as the phases see it: the heap at the start plus the run's own.
    let within = limits.starting_at(std::time::Instant::now());
    assert_eq!(within.memory_limit_bytes, Some((1 << 40) + (16 << 20)));
    assert_eq!(within.reached(|| 0), None);
}

#[test]
fn every_level_that_reaches_its_memory_limit_says_so() {
    let limits = RunLimits {
        time: Some(Duration::from_secs(60)),
        memory_bytes: Some(64 << 20),
        memory: Some(MemoryProbe {
            in_use: growing,
            reset: nothing,
            peak: growing,
        }),
    };
    let solved = solve_goal(limits);
    assert!(solved.plan_level().is_none());
    assert!(solved.any_limit());
    // Priority 1's goal is unreachable even in the relaxation: its translation may
    // prove that before it checks the limit. Every other level stops at the limit.
    for level in &solved.levels {
        assert!(
            matches!(
                level.run.outcome,
                Outcome::MemoryLimit | Outcome::RelaxedUnreachable
            ),
            "prio {}: {:?}",
            level.prio,
            level.run.outcome
        );
        assert!(level.run.plan.is_empty() && level.run.cost.is_none());
    }
    assert!(solved
        .levels
        .iter()
        .any(|l| l.run.outcome == Outcome::MemoryLimit));
    assert_eq!(Outcome::MemoryLimit.word(), "memory");
}

#[test]
fn without_a_probe_a_run_counts_its_own_structures_against_the_limit() {
    let limits = RunLimits {
        time: Some(Duration::from_secs(60)),
        memory_bytes: Some(1),
        memory: None,
    };
    let domain = learn::domain(
        "demoplan",
        &learn::levels(&fixture(), DomainOptions::default())
            .last()
            .unwrap()
            .operators,
    );
    let run = lmcut().plan(&domain, &goal_problem(), &limits);
    assert_eq!(run.outcome, Outcome::MemoryLimit, "{run:?}");
    assert!(run.plan.is_empty());
    assert_eq!(run.peak_memory_kb, None, "nothing measured without a probe");
}
