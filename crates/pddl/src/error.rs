//! Errors of reading PDDL.

use crate::Span;

/// What kind of mistake a [`PddlError`] reports; it decides the exit code a planner uses
/// (Fast Downward's table: 31 for input errors, 34 for unsupported features).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum ErrorKind {
    /// The text is not well-formed PDDL (parentheses, section layout, tokens).
    Syntax,
    /// Well-formed, but inconsistent: undefined names, wrong arity, duplicates.
    Semantic,
    /// Valid PDDL outside the supported fragment (conditional effects, quantifiers, ...).
    Unsupported,
}

/// A mistake in a PDDL text, with the span it is about.
///
/// Errors from [`crate::parse_domain`] point into the domain text, errors from
/// [`crate::parse_problem`] and [`crate::check_problem`] into the problem text.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[error("{message}")]
pub struct PddlError {
    /// Syntax, semantic or unsupported.
    pub kind: ErrorKind,
    /// One sentence saying what is wrong.
    pub message: String,
    /// Where.
    pub span: Span,
    /// A short text to show under the span.
    pub label: String,
    /// How to fix it, when there is something useful to say.
    pub help: Option<String>,
}

impl PddlError {
    pub(crate) fn new(kind: ErrorKind, span: Span, message: impl Into<String>) -> PddlError {
        PddlError {
            kind,
            message: message.into(),
            span,
            label: String::from("here"),
            help: None,
        }
    }

    pub(crate) fn syntax(span: Span, message: impl Into<String>) -> PddlError {
        PddlError::new(ErrorKind::Syntax, span, message)
    }

    pub(crate) fn semantic(span: Span, message: impl Into<String>) -> PddlError {
        PddlError::new(ErrorKind::Semantic, span, message)
    }

    /// `feature` names the PDDL construct, e.g. "conditional effects (`when`)".
    pub(crate) fn unsupported(span: Span, feature: &str) -> PddlError {
        PddlError::new(
            ErrorKind::Unsupported,
            span,
            format!("{feature} are not supported"),
        )
        .with_label("outside the supported fragment")
        .with_help(
            "demoplan plans on STRIPS with typing, negative preconditions, equality and \
                 action costs",
        )
    }

    pub(crate) fn with_label(mut self, label: impl Into<String>) -> PddlError {
        self.label = label.into();
        self
    }

    pub(crate) fn with_help(mut self, help: impl Into<String>) -> PddlError {
        self.help = Some(help.into());
        self
    }

    /// The exit code Fast Downward uses for this kind of error: 31 (translator input
    /// error) or 34 (unsupported).
    pub fn exit_code(&self) -> i32 {
        match self.kind {
            ErrorKind::Syntax | ErrorKind::Semantic => 31,
            ErrorKind::Unsupported => 34,
        }
    }
}
