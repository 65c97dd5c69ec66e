//! The paper's Algorithm 1 and the planning runs it is made of.
//!
//! [`solve`] builds the domain of priority 1, 2, ... of an operator library
//! ([`learn::levels`]) and plans on each until a plan is found. A level whose goal is
//! unreachable even when deletes are ignored is rejected by the translator's relaxed
//! reachability before any search; other levels are searched until proven unsolvable or
//! out of time. A [`Backend`] plans one task: demoplan's own planner in-process, or an
//! installed Fast Downward run as a separate program (never linked: it is GPL).

mod fast_downward;
mod logged;
mod run;

use std::time::{Duration, Instant};

pub use fast_downward::{parse_log, FastDownward, FdLog};
pub use logged::{plan_logged, LoggedRun, PlanInput, RunError, StatisticsRecord};
pub use run::{
    plan_task, translate_checked, translate_checked_until, MemoryProbe, Outcome, PlanRun,
    Translated,
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

impl Backend {
    /// Plans a domain and problem with a time limit.
    pub fn plan(
        &self,
        domain: &pddl::Domain,
        problem: &pddl::Problem,
        time_limit: Option<Duration>,
    ) -> PlanRun {
        self.plan_measured(domain, problem, time_limit, None)
    }

    /// Like [`plan`](Self::plan), and for demoplan's planner the run's peak heap
    /// through `memory` (Fast Downward reports its own peak).
    pub fn plan_measured(
        &self,
        domain: &pddl::Domain,
        problem: &pddl::Problem,
        time_limit: Option<Duration>,
        memory: Option<MemoryProbe>,
    ) -> PlanRun {
        let start = Instant::now();
        // One deadline for the whole run, translation included; a limit too far away to
        // be an instant is no limit.
        let deadline = task::deadline_after(start, time_limit);
        if let (Backend::Demoplan(_), Some(probe)) = (self, memory) {
            (probe.reset)();
        }
        let mut run = match self {
            Backend::Demoplan(config) => match translate_checked_until(domain, problem, deadline) {
                Translated::Task(task, translate_time) => {
                    let mut run = plan_task(&task, config, deadline);
                    run.translate_time = translate_time;
                    run.total_time = start.elapsed();
                    run
                }
                Translated::Done(run) => run,
            },
            Backend::FastDownward(fd, search) => fd.plan(
                &domain.to_string(),
                &problem.to_string(),
                search,
                time_limit,
            ),
        };
        if let (Backend::Demoplan(_), Some(probe)) = (self, memory) {
            run.peak_memory_kb = Some((probe.peak)().div_ceil(1024));
        }
        run
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
/// domain and plan; stop at the first plan. Every level gets `time_limit`. A level whose
/// goal the relaxation cannot reach is rejected before search (also with Fast Downward:
/// demoplan's translator decides it in milliseconds). `progress` sees each level as it
/// ends.
pub fn solve(
    library: &Library,
    options: DomainOptions,
    problem: &pddl::Problem,
    backend: &Backend,
    time_limit: Option<Duration>,
    mut progress: impl FnMut(&LevelResult),
) -> Solved {
    let start = Instant::now();
    let mut results = Vec::new();
    for level in levels(library, options) {
        let domain = domain("demoplan", &level.operators);
        // Each level's run has the time limit, translation included.
        let level_start = Instant::now();
        let deadline = match backend {
            Backend::Demoplan(_) => task::deadline_after(level_start, time_limit),
            Backend::FastDownward(..) => None,
        };
        let run = match (backend, translate_checked_until(&domain, problem, deadline)) {
            // Rejected (or broken) before search, whoever plans.
            (_, Translated::Done(run)) => run,
            (Backend::Demoplan(config), Translated::Task(task, translate_time)) => {
                let mut run = plan_task(&task, config, deadline);
                run.translate_time = translate_time;
                run.total_time = level_start.elapsed();
                run
            }
            (Backend::FastDownward(..), Translated::Task(..)) => {
                backend.plan(&domain, problem, time_limit)
            }
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
    use super::PlannerName;

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
