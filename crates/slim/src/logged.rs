//! One planning run that speaks Fast Downward's protocol: the run `demoplan plan` makes
//! and the Python package's in-process `plan` will make.
//!
//! [`plan_logged`] translates (or takes a finite-domain task as read from `output.sas`),
//! builds the heuristic and searches, all under one [`task::Limits`], and hands every log
//! line Fast Downward would print (translator sizes, `Search: ...`, the f-layers, the
//! plan's operators, the outcome) to the caller's `log`, in Fast Downward's order. The
//! caller prints them; this module does no I/O. [`LoggedRun::closing_statistics`] is the
//! block Fast Downward ends with, and [`LoggedRun::statistics_record`] the same numbers
//! as `--stats-json` writes them.

use std::time::{Duration, Instant};

use crate::run::{Outcome, PlanRun};

/// What a run plans on.
#[derive(Debug)]
pub enum PlanInput<'a> {
    /// A parsed and checked PDDL domain and problem, translated by the run.
    Pddl {
        /// The domain.
        domain: &'a pddl::Domain,
        /// The problem.
        problem: &'a pddl::Problem,
        /// The translator's options beyond Fast Downward's translation.
        options: translate::TranslateOptions,
    },
    /// A finite-domain task (Fast Downward's `output.sas`, or one translated before),
    /// searched as it is.
    Task(&'a task::Task),
}

