//! Tokens and S-expressions: the layer below PDDL's grammar.
//!
//! PDDL is case-insensitive, so every token is lowercased here and nothing above this
//! module sees upper case. A `?` always starts a new token, so `(aircraft?a)` reads as
//! `aircraft ?a`, as Fast Downward's reader does.

// A reader of untrusted input (issue 23): no arithmetic that can wrap or panic, no
// cast that can truncate; each such operation is checked, saturating or proved in range.
#![deny(clippy::arithmetic_side_effects, clippy::cast_possible_truncation)]

use crate::{PddlError, Span};

/// A token that is not a parenthesis: a name, a `?variable`, a `:keyword`, a number or `-`.
#[derive(Debug, Clone)]
pub(crate) struct Token {
    pub text: String,
    pub span: Span,
}

/// A parenthesised list or a token.
#[derive(Debug, Clone)]
pub(crate) enum SExpr {
    Token(Token),
    List { items: Vec<SExpr>, span: Span },
}

impl SExpr {
    pub fn span(&self) -> Span {
        match self {
            SExpr::Token(t) => t.span,
            SExpr::List { span, .. } => *span,
        }
    }
}

/// Comments seen while reading, kept so a formatter can say what it drops.
#[derive(Debug, Default, Clone)]
pub(crate) struct Comments {
    /// Spans of all `;` comments, in order.
    pub spans: Vec<Span>,
}

/// Reads exactly one top-level list from `source`.
pub(crate) fn read_single_list(source: &str) -> Result<(SExpr, Comments), PddlError> {
    if source.len() >= u32::MAX as usize {
        return Err(PddlError::syntax(Span::NONE, "file is larger than 4 GiB"));
    }
    let mut reader = Reader {
        src: source.as_bytes(),
        pos: 0,
        comments: Comments::default(),
    };
    reader.skip_blanks();
    let top = match reader.peek() {
        None => {
            return Err(PddlError::syntax(Span::new(0, 0), "file is empty")
                .with_label("expected `(define ...)`"))
        }
        Some(b'(') => reader.list()?,
        Some(b')') => return Err(reader.unexpected_close()),
        Some(_) => {
            let token = reader.token();
            return Err(PddlError::syntax(
                token.span,
                format!("expected `(define`, found `{}`", token.text),
            )
            .with_label("expected `(`"));
        }
    };
    reader.skip_blanks();
    match reader.peek() {
        None => Ok((top, reader.comments)),
        Some(b')') => Err(reader.unexpected_close()),
        Some(_) => {
            let start = reader.pos;
            Err(PddlError::syntax(
                Span::new(start, start.saturating_add(1)),
                "unexpected text after the end of the definition",
            )
            .with_label("the `(define ...)` closed before this")
            .with_help("a PDDL file holds one `(define ...)`; check the parentheses above"))
        }
    }
}

/// Deeper lists are rejected: no PDDL file needs them, and the recursive walks above
/// this module (and dropping the tree) must not overflow the stack.
const MAX_DEPTH: usize = 512;

struct Reader<'a> {
    src: &'a [u8],
    pos: usize,
    comments: Comments,
}

fn is_delimiter(b: u8) -> bool {
    b.is_ascii_whitespace() || matches!(b, b'(' | b')' | b';')
}

