//! A PDDL file rewritten in canonical form (`demoplan fmt`): the canonical writer's text
//! after the file's leading `;` comment lines, which the AST has no place for.

use crate::{parse_file, PddlError, PddlFile};

/// A file in canonical form, and how many of its comments that form could not keep.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Canonical {
    /// The leading comment lines (each trimmed), a blank line, the canonical definition.
    pub text: String,
    /// Comments inside the definition, which are dropped.
    pub dropped_comments: usize,
}

/// Parses `source` (a domain or a problem) and writes it in canonical form. Idempotent:
/// the canonical form of a canonical text is itself.
pub fn canonical_form(source: &str) -> Result<Canonical, PddlError> {
    let parsed = parse_file(source)?;
    let header = leading_comments(source);
    let body = match &parsed.content {
        PddlFile::Domain(d) => d.to_string(),
        PddlFile::Problem(p) => p.to_string(),
    };
    let kept = header.lines().count();
    Ok(Canonical {
        text: if header.is_empty() {
            body
        } else {
            format!("{header}\n{body}")
        },
        dropped_comments: parsed.comments.len().saturating_sub(kept),
    })
}

/// The `;` comment lines before the definition, each trimmed at the end.
fn leading_comments(source: &str) -> String {
    let mut out = String::new();
    for l in source.lines() {
        let t = l.trim();
        if t.starts_with(';') {
            out.push_str(t);
            out.push('\n');
        } else if !t.is_empty() {
            break;
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_header_stays_inner_comments_are_counted_and_the_form_is_idempotent() {
        let source = "; made by hand\n  ; second line  \n(define (domain D) ; inner\n \
                      (:predicates (P)) (:action a :parameters () :effect (P)))\n";
        let once = canonical_form(source).unwrap();
        assert!(
            once.text
                .starts_with("; made by hand\n; second line\n\n(define (domain d)"),
            "{}",
            once.text
        );
        assert_eq!(once.dropped_comments, 1);
        let twice = canonical_form(&once.text).unwrap();
        assert_eq!(twice.text, once.text);
        assert_eq!(twice.dropped_comments, 0);
    }
}