/// Why a run could not be made (as opposed to how it ended, its [`Outcome`]).
#[derive(Debug, thiserror::Error)]
pub enum RunError {
    /// The PDDL task cannot be translated.
    #[error(transparent)]
    Translate(#[from] translate::TranslateError),
    /// The heuristic cannot be built for this task, or the search cannot run on it.
    #[error(transparent)]
    Search(#[from] search::SearchError),
}

/// A finished run: the [`PlanRun`] every planning run gives, and what Fast Downward's
/// closing statistics add to it.
#[derive(Debug, Clone)]
pub struct LoggedRun {
    /// Outcome, plan, cost and times.
    pub run: PlanRun,
    /// The search's counters; `None` where the run ended before a search.
    pub statistics: Option<search::Statistics>,
    /// The searched task's sizes; `None` where the run ended before a search.
    pub sizes: Option<task::TaskSizes>,
    /// The translation's statistics (its options among them); `None` for a task given
    /// as it is.
    pub translator: Option<translate::TranslateStats>,
    /// What saturated cost partitioning built (and, online, added during the search);
    /// `None` for other heuristics and for runs that ended before a search.
    pub scp: Option<search::ScpStatistics>,
}

/// Plans `input` with `config` under `limits`, every time measured from `start` (the
/// start of the process for the command line, so that the one deadline covers
/// translation, heuristic construction and search). `log` receives each line Fast
/// Downward would print, without its newline.
pub fn plan_logged(
    input: PlanInput<'_>,
    config: &search::SearchConfig,
    limits: &task::Limits,
    start: Instant,
    log: &mut dyn FnMut(&str),
) -> Result<LoggedRun, RunError> {
    let mut translator = None;
    let mut logged = plan_logged_with(input, config, limits, start, log, &mut translator)?;
    logged.translator = translator;
    Ok(logged)
}

/// [`plan_logged`], leaving the translation's statistics in `translator`.
fn plan_logged_with(
    input: PlanInput<'_>,
    config: &search::SearchConfig,
    limits: &task::Limits,
    start: Instant,
    log: &mut dyn FnMut(&str),
    translator: &mut Option<translate::TranslateStats>,
) -> Result<LoggedRun, RunError> {
    let translated;
    let task = match input {
        PlanInput::Task(task) => task,
        PlanInput::Pddl {
            domain,
            problem,
            options,
        } => {
            let translation = translate::translate_with_options(domain, problem, limits, &options)?;
            for line in translation.log().lines() {
                log(line);
            }
            *translator = Some(match &translation {
                translate::Translation::Task(t) => t.stats.clone(),
                translate::Translation::Unsolvable { stats, .. }
                | translate::Translation::Stopped { stats, .. } => stats.clone(),
            });
            log(&format!(
                "Translation done! [{:.3}s wall-clock]",
                start.elapsed().as_secs_f64()
            ));
            match translation {
                translate::Translation::Task(t) => {
                    translated = t.task;
                    &translated
                }
                translate::Translation::Unsolvable { .. } => {
                    log("Search stopped without finding a solution.");
                    return Ok(ended_before_search(
                        Outcome::RelaxedUnreachable,
                        start.elapsed(),
                        start,
                    ));
                }
                translate::Translation::Stopped { limit, .. } => {
                    return Ok(stopped_before_search(limit, start.elapsed(), start, log));
                }
            }
        }
    };
    let translate_time = start.elapsed();

    log(&format!("Search: {config}"));
    // The heuristic first, so that what building it did (the hill climbing of ipdb())
    // is reported before the search, as Fast Downward does.
    let mut heuristic = match config.heuristic.build_with_limits(task, limits)? {
        search::Built::Heuristic(h) => h,
        search::Built::Stopped(limit) => {
            return Ok(stopped_before_search(limit, translate_time, start, log))
        }
    };
    if let Some(lines) = heuristic.construction_log() {
        log(&lines);
    }
    let heuristic_time = start.elapsed();
    let mut pruning = config.pruning.build(task);
    if pruning.is_some() {
        for line in config.pruning.setup_lines() {
            log(line);
        }
    }
    let mut observer = |p: search::Progress| {
        log(&format!(
            "f = {}, {} evaluated, {} expanded [t={:.3}s]",
            p.f,
            p.evaluated,
            p.expanded,
            start.elapsed().as_secs_f64()
        ));
    };
    let result = match config.engine {
        search::Engine::AStar => search::astar_with_pruning(
            task,
            &mut heuristic,
            pruning.as_mut(),
            limits,
            Some(&mut observer),
        ),
    }?;
    let statistics = result.statistics;
    // Fast Downward prints limited pruning's check when it makes it, during the
    // search; the search reports it at its end, so it comes before the outcome here.
    if let Some(check) = statistics.pruning.and_then(|p| p.check) {
        for line in check.log_lines() {
            log(&line);
        }
    }
    if let Some(h) = statistics.initial_h {
        log(&format!("Initial heuristic value: {h}"));
    }
    let mut run = PlanRun::ended(match &result.outcome {
        search::Outcome::Solved(_) => Outcome::Solved,
        search::Outcome::Unsolvable => Outcome::Unsolvable,
        search::Outcome::TimeLimit => Outcome::TimeLimit,
        search::Outcome::MemoryLimit => Outcome::MemoryLimit,
        search::Outcome::Cancelled => Outcome::Cancelled,
    });
    log(outcome_line(&run.outcome));
    if let search::Outcome::Solved(plan) = &result.outcome {
        for op in &plan.operators {
            let o = &task.operators[op.index()];
            log(&format!("{} ({})", o.name, task.cost(o)));
        }
        run.plan = translate::plan_steps(task, &plan.operators);
        run.cost = Some(plan.cost);
        run.cost_kind = translate::cost_kind(task);
    }
    run.expansions = Some(statistics.expanded);
    run.generated = Some(statistics.generated);
    run.translate_time = translate_time;
    run.heuristic_time = heuristic_time.saturating_sub(translate_time);
    run.search_time = statistics.search_time;
    run.total_time = start.elapsed();
    Ok(LoggedRun {
        run,
        statistics: Some(statistics),
        sizes: Some(task.sizes()),
        translator: None,
        scp: heuristic.scp_statistics().cloned(),
    })
}

/// The line Fast Downward prints when its search ends this way.
fn outcome_line(outcome: &Outcome) -> &'static str {
    match outcome {
        Outcome::Solved => "Solution found!",
        Outcome::Unsolvable => "Completely explored state space -- no solution!",
        Outcome::TimeLimit => "Time limit reached. Abort search.",
        Outcome::MemoryLimit => "Memory limit has been reached.",
        Outcome::RelaxedUnreachable => "Search stopped without finding a solution.",
        Outcome::Cancelled => "Search cancelled.",
        Outcome::Error => "Search stopped with an error.",
    }
}

/// A run that ended before its search: translation took `translate_time` (all of the
/// run when it ended there), heuristic construction the rest.
fn ended_before_search(outcome: Outcome, translate_time: Duration, start: Instant) -> LoggedRun {
    let mut run = PlanRun::ended(outcome);
    run.total_time = start.elapsed();
    run.translate_time = translate_time;
    run.heuristic_time = run.total_time.saturating_sub(translate_time);
    LoggedRun {
        run,
        statistics: None,
        sizes: None,
        translator: None,
        scp: None,
    }
}

/// A run stopped at `limit` before its search began (in translation, or building a
/// pattern database that does not fit): Fast Downward's line for that limit.
fn stopped_before_search(
    limit: task::Limit,
    translate_time: Duration,
    start: Instant,
    log: &mut dyn FnMut(&str),
) -> LoggedRun {
    let outcome = Outcome::limit(limit);
    log(outcome_line(&outcome));
    ended_before_search(outcome, translate_time, start)
}

impl LoggedRun {
    /// Fast Downward's closing block: the search's counters (where it searched), total
    /// time, peak memory (where the caller measured it), and `Solution found.` after a
    /// plan. One line each, every line ending in a newline.
    pub fn closing_statistics(&self, peak_memory_kb: Option<u64>) -> String {
        let mut out = String::new();
        let mut line = |text: String| {
            out.push_str(&text);
            out.push('\n');
        };
        if let Some(s) = &self.statistics {
            line(format!("Expanded {} state(s).", s.expanded));
            line(format!("Reopened {} state(s).", s.reopened));
            line(format!("Evaluated {} state(s).", s.evaluated));
            line(format!("Generated {} state(s).", s.generated));
            line(format!("Dead ends: {} state(s).", s.dead_ends));
            line(format!(
                "Expanded until last jump: {} state(s).",
                s.expanded_until_last_jump
            ));
            line(format!(
                "Evaluated until last jump: {} state(s).",
                s.evaluated_until_last_jump
            ));
            line(format!(
                "Generated until last jump: {} state(s).",
                s.generated_until_last_jump
            ));
            line(format!(
                "Number of registered states: {}",
                s.registered_states
            ));
            if let Some(p) = &s.pruning {
                line(format!(
                    "total successors before pruning: {}",
                    p.successors_before
                ));
                line(format!(
                    "total successors after pruning: {}",
                    p.successors_after
                ));
                line(format!("Pruning ratio: {:.6}", p.ratio()));
            }
            line(format!("Search time: {:.6}s", s.search_time.as_secs_f64()));
        }
        line(format!(
            "Total time: {:.6}s",
            self.run.total_time.as_secs_f64()
        ));
        if let Some(kb) = peak_memory_kb {
            line(format!("Peak memory: {kb} KB"));
        }
        if self.run.outcome == Outcome::Solved {
            line("Solution found.".to_string());
        }
        out
    }

