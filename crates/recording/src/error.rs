//! What can go wrong reading or writing a recording.

use crate::FORMAT_VERSION;

/// A malformed recording: where (line, column, field) and what.
///
/// `line` is 1-based; `column` is the 1-based byte column of the offending token in that
/// line and `width` its length in bytes (0 at the end of a line). `field` names the JSON
/// field with a path such as `entities.cube_1.pos[2]`, `t`, `contacts[0][1]` or, in the
/// header, `entities[2].kind`.
#[derive(Debug, thiserror::Error)]
#[error("line {line}, field `{field}`: {kind}")]
pub struct ReadError {
    /// 1-based line number.
    pub line: u64,
    /// 1-based byte column of the offending token.
    pub column: u32,
    /// Length of the offending token in bytes.
    pub width: u32,
    /// The field, as a path.
    pub field: String,
    /// What is wrong.
    #[source]
    pub kind: ErrorKind,
}

/// The kinds of mistake in a recording. The CLI maps them all to exit code 31 (input
/// error) except [`ErrorKind::Io`].
#[derive(Debug, thiserror::Error)]
pub enum ErrorKind {
    /// The input could not be read.
    #[error("cannot read: {0}")]
    Io(#[source] std::io::Error),
    /// The file has no line at all.
    #[error("empty file: expected the header line")]
    Empty,
    /// The first line is not a header (it is a frame, or another JSON object).
    #[error("missing header: the first line must be the recording header, with `format`")]
    MissingHeader,
    /// The header names another format.
    #[error("`{0}` is not a demoplan recording (expected `demoplan-recording`)")]
    NotARecording(String),
    /// The header names a version this reader does not read.
    #[error("unsupported format version {0} (this reader reads version {FORMAT_VERSION})")]
    Version(String),
    /// Not JSON, or JSON of the wrong shape.
    #[error("{0}")]
    Syntax(String),
    /// The line ends inside a value: a truncated file or a broken line.
    #[error("the line ends inside this field (truncated line)")]
    Truncated,
    /// NaN, infinity, or a number too large for its field.
    #[error("`{0}` is not a usable number: NaN, an infinity, or too large for its field")]
    NotFinite(String),
    /// A frame's time is not after the previous frame's.
    #[error("time {time} s is not after the previous frame's {previous} s (line {previous_line})")]
    Time {
        /// This frame's time.
        time: f64,
        /// The previous frame's time.
        previous: f64,
        /// The previous frame's line.
        previous_line: u64,
    },
    /// A name that the header does not declare.
    #[error("unknown entity `{0}`: the header declares no entity of that name")]
    UnknownEntity(String),
    /// Well-formed but inconsistent: a grip out of range, a missing field, a duplicate.
    #[error("{0}")]
    Invalid(String),
    /// A line longer than [`crate::MAX_LINE_BYTES`] (or a file with no line end in that
    /// many bytes).
    #[error(
        "the line is longer than {max} bytes, the most a recording line may have (one line \
         holds the header or one frame)"
    )]
    LineTooLong {
        /// The longest line accepted, in bytes.
        max: usize,
    },
}

impl ErrorKind {
    /// A short stable name of the kind, for diagnostics codes (`recording::time`).
    pub fn code(&self) -> &'static str {
        match self {
            ErrorKind::Io(_) => "io",
            ErrorKind::Empty => "empty",
            ErrorKind::MissingHeader => "missing-header",
            ErrorKind::NotARecording(_) => "format",
            ErrorKind::Version(_) => "version",
            ErrorKind::Syntax(_) => "syntax",
            ErrorKind::Truncated => "truncated",
            ErrorKind::NotFinite(_) => "not-finite",
            ErrorKind::Time { .. } => "time",
            ErrorKind::UnknownEntity(_) => "unknown-entity",
            ErrorKind::Invalid(_) => "invalid",
            ErrorKind::LineTooLong { .. } => "line-too-long",
        }
    }

    /// What to do about the error, for the people reading the message; `None` where the
    /// message says it all.
    pub fn help(&self) -> Option<&'static str> {
        use ErrorKind as K;
        Some(match self {
            K::Empty | K::MissingHeader => {
                "a recording starts with its header line: {\"format\":\"demoplan-recording\",\
                 \"version\":1,\"id\":...,\"entities\":[...]} (see docs/recording-format.md)"
            }
            K::Version(_) => {
                "this demoplan reads version 1 of the format (docs/recording-format.md)"
            }
            K::NotFinite(_) => {
                "JSON has no NaN or infinity; leave an entity out of a frame when it was not tracked"
            }
            K::Time { .. } => "frames are in time order, each strictly later than the one before",
            K::UnknownEntity(_) => {
                "every entity a frame names is declared in the header's `entities`"
            }
            K::Truncated => "the file may have been cut short while it was written",
            _ => return None,
        })
    }
}

impl ReadError {
    pub(crate) fn new(
        line: u64,
        column: usize,
        width: usize,
        field: impl Into<String>,
        kind: ErrorKind,
    ) -> ReadError {
        ReadError {
            line,
            column: u32::try_from(column).unwrap_or(u32::MAX),
            width: u32::try_from(width).unwrap_or(u32::MAX),
            field: field.into(),
            kind,
        }
    }
}

/// A frame or header that the writer refuses, because the reader would refuse it.
#[derive(Debug, thiserror::Error)]
pub enum WriteError {
    /// The output could not be written.
    #[error("cannot write: {0}")]
    Io(#[from] std::io::Error),
    /// The header breaks a rule of the format.
    #[error("header, field `{field}`: {message}")]
    Header {
        /// The field, as a path.
        field: String,
        /// What is wrong.
        message: String,
    },
    /// A frame breaks a rule of the format.
    #[error("frame {frame} (time {time} s), field `{field}`: {message}")]
    Frame {
        /// 0-based index of the frame among those written.
        frame: u64,
        /// Its time.
        time: f64,
        /// The field, as a path.
        field: String,
        /// What is wrong.
        message: String,
    },
}
