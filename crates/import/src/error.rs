//! Errors of an import: where in the source, and what is wrong.

use std::fmt;

/// Something wrong with what a source said, without its place in the source: the
/// source adds that ([`ImportError::Input`]).
#[derive(Debug, Clone, PartialEq)]
pub struct Problem {
    /// The source entity concerned, if one is.
    pub entity: Option<String>,
    /// The field concerned (`position`, `events[0].property`, ...), if one is.
    pub field: Option<String>,
    /// What is wrong.
    pub message: String,
}

impl Problem {
    /// A problem with no entity or field.
    pub fn new(message: impl Into<String>) -> Problem {
        Problem {
            entity: None,
            field: None,
            message: message.into(),
        }
    }

    /// A problem with an entity's field.
    pub fn at(entity: &str, field: &str, message: impl Into<String>) -> Problem {
        Problem {
            entity: Some(entity.to_string()),
            field: (!field.is_empty()).then(|| field.to_string()),
            message: message.into(),
        }
    }
}

impl fmt::Display for Problem {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match (&self.entity, &self.field) {
            (Some(e), Some(field)) => write!(f, "entity `{e}`, field `{field}`: ")?,
            (Some(e), None) => write!(f, "entity `{e}`: ")?,
            (None, Some(field)) => write!(f, "field `{field}`: ")?,
            (None, None) => {}
        }
        f.write_str(&self.message)
    }
}

/// A place in a source. Sources fill what they know: a Unity log its step and the JSON
/// line and column; a bag its topic and message index.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Location {
    /// 0-based index of the step (Unity) or frame.
    pub step: Option<u64>,
    /// 1-based line in a text source.
    pub line: Option<u64>,
    /// 1-based column in a text source.
    pub column: Option<u64>,
    /// The topic, in a bag.
    pub topic: Option<String>,
    /// 0-based index of the message on its topic, in a bag.
    pub message: Option<u64>,
}

impl Location {
    /// Whether nothing is known.
    pub fn is_empty(&self) -> bool {
        *self == Location::default()
    }
}

impl fmt::Display for Location {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let mut parts = Vec::new();
        if let Some(t) = &self.topic {
            parts.push(format!("topic {t}"));
        }
        if let Some(m) = self.message {
            parts.push(format!("message {m}"));
        }
        if let Some(s) = self.step {
            parts.push(format!("step {s}"));
        }
        match (self.line, self.column) {
            (Some(l), Some(c)) => parts.push(format!("line {l}, column {c}")),
            (Some(l), None) => parts.push(format!("line {l}")),
            _ => {}
        }
        f.write_str(&parts.join(", "))
    }
}

/// Why an import failed.
#[derive(Debug, thiserror::Error)]
pub enum ImportError {
    /// The source's content is wrong (exit 31 in the CLI).
    #[error("{0}")]
    Input(Box<InputError>),
    /// Reading the source failed.
    #[error("{0}")]
    Io(#[from] std::io::Error),
    /// Writing the native recording failed.
    #[error("{0}")]
    Write(#[from] recording::WriteError),
}

/// Wrong content in a source: where, and what.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("{}{problem}", if location.is_empty() { String::new() } else { format!("{location}: ") })]
pub struct InputError {
    /// Where.
    pub location: Location,
    /// What.
    pub problem: Problem,
}

impl ImportError {
    /// An input error at a location.
    pub fn input(location: Location, problem: Problem) -> ImportError {
        ImportError::Input(Box::new(InputError { location, problem }))
    }
}
