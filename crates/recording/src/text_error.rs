//! [`TextError`]: the one error type of the readers of small text files (grounding
//! configurations, tree files, ARFF tables, import mappings, operator libraries), so
//! that a program shows every one of them the same way, on its line.

/// A text file that cannot be used: where (1-based line and column; 0 when unknown:
/// line 0 is the file as a whole, column 0 the whole line), which field (a dotted path
/// such as `hand_open.close_above` or `entity[2].size`; empty when unknown) and what is
/// wrong.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[error("line {line}, field `{field}`: {message}")]
pub struct TextError {
    /// 1-based line (0: the file as a whole).
    pub line: usize,
    /// 1-based column (0: the whole line).
    pub column: usize,
    /// The field, as a dotted path; empty when unknown.
    pub field: String,
    /// What is wrong.
    pub message: String,
}

impl TextError {
    /// An error at the first place `needle` occurs in `text` (line 0 when it does not).
    pub fn at(text: &str, needle: &str, field: &str, message: String) -> TextError {
        let (line, column) = match text.find(needle) {
            Some(offset) => {
                let before = &text[..offset];
                let line = before.matches('\n').count().saturating_add(1);
                let line_start = before.rfind('\n').map_or(0, |i| i.saturating_add(1));
                (line, offset.saturating_sub(line_start).saturating_add(1))
            }
            None => (0, 0),
        };
        TextError {
            line,
            column,
            field: field.to_string(),
            message,
        }
    }

    /// The bytes of `text` to underline: `(offset, width)` of the token that starts at
    /// the column (up to white space or a comma), or of the line's text without its
    /// indentation when the column is 0. `None` when the line is 0 or not in `text`.
    pub fn span(&self, text: &str) -> Option<(usize, usize)> {
        if self.line == 0 {
            return None;
        }
        let mut start = 0;
        for _ in 1..self.line {
            start += text[start..].find('\n')? + 1;
        }
        let line_text = text[start..]
            .split('\n')
            .next()
            .unwrap_or("")
            .trim_end_matches('\r');
        let (offset, width) = if self.column == 0 {
            let indent = line_text.len() - line_text.trim_start().len();
            (indent, line_text.trim().len())
        } else {
            let at = (self.column - 1).min(line_text.len());
            let token = line_text[at..]
                .find(|c: char| c.is_whitespace() || c == ',')
                .unwrap_or(line_text.len() - at);
            (at, token.max(1).min(line_text.len().saturating_sub(at)))
        };
        Some((start + offset, width))
    }
}

#[cfg(test)]
mod tests {
    use super::TextError;

    fn error(line: usize, column: usize) -> TextError {
        TextError {
            line,
            column,
            field: "f".into(),
            message: "bad".into(),
        }
    }

    #[test]
    fn the_span_is_the_token_at_the_column_or_the_line_without_indentation() {
        let text = "a = 1\n  b = [2, 3]\r\nc";
        assert_eq!(error(2, 8).span(text), Some((13, 1)));
        assert_eq!(error(2, 3).span(text), Some((8, 1)));
        assert_eq!(error(2, 0).span(text), Some((8, 10)));
        assert_eq!(error(3, 0).span(text), Some((20, 1)));
        // Past the line's end: an empty span at its end, never out of the text.
        assert_eq!(error(1, 40).span(text), Some((5, 0)));
        assert_eq!(error(0, 0).span(text), None);
        assert_eq!(error(5, 1).span(text), None);
    }

    #[test]
    fn at_finds_the_first_occurrence_or_says_the_whole_file() {
        let text = "{\n  \"lambda\": 3,\n  \"x\": 1\n}";
        let e = TextError::at(text, "\"x\"", "x", "unknown".into());
        assert_eq!((e.line, e.column), (3, 3));
        assert_eq!(TextError::at(text, "nowhere", "y", String::new()).line, 0);
        assert_eq!(e.to_string(), "line 3, field `x`: unknown");
    }
}
