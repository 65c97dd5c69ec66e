//! Translation from PDDL to a finite-domain planning task.
//!
//! 1. [`model`]: names resolved to indices, predicates split into static and fluent,
//!    parameter types turned into object lists.
//! 2. [`ground`]: relaxed reachability instantiates only reachable actions; static facts,
//!    equality and costs are evaluated and compiled away.
//! 3. [`invariants`]: mutex groups by invariant synthesis.
//! 4. [`sas`]: groups become multi-valued variables, the rest binary; variables that
//!    cannot influence the goal are removed.
//!
//! A goal unreachable even in the relaxation is reported as [`Translation::Unsolvable`]
//! at once; [`Translation::log`] gives Fast Downward's size lines. The crate knows
//! nothing of search.
//!
//! ```
//! let domain = pddl::parse_domain(
//!     "(define (domain d) (:predicates (at ?x) (link ?x ?y))
//!        (:action go :parameters (?x ?y) :precondition (and (at ?x) (link ?x ?y))
//!          :effect (and (at ?y) (not (at ?x)))))",
//! )?;
//! let problem = pddl::parse_problem(
//!     "(define (problem p) (:domain d) (:objects a b c)
//!        (:init (at a) (link a b) (link b c)) (:goal (at c)))",
//! )?;
//! let translate::Translation::Task(t) = translate::translate(&domain, &problem)? else {
//!     panic!("solvable")
//! };
//! // `at` is one variable with three values; the static `link` is compiled away.
//! assert_eq!(t.task.variables.len(), 1);
//! assert_eq!(t.task.operators.len(), 2);
//! assert!(translate::Translation::Task(t).log().contains("Translator variables: 1\n"));
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

mod dominated;
mod ground;
mod h2;
mod invariants;
mod log;
mod model;
mod sas;
mod variable_order;
mod watch;

pub use dominated::remove_dominated_operators;
pub use h2::{h2_mutexes, H2Outcome, H2Stats};

/// What translation can fail on, beyond what the PDDL checker already rejects.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum TranslateError {
    /// An action's cost uses a function value that `:init` does not set.
    #[error("action `{action}` costs {term}, but :init gives {term} no value")]
    MissingFunctionValue {
        /// The ground function term.
        term: String,
        /// The action schema.
        action: String,
    },
    /// A cost function value is negative.
    #[error("{term} = {value} is a negative action cost")]
    NegativeCost {
        /// The ground function term.
        term: String,
        /// Its value.
        value: i64,
    },
    /// An action's cost does not fit in 64 bits.
    #[error("an action cost exceeds 2^64 - 1")]
    CostOverflow,
    /// A broken assumption inside the translator: a bug, reported rather than panicking.
    #[error("internal translator error: {0}")]
    Internal(String),
}

/// Sizes of each stage, for logs (Fast Downward's translator prints the like).
#[derive(Debug, Clone, Default, PartialEq, Eq)]
pub struct TranslateStats {
    /// Relaxed-reachable atoms, static ones included.
    pub reachable_atoms: usize,
    /// Reachable fluent atoms.
    pub fluent_atoms: usize,
    /// Ground actions instantiated.
    pub ground_actions: usize,
    /// Mutex groups found by invariant synthesis.
    pub mutex_groups: usize,
    /// Variables before goal-irrelevant ones were removed.
    pub variables_before_relevance: usize,
    /// Dominated operators removed ([`TranslateOptions::remove_dominated_operators`]);
    /// `None` when that was not asked for.
    pub dominated_operators_removed: Option<usize>,
    /// What h² removed and found ([`TranslateOptions::h2_mutexes`]); `None` when that
    /// was not asked for.
    pub h2: Option<H2Stats>,
    /// The options the translation ran with.
    pub options: TranslateOptions,
}

