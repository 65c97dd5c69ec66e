//! The paper's Algorithm 1 and the planning runs it is made of.
//!
//! [`solve`] builds the domain of priority 1, 2, ... of an operator library
//! ([`learn::levels`]) and plans on each until a plan is found. A level whose goal is
//! unreachable even when deletes are ignored is rejected by the translator's relaxed
//! reachability before any search; other levels are searched until proven unsolvable or
//! out of time. A [`Backend`] plans one task: demoplan's own planner in-process, or an
//! installed Fast Downward run as a separate program (never linked: it is GPL).

mod exit_code;
mod fast_downward;
mod logged;
mod printout;
mod run;

use std::time::{Duration, Instant};

pub use exit_code::ExitCode;
pub use fast_downward::{parse_log, FastDownward, FdLog};
pub use logged::{plan_logged, LoggedRun, PlanInput, PruningRecord, RunError, StatisticsRecord};
pub use printout::{compare_full, level_header, level_row};
pub use run::{
    plan_task, translate_checked, translate_checked_within, MemoryProbe, Outcome, PlanRun,
    RunLimits, Translated,
};

use learn::{domain, levels, DomainOptions, Library};

/// Who plans, by name (`demoplan solve --planner`); a [`Backend`] adds its settings.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum PlannerName {
    /// demoplan's own planner, in-process.
    Demoplan,
    /// An installed Fast Downward, run as a separate program.
    FastDownward,
}

impl PlannerName {
    /// Every planner, in the order help texts list them.
    pub const ALL: [PlannerName; 2] = [PlannerName::Demoplan, PlannerName::FastDownward];

    /// The name on the command line: `demoplan` or `fast-downward`.
    pub fn name(self) -> &'static str {
        match self {
            PlannerName::Demoplan => "demoplan",
            PlannerName::FastDownward => "fast-downward",
        }
    }

    /// The planner of a name, if there is one.
    pub fn from_name(name: &str) -> Option<PlannerName> {
        PlannerName::ALL.into_iter().find(|p| p.name() == name)
    }
}

/// Who plans.
#[derive(Debug, Clone)]
pub enum Backend {
    /// demoplan's planner with this search configuration.
    Demoplan(search::SearchConfig),
    /// Fast Downward with this search string.
    FastDownward(FastDownward, String),
}

/// Why a [`Backend`] could not be made: a search string that does not parse
/// ([`ExitCode::SEARCH_INPUT_ERROR`]), or no Fast Downward to run ([`ExitCode::USAGE`]).
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum BackendError {
    #[error("--search {search}: {error}")]
    Search {
        search: String,
        error: search::ConfigError,
    },
    #[error("{0}")]
    NoFastDownward(String),
}

impl BackendError {
    /// The exit code of a command that stops here.
    pub fn exit_code(&self) -> ExitCode {
        match self {
            BackendError::Search { .. } => ExitCode::SEARCH_INPUT_ERROR,
            BackendError::NoFastDownward(_) => ExitCode::USAGE,
        }
    }
}

impl Backend {
    /// The backend `planner` names, with its search string (Fast Downward's syntax; for
    /// demoplan, parsed now) and, for Fast Downward, its driver ([`FastDownward::locate`]).
    pub fn new(
        planner: PlannerName,
        search: &str,
        fd: Option<&std::path::Path>,
    ) -> Result<Backend, BackendError> {
        match planner {
            PlannerName::Demoplan => {
                search::parse_search(search)
                    .map(Backend::Demoplan)
                    .map_err(|error| BackendError::Search {
                        search: search.to_string(),
                        error,
                    })
            }
            PlannerName::FastDownward => FastDownward::locate(fd)
                .map(|driver| Backend::FastDownward(driver, search.to_string()))
                .map_err(BackendError::NoFastDownward),
        }
    }

    /// Plans a domain and problem within `limits`, counted from now: one deadline and
    /// one memory limit for the whole run, translation included. With a
    /// [`MemoryProbe`], demoplan's run also measures its peak heap (Fast Downward
    /// reports its own peak, and gets the limits as its `--overall-time-limit` and
    /// `--overall-memory-limit`).
    pub fn plan(
        &self,
        domain: &pddl::Domain,
        problem: &pddl::Problem,
        limits: &RunLimits,
    ) -> PlanRun {
        let start = Instant::now();
        match self {
            Backend::Demoplan(config) => {
                if let Some(probe) = limits.memory {
                    (probe.reset)();
                }
                let within = limits.starting_at(start);
                let mut run = match translate_checked_within(domain, problem, &within) {
                    Translated::Task(task, translate_time) => {
                        let mut run = plan_task(&task, config, &within);
                        run.translate_time = translate_time;
                        run.total_time = start.elapsed();
                        run
                    }
                    Translated::Done(run) => run,
                };
                if let Some(probe) = limits.memory {
                    run.peak_memory_kb = Some((probe.peak)().div_ceil(1024));
                }
                run
            }
            Backend::FastDownward(fd, search) => fd.plan(
                &domain.to_string(),
                &problem.to_string(),
                search,
                limits.time,
                limits.memory_bytes,
            ),
        }
    }
}

