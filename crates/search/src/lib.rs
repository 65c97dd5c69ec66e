//! Optimal search over finite-domain tasks: eager A* with admissible heuristics.
//!
//! The crate consumes a [`task::Task`] and knows nothing of PDDL. Its parts:
//!
//! - [`state`]: states packed into `u64` words ([`StatePacker`]), stored once in an arena
//!   with a hash table of dense [`StateId`]s ([`StateRegistry`]);
//! - [`SuccessorGenerator`]: a decision tree over variables that finds applicable
//!   operators without testing every operator;
//! - [`Heuristic`]: the interface heuristics implement, with [`Blind`], [`HMax`] and
//!   [`LmCut`];
//! - pattern databases: [`PatternDatabase`] (one pattern's abstract costs, by a backward
//!   search over regression operators), [`CanonicalPdbs`] (the canonical heuristic over a
//!   collection) and [`ipdb`] (the collection chosen by hill climbing, Fast Downward's
//!   `ipdb()`), with what building them did in [`PdbStatistics`];
//! - saturated cost partitioning over projections: [`Scp`] (`scp(...)`,
//!   `scp_online(...)`, configured by [`ScpConfig`]), with Sys-SCP pattern selection;
//! - [`astar`]: eager A* with reopening, returning a [`SearchResult`] (an [`Outcome`] and
//!   Fast Downward-style [`Statistics`]) under [`SearchLimits`], reporting each new
//!   f-layer to an optional observer;
//! - partial-order reduction: [`PruningConfig`] (`pruning=atom_centric_stubborn_sets()`,
//!   `limited_pruning(...)`) built into a [`Pruning`] that [`astar_with_pruning`] applies
//!   to each expansion, with what it pruned in [`PruningStatistics`];
//! - [`parse_search`]: Fast Downward-style search strings (`astar(hmax())`), and
//!   [`search`] to run one (aliases, which add translator options, are `slim`'s);
//! - [`replay`]: applies a plan to the initial state, checking every step.
//!
//! The library never prints and does no I/O; results are values.
//!
//! ```
//! use search::{parse_search, replay, search, Outcome, SearchLimits};
//! use task::{Fact, Operator, Task, VarId, Variable};
//!
//! // A robot at position 0, 1 or 2 on a line must reach 2.
//! let step = |from: u32, to: u32| Operator {
//!     name: format!("move p{from} p{to}"),
//!     preconditions: vec![Fact::new(VarId(0), from)],
//!     effects: vec![Fact::new(VarId(0), to)],
//!     cost: 1,
//! };
//! let task = Task {
//!     variables: vec![Variable {
//!         name: "at".into(),
//!         value_names: vec!["p0".into(), "p1".into(), "p2".into()],
//!     }],
//!     mutexes: vec![],
//!     initial_state: vec![0],
//!     goal: vec![Fact::new(VarId(0), 2)],
//!     operators: vec![step(0, 1), step(1, 0), step(1, 2), step(2, 1)],
//!     use_costs: false,
//! };
//! let config = parse_search("astar(hmax())")?;
//! let mut layers = Vec::new();
//! let result = search(&task, &config, &SearchLimits::default(), Some(&mut |p| layers.push(p.f)))?;
//! let Outcome::Solved(plan) = result.outcome else { panic!("solvable") };
//! assert_eq!(plan.cost, 2);
//! let names: Vec<&str> = plan.operators.iter().map(|op| task.operators[op.index()].name.as_str()).collect();
//! assert_eq!(names, ["move p0 p1", "move p1 p2"]);
//! assert!(task.is_goal(&replay(&task, &plan.operators)?));
//! assert_eq!(result.statistics.initial_h, Some(2)); // h^max is exact on a line
//! assert_eq!(layers, [2]); // one f-layer: A* went straight to the goal
//! assert_eq!(result.statistics.expanded, 3);
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

mod astar;
mod config;
mod cpdbs;
mod fd_random;
mod heuristic;
mod hmax;
mod ipdb;
mod lmcut;
mod open_list;
mod pdb;
mod plan;
mod pruning;
mod radix_heap;
mod scp;
mod segmented;
pub mod state;
mod successor;

/// Tasks for the unit tests, the integration tests' own: random valid ones for property
/// tests, and operators written briefly.
#[cfg(test)]
#[path = "../tests/common/mod.rs"]
mod test_tasks;

pub use astar::{
    astar, astar_with_pruning, Outcome, Progress, SearchError, SearchLimits, SearchResult,
    Statistics,
};
pub use config::{
    parse_search, Built, ConfigError, Engine, HeuristicConfig, HeuristicName,
    PatternCollectionConfig, SearchConfig, SEARCH_ENGINES,
};
pub use cpdbs::{CanonicalPdbs, PdbStatistics};
pub use heuristic::{Blind, Heuristic};
pub use hmax::HMax;
pub use ipdb::{ipdb, ClimbEnd, HillClimbingStatistics, IpdbConfig, DEFAULT_SEED};
pub use lmcut::{tie_breaking_order, LmCut};
pub use pdb::{construction_bytes, PatternDatabase, PatternError, MAX_PDB_SIZE};
pub use plan::{replay, Plan, ReplayError};
pub use pruning::{
    AtomSelectionStrategy, LimitedPruningConfig, Pruning, PruningConfig, PruningStatistics, Ratio,
    RatioCheck, StubbornSetsConfig,
};
pub use scp::{
    systematic_up_to, PatternGenerator, Projection, Scp, ScpConfig, ScpStatistics, SysScpConfig,
};
pub use state::{StateId, StatePacker, StateRegistry};
pub use successor::SuccessorGenerator;

/// Runs the search `config` describes on `task`: builds its heuristic (see
/// [`HeuristicConfig::build_with_limits`]: the hill climbing of `ipdb` stops at the
/// limits too, and a fixed pattern collection that does not fit the memory limit ends
/// the run with [`Outcome::MemoryLimit`] before it is built) and calls the engine
/// ([`astar`]). Fails only if the task is invalid or a
/// pattern of the search string does not fit it.
pub fn search(
    task: &task::Task,
    config: &SearchConfig,
    limits: &SearchLimits,
    observer: Option<&mut dyn FnMut(Progress)>,
) -> Result<SearchResult, SearchError> {
    let mut heuristic = match config.heuristic.build_with_limits(task, limits)? {
        Built::Heuristic(h) => h,
        Built::Stopped(limit) => {
            return Ok(SearchResult {
                outcome: Outcome::limit(limit),
                statistics: Statistics::default(),
            })
        }
    };
    let mut pruning = config.pruning.build(task);
    match config.engine {
        Engine::AStar => {
            astar_with_pruning(task, &mut heuristic, pruning.as_mut(), limits, observer)
        }
    }
}