/// What the translator does beyond Fast Downward's translation; the default is exactly
/// Fast Downward's (its variables, values and operators, in its order). With the `clap`
/// feature these are the command line's options of `translate` and `plan`, declared
/// once here (the doc comments of the fields are their `--help` texts). Each option
/// keeps the optimal cost and solvability; both on run h² first.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
#[cfg_attr(feature = "clap", derive(clap::Args))]
pub struct TranslateOptions {
    /// Remove what h² proves unreachable (operators, facts) and add the mutexes it finds
    #[cfg_attr(feature = "clap", arg(long, help_heading = "Translator options"))]
    pub h2_mutexes: bool,
    /// Remove each operator another dominates: same effects, a subset of its preconditions, no
    /// higher cost
    #[cfg_attr(feature = "clap", arg(long, help_heading = "Translator options"))]
    pub remove_dominated_operators: bool,
}

impl TranslateOptions {
    /// The options in Fast Downward's log style (`Translator option h2_mutexes: true`),
    /// one line each, without newlines.
    pub fn log_lines(&self) -> [String; 2] {
        [
            format!("Translator option h2_mutexes: {}", self.h2_mutexes),
            format!(
                "Translator option remove_dominated_operators: {}",
                self.remove_dominated_operators
            ),
        ]
    }
}

/// A translated task with statistics.
#[derive(Debug, Clone)]
pub struct TranslatedTask {
    /// The finite-domain task.
    pub task: task::Task,
    /// Sizes.
    pub stats: TranslateStats,
}

/// The result of translation.
#[derive(Debug, Clone)]
pub enum Translation {
    /// A task to search.
    Task(TranslatedTask),
    /// The goal cannot be reached even when deletes are ignored.
    Unsolvable {
        /// Why, in words.
        reason: String,
        /// Sizes up to the point of the verdict.
        stats: TranslateStats,
    },
    /// Translation stopped at a limit of [`translate_within`] before it was done.
    Stopped {
        /// The limit reached.
        limit: task::Limit,
        /// Sizes of the stages completed (zero for the rest).
        stats: TranslateStats,
    },
}

/// The plan steps of a sequence of a task's operators (a plan found by search): each
/// operator's name, `action arg1 arg2` as the translator writes it (and as Fast
/// Downward's `output.sas` names operators), as a [`pddl::Step`]. The one place plans of
/// a finite-domain task become PDDL steps.
pub fn plan_steps(task: &task::Task, operators: &[task::OpId]) -> Vec<pddl::Step> {
    operators
        .iter()
        .map(|op| {
            let name = &task.operators[op.index()].name;
            pddl::Step::from_words(name).unwrap_or_else(|| pddl::Step::new(name.trim(), [""; 0]))
        })
        .collect()
}

/// Whether a task's plan files say `unit cost` or `general cost`: unit if and only if
/// every operator costs 1 (as [`task::Task::cost`] counts it).
pub fn cost_kind(task: &task::Task) -> pddl::CostKind {
    pddl::CostKind::of_costs(task.operators.iter().map(|o| task.cost(o)))
}

/// What Fast Downward's translator writes for a task it found unsolvable
/// ([`Translation::Unsolvable`]): one variable whose goal value no operator reaches.
pub fn unsolvable_task() -> task::Task {
    task::Task {
        variables: vec![task::Variable {
            name: "var0".into(),
            value_names: vec!["Atom dummy(val1)".into(), "Atom dummy(val2)".into()],
        }],
        mutexes: Vec::new(),
        initial_state: vec![0],
        goal: vec![task::Fact::new(task::VarId(0), 1)],
        operators: Vec::new(),
        use_costs: false,
    }
}

/// Translates a checked domain and problem (see [`pddl::check_problem`]).
pub fn translate(
    domain: &pddl::Domain,
    problem: &pddl::Problem,
) -> Result<Translation, TranslateError> {
    translate_within(domain, problem, &task::Limits::default())
}

/// Like [`translate`], under the run's `limits` (`--overall-time-limit`,
/// `--overall-memory-limit`): grounding checks them per binding, atom and action,
/// invariant synthesis per candidate and per atom it groups, and every stage at its end
/// (see `watch.rs`); once one is reached translation returns
/// [`Translation::Stopped`] within a few microseconds. Memory is read through
/// `limits.memory_usage` only: without that probe only the deadline is checked.
pub fn translate_within(
    domain: &pddl::Domain,
    problem: &pddl::Problem,
    limits: &task::Limits,
) -> Result<Translation, TranslateError> {
    translate_with_options(domain, problem, limits, &TranslateOptions::default())
}