impl Reader<'_> {
    fn peek(&self) -> Option<u8> {
        self.src.get(self.pos).copied()
    }

    /// Moves past the byte at `pos` (there is one: callers have peeked it, so `pos` is
    /// below the text's length and cannot wrap).
    fn advance(&mut self) {
        self.pos = self.pos.saturating_add(1);
    }

    fn skip_blanks(&mut self) {
        while let Some(b) = self.peek() {
            if b.is_ascii_whitespace() {
                self.advance();
            } else if b == b';' {
                let start = self.pos;
                while self.peek().is_some_and(|b| b != b'\n') {
                    self.advance();
                }
                self.comments.spans.push(Span::new(start, self.pos));
            } else {
                break;
            }
        }
    }

    fn unexpected_close(&self) -> PddlError {
        PddlError::syntax(
            Span::new(self.pos, self.pos.saturating_add(1)),
            "unexpected `)`",
        )
        .with_label("no `(` is open here")
    }

    /// Reads a list; `self.pos` is at its `(`. Iterative, so deep nesting cannot
    /// overflow the stack.
    fn list(&mut self) -> Result<SExpr, PddlError> {
        let mut stack: Vec<(usize, Vec<SExpr>)> = vec![(self.pos, Vec::new())];
        self.advance();
        loop {
            self.skip_blanks();
            match self.peek() {
                None => {
                    let open = stack.last().map_or(0, |(open, _)| *open);
                    return Err(PddlError::syntax(
                        Span::new(open, open.saturating_add(1)),
                        "unclosed `(`",
                    )
                    .with_label("this `(` is never closed")
                    .with_help("add the missing `)`"));
                }
                Some(b'(') => {
                    if stack.len() >= MAX_DEPTH {
                        return Err(PddlError::syntax(
                            Span::new(self.pos, self.pos.saturating_add(1)),
                            format!("parentheses nested deeper than {MAX_DEPTH} levels"),
                        )
                        .with_label("too deep"));
                    }
                    stack.push((self.pos, Vec::new()));
                    self.advance();
                }
                Some(b')') => {
                    self.advance();
                    let Some((open, items)) = stack.pop() else {
                        return Err(self.unexpected_close());
                    };
                    let list = SExpr::List {
                        items,
                        span: Span::new(open, self.pos),
                    };
                    match stack.last_mut() {
                        Some((_, parent)) => parent.push(list),
                        None => return Ok(list),
                    }
                }
                Some(_) => {
                    let token = self.token();
                    if let Some((_, items)) = stack.last_mut() {
                        items.push(SExpr::Token(token));
                    }
                }
            }
        }
    }

    /// Reads a token at `self.pos` (not a delimiter). A `?` inside a token starts a new one.
    fn token(&mut self) -> Token {
        let start = self.pos;
        self.advance();
        while let Some(b) = self.peek() {
            if is_delimiter(b) || b == b'?' {
                break;
            }
            self.advance();
        }
        let raw = String::from_utf8_lossy(&self.src[start..self.pos]);
        Token {
            text: raw.to_lowercase(),
            span: Span::new(start, self.pos),
        }
    }
}

#[cfg(test)]
#[allow(clippy::arithmetic_side_effects, clippy::cast_possible_truncation)] // tests, not readers
mod tests {
    use super::*;

    fn texts(e: &SExpr) -> String {
        match e {
            SExpr::Token(t) => t.text.clone(),
            SExpr::List { items, .. } => {
                format!(
                    "[{}]",
                    items.iter().map(texts).collect::<Vec<_>>().join(" ")
                )
            }
        }
    }

    #[test]
    fn splits_before_question_mark_and_lowercases() {
        let (e, _) = read_single_list("(AirCraft?A ?b)").unwrap();
        assert_eq!(texts(&e), "[aircraft ?a ?b]");
    }

    #[test]
    fn skips_comments() {
        let (e, c) = read_single_list("; head\n(a ; x\n b)").unwrap();
        assert_eq!(texts(&e), "[a b]");
        assert_eq!(c.spans.len(), 2);
    }

    #[test]
    fn reports_unclosed_paren_at_its_opening() {
        let err = read_single_list("(a (b c)").unwrap_err();
        assert_eq!(err.span.start, 0);
    }

    #[test]
    fn deep_nesting_is_an_error_not_a_stack_overflow() {
        let src = format!("{}{}", "(".repeat(200_000), ")".repeat(200_000));
        let err = read_single_list(&src).unwrap_err();
        assert!(err.message.contains("nested deeper"), "{}", err.message);
        assert!(read_single_list(&format!("{}{}", "(".repeat(500), ")".repeat(500))).is_ok());
    }
}
