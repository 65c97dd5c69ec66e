//! What the fuzz targets share: a few steps of search on a task, with the properties
//! every finished search must have.

use std::sync::OnceLock;
use std::time::{Duration, Instant};

use search::{Outcome, SearchLimits};

/// How long each search may run. Short: the point is to reach the search code with odd
/// tasks, not to solve them.
const SEARCH_TIME: Duration = Duration::from_millis(5);

/// How many bytes of its own structures a search may use.
const SEARCH_BYTES: u64 = 32 << 20;

/// Notes how far an input got, on standard error, when `FUZZ_TRACE` is set: run a
/// target with `-runs=0` over its corpus to see how many inputs reach each stage.
pub fn trace(stage: &str) {
    static ON: OnceLock<bool> = OnceLock::new();
    if *ON.get_or_init(|| std::env::var_os("FUZZ_TRACE").is_some()) {
        eprintln!("FUZZ_TRACE {stage}");
    }
}

/// Searches `task` with `astar(blind())` and `astar(lmcut())` for a few milliseconds
/// each. Panics (a finding) if a search fails on a task that validates, if a plan does
/// not replay to a goal or its cost is not the sum of its operators' costs, or if both
/// searches finish with different verdicts or plan costs (both are optimal).
pub fn search_a_little(task: &task::Task) {
    let valid = task.validate().is_ok();
    let mut costs = Vec::new();
    for config in ["astar(blind())", "astar(lmcut())"] {
        let Ok(config) = search::parse_search(config) else {
            panic!("the fixed search string {config} does not parse");
        };
        let limits = SearchLimits {
            deadline: Some(Instant::now() + SEARCH_TIME),
            memory_limit_bytes: Some(SEARCH_BYTES),
            memory_usage: None,
        };
        let result = match search::search(task, &config, &limits, None) {
            Ok(result) => result,
            Err(e) => {
                assert!(!valid, "search failed on a valid task: {e}");
                trace("search refused the task");
                return;
            }
        };
        match result.outcome {
            Outcome::Solved(plan) => {
                let end = match search::replay(task, &plan.operators) {
                    Ok(end) => end,
                    Err(e) => panic!("a plan found by search does not replay: {e}"),
                };
                assert!(task.is_goal(&end), "a plan found by search misses the goal");
                let cost: u64 = plan
                    .operators
                    .iter()
                    .map(|&op| task.cost(&task.operators[op.index()]))
                    .sum();
                assert_eq!(cost, plan.cost, "a plan's cost is not its operators' sum");
                costs.push(Some(plan.cost));
            }
            Outcome::Unsolvable => costs.push(None),
            Outcome::TimeLimit | Outcome::MemoryLimit => {
                trace("search stopped at a limit");
                return;
            }
        }
    }
    trace(if costs[0].is_some() {
        "search solved"
    } else {
        "search proved unsolvable"
    });
    if let [a, b] = costs[..] {
        assert_eq!(a, b, "blind and lmcut disagree (cost, or solvable or not)");
    }
}