/// Like [`translate_within`], with `options` beyond Fast Downward's translation, applied
/// to the finished task under the same limits (h² first, then dominated operators).
pub fn translate_with_options(
    domain: &pddl::Domain,
    problem: &pddl::Problem,
    limits: &task::Limits,
    options: &TranslateOptions,
) -> Result<Translation, TranslateError> {
    let mut translation = translate_stages(domain, problem, limits, options)?;
    let (Translation::Task(TranslatedTask { stats, .. })
    | Translation::Unsolvable { stats, .. }
    | Translation::Stopped { stats, .. }) = &mut translation;
    stats.options = *options;
    Ok(translation)
}

fn translate_stages(
    domain: &pddl::Domain,
    problem: &pddl::Problem,
    limits: &task::Limits,
    options: &TranslateOptions,
) -> Result<Translation, TranslateError> {
    let watch = watch::Watch::new(limits);
    let stopped = |stats: TranslateStats| {
        let limit = watch.stopped().unwrap_or(task::Limit::Time);
        Ok(Translation::Stopped { limit, stats })
    };
    let model = model::Model::build(domain, problem)?;
    if watch.check() {
        return stopped(TranslateStats::default());
    }
    let Some(grounding) = ground::ground(&model, &watch)? else {
        return stopped(TranslateStats::default());
    };
    let mut stats = TranslateStats {
        reachable_atoms: grounding.atoms.len(),
        fluent_atoms: grounding.fluent.iter().filter(|&&f| f).count(),
        ground_actions: grounding.actions.len(),
        ..TranslateStats::default()
    };
    if let Some(reason) = grounding.unsolvable.clone() {
        return Ok(Translation::Unsolvable { reason, stats });
    }
    let mut grounding = grounding;
    let Some(groups) = invariants::mutex_groups(&model, &grounding, &watch) else {
        return stopped(stats);
    };
    let reachable = grounding.prune_with_mutexes(&groups);
    if watch.check() {
        return stopped(stats);
    }
    if !reachable {
        let reason = "the goal is not reachable by actions whose preconditions are not mutex";
        return Ok(Translation::Unsolvable {
            reason: reason.into(),
            stats,
        });
    }
    // Groups over the atoms that stayed reachable.
    let groups: Vec<Vec<ground::AtomId>> = groups
        .into_iter()
        .map(|g| {
            g.into_iter()
                .filter(|&a| grounding.fluent[a as usize])
                .collect::<Vec<_>>()
        })
        .filter(|g| g.len() >= 2)
        .collect();
    stats.mutex_groups = groups.len();
    stats.ground_actions = grounding.actions.len();
    let result = match sas::build(&model, &grounding, &groups)? {
        sas::Built::Task(result) => result,
        sas::Built::Unsolvable(reason) => return Ok(Translation::Unsolvable { reason, stats }),
    };
    if watch.check() {
        return stopped(stats);
    }
    stats.variables_before_relevance = result.variables_before_relevance;
    let mut task = result.task;
    if options.h2_mutexes {
        match h2::run(&mut task, &watch) {
            H2Outcome::Pruned(h2) => stats.h2 = Some(h2),
            H2Outcome::Unsolvable(reason) => return Ok(Translation::Unsolvable { reason, stats }),
            H2Outcome::Stopped(_) => return stopped(stats),
        }
    }
    if options.remove_dominated_operators {
        let removed = remove_dominated_operators(&mut task, &mut || watch.check());
        stats.dominated_operators_removed = Some(removed);
        if watch.check() {
            return stopped(stats);
        }
    }
    task.validate()
        .map_err(|e| TranslateError::Internal(e.to_string()))?;
    Ok(Translation::Task(TranslatedTask { task, stats }))
}

#[cfg(test)]
mod unsolvable_task_tests {
    #[test]
    fn the_unsolvable_task_is_valid_and_its_goal_is_out_of_reach() {
        let task = super::unsolvable_task();
        assert!(task.validate().is_ok());
        assert!(task.operators.is_empty());
        assert!(task
            .goal
            .iter()
            .any(|g| task.initial_state[g.var.index()] != g.value));
    }
}