    /// The run's numbers as `demoplan plan --stats-json` writes them.
    pub fn statistics_record(&self, peak_memory_kb: Option<u64>) -> StatisticsRecord {
        let s = self.statistics.as_ref();
        let seconds = |d: Duration| d.as_secs_f64();
        StatisticsRecord {
            dead_ends: s.map(|s| s.dead_ends),
            evaluated: s.map(|s| s.evaluated),
            expanded: s.map(|s| s.expanded),
            expanded_until_last_jump: s.map(|s| s.expanded_until_last_jump),
            facts: self.sizes.map(|z| z.facts),
            generated: s.map(|s| s.generated),
            initial_h: s.and_then(|s| s.initial_h),
            operators: self.sizes.map(|z| z.operators),
            outcome: match self.run.outcome {
                Outcome::Solved => "solved",
                Outcome::RelaxedUnreachable | Outcome::Unsolvable => "unsolvable",
                Outcome::TimeLimit => "out_of_time",
                Outcome::MemoryLimit => "out_of_memory",
                Outcome::Cancelled => "cancelled",
                Outcome::Error => "error",
            },
            peak_memory_kb,
            plan_cost: self.run.cost,
            pruning: s.and_then(|s| s.pruning).map(PruningRecord::from),
            plan_length: self.run.cost.map(|_| self.run.plan.len()),
            registered_states: s.map(|s| s.registered_states),
            reopened: s.map(|s| s.reopened),
            scp: self.scp.as_ref().map(ScpRecord::from),
            search_time_s: s.map(|s| seconds(s.search_time)),
            total_time_s: seconds(self.run.total_time),
            translate_time_s: seconds(self.run.translate_time),
            translator: self.translator.as_ref().map(TranslatorRecord::from),
            variables: self.sizes.map(|z| z.variables),
        }
    }
}

/// A run's numbers for a machine: `null` where the run ended before producing one.
/// The fields are declared in alphabetical order, the order the file has always had.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct StatisticsRecord {
    /// Dead ends the search met.
    pub dead_ends: Option<u64>,
    /// States evaluated.
    pub evaluated: Option<u64>,
    /// States expanded.
    pub expanded: Option<u64>,
    /// States expanded before the last f-layer.
    pub expanded_until_last_jump: Option<u64>,
    /// Facts of the searched task.
    pub facts: Option<usize>,
    /// Successors generated.
    pub generated: Option<u64>,
    /// The heuristic value of the initial state.
    pub initial_h: Option<u64>,
    /// Operators of the searched task.
    pub operators: Option<usize>,
    /// `solved`, `unsolvable`, `out_of_time` or `out_of_memory`.
    pub outcome: &'static str,
    /// Peak memory in KiB, where measured.
    pub peak_memory_kb: Option<u64>,
    /// The plan's cost.
    pub plan_cost: Option<u64>,
    /// The plan's steps.
    pub plan_length: Option<usize>,
    /// What partial-order reduction did; `null` without `pruning=`.
    pub pruning: Option<PruningRecord>,
    /// States registered.
    pub registered_states: Option<u64>,
    /// States reopened.
    pub reopened: Option<u64>,
    /// What saturated cost partitioning built; `null` for other heuristics.
    pub scp: Option<ScpRecord>,
    /// The search's time in seconds.
    pub search_time_s: Option<f64>,
    /// The whole run in seconds.
    pub total_time_s: f64,
    /// Translation (or reading the task) in seconds.
    pub translate_time_s: f64,
    /// The translator's options and what they removed; `null` for a task given as it is.
    pub translator: Option<TranslatorRecord>,
    /// Variables of the searched task.
    pub variables: Option<usize>,
}

