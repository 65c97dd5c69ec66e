//! Executing a plan on the initial state: the validator proper.

use std::collections::{BTreeMap, BTreeSet, HashMap};
use std::fmt;

use pddl::{Atom, CostExpr, Domain, Effect, FunctionTerm, InitEntry, Literal, Problem, Term, Type};

use crate::world::World;
use pddl::{Plan, Step};

/// A ground atom, `(on a b)`; also a ground function term, `(road-length a b)`.
#[derive(Debug, Clone, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct GroundAtom {
    /// The predicate (or function) name; `=` for equality.
    pub predicate: String,
    /// The objects.
    pub args: Vec<String>,
}

impl GroundAtom {
    /// A ground atom from names.
    pub fn new(
        predicate: impl Into<String>,
        args: impl IntoIterator<Item = impl Into<String>>,
    ) -> GroundAtom {
        GroundAtom {
            predicate: predicate.into(),
            args: args.into_iter().map(Into::into).collect(),
        }
    }
}

/// `(on a b)`.
impl fmt::Display for GroundAtom {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "({}", self.predicate)?;
        for a in &self.args {
            write!(f, " {a}")?;
        }
        f.write_str(")")
    }
}

/// A ground atom or its negation, as a precondition or goal demands it.
#[derive(Debug, Clone, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct GroundLiteral {
    /// False for `(not atom)`.
    pub positive: bool,
    /// The atom.
    pub atom: GroundAtom,
}

/// `(on a b)` or `(not (on a b))`.
impl fmt::Display for GroundLiteral {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if self.positive {
            write!(f, "{}", self.atom)
        } else {
            write!(f, "(not {})", self.atom)
        }
    }
}

/// What the final value of a plan counts.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum CostModel {
    /// The problem has `(:metric minimize (total-cost))` and the domain has action costs:
    /// the value is `total-cost` (its initial value, 0 if `:init` sets none, plus every
    /// step's increase; a step without an increase costs 0).
    ActionCosts,
    /// No metric, or a domain without action costs: every step costs 1, and the value
    /// is the plan length (as VAL reports it).
    PlanLength,
}

/// Why a step of a plan cannot be executed.
#[derive(Debug, Clone, PartialEq, Eq, Hash)]
pub enum Reason {
    /// The domain has no action of that name.
    UnknownAction,
    /// The action takes a different number of parameters.
    WrongArgumentCount {
        /// The number of parameters.
        expected: usize,
        /// The number of arguments in the plan.
        found: usize,
    },
    /// An argument is neither an object of the problem nor a constant of the domain.
    UnknownObject {
        /// The argument.
        object: String,
    },
    /// An argument is not of its parameter's type.
    WrongType {
        /// The argument.
        object: String,
        /// The parameter, with its `?`.
        parameter: String,
        /// The parameter's type: `block` or `(either a b)`.
        expected: String,
        /// The object's declared types (`object` when untyped).
        declared: Vec<String>,
    },
    /// Some precondition literals are false in the state the step is applied in.
    UnsatisfiedPrecondition {
        /// The false literals, ground, in the order the action lists them.
        unsatisfied: Vec<GroundLiteral>,
    },
}

impl fmt::Display for Reason {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Reason::UnknownAction => f.write_str("the domain has no action of this name"),
            Reason::WrongArgumentCount { expected, found } => write!(
                f,
                "the action takes {expected} argument{}, the plan gives {found}",
                if *expected == 1 { "" } else { "s" }
            ),
            Reason::UnknownObject { object } => write!(
                f,
                "`{object}` is neither an object of the problem nor a constant of the domain"
            ),
            Reason::WrongType {
                object,
                parameter,
                expected,
                declared,
            } => write!(
                f,
                "`{object}` (of type {}) is not of type {expected}, as parameter {parameter} \
                 requires",
                declared.join(", ")
            ),
            Reason::UnsatisfiedPrecondition { unsatisfied } => {
                f.write_str("unsatisfied precondition: ")?;
                join(f, unsatisfied)
            }
        }
    }
}

