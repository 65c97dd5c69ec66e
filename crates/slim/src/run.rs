//! One planning run with demoplan's planner, in-process.

use std::time::{Duration, Instant};

/// How a planning run ended.
#[derive(Debug, Clone, PartialEq, Eq)]
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
    /// The run could not be made (bad input, a planner that failed); the reason.
    Error(String),
}

impl Outcome {
    /// A short word for tables: `solved`, `relaxed-unreachable`, `unsolvable`, `limit`,
    /// `memory`, `error`.
    pub fn word(&self) -> &'static str {
        match self {
            Outcome::Solved => "solved",
            Outcome::RelaxedUnreachable => "relaxed-unreachable",
            Outcome::Unsolvable => "unsolvable",
            Outcome::TimeLimit => "limit",
            Outcome::MemoryLimit => "memory",
            Outcome::Error(_) => "error",
        }
    }
}

/// A planning run: outcome, plan and what it cost.
#[derive(Debug, Clone)]
pub struct PlanRun {
    /// How it ended.
    pub outcome: Outcome,
    /// The plan: ground actions as plan lines say them without parentheses.
    pub plan: Vec<String>,
    /// The plan's cost.
    pub cost: Option<u64>,
    /// States expanded.
    pub expansions: Option<u64>,
    /// Translation (parse, ground, invariants).
    pub translate_time: Duration,
    /// Search (heuristic construction included, as Fast Downward counts it).
    pub search_time: Duration,
    /// Everything.
    pub total_time: Duration,
}

impl PlanRun {
    /// A run that ended with `outcome` before producing anything: no plan, no counts,
    /// zero times (callers fill in what they measured).
    pub fn ended(outcome: Outcome) -> PlanRun {
        PlanRun {
            outcome,
            plan: Vec::new(),
            cost: None,
            expansions: None,
            translate_time: Duration::ZERO,
            search_time: Duration::ZERO,
            total_time: Duration::ZERO,
        }
    }

    /// The plan file's text: `(action args)` lines and the cost comment.
    pub fn plan_text(&self) -> String {
        let mut s = String::new();
        for a in &self.plan {
            s.push_str(&format!("({a})\n"));
        }
        if let Some(c) = self.cost {
            s.push_str(&format!("; cost = {c} (general cost)\n"));
        }
        s
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
    let start = Instant::now();
    let done = |outcome: Outcome| {
        let mut run = PlanRun::ended(outcome);
        run.translate_time = start.elapsed();
        run.total_time = run.translate_time;
        Translated::Done(run)
    };
    if let Err(e) = pddl::check_problem(domain, problem) {
        return done(Outcome::Error(format!(
            "problem does not fit the domain: {e}"
        )));
    }
    match translate::translate(domain, problem) {
        Ok(translate::Translation::Task(t)) => Translated::Task(Box::new(t.task), start.elapsed()),
        Ok(translate::Translation::Unsolvable { .. }) => done(Outcome::RelaxedUnreachable),
        Err(e) => done(Outcome::Error(e.to_string())),
    }
}

/// Searches a translated task until `deadline`.
pub fn plan_task(
    task: &task::Task,
    config: &search::SearchConfig,
    deadline: Option<Instant>,
) -> PlanRun {
    let start = Instant::now();
    let limits = search::SearchLimits {
        deadline,
        ..search::SearchLimits::default()
    };
    let result = match search::search(task, config, &limits, None) {
        Ok(r) => r,
        Err(e) => return PlanRun::ended(Outcome::Error(e.to_string())),
    };
    let mut run = PlanRun::ended(match &result.outcome {
        search::Outcome::Solved(_) => Outcome::Solved,
        search::Outcome::Unsolvable => Outcome::Unsolvable,
        search::Outcome::TimeLimit => Outcome::TimeLimit,
        search::Outcome::MemoryLimit => Outcome::MemoryLimit,
    });
    if let search::Outcome::Solved(plan) = &result.outcome {
        run.plan = plan
            .operators
            .iter()
            .map(|op| task.operators[op.index()].name.clone())
            .collect();
        run.cost = Some(plan.cost);
    }
    run.expansions = Some(result.statistics.expanded);
    run.search_time = start.elapsed();
    run.total_time = run.search_time;
    run
}
