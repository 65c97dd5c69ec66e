//! Source locations.

use std::fmt;
use std::hash::{Hash, Hasher};

/// A byte range `start..end` in the source text a node was parsed from.
///
/// Spans are locations, not content: two spans always compare equal and hash alike, so
/// that AST nodes compare by what they say, not by where they were written. This is what
/// makes `parse(write(x)) == x` meaningful. Nodes built by hand use [`Span::NONE`].
#[derive(Clone, Copy, Default)]
pub struct Span {
    /// Byte offset of the first character.
    pub start: u32,
    /// Byte offset one past the last character.
    pub end: u32,
}

impl Span {
    /// The span of a node that was not parsed from text.
    pub const NONE: Span = Span { start: 0, end: 0 };

    /// A span from `start` to `end` (byte offsets).
    pub fn new(start: usize, end: usize) -> Span {
        Span {
            start: to_u32(start),
            end: to_u32(end),
        }
    }

    /// The smallest span covering both.
    pub fn join(self, other: Span) -> Span {
        Span {
            start: self.start.min(other.start),
            end: self.end.max(other.end),
        }
    }

    /// Length in bytes.
    pub fn len(self) -> usize {
        (self.end - self.start) as usize
    }

    /// True for an empty span.
    pub fn is_empty(self) -> bool {
        self.start == self.end
    }

    /// One-based line and column (in characters) of the span's start in `source`.
    pub fn line_col(self, source: &str) -> (usize, usize) {
        let start = (self.start as usize).min(source.len());
        let before = source.get(..start).unwrap_or("");
        let line = before.matches('\n').count() + 1;
        let column = before.rsplit('\n').next().map_or(0, |l| l.chars().count()) + 1;
        (line, column)
    }
}

fn to_u32(offset: usize) -> u32 {
    // Source texts over 4 GiB are rejected before lexing, so this never saturates there.
    u32::try_from(offset).unwrap_or(u32::MAX)
}

impl PartialEq for Span {
    fn eq(&self, _other: &Span) -> bool {
        true
    }
}

impl Eq for Span {}

impl Hash for Span {
    fn hash<H: Hasher>(&self, _state: &mut H) {}
}

impl fmt::Debug for Span {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}..{}", self.start, self.end)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn line_col_counts_lines_and_characters() {
        let src = "(define\n  (domain x))";
        assert_eq!(Span::new(0, 1).line_col(src), (1, 1));
        assert_eq!(Span::new(10, 16).line_col(src), (2, 3));
    }
}