fn join(f: &mut fmt::Formatter<'_>, items: &[GroundLiteral]) -> fmt::Result {
    for (i, l) in items.iter().enumerate() {
        if i > 0 {
            f.write_str(", ")?;
        }
        write!(f, "{l}")?;
    }
    Ok(())
}

/// The step of a plan that could not be executed, and why.
#[derive(Debug, Clone, PartialEq, Eq, Hash)]
pub struct StepFailure {
    /// The 1-based position of the step in the plan (VAL's "time").
    pub step: usize,
    /// The step as `(name arg1 arg2)`.
    pub action: String,
    /// The line of the plan text it came from (0 for a plan built in code).
    pub line: usize,
    /// Why it failed.
    pub reason: Reason,
}

impl fmt::Display for StepFailure {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "step {} {}: {}", self.step, self.action, self.reason)
    }
}

/// Whether a plan is valid, and if not, where it went wrong.
#[derive(Debug, Clone, PartialEq, Eq, Hash)]
pub enum Verdict {
    /// Every step was applicable and the goal holds at the end.
    Valid,
    /// A step could not be executed; the steps after it were not looked at.
    StepFailed(StepFailure),
    /// Every step was executed, but the goal does not hold at the end.
    GoalNotSatisfied {
        /// The false goal literals, in the order the goal lists them.
        unsatisfied: Vec<GroundLiteral>,
    },
}

/// The result of validating a plan.
#[derive(Debug, Clone, PartialEq, Eq, Hash)]
pub struct Report {
    /// Valid, or what made it invalid.
    pub verdict: Verdict,
    /// The plan's value (see [`CostModel`]) after the last step executed: for a failed
    /// step, the value of the steps before it.
    pub value: i64,
    /// What the value counts.
    pub cost_model: CostModel,
    /// How many steps were executed.
    pub steps_executed: usize,
}

impl Report {
    /// True for a valid plan.
    pub fn is_valid(&self) -> bool {
        self.verdict == Verdict::Valid
    }
}

/// A defect of the domain or problem that stops the validation: the plan cannot be
/// judged on them. (A plan's own mistakes are a [`Verdict`], not an error.)
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum ValidateError {
    /// A step's cost is a function term that `:init` gives no value.
    #[error("step {step} {action}: the problem's :init gives no value for the cost {term}")]
    MissingFunctionValue {
        /// The 1-based step.
        step: usize,
        /// The step as `(name arg1 arg2)`.
        action: String,
        /// The ground function term.
        term: GroundAtom,
    },
    /// A variable that is not a parameter of its action, or a variable in the goal.
    #[error("{place}: variable `{variable}` is not bound (not a parameter of the action)")]
    UnboundVariable {
        /// The action, or `goal`.
        place: String,
        /// The variable, with its `?`.
        variable: String,
    },
    /// The value left the 64-bit range.
    #[error("step {step} {action}: the plan's value overflows 64 bits")]
    CostOverflow {
        /// The 1-based step.
        step: usize,
        /// The step as `(name arg1 arg2)`.
        action: String,
    },
}

