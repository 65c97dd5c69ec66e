//! The offending line of a [`ReadError`], cut for showing: a frame line can be a
//! kilobyte, so at most about 100 characters around the error are kept.

use std::io::{BufRead, Read};

use crate::{ReadError, MAX_LINE_BYTES};

/// What to show of a read error on its line.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Excerpt {
    /// The line, cut around the error with `…`.
    pub text: String,
    /// Where the offending token starts in `text` (bytes).
    pub offset: usize,
    /// The token's length in bytes; at the end of a cut-short line, its last character.
    pub width: usize,
    /// What is wrong; with no line to show (an empty file) it names the field too.
    pub message: String,
    /// What the underline says: the field, or that the line as a whole is wrong.
    pub label: String,
}

impl ReadError {
    /// The excerpt of `line`, the text of line [`ReadError::line`] (as
    /// [`offending_line`] reads it).
    pub fn excerpt(&self, line: &str) -> Excerpt {
        let (text, mut offset) = cut(line, self.column.saturating_sub(1) as usize);
        let mut width = (self.width as usize).min(text.len().saturating_sub(offset));
        if width == 0 && offset >= text.len() {
            // At the end of the line (a truncated line): point at its last character.
            if let Some(c) = text.chars().next_back() {
                offset = text.len() - c.len_utf8();
                width = c.len_utf8();
            }
        }
        let mut message = self.kind.to_string();
        if text.is_empty() && !self.field.is_empty() {
            message.push_str(&format!(" (field `{}`)", self.field));
        }
        let label = if self.field.is_empty() {
            "the whole line (no field: not a JSON object of the format)".to_string()
        } else {
            format!("field `{}`", self.field)
        };
        Excerpt {
            text,
            offset,
            width,
            message,
            label,
        }
    }
}

/// Line `n` (1-based) of `input`, without its line ending; empty if there is none. No
/// more of a line is read than the reader takes: a line it refused as too long is cut.
pub fn offending_line(mut input: impl BufRead, n: u64) -> String {
    let mut buf = Vec::new();
    for _ in 0..n {
        buf.clear();
        let most = MAX_LINE_BYTES as u64 + 2;
        match (&mut input).take(most).read_until(b'\n', &mut buf) {
            Ok(0) | Err(_) => return String::new(),
            Ok(_) => {}
        }
    }
    while matches!(buf.last(), Some(b'\n' | b'\r')) {
        buf.pop();
    }
    String::from_utf8_lossy(&buf).into_owned()
}

/// At most about 100 characters of `line` around byte `at`, with `…` where it is cut;
/// returns the excerpt and where `at` is in it.
fn cut(line: &str, at: usize) -> (String, usize) {
    const BEFORE: usize = 50;
    const AFTER: usize = 50;
    if line.len() <= BEFORE + AFTER + 20 {
        return (line.to_string(), at.min(line.len()));
    }
    let mut start = at.saturating_sub(BEFORE).min(line.len());
    while !line.is_char_boundary(start) {
        start -= 1;
    }
    let mut end = (at + AFTER).min(line.len());
    while !line.is_char_boundary(end) {
        end += 1;
    }
    let mut text = String::new();
    if start > 0 {
        text.push('…');
    }
    let offset = text.len() + at.min(line.len()) - start;
    text.push_str(&line[start..end]);
    if end < line.len() {
        text.push('…');
    }
    (text, offset)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn long_lines_are_cut_around_the_error() {
        let line = "x".repeat(500);
        let (text, at) = cut(&line, 300);
        assert!(text.starts_with('…') && text.ends_with('…'));
        assert_eq!(&text[at..at + 1], "x");
        assert!(text.chars().count() < 110);
        let (short, at) = cut("{\"t\":1}", 5);
        assert_eq!((short.as_str(), at), ("{\"t\":1}", 5));
    }

    #[test]
    fn the_offending_line_is_read_without_its_ending() {
        let text = "first\r\nsecond\nthird";
        assert_eq!(offending_line(text.as_bytes(), 2), "second");
        assert_eq!(offending_line(text.as_bytes(), 3), "third");
        assert_eq!(offending_line(text.as_bytes(), 4), "");
    }
}
