//! Execution in the loop: the paper's Algorithm 1 ([`slim::solve`]) whose every plan is
//! executed in the cube world ([`cubeworld::execute`]) before it is given out.
//!
//! [`solve`] plans priority 1, 2, ... of a library as Algorithm 1 does. With
//! [`Execution::On`] each plan found is executed; when a step fails (its effects are not
//! in the grounded geometry, or its motion moves things through each other), the
//! operator of that step is *set aside* for this problem, reported with the step, the
//! facts it promised and what the world gave ([`SetAside`]), and the same level is
//! searched again without it. A level with no plan left widens to the next, and an
//! operator set aside stays aside at every wider level. A plan whose steps all execute
//! but whose goal the final geometry does not satisfy blames no operator: nothing is set
//! aside, and the loop widens ([`Check::GoalNotReached`]). The answer ([`Verdict`]) is a
//! plan that executes, or "no executable plan" (some plan was found, none executed) with
//! the operators set aside, or, as without execution, unsolvable or a limit reached.
//!
//! Each planning run keeps its own [`slim::RunLimits`], a replan as much as a first
//! plan; executions have no limit (they take milliseconds to a second per plan). The
//! loop ends: each replan sets aside one more operator of a finite library.
//!
//! `slim` knows nothing of the cube world; this crate is the one place the two meet for
//! `demoplan solve`, the Python `solve()` and the experiment's Algorithm 1 cells.

mod text;

use std::time::{Duration, Instant};

use learn::{DomainOptions, Library, Ranked};
use slim::{plan_level, Backend, ExitCode, LevelResult, Outcome, RunLimits};

pub use text::{attempt_lines, attempt_note, set_aside_list};

/// Whether [`solve`] executes its plans.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Execution {
    /// Execute every plan in the cube world; set aside the operator of a failing step
    /// and search again (the default of `demoplan solve`).
    On,
    /// Algorithm 1 alone, as [`slim::solve`]: the first plan is the answer
    /// (`demoplan solve --no-execute`).
    Off,
}

/// `demoplan solve --no-execute`, declared here beside what it switches off.
#[cfg_attr(feature = "clap", derive(clap::Args))]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ExecutionArgs {
    /// Do not execute plans in the cube world: the first plan found is the answer, as in
    /// the paper's Algorithm 1 (by default each plan is executed, an operator whose step
    /// fails is set aside and the level searched again).
    #[cfg_attr(feature = "clap", arg(long))]
    pub no_execute: bool,
}

impl ExecutionArgs {
    /// The [`Execution`] the options ask for.
    pub fn execution(self) -> Execution {
        if self.no_execute {
            Execution::Off
        } else {
            Execution::On
        }
    }
}

/// An operator set aside for this problem: whose step failed, where, and how.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct SetAside {
    /// The operator's display name in the library (`put2`), which is its action's name.
    pub name: String,
    /// Its stable id ([`learn::Operator::id`]).
    pub id: String,
    /// The priority of the level whose plan failed.
    pub prio: usize,
    /// The failing step's 1-based position in that plan.
    pub step: usize,
    /// The step as a plan line: `(put left_hand cube_2 cube_1)`.
    pub action: String,
    /// The effects promised that the grounded state did not give: `(inhand left_hand
    /// cube_2)`, `(not (handopen left_hand))` for a delete.
    pub promised: Vec<String>,
    /// The grounded facts over the step's objects at its end: what the world gave.
    pub found: Vec<String>,
    /// Things the step's motion moved through each other (`(cube_2 cube_3)`).
    pub collisions: Vec<String>,
    /// The whole reason, in the words of `demoplan execute` ([`cubeworld::StepReport::failure_text`]).
    pub why: String,
}

/// What execution said of an attempt's plan.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Check {
    /// Not executed: no plan, or [`Execution::Off`].
    NotRun,
    /// Every step gave its effects and the goal holds in the final geometry.
    Executed,
    /// A step failed; its operator was set aside.
    StepFailed(SetAside),
    /// Every step gave its effects, yet the final geometry misses these goal facts. No
    /// operator is to blame; the loop widens.
    GoalNotReached {
        /// The goal literals that do not hold.
        unsatisfied: Vec<String>,
    },
}

/// One planning run of the loop (a level, or a level again without what was set aside)
/// and what execution said of its plan.
#[derive(Debug, Clone)]
pub struct Attempt {
    /// The level as planned: its priority, the number of operators left in it, its
    /// domain (without the operators set aside) and the run.
    pub level: LevelResult,
    /// What execution said.
    pub check: Check,
    /// Time spent executing the plan (zero when not executed).
    pub execution_time: Duration,
}

impl Attempt {
    /// Whether this attempt's plan is the answer: solved, and executed (or not checked,
    /// without execution).
    pub fn answers(&self) -> bool {
        self.level.run.outcome == Outcome::Solved
            && matches!(self.check, Check::Executed | Check::NotRun)
    }