/// Validates `plan` on `domain` and `problem`, which should have passed
/// [`pddl::check_problem`].
///
/// Starts in the initial state under the closed-world assumption (every atom `:init` does
/// not list is false) and, for each step in order, checks that the action exists, that it
/// gets one object per parameter, that every object is declared (problem objects and
/// domain constants) and of the parameter's type, and that every precondition literal
/// holds (equality compares names). It then applies the effects with PDDL's semantics:
/// delete effects first, then add effects, so an atom both deleted and added ends true.
/// At the end it checks the goal. The first failing step ends the execution.
///
/// The value follows [`CostModel`]: `total-cost` when the problem has a metric and the
/// domain has action costs (constant costs, or static function values from `:init`; a
/// value missing for a term a step uses is a [`ValidateError`]), the plan length
/// otherwise.
///
/// Uses no translator or search code: it reads the syntax tree directly, so that it is an
/// independent check of the planner. Time: `O(steps * (preconditions + effects) * log
/// |state|)`.
pub fn validate(domain: &Domain, problem: &Problem, plan: &Plan) -> Result<Report, ValidateError> {
    let world = World::new(domain, problem);
    let cost_model = cost_model(domain, problem);
    let mut state: BTreeSet<GroundAtom> = BTreeSet::new();
    let mut functions: BTreeMap<GroundAtom, i64> = BTreeMap::new();
    for entry in &problem.init {
        let none = HashMap::new();
        match entry {
            InitEntry::Fact(atom) => {
                state.insert(ground_atom(atom, &none, "init")?);
            }
            // A later value of the same term replaces an earlier one.
            InitEntry::FunctionValue { term, value } => {
                functions.insert(ground_function(term, &none, "init")?, value.value);
            }
        }
    }
    let mut value = match cost_model {
        CostModel::ActionCosts => functions
            .get(&GroundAtom::new("total-cost", Vec::<String>::new()))
            .copied()
            .unwrap_or(0),
        CostModel::PlanLength => 0,
    };
    for (index, step) in plan.steps.iter().enumerate() {
        let number = index + 1;
        let failed = |reason: Reason, value: i64| Report {
            verdict: Verdict::StepFailed(StepFailure {
                step: number,
                action: step.to_string(),
                line: plan.line(index),
                reason,
            }),
            value,
            cost_model,
            steps_executed: index,
        };
        let action = match check_step(&world, step) {
            Ok(action) => action,
            Err(reason) => return Ok(failed(reason, value)),
        };
        let binding: HashMap<&str, &str> = action
            .params
            .iter()
            .map(|p| p.name.as_str())
            .zip(step.args.iter().map(String::as_str))
            .collect();
        let place = action.name.as_str();
        let mut unsatisfied = Vec::new();
        for literal in &action.precondition {
            let ground = ground_literal(literal, &binding, place)?;
            if !holds(&state, &ground) {
                unsatisfied.push(ground);
            }
        }
        if !unsatisfied.is_empty() {
            return Ok(failed(
                Reason::UnsatisfiedPrecondition { unsatisfied },
                value,
            ));
        }
        let mut adds = Vec::new();
        let mut cost: i64 = 0;
        let overflow = || ValidateError::CostOverflow {
            step: number,
            action: step.to_string(),
        };
        for effect in &action.effects {
            match effect {
                Effect::Delete(atom) => {
                    state.remove(&ground_atom(atom, &binding, place)?);
                }
                Effect::Add(atom) => adds.push(ground_atom(atom, &binding, place)?),
                // Without action costs the value counts steps: cost terms are not read.
                Effect::IncreaseCost(_) if cost_model == CostModel::PlanLength => {}
                Effect::IncreaseCost(CostExpr::Constant(n)) => {
                    cost = cost.checked_add(n.value).ok_or_else(overflow)?;
                }
                Effect::IncreaseCost(CostExpr::Function(term)) => {
                    let term = ground_function(term, &binding, place)?;
                    let Some(v) = functions.get(&term).copied() else {
                        return Err(ValidateError::MissingFunctionValue {
                            step: number,
                            action: step.to_string(),
                            term,
                        });
                    };
                    cost = cost.checked_add(v).ok_or_else(overflow)?;
                }
            }
        }
        // Deletes went first (above); adds win over them.
        state.extend(adds);
        if cost_model == CostModel::PlanLength {
            cost = 1;
        }
        value = value.checked_add(cost).ok_or_else(overflow)?;
    }
    let none = HashMap::new();
    let mut unsatisfied = Vec::new();
    for literal in &problem.goal {
        let ground = ground_literal(literal, &none, "goal")?;
        if !holds(&state, &ground) {
            unsatisfied.push(ground);
        }
    }
    let verdict = if unsatisfied.is_empty() {
        Verdict::Valid
    } else {
        Verdict::GoalNotSatisfied { unsatisfied }
    };
    Ok(Report {
        verdict,
        value,
        cost_model,
        steps_executed: plan.steps.len(),
    })
}

