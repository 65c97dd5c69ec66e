//! One planning run with demoplan's planner, in-process.

use std::time::{Duration, Instant};

use serde::{Deserialize, Serialize};

/// How a planning run ended: the one type of the concept, also in the experiment's
/// records, where it is written as its [`word`](Outcome::word) (`"outcome":"memory"`).
/// Why a run is an [`Outcome::Error`] is [`PlanRun::error`].
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(try_from = "String", into = "&'static str")]
pub enum Outcome {
    /// A plan was found (optimal within its domain).
    Solved,
    /// The goal is unreachable even when deletes are ignored: rejected before search.
    RelaxedUnreachable,
    /// The search space was exhausted: no plan.
    Unsolvable,
    /// The time limit was reached.
    TimeLimit,
    /// The memory limit was reached.
    MemoryLimit,
    /// The caller cancelled the run (`task::Limits::cancel`): no result, and no limit
    /// reached either.
    Cancelled,
    /// The run could not be made (bad input, a planner that failed); the reason is
    /// [`PlanRun::error`].
    Error,
}

impl Outcome {
    /// Every outcome, in the order of the words' documentation.
    pub const ALL: [Outcome; 7] = [
        Outcome::Solved,
        Outcome::RelaxedUnreachable,
        Outcome::Unsolvable,
        Outcome::TimeLimit,
        Outcome::MemoryLimit,
        Outcome::Cancelled,
        Outcome::Error,
    ];

    /// The outcome of a run stopped at `limit`.
    pub fn limit(limit: task::Limit) -> Outcome {
        match limit {
            task::Limit::Time => Outcome::TimeLimit,
            task::Limit::Memory => Outcome::MemoryLimit,
            task::Limit::Cancelled => Outcome::Cancelled,
        }
    }

    /// A short word for tables: `solved`, `relaxed-unreachable`, `unsolvable`, `limit`,
    /// `memory`, `error`.
    pub fn word(&self) -> &'static str {
        match self {
            Outcome::Solved => "solved",
            Outcome::RelaxedUnreachable => "relaxed-unreachable",
            Outcome::Unsolvable => "unsolvable",
            Outcome::TimeLimit => "limit",
            Outcome::MemoryLimit => "memory",
            Outcome::Cancelled => "cancelled",
            Outcome::Error => "error",
        }
    }

    /// The outcome of a [`word`](Outcome::word), if it is one.
    pub fn from_word(word: &str) -> Option<Outcome> {
        Outcome::ALL.into_iter().find(|o| o.word() == word)
    }

    /// Whether the run stopped at its time or memory limit (its times are lower
    /// bounds).
    pub fn hit_limit(self) -> bool {
        matches!(self, Outcome::TimeLimit | Outcome::MemoryLimit)
    }
}

impl std::fmt::Display for Outcome {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.word())
    }
}

impl From<Outcome> for &'static str {
    fn from(outcome: Outcome) -> &'static str {
        outcome.word()
    }
}

impl TryFrom<String> for Outcome {
    type Error = String;

    /// What a record file says, read back; an unknown word names the field and the
    /// words it may be.
    fn try_from(word: String) -> Result<Outcome, String> {
        Outcome::from_word(&word).ok_or_else(|| {
            let words: Vec<&str> = Outcome::ALL.iter().map(|o| o.word()).collect();
            format!("outcome `{word}` is none of {}", words.join(", "))
        })
    }
}

