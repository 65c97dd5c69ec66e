//! The paper's Algorithm 1 and the planning runs it is made of.
//!
//! [`solve`] builds the domain of priority 1, 2, ... of an operator library
//! ([`learn::levels`]) and plans on each until a plan is found. A level whose goal is
//! unreachable even when deletes are ignored is rejected by the translator's relaxed
//! reachability before any search; other levels are searched until proven unsolvable or
//! out of time. A [`Backend`] plans one task: demoplan's own planner in-process, or an
//! installed Fast Downward run as a separate program (never linked: it is GPL).

mod config;
mod exit_code;
mod fast_downward;
mod logged;
mod printout;
mod run;

use std::time::{Duration, Instant};

pub use config::{alias_names, Alias, ConfigError, PlannerConfig, ALIASES};
pub use exit_code::ExitCode;
pub use fast_downward::{parse_log, FastDownward, FdLog};
pub use logged::{
    plan_logged, LoggedRun, PlanInput, PruningRecord, RunError, ScpRecord, StatisticsRecord,
};
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

/// `solve --planner`: the planners by [`PlannerName::name`], in [`PlannerName::ALL`]'s
/// order.
#[cfg(feature = "clap")]
impl clap::ValueEnum for PlannerName {
    fn value_variants<'a>() -> &'a [Self] {
        &PlannerName::ALL
    }

    fn to_possible_value(&self) -> Option<clap::builder::PossibleValue> {
        Some(clap::builder::PossibleValue::new(self.name()))
    }
}

/// Who plans.
#[derive(Debug, Clone)]
pub enum Backend {
    /// demoplan's planner with this configuration (search and translator options).
    Demoplan(PlannerConfig),
    /// Fast Downward with this search string.
    FastDownward(FastDownward, String),
}

/// Why a [`Backend`] could not be made: a search string that does not parse
/// ([`ExitCode::SEARCH_INPUT_ERROR`]), an unknown alias or an alias for Fast Downward, or
/// no Fast Downward to run ([`ExitCode::USAGE`]).
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum BackendError {
    #[error(transparent)]
    Config(#[from] ConfigError),
    #[error("--alias names a configuration of demoplan's planner; give Fast Downward a --search")]
    AliasForFastDownward,
    #[error("{0}")]
    NoFastDownward(String),
}

impl BackendError {
    /// The exit code of a command that stops here.
    pub fn exit_code(&self) -> ExitCode {
        match self {
            BackendError::Config(e) => e.exit_code(),
            BackendError::AliasForFastDownward | BackendError::NoFastDownward(_) => ExitCode::USAGE,
        }
    }
}

impl Backend {
    /// The backend `planner` names, with its search string (Fast Downward's syntax) or,
    /// for demoplan, an alias ([`PlannerConfig::resolve`], parsed now), and for Fast
    /// Downward its driver ([`FastDownward::locate`]).
    pub fn new(
        planner: PlannerName,
        search: Option<&str>,
        alias: Option<&str>,
        fd: Option<&std::path::Path>,
    ) -> Result<Backend, BackendError> {
        match planner {
            PlannerName::Demoplan => Ok(Backend::Demoplan(PlannerConfig::resolve(
                search,
                alias,
                translate::TranslateOptions::default(),
            )?)),
            PlannerName::FastDownward => {
                let search = match (search, alias) {
                    (_, Some(_)) => return Err(BackendError::AliasForFastDownward),
                    (Some(search), None) => search,
                    (None, None) => return Err(ConfigError::Missing.into()),
                };
                FastDownward::locate(fd)
                    .map(|driver| Backend::FastDownward(driver, search.to_string()))
                    .map_err(BackendError::NoFastDownward)
            }
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
                let options = &config.translator;
                let mut run = match translate_checked_within(domain, problem, options, &within) {
                    Translated::Task(task, translate_time) => {
                        let mut run = plan_task(&task, &config.search, &within);
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

/// One level's planning run, as [`solve`] makes it: with demoplan, [`Backend::plan`];
/// with Fast Downward, demoplan's translator first rejects a level whose goal the
/// relaxation cannot reach (or whose task is broken), with no limits (it takes
/// milliseconds), and only a level it accepts is planned by Fast Downward. Callers that
/// wrap Algorithm 1 (the execution loop of the `closed-loop` crate) plan their levels
/// through it, so that every level is planned one way.
pub fn plan_level(
    backend: &Backend,
    domain: &pddl::Domain,
    problem: &pddl::Problem,
    limits: &RunLimits,
) -> PlanRun {
    match backend {
        Backend::Demoplan(_) => backend.plan(domain, problem, limits),
        Backend::FastDownward(..) => match translate_checked(domain, problem) {
            Translated::Done(run) => run,
            Translated::Task(..) => backend.plan(domain, problem, limits),
        },
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
        let run = plan_level(backend, &domain, problem, &limits);
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
        let backend = Backend::new(PlannerName::Demoplan, Some("astar(lmcut())"), None, None);
        assert!(matches!(backend, Ok(Backend::Demoplan(_))), "{backend:?}");
        let e = Backend::new(PlannerName::Demoplan, Some("astar(nope())"), None, None);
        let e = e.unwrap_err();
        assert_eq!(e.exit_code(), ExitCode::SEARCH_INPUT_ERROR);
        assert!(
            e.to_string()
                .starts_with("--search: unknown heuristic `nope`"),
            "{e}"
        );
        let missing = std::path::Path::new("/nonexistent/fast-downward.py");
        let search = Some("astar(lmcut())");
        let e = Backend::new(PlannerName::FastDownward, search, None, Some(missing));
        assert!(matches!(&e, Err(BackendError::NoFastDownward(_))), "{e:?}");
        assert_eq!(e.unwrap_err().exit_code(), ExitCode::USAGE);
    }

    #[test]
    fn an_alias_gives_demoplan_its_translator_options_and_fast_downward_an_error() {
        let opt = Backend::new(PlannerName::Demoplan, None, Some("demoplan-opt"), None);
        let Ok(Backend::Demoplan(config)) = opt else {
            panic!("{opt:?}")
        };
        assert_eq!(config, crate::PlannerConfig::alias("demoplan-opt").unwrap());
        let fd = Backend::new(PlannerName::FastDownward, None, Some("demoplan-opt"), None);
        assert_eq!(fd.unwrap_err(), BackendError::AliasForFastDownward);
        let e = Backend::new(PlannerName::Demoplan, None, Some("nope"), None).unwrap_err();
        assert_eq!(e.exit_code(), ExitCode::USAGE);
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