/// What `scp()` and `scp_online()` built, in `--stats-json`: the counts their log lines
/// (`Number of abstractions`, `Orders computed`, `Orders stored`, ...) give; for
/// `scp_online` the orders include those the search added.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct ScpRecord {
    /// Abstract states over all projections.
    pub abstract_states: u64,
    /// Abstract transitions over all projections.
    pub abstract_transitions: u64,
    /// Projections, after deduplication (`Number of abstractions`).
    pub abstractions: usize,
    /// Seconds to generate the patterns and build the projections.
    pub abstractions_time_s: f64,
    /// Seconds to build the whole heuristic.
    pub construction_time_s: f64,
    /// Orders kept (`Orders stored`).
    pub orders: usize,
    /// Orders computed, kept or not.
    pub orders_computed: u64,
    /// Patterns `sys_scp` kept.
    pub sys_scp_patterns: usize,
}

impl From<&search::ScpStatistics> for ScpRecord {
    fn from(s: &search::ScpStatistics) -> ScpRecord {
        ScpRecord {
            abstract_states: s.total_size,
            abstract_transitions: s.total_transitions,
            abstractions: s.projections,
            abstractions_time_s: s.abstraction_time.as_secs_f64(),
            construction_time_s: s.total_time.as_secs_f64(),
            orders: s.orders,
            orders_computed: s.orders_computed,
            sys_scp_patterns: s.sys_scp_patterns,
        }
    }
}

/// The translator's options (`--h2-mutexes`, `--remove-dominated-operators`) and what
/// they removed, in `--stats-json`; the counts are `null` where the option was off.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct TranslatorRecord {
    /// Operators `--remove-dominated-operators` removed.
    pub dominated_operators_removed: Option<usize>,
    /// Unreachable facts h² removed.
    pub h2_facts_removed: Option<usize>,
    /// Whether h² ran (`--h2-mutexes`).
    pub h2_mutexes: bool,
    /// Mutex pairs h² added.
    pub h2_mutexes_added: Option<usize>,
    /// Operators h² removed.
    pub h2_operators_removed: Option<usize>,
    /// Constant variables h² removed.
    pub h2_variables_removed: Option<usize>,
    /// Whether dominated operators were removed (`--remove-dominated-operators`).
    pub remove_dominated_operators: bool,
}

impl From<&translate::TranslateStats> for TranslatorRecord {
    fn from(s: &translate::TranslateStats) -> TranslatorRecord {
        let options = s.options;
        TranslatorRecord {
            dominated_operators_removed: s.dominated_operators_removed,
            h2_facts_removed: s.h2.map(|h| h.facts_removed),
            h2_mutexes: options.h2_mutexes,
            h2_mutexes_added: s.h2.map(|h| h.mutexes_added),
            h2_operators_removed: s.h2.map(|h| h.operators_removed),
            h2_variables_removed: s.h2.map(|h| h.variables_removed),
            remove_dominated_operators: options.remove_dominated_operators,
        }
    }
}

/// Partial-order reduction's numbers in `--stats-json`: the closing lines' counts and
/// ratio, and limited pruning's check.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct PruningRecord {
    /// Applicable operators of the pruned states ("total successors before pruning").
    pub successors_before: u64,
    /// Operators left ("total successors after pruning").
    pub successors_after: u64,
    /// "Pruning ratio": the share pruned.
    pub ratio: f64,
    /// Calls before limited pruning checked its ratio; `null` where it did not.
    pub checked_after_calls: Option<u64>,
    /// The ratio at that check.
    pub ratio_at_check: Option<f64>,
    /// Whether the check switched pruning off.
    pub switched_off: bool,
}