/// Action costs count when the problem asks to minimise `total-cost` and the domain has
/// them (declares `total-cost` or increases it).
fn cost_model(domain: &Domain, problem: &Problem) -> CostModel {
    let domain_has_costs = domain
        .functions
        .iter()
        .any(|f| f.name.as_str() == "total-cost")
        || domain
            .actions
            .iter()
            .flat_map(|a| &a.effects)
            .any(|e| matches!(e, Effect::IncreaseCost(_)));
    if problem.metric.is_some() && domain_has_costs {
        CostModel::ActionCosts
    } else {
        CostModel::PlanLength
    }
}

/// The checks before the precondition: the action exists, the arguments are declared
/// objects, as many as the parameters, each of its parameter's type.
fn check_step<'a>(world: &World<'a>, step: &Step) -> Result<&'a pddl::Action, Reason> {
    let action = world.action(&step.action).ok_or(Reason::UnknownAction)?;
    if action.params.len() != step.args.len() {
        return Err(Reason::WrongArgumentCount {
            expected: action.params.len(),
            found: step.args.len(),
        });
    }
    if let Some(object) = step.args.iter().find(|a| world.object_types(a).is_none()) {
        return Err(Reason::UnknownObject {
            object: object.clone(),
        });
    }
    for (param, arg) in action.params.iter().zip(&step.args) {
        if !world.has_type(arg, param.ty.as_ref()) {
            return Err(Reason::WrongType {
                object: arg.clone(),
                parameter: param.name.text.clone(),
                expected: param.ty.as_ref().map_or("object".into(), type_text),
                declared: world
                    .object_types(arg)
                    .unwrap_or_default()
                    .iter()
                    .map(|t| t.to_string())
                    .collect(),
            });
        }
    }
    Ok(action)
}

fn type_text(ty: &Type) -> String {
    match ty {
        Type::Named(n) => n.text.clone(),
        Type::Either(names) => {
            let names: Vec<&str> = names.iter().map(|n| n.as_str()).collect();
            format!("(either {})", names.join(" "))
        }
    }
}

/// Whether a ground literal holds in a state; equality compares the objects' names.
fn holds(state: &BTreeSet<GroundAtom>, literal: &GroundLiteral) -> bool {
    let atom = &literal.atom;
    let truth = if atom.predicate == "=" {
        atom.args.windows(2).all(|w| w[0] == w[1])
    } else {
        state.contains(atom)
    };
    truth == literal.positive
}

fn ground_term(
    term: &Term,
    binding: &HashMap<&str, &str>,
    place: &str,
) -> Result<String, ValidateError> {
    match term {
        Term::Object(n) => Ok(n.text.clone()),
        Term::Variable(v) => binding
            .get(v.as_str())
            .map(|o| o.to_string())
            .ok_or_else(|| ValidateError::UnboundVariable {
                place: place.to_string(),
                variable: v.text.clone(),
            }),
    }
}

fn ground_args(
    args: &[Term],
    binding: &HashMap<&str, &str>,
    place: &str,
) -> Result<Vec<String>, ValidateError> {
    args.iter()
        .map(|t| ground_term(t, binding, place))
        .collect()
}

fn ground_atom(
    atom: &Atom,
    binding: &HashMap<&str, &str>,
    place: &str,
) -> Result<GroundAtom, ValidateError> {
    Ok(GroundAtom {
        predicate: atom.predicate.text.clone(),
        args: ground_args(&atom.args, binding, place)?,
    })
}

fn ground_literal(
    literal: &Literal,
    binding: &HashMap<&str, &str>,
    place: &str,
) -> Result<GroundLiteral, ValidateError> {
    Ok(GroundLiteral {
        positive: literal.positive,
        atom: ground_atom(&literal.atom, binding, place)?,
    })
}

fn ground_function(
    term: &FunctionTerm,
    binding: &HashMap<&str, &str>,
    place: &str,
) -> Result<GroundAtom, ValidateError> {
    Ok(GroundAtom {
        predicate: term.function.text.clone(),
        args: ground_args(&term.args, binding, place)?,
    })
}