    /// Whether execution failed this attempt's plan (a step, or the goal).
    pub fn failed_execution(&self) -> bool {
        matches!(
            self.check,
            Check::StepFailed(_) | Check::GoalNotReached { .. }
        )
    }
}

/// The result of the loop: every attempt in order, and the times.
#[derive(Debug, Clone)]
pub struct Solved {
    /// Whether plans were executed.
    pub execution: Execution,
    /// Every planning run, in order (with [`Execution::Off`], one per level, as
    /// [`slim::Solved::levels`]).
    pub attempts: Vec<Attempt>,
    /// Wall time of the whole loop: planning, failed levels and executions included.
    pub cumulative: Duration,
    /// The part of `cumulative` spent executing plans.
    pub execution_time: Duration,
}

/// How the loop ended.
#[derive(Debug, Clone, Copy)]
pub enum Verdict<'a> {
    /// A plan: one that executes, or with [`Execution::Off`] the first found.
    Plan(&'a Attempt),
    /// Plans were found, and execution failed every one: exit
    /// [`NO_EXECUTABLE_PLAN`]. Takes precedence over limits reached at other levels.
    NoExecutablePlan,
    /// No plan was found and some level reached its time or memory limit (exit 12).
    LimitReached,
    /// No plan was found and every level is unsolvable (exit 11).
    Unsolvable,
}

/// The exit code of "no executable plan": plans were found and the cube world executed
/// none of them. Not one of Fast Downward's codes (it has none in the 40s).
pub const NO_EXECUTABLE_PLAN: ExitCode = ExitCode(45);

impl Solved {
    /// The attempt whose plan is the answer, if any (the last attempt when there is one).
    pub fn plan(&self) -> Option<&Attempt> {
        self.attempts.last().filter(|a| a.answers())
    }

    /// How the loop ended.
    pub fn verdict(&self) -> Verdict<'_> {
        if let Some(a) = self.plan() {
            Verdict::Plan(a)
        } else if self.attempts.iter().any(Attempt::failed_execution) {
            Verdict::NoExecutablePlan
        } else if self.limits_reached().is_some() {
            Verdict::LimitReached
        } else {
            Verdict::Unsolvable
        }
    }

    /// The exit code of `demoplan solve` for this result: 0 with a plan,
    /// [`NO_EXECUTABLE_PLAN`], 12 when a limit was reached, 11 when unsolvable.
    pub fn exit_code(&self) -> ExitCode {
        match self.verdict() {
            Verdict::Plan(_) => ExitCode::SUCCESS,
            Verdict::NoExecutablePlan => NO_EXECUTABLE_PLAN,
            Verdict::LimitReached => ExitCode(12),
            Verdict::Unsolvable => ExitCode::UNSOLVABLE,
        }
    }

    /// The operators set aside, in the order they were.
    pub fn set_aside(&self) -> Vec<&SetAside> {
        self.attempts
            .iter()
            .filter_map(|a| match &a.check {
                Check::StepFailed(s) => Some(s),
                _ => None,
            })
            .collect()
    }

    /// Plans that execution failed, each followed by another search (of the same level
    /// or a wider one): the replans.
    pub fn replans(&self) -> usize {
        self.attempts
            .iter()
            .filter(|a| a.failed_execution())
            .count()
    }

    /// Algorithm 1's own view: every attempt's level, in order, and the cumulative
    /// time, for what prints or records a [`slim::Solved`].
    pub fn levels(&self) -> slim::Solved {
        slim::Solved {
            levels: self.attempts.iter().map(|a| a.level.clone()).collect(),
            cumulative: self.cumulative,
        }
    }

    /// Which limit stopped some level (`its time limit`, ...), as
    /// [`slim::Solved::limits_reached`].
    pub fn limits_reached(&self) -> Option<&'static str> {
        let reached = |o: Outcome| self.attempts.iter().any(|a| a.level.run.outcome == o);
        match (reached(Outcome::TimeLimit), reached(Outcome::MemoryLimit)) {
            (true, true) => Some("its time or memory limit"),
            (false, true) => Some("its memory limit"),
            (true, false) => Some("its time limit"),
            (false, false) => None,
        }
    }
}

/// A problem or plan the cube world cannot execute at all: a scene of other objects
/// than hands, cubes and a table, or an initial state it cannot lay out (found before
/// any planning), or a plan step it cannot run. Bad input, not a failed execution.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum LoopError {
    /// The problem's scene ([`cubeworld::ExecuteError::Scene`]).
    #[error("the cube world cannot lay out this problem (use --no-execute to plan without executing): {0}")]
    Scene(String),
    /// A step of a plan found ([`cubeworld::ExecuteError::Plan`]).
    #[error("the cube world cannot execute the plan of priority {prio}: {message}")]
    Plan {
        /// The level.
        prio: usize,
        /// Why.
        message: String,
    },
}