impl From<search::PruningStatistics> for PruningRecord {
    fn from(p: search::PruningStatistics) -> PruningRecord {
        PruningRecord {
            successors_before: p.successors_before,
            successors_after: p.successors_after,
            ratio: p.ratio(),
            checked_after_calls: p.check.map(|c| c.calls),
            ratio_at_check: p.check.map(|c| c.ratio()),
            switched_off: p.check.is_some_and(|c| c.switched_off),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const DOMAIN: &str = "(define (domain switch) (:requirements :strips)
        (:predicates (on) (off))
        (:action flip :parameters () :precondition (off) :effect (and (on) (not (off)))))";

    const SWITCH_ON: &str = "(define (problem p) (:domain switch) (:init (off)) (:goal (on)))";

    fn run_within(
        problem: &str,
        limits: &task::Limits,
        start: Instant,
    ) -> (Result<LoggedRun, RunError>, Vec<String>) {
        let domain = pddl::parse_domain(DOMAIN).unwrap();
        let problem = pddl::parse_problem(problem).unwrap();
        let config = search::parse_search("astar(blind())").unwrap();
        let mut lines = Vec::new();
        let input = PlanInput::Pddl {
            domain: &domain,
            problem: &problem,
            options: translate::TranslateOptions::default(),
        };
        let result = plan_logged(input, &config, limits, start, &mut |l| {
            lines.push(l.to_string())
        });
        (result, lines)
    }

    fn run(problem: &str) -> (Result<LoggedRun, RunError>, Vec<String>) {
        run_within(problem, &task::Limits::default(), Instant::now())
    }

    #[test]
    fn a_solved_run_logs_fast_downwards_lines_in_order_and_gives_a_unit_cost_plan() {
        let (result, lines) = run(SWITCH_ON);
        let logged = result.unwrap();
        let position = |prefix: &str| {
            lines
                .iter()
                .position(|l| l.starts_with(prefix))
                .unwrap_or_else(|| panic!("no line {prefix} in {lines:?}"))
        };
        assert!(position("Translation done!") < position("Search: astar(blind())"));
        assert!(position("Search:") < position("Solution found!"));
        assert!(position("Solution found!") < position("flip (1)"));
        assert_eq!(logged.run.outcome, Outcome::Solved);
        assert_eq!(
            logged.run.plan_text().unwrap(),
            "(flip)\n; cost = 1 (unit cost)\n"
        );
        let closing = logged.closing_statistics(Some(7));
        let expanded = logged.statistics.map(|s| s.expanded).unwrap();
        assert!(
            closing.starts_with(&format!("Expanded {expanded} state(s).\n")),
            "{closing}"
        );
        assert!(
            closing.ends_with("Peak memory: 7 KB\nSolution found.\n"),
            "{closing}"
        );
        let record = logged.statistics_record(None);
        assert_eq!(
            (record.outcome, record.plan_cost, record.plan_length),
            ("solved", Some(1), Some(1))
        );
        assert_eq!(record.operators, Some(1));
    }

    #[test]
    fn a_goal_the_relaxation_cannot_reach_ends_before_search() {
        let (result, lines) =
            run("(define (problem p) (:domain switch) (:init (on)) (:goal (off)))");
        let logged = result.unwrap();
        assert_eq!(logged.run.outcome, Outcome::RelaxedUnreachable);
        assert_eq!(
            lines.last().map(String::as_str),
            Some("Search stopped without finding a solution.")
        );
        assert!(!lines.iter().any(|l| l.starts_with("Search:")));
        assert!(logged.statistics.is_none());
        let closing = logged.closing_statistics(None);
        assert!(closing.starts_with("Total time: "), "{closing}");
        assert_eq!(logged.statistics_record(None).outcome, "unsolvable");
    }

    #[test]
    fn a_deadline_already_passed_stops_the_run_at_its_time_limit() {
        let start = Instant::now();
        let limits = task::Limits {
            deadline: Some(start),
            ..task::Limits::default()
        };
        let (result, lines) = run_within(SWITCH_ON, &limits, start);
        let logged = result.unwrap();
        assert_eq!(logged.run.outcome, Outcome::TimeLimit);
        assert!(lines
            .iter()
            .any(|l| l == "Time limit reached. Abort search."));
        assert_eq!(logged.statistics_record(None).outcome, "out_of_time");
    }
}