/// A planning run: outcome, plan and what it cost.
#[derive(Debug, Clone)]
pub struct PlanRun {
    /// How it ended.
    pub outcome: Outcome,
    /// Why the run could not be made, for an [`Outcome::Error`] (and only for one).
    pub error: Option<String>,
    /// The plan's steps.
    pub plan: Vec<pddl::Step>,
    /// The plan's cost.
    pub cost: Option<u64>,
    /// Whether every operator of the task costs 1 (`unit cost` in the plan file).
    pub cost_kind: pddl::CostKind,
    /// States expanded.
    pub expansions: Option<u64>,
    /// Successor states generated.
    pub generated: Option<u64>,
    /// Translation (check, ground, invariants); for Fast Downward its translator's
    /// wall-clock time ("Done! [... wall-clock]").
    pub translate_time: Duration,
    /// Building the heuristic before the first expansion (iPDB's hill climbing,
    /// LM-cut's relaxed task); for Fast Downward its "Total time" minus its "Search
    /// time".
    pub heuristic_time: Duration,
    /// The search proper, from the first expansion: what Fast Downward prints as
    /// "Search time" and the paper's tables report.
    pub search_time: Duration,
    /// Wall time of the whole run (for Fast Downward the whole process tree, Python
    /// driver included).
    pub total_time: Duration,
    /// Peak memory of the run in KiB, where it was measured: for Fast Downward its
    /// "Peak memory" line (the search component's peak resident set); for demoplan
    /// the peak of the heap the caller's probe reports (see [`MemoryProbe`]).
    pub peak_memory_kb: Option<u64>,
}

/// How a caller that counts allocations lets runs measure and limit their heap:
/// `in_use` reads the bytes allocated now, `reset` starts a new peak at what is in use
/// now, `peak` reads it in bytes. Library crates cannot install a global allocator; the
/// executable that does hands these in.
#[derive(Debug, Clone, Copy)]
pub struct MemoryProbe {
    /// The heap in use now, in bytes (what [`task::Limits::memory_usage`] reads).
    pub in_use: fn() -> u64,
    /// Starts a new peak.
    pub reset: fn(),
    /// The peak since the last reset, in bytes.
    pub peak: fn() -> u64,
}

impl MemoryProbe {
    /// The readings of [`task::memory::CountingAllocator`], for a program that declares
    /// it as its global allocator (the command line and the Python extension do).
    pub fn counting() -> MemoryProbe {
        MemoryProbe {
            in_use: task::memory::heap_in_use,
            reset: task::memory::reset_peak,
            peak: task::memory::peak_heap,
        }
    }
}

/// The limits every planning run gets, each counted from that run's own start: a time
/// limit (translation, heuristic construction and search together) and a memory limit
/// on the heap the run itself allocates. What the process held before the run (the
/// library, the simulated study, earlier results of a grid computed in one process) is
/// not the run's: the limit is charged on top of the heap in use at its start. The
/// default has no limits and measures nothing.
#[derive(Debug, Clone, Copy, Default)]
pub struct RunLimits {
    /// Wall time per run; `None` is no limit.
    pub time: Option<Duration>,
    /// Heap bytes per run; `None` is no limit. Without a [`MemoryProbe`] each phase
    /// counts the bytes of its own main structures instead (see [`task::Limits`]).
    pub memory_bytes: Option<u64>,
    /// How the heap is read, for the memory limit and the run's peak.
    pub memory: Option<MemoryProbe>,
}

impl RunLimits {
    /// A time limit alone, nothing measured.
    pub fn time(limit: Duration) -> RunLimits {
        RunLimits {
            time: Some(limit),
            ..RunLimits::default()
        }
    }

    /// The same limits with another time limit.
    pub fn with_time(self, time: Option<Duration>) -> RunLimits {
        RunLimits { time, ..self }
    }

    /// The limits of a run that starts at `start`, as every phase checks them: the
    /// deadline `time` after `start` (none if it cannot be represented), and the memory
    /// limit on top of the heap in use now. Never overflows.
    pub fn starting_at(&self, start: Instant) -> task::Limits {
        let in_use = self.memory.map(|probe| probe.in_use);
        let baseline = in_use.map_or(0, |read| read());
        task::Limits {
            deadline: task::deadline_after(start, self.time),
            memory_limit_bytes: self.memory_bytes.map(|m| baseline.saturating_add(m)),
            memory_usage: in_use,
            cancel: None,
        }
    }
}

