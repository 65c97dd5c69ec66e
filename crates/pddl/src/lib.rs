//! PDDL for demoplan: a reader with diagnostics, a typed AST, and a canonical writer.
//!
//! The supported fragment is STRIPS with `:typing` (hierarchies, `either`, types declared
//! more than once), `:negative-preconditions`, `:equality`, `:action-costs` (constant
//! costs and static cost functions), constants, negative goals and untyped domains.
//! Everything else PDDL can say is rejected with an [`ErrorKind::Unsupported`] error that
//! points at the construct. Names are case-insensitive and stored lowercase. The crate does
//! no I/O: it reads and writes strings.
//!
//! ```
//! let domain = pddl::parse_domain(
//!     "(define (domain d) (:predicates (p ?x)) (:action a :parameters (?x) \
//!      :precondition (p ?x) :effect (not (p ?x))))",
//! )?;
//! let problem = pddl::parse_problem(
//!     "(define (problem q) (:domain d) (:objects o) (:init (P o)) (:goal (not (p o))))",
//! )?;
//! pddl::check_problem(&domain, &problem)?;
//! assert_eq!(problem.init.len(), 1);
//! // The writer's output reads back as the same tree.
//! assert_eq!(pddl::parse_domain(&domain.to_string())?, domain);
//! # Ok::<(), pddl::PddlError>(())
//! ```

mod ast;
mod canonical;
mod check;
mod error;
mod files;
mod lexer;
mod parser;
mod plan;
mod span;
mod summary;
mod writer;

pub use ast::*;
pub use canonical::{canonical_form, Canonical};
pub use error::{ErrorKind, PddlError};
pub use files::{domain_file_candidates, find_domain_file, NoDomainFile};
pub use parser::PddlFile;
pub use plan::{parse_plan, write_plan, CostKind, Plan, PlanError, PlanErrorKind, Step};
pub use span::Span;
pub use summary::{summary_text, SummaryRow};

/// Parses and checks a domain: its syntax, and that every name it uses is declared.
pub fn parse_domain(source: &str) -> Result<Domain, PddlError> {
    match parse_file(source)?.content {
        PddlFile::Domain(d) => Ok(d),
        PddlFile::Problem(p) => Err(PddlError::syntax(
            p.name.span,
            "expected a domain, found a problem",
        )
        .with_label("this file defines a problem")),
    }
}

/// Parses a problem. Whether its names exist in the domain is [`check_problem`]'s part.
pub fn parse_problem(source: &str) -> Result<Problem, PddlError> {
    match parse_file(source)?.content {
        PddlFile::Problem(p) => Ok(p),
        PddlFile::Domain(d) => Err(PddlError::syntax(
            d.name.span,
            "expected a problem, found a domain",
        )
        .with_label("this file defines a domain")),
    }
}

/// Checks a problem against its domain: declared predicates, functions, types and
/// objects, arities, no object declared twice. Error spans point into the problem text.
pub fn check_problem(domain: &Domain, problem: &Problem) -> Result<(), PddlError> {
    check::check_problem(domain, problem)
}

/// A parsed file and the comments it held (the AST has no place for them).
#[derive(Debug, Clone)]
pub struct ParsedFile {
    /// The domain or problem; a domain has passed its semantic checks.
    pub content: PddlFile,
    /// The spans of its `;` comments, in order.
    pub comments: Vec<Span>,
}

/// Parses a domain or a problem, whichever the text defines.
pub fn parse_file(source: &str) -> Result<ParsedFile, PddlError> {
    let (content, comments) = parser::parse_file(source)?;
    if let PddlFile::Domain(d) = &content {
        check::check_domain(d)?;
    }
    Ok(ParsedFile {
        content,
        comments: comments.spans,
    })
}

impl Domain {
    /// The requirement flags the domain and problem actually need, in a fixed order,
    /// whatever they declare.
    pub fn used_requirements(&self, problem: Option<&Problem>) -> Vec<&'static str> {
        let mut used = vec![":strips"];
        let typed = |items: &[Typed]| items.iter().any(|t| t.ty.is_some());
        let uses_typing = !self.types.is_empty()
            || typed(&self.constants)
            || self.predicates.iter().any(|p| typed(&p.params))
            || self.actions.iter().any(|a| typed(&a.params))
            || problem.is_some_and(|p| typed(&p.objects));
        let goal = problem.map_or(&[][..], |p| &p.goal[..]);
        let literals = || {
            self.actions
                .iter()
                .flat_map(|a| &a.precondition)
                .chain(goal)
        };
        let uses_negation = literals().any(|l| !l.positive && !l.atom.is_equality());
        let uses_equality = literals().any(|l| l.atom.is_equality());
        let uses_costs = !self.functions.is_empty()
            || self
                .actions
                .iter()
                .flat_map(|a| &a.effects)
                .any(|e| matches!(e, Effect::IncreaseCost(_)))
            || problem.is_some_and(|p| p.metric.is_some());
        for (flag, on) in [
            (":typing", uses_typing),
            (":negative-preconditions", uses_negation),
            (":equality", uses_equality),
            (":action-costs", uses_costs),
        ] {
            if on {
                used.push(flag);
            }
        }
        used
    }
}