/// One level of Algorithm 1 and how planning on it went.
#[derive(Debug, Clone)]
pub struct LevelResult {
    /// The priority.
    pub prio: usize,
    /// Operators in its domain.
    pub operators: usize,
    /// The domain.
    pub domain: pddl::Domain,
    /// The run (for a level rejected by relaxed reachability: that verdict).
    pub run: PlanRun,
}

/// The result of Algorithm 1.
#[derive(Debug, Clone)]
pub struct Solved {
    /// Every level tried, in order.
    pub levels: Vec<LevelResult>,
    /// Wall time over all levels, failed ones included (the paper's own argument: a
    /// failed slim level costs time too).
    pub cumulative: Duration,
}

impl Solved {
    /// The level that gave the plan, if any.
    pub fn plan_level(&self) -> Option<&LevelResult> {
        self.levels
            .iter()
            .find(|l| l.run.outcome == Outcome::Solved)
    }

    /// Whether some level stopped at its time (or memory) limit.
    pub fn any_limit(&self) -> bool {
        self.levels
            .iter()
            .any(|l| matches!(l.run.outcome, Outcome::TimeLimit | Outcome::MemoryLimit))
    }
}

/// Algorithm 1: for priority 1, 2, ... over the distinct operator subsets, build the
/// domain and plan; stop at the first plan. Every level gets `limits` of its own (time,
/// translation included, and memory: a level that reaches either has that outcome and
/// the loop widens on). A level whose goal the relaxation cannot reach is rejected
/// before search (also with Fast Downward: demoplan's translator decides it in
/// milliseconds). `progress` sees each level as it ends.
pub fn solve(
    library: &Library,
    options: DomainOptions,
    problem: &pddl::Problem,
    backend: &Backend,
    limits: RunLimits,
    mut progress: impl FnMut(&LevelResult),
) -> Solved {
    let start = Instant::now();
    let mut results = Vec::new();
    for level in levels(library, options) {
        let domain = domain("demoplan", &level.operators);
        let run = match backend {
            Backend::Demoplan(_) => backend.plan(&domain, problem, &limits),
            // Rejected (or broken) before search by demoplan's translator, with no
            // limits (it takes milliseconds), then planned by Fast Downward.
            Backend::FastDownward(..) => match translate_checked(&domain, problem) {
                Translated::Done(run) => run,
                Translated::Task(..) => backend.plan(&domain, problem, &limits),
            },
        };
        let result = LevelResult {
            prio: level.prio,
            operators: level.operators.len(),
            domain,
            run,
        };
        progress(&result);
        let solved = result.run.outcome == Outcome::Solved;
        results.push(result);
        if solved {
            break;
        }
    }
    Solved {
        levels: results,
        cumulative: start.elapsed(),
    }
}

#[cfg(test)]
mod tests {
    use super::{Backend, BackendError, ExitCode, PlannerName};

    #[test]
    fn a_backend_parses_demoplan_searches_and_needs_a_fast_downward() {
        let backend = Backend::new(PlannerName::Demoplan, "astar(lmcut())", None);
        assert!(matches!(backend, Ok(Backend::Demoplan(_))), "{backend:?}");
        let e = Backend::new(PlannerName::Demoplan, "astar(nope())", None).unwrap_err();
        assert_eq!(e.exit_code(), ExitCode::SEARCH_INPUT_ERROR);
        assert!(e.to_string().starts_with("--search astar(nope()): "), "{e}");
        let missing = std::path::Path::new("/nonexistent/fast-downward.py");
        let e = Backend::new(PlannerName::FastDownward, "astar(lmcut())", Some(missing));
        assert!(matches!(&e, Err(BackendError::NoFastDownward(_))), "{e:?}");
        assert_eq!(e.unwrap_err().exit_code(), ExitCode::USAGE);
    }

    #[test]
    fn planner_names_read_back_and_nothing_else_reads() {
        for planner in PlannerName::ALL {
            assert_eq!(PlannerName::from_name(planner.name()), Some(planner));
        }
        for other in ["", "Demoplan", "fast_downward", "lama"] {
            assert_eq!(PlannerName::from_name(other), None, "{other}");
        }
    }
}
