//! Plan files: one ground action per line, as Fast Downward writes them.

use std::fmt;

/// One step of a plan: a ground action, lowercase, as `(name arg1 arg2)` wrote it.
#[derive(Debug, Clone, PartialEq, Eq, Hash)]
pub struct Step {
    /// The action's name.
    pub action: String,
    /// The objects it is applied to, in order.
    pub args: Vec<String>,
    /// The 1-based line of the plan text it was read from (0 for a step built in code).
    pub line: usize,
}

impl Step {
    /// A step that was not read from a plan text.
    pub fn new(
        action: impl Into<String>,
        args: impl IntoIterator<Item = impl Into<String>>,
    ) -> Step {
        Step {
            action: action.into(),
            args: args.into_iter().map(Into::into).collect(),
            line: 0,
        }
    }
}

/// Writes the step as a plan file line: `(name arg1 arg2)`.
impl fmt::Display for Step {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "({}", self.action)?;
        for a in &self.args {
            write!(f, " {a}")?;
        }
        f.write_str(")")
    }
}

/// A sequential plan: the steps in the order they are executed.
#[derive(Debug, Clone, Default, PartialEq, Eq, Hash)]
pub struct Plan {
    /// The steps.
    pub steps: Vec<Step>,
}

/// Writes the plan as a plan file, one step per line.
impl fmt::Display for Plan {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        for s in &self.steps {
            writeln!(f, "{s}")?;
        }
        Ok(())
    }
}

/// A line of a plan text that is not a ground action.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[error("line {line}: {kind}")]
pub struct PlanError {
    /// The 1-based line number.
    pub line: usize,
    /// What is wrong with it.
    pub kind: PlanErrorKind,
}

/// What is wrong with a line of a plan text.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum PlanErrorKind {
    /// The line does not start with `(`.
    #[error("expected an action such as `(name arg1 arg2)`, found `{0}`")]
    NotAnAction(String),
    /// The line opens an action but never closes it.
    #[error("the action is not closed: `)` is missing")]
    Unclosed,
    /// `()`.
    #[error("the action has no name: `()`")]
    NoName,
    /// A `(` inside an action.
    #[error("unexpected `(` inside the action: its arguments are object names")]
    Nested,
    /// Something after the closing `)` other than a comment.
    #[error("unexpected `{0}` after the action: one action per line")]
    TrailingText(String),
}

/// Reads a plan text: one ground action `(name arg1 arg2)` per line, case-insensitive
/// (stored lowercase). Everything after a `;` is a comment, so Fast Downward's closing
/// `; cost = 6 (unit cost)` line and the reference plans' `;; Optimal cost: 6` header are
/// skipped, as are blank lines.
///
/// Runs in time linear in the length of the text.
pub fn parse_plan(text: &str) -> Result<Plan, PlanError> {
    let mut steps = Vec::new();
    for (index, raw) in text.lines().enumerate() {
        let line = index + 1;
        let content = raw.split(';').next().unwrap_or_default().trim();
        if content.is_empty() {
            continue;
        }
        let step = parse_step(content).map_err(|kind| PlanError { line, kind })?;
        steps.push(Step { line, ..step });
    }
    Ok(Plan { steps })
}

fn parse_step(content: &str) -> Result<Step, PlanErrorKind> {
    let content = content.to_lowercase();
    let Some(rest) = content.strip_prefix('(') else {
        let word = content.split_whitespace().next().unwrap_or_default();
        return Err(PlanErrorKind::NotAnAction(word.to_string()));
    };
    let close = rest.find(')');
    let open = rest.find('(');
    if let Some(open) = open {
        if close.is_none_or(|c| open < c) {
            return Err(PlanErrorKind::Nested);
        }
    }
    let Some(close) = close else {
        return Err(PlanErrorKind::Unclosed);
    };
    let after = rest[close + 1..].trim();
    if !after.is_empty() {
        return Err(PlanErrorKind::TrailingText(after.to_string()));
    }
    let mut words = rest[..close].split_whitespace().map(str::to_string);
    let action = words.next().ok_or(PlanErrorKind::NoName)?;
    Ok(Step {
        action,
        args: words.collect(),
        line: 0,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn error(text: &str) -> PlanError {
        match parse_plan(text) {
            Ok(plan) => panic!("{text:?} parsed as {plan:?}"),
            Err(e) => e,
        }
    }

    #[test]
    fn reads_fast_downward_plan_files() {
        let plan = parse_plan(
            ";; Optimal cost: 2\n\n(PICK-UP B)\n  (stack b   a) ; on a\n; cost = 2 (unit cost)\n",
        )
        .map_err(|e| e.to_string());
        let expected = Plan {
            steps: vec![
                Step {
                    line: 3,
                    ..Step::new("pick-up", ["b"])
                },
                Step {
                    line: 4,
                    ..Step::new("stack", ["b", "a"])
                },
            ],
        };
        assert_eq!(plan, Ok(expected));
    }

    #[test]
    fn an_empty_text_is_the_empty_plan() {
        assert_eq!(parse_plan(""), Ok(Plan::default()));
        assert_eq!(parse_plan("; cost = 0 (unit cost)\n"), Ok(Plan::default()));
    }

    #[test]
    fn nullary_actions_and_display() {
        let plan = parse_plan("(initialize)\n(Drive T1 A B)").map_err(|e| e.to_string());
        let Ok(plan) = plan else { panic!("{plan:?}") };
        assert_eq!(plan.steps[0].args, Vec::<String>::new());
        assert_eq!(plan.to_string(), "(initialize)\n(drive t1 a b)\n");
    }

    #[test]
    fn malformed_lines_name_their_line() {
        let cases = [
            (
                "(a)\npick-up b\n",
                2,
                PlanErrorKind::NotAnAction("pick-up".into()),
            ),
            ("\n\n(pick-up b", 3, PlanErrorKind::Unclosed),
            ("()", 1, PlanErrorKind::NoName),
            ("(  )", 1, PlanErrorKind::NoName),
            ("(a)\n(a (b))", 2, PlanErrorKind::Nested),
            ("((a b)", 1, PlanErrorKind::Nested),
            (
                "(a b) (c d)",
                1,
                PlanErrorKind::TrailingText("(c d)".into()),
            ),
            ("(a b))", 1, PlanErrorKind::TrailingText(")".into())),
            ("0: (a b)", 1, PlanErrorKind::NotAnAction("0:".into())),
        ];
        for (text, line, kind) in cases {
            assert_eq!(error(text), PlanError { line, kind }, "{text:?}");
        }
    }

    #[test]
    fn error_messages_read_well() {
        assert_eq!(
            error("(a)\n\n  pick-up b").to_string(),
            "line 3: expected an action such as `(name arg1 arg2)`, found `pick-up`"
        );
        assert_eq!(
            error("(a b) junk ; comment").to_string(),
            "line 1: unexpected `junk` after the action: one action per line"
        );
    }
}
