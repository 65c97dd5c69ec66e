//! An independent plan validator in the manner of VAL, for the PDDL fragment demoplan
//! supports.
//!
//! [`pddl::parse_plan`] reads a plan text (one ground action `(name arg1 arg2)` per line, as
//! Fast Downward writes it); [`validate`] executes it on a [`pddl::Domain`] and
//! [`pddl::Problem`] and returns a [`Report`]: valid or not, the failing step and the
//! reason, and the plan's value. The crate reads the PDDL syntax tree directly and shares
//! no code with the translator or the search, so that it is an independent check of the
//! planner. It does no I/O and never prints; [`Report::val_text`] gives VAL's wording.
//!
//! ```
//! let domain = pddl::parse_domain(
//!     "(define (domain d) (:predicates (p ?x) (q ?x)) \
//!      (:action a :parameters (?x) :precondition (p ?x) :effect (and (not (p ?x)) (q ?x))))",
//! )?;
//! let problem = pddl::parse_problem(
//!     "(define (problem q) (:domain d) (:objects o) (:init (p o)) (:goal (q o)))",
//! )?;
//! pddl::check_problem(&domain, &problem)?;
//!
//! let plan = pddl::parse_plan("(A O)\n; cost = 1 (unit cost)\n")?;
//! let report = validate::validate(&domain, &problem, &plan)?;
//! assert!(report.is_valid());
//! assert_eq!(report.value, 1); // no metric: the value is the plan length
//! assert!(report.val_text().ends_with("Plan valid\nFinal value: 1\n"));
//!
//! // Twice is once too often: the second step's precondition is false.
//! let plan = pddl::parse_plan("(a o)\n(a o)")?;
//! let report = validate::validate(&domain, &problem, &plan)?;
//! let validate::Verdict::StepFailed(failure) = &report.verdict else { panic!() };
//! assert_eq!(failure.to_string(), "step 2 (a o): unsatisfied precondition: (p o)");
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

mod execute;
mod val_text;
mod world;

pub use execute::{
    validate, CostModel, GroundAtom, GroundLiteral, Reason, Report, StepFailure, ValidateError,
    Verdict,
};
pub use val_text::val_text_of_file;

#[cfg(test)]
mod tests;