impl LoopError {
    /// The exit code: an input error (31), as `demoplan execute`'s malformed inputs.
    pub fn exit_code(&self) -> ExitCode {
        ExitCode::INPUT_ERROR
    }
}

/// Algorithm 1 with execution in the loop (see the crate's documentation). `progress`
/// sees each attempt as it ends, its execution checked. With [`Execution::Off`] the
/// levels and plan are those of [`slim::solve`].
pub fn solve(
    library: &Library,
    options: DomainOptions,
    problem: &pddl::Problem,
    backend: &Backend,
    limits: RunLimits,
    execution: Execution,
    mut progress: impl FnMut(&Attempt),
) -> Result<Solved, LoopError> {
    let start = Instant::now();
    let mut execution_time = Duration::ZERO;
    if execution == Execution::On {
        // The scene alone, before any planning: a problem the cube world cannot lay out
        // is bad input, whatever the plans.
        let t = Instant::now();
        let empty = learn::domain("demoplan", &[]);
        match cubeworld::execute(&empty, problem, &[]) {
            Err(cubeworld::ExecuteError::Scene(e)) => return Err(LoopError::Scene(e)),
            Err(cubeworld::ExecuteError::Plan(e)) => {
                return Err(LoopError::Plan {
                    prio: 0,
                    message: e,
                })
            }
            Ok(_) => {}
        }
        execution_time += t.elapsed();
    }
    let mut attempts: Vec<Attempt> = Vec::new();
    let mut aside: Vec<String> = Vec::new();
    'levels: for level in learn::levels(library, options) {
        loop {
            let operators: Vec<Ranked<'_>> = level
                .operators
                .iter()
                .filter(|r| !aside.contains(&r.operator().id()))
                .copied()
                .collect();
            let domain = learn::domain("demoplan", &operators);
            let run = plan_level(backend, &domain, problem, &limits);
            let mut attempt = Attempt {
                level: LevelResult {
                    prio: level.prio,
                    operators: operators.len(),
                    domain,
                    run,
                },
                check: Check::NotRun,
                execution_time: Duration::ZERO,
            };
            if execution == Execution::On && attempt.level.run.outcome == Outcome::Solved {
                let t = Instant::now();
                let level = &attempt.level;
                attempt.check = check(
                    level.prio,
                    &level.domain,
                    &operators,
                    problem,
                    &level.run.plan,
                )?;
                attempt.execution_time = t.elapsed();
                execution_time += attempt.execution_time;
            }
            progress(&attempt);
            let next = match &attempt.check {
                Check::StepFailed(s) => {
                    aside.push(s.id.clone());
                    Next::Replan
                }
                Check::GoalNotReached { .. } => Next::Widen,
                Check::Executed | Check::NotRun if attempt.answers() => Next::Done,
                Check::Executed | Check::NotRun => Next::Widen,
            };
            attempts.push(attempt);
            match next {
                Next::Replan => continue,
                Next::Widen => continue 'levels,
                Next::Done => break 'levels,
            }
        }
    }
    Ok(Solved {
        execution,
        attempts,
        cumulative: start.elapsed(),
        execution_time,
    })
}

enum Next {
    Replan,
    Widen,
    Done,
}

/// Executes `plan`, found at priority `prio` on `domain` (the domain of `operators`),
/// and says what happened; a failing step's operator is found among `operators` by its
/// action's name. What [`solve`] does with each plan, for callers that run Algorithm 1
/// their own way (the experiment's cells, under one time budget).
pub fn check(
    prio: usize,
    domain: &pddl::Domain,
    operators: &[Ranked<'_>],
    problem: &pddl::Problem,
    plan: &[pddl::Step],
) -> Result<Check, LoopError> {
    let report = cubeworld::execute(domain, problem, plan).map_err(|e| LoopError::Plan {
        prio,
        message: e.to_string(),
    })?;
    let Some(i) = report.first_failure() else {
        return Ok(if report.goal.reached {
            Check::Executed
        } else {
            Check::GoalNotReached {
                unsatisfied: report.goal.unsatisfied.clone(),
            }
        });
    };
    let step = &report.steps[i];
    let operator = operators
        .iter()
        .find(|r| r.name() == step.name)
        .ok_or_else(|| LoopError::Plan {
            prio,
            message: format!("step {}: no operator is named {}", step.index, step.name),
        })?;
    Ok(Check::StepFailed(SetAside {
        name: operator.name(),
        id: operator.operator().id(),
        prio,
        step: step.index,
        action: step.action_text(),
        promised: step.promised(),
        found: step.grounded.clone(),
        collisions: step.collisions.clone(),
        why: step.failure_text().unwrap_or_default(),
    }))
}