impl PlanRun {
    /// A run that ended with `outcome` before producing anything: no plan, no counts,
    /// zero times (callers fill in what they measured).
    pub fn ended(outcome: Outcome) -> PlanRun {
        PlanRun {
            outcome,
            error: None,
            plan: Vec::new(),
            cost: None,
            cost_kind: pddl::CostKind::General,
            expansions: None,
            generated: None,
            translate_time: Duration::ZERO,
            heuristic_time: Duration::ZERO,
            search_time: Duration::ZERO,
            total_time: Duration::ZERO,
            peak_memory_kb: None,
        }
    }

    /// A run that could not be made, and why: [`Outcome::Error`].
    pub fn failed(reason: String) -> PlanRun {
        PlanRun {
            error: Some(reason),
            ..PlanRun::ended(Outcome::Error)
        }
    }

    /// Makes this run an [`Outcome::Error`], for `reason`.
    pub fn fail(&mut self, reason: String) {
        self.outcome = Outcome::Error;
        self.error = Some(reason);
    }

    /// The plan file's text: `(action args)` lines and the cost line, `unit cost` if and
    /// only if every operator of the task costs 1 ([`pddl::write_plan`]); `None` without
    /// a plan.
    pub fn plan_text(&self) -> Option<String> {
        self.cost
            .map(|cost| pddl::write_plan(&self.plan, cost, self.cost_kind))
    }
}

/// A translated task, or a run that ended before search.
#[derive(Debug, Clone)]
pub enum Translated {
    /// The task to search, and the time translation took.
    Task(Box<task::Task>, Duration),
    /// Rejected by relaxed reachability, or an error.
    Done(PlanRun),
}

/// Checks and translates a domain and problem.
pub fn translate_checked(domain: &pddl::Domain, problem: &pddl::Problem) -> Translated {
    let options = translate::TranslateOptions::default();
    translate_checked_within(domain, problem, &options, &task::Limits::default())
}

/// Like [`translate_checked`], with the translator's `options` and stopping at the run's
/// `limits` (then the run is done with [`Outcome::TimeLimit`] or [`Outcome::MemoryLimit`]).
pub fn translate_checked_within(
    domain: &pddl::Domain,
    problem: &pddl::Problem,
    options: &translate::TranslateOptions,
    limits: &task::Limits,
) -> Translated {
    let start = Instant::now();
    let done = |mut run: PlanRun| {
        run.translate_time = start.elapsed();
        run.total_time = run.translate_time;
        Translated::Done(run)
    };
    if let Err(e) = pddl::check_problem(domain, problem) {
        return done(PlanRun::failed(format!(
            "problem does not fit the domain: {e}"
        )));
    }
    match translate::translate_with_options(domain, problem, limits, options) {
        Ok(translate::Translation::Task(t)) => Translated::Task(Box::new(t.task), start.elapsed()),
        Ok(translate::Translation::Unsolvable { .. }) => {
            done(PlanRun::ended(Outcome::RelaxedUnreachable))
        }
        Ok(translate::Translation::Stopped { limit, .. }) => {
            done(PlanRun::ended(Outcome::limit(limit)))
        }
        Err(e) => done(PlanRun::failed(e.to_string())),
    }
}

/// Searches a translated task within the run's `limits`: builds the heuristic (timed as
/// [`PlanRun::heuristic_time`]), then runs the search (timed as
/// [`PlanRun::search_time`]); `total_time` is both. A limit reached in either is the
/// run's outcome ([`Outcome::TimeLimit`], [`Outcome::MemoryLimit`]); a search that
/// cannot run is [`Outcome::Error`]. [`plan_logged`] without its log.
///
/// [`plan_logged`]: crate::plan_logged
pub fn plan_task(
    task: &task::Task,
    config: &search::SearchConfig,
    limits: &task::Limits,
) -> PlanRun {
    let input = crate::PlanInput::Task(task);
    match crate::plan_logged(input, config, limits, Instant::now(), &mut |_| {}) {
        Ok(logged) => logged.run,
        Err(e) => PlanRun::failed(e.to_string()),
    }
}
