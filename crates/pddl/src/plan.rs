//! Plans as text: one ground action per line, as Fast Downward writes them, and the
//! plan-step type every crate that reads or writes plans shares.

use std::fmt;

/// One step of a plan: a ground action, lowercase, as `(name arg1 arg2)` says it.
#[derive(Debug, Clone, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct Step {
    /// The action's name.
    pub action: String,
    /// The objects it is applied to, in order.
    pub args: Vec<String>,
}

impl Step {
    /// A step from its action and arguments.
    pub fn new(
        action: impl Into<String>,
        args: impl IntoIterator<Item = impl Into<String>>,
    ) -> Step {
        Step {
            action: action.into(),
            args: args.into_iter().map(Into::into).collect(),
        }
    }

    /// The step named by a ground action's name as a finite-domain task states it,
    /// `name arg1 arg2` (Fast Downward's `output.sas` and the translator's operator
    /// names): the words, without parentheses. `None` for a name without words.
    pub fn from_words(name: &str) -> Option<Step> {
        let mut words = name.split_whitespace();
        let action = words.next()?;
        Some(Step::new(action, words))
    }

    /// The step as a ground action's name: `name arg1 arg2`, the inverse of
    /// [`Step::from_words`].
    pub fn words(&self) -> String {
        let mut s = self.action.clone();
        for a in &self.args {
            s.push(' ');
            s.push_str(a);
        }
        s
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

/// A sequential plan: the steps in the order they are executed, and for a plan read
/// from a text the line each step was read from.
#[derive(Debug, Clone, Default, PartialEq, Eq, Hash)]
pub struct Plan {
    /// The steps.
    pub steps: Vec<Step>,
    /// The 1-based line of each step in the text it was read from; empty for a plan
    /// built in code.
    pub lines: Vec<usize>,
}

impl Plan {
    /// A plan built in code (no lines).
    pub fn new(steps: Vec<Step>) -> Plan {
        Plan {
            steps,
            lines: Vec::new(),
        }
    }

    /// The 1-based line step `index` was read from, 0 for a step built in code.
    pub fn line(&self, index: usize) -> usize {
        self.lines.get(index).copied().unwrap_or(0)
    }
}

/// Writes the plan's steps, one per line (no cost line: see [`write_plan`]).
impl fmt::Display for Plan {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        for s in &self.steps {
            writeln!(f, "{s}")?;
        }
        Ok(())
    }
}

/// What the cost line of a plan file calls the cost, as Fast Downward does: `unit cost`
/// when every operator of the task costs 1, `general cost` otherwise.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum CostKind {
    /// Every operator of the task costs 1 (so the cost is the plan's length).
    Unit,
    /// Some operator costs other than 1.
    General,
}

impl CostKind {
    /// The kind for a task whose operators cost `costs`: unit if and only if every one
    /// costs 1 (a task without operators is unit cost).
    pub fn of_costs(costs: impl IntoIterator<Item = u64>) -> CostKind {
        if costs.into_iter().all(|c| c == 1) {
            CostKind::Unit
        } else {
            CostKind::General
        }
    }

    /// `unit cost` or `general cost`, as the plan file says it.
    pub fn words(self) -> &'static str {
        match self {
            CostKind::Unit => "unit cost",
            CostKind::General => "general cost",
        }
    }
}

/// A plan file as Fast Downward writes one: `(name arg1 arg2)` per step and the closing
/// `; cost = N (unit cost)` or `(general cost)` line. The one writer of plan files.
pub fn write_plan(steps: &[Step], cost: u64, kind: CostKind) -> String {
    let mut s = String::new();
    for step in steps {
        s.push_str(&step.to_string());
        s.push('\n');
    }
    s.push_str(&format!("; cost = {cost} ({})\n", kind.words()));
    s
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
    let mut plan = Plan::default();
    for (index, raw) in text.lines().enumerate() {
        let line = index + 1;
        let content = raw.split(';').next().unwrap_or_default().trim();
        if content.is_empty() {
            continue;
        }
        let step = parse_step(content).map_err(|kind| PlanError { line, kind })?;
        plan.steps.push(step);
        plan.lines.push(line);
    }
    Ok(plan)
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
            steps: vec![Step::new("pick-up", ["b"]), Step::new("stack", ["b", "a"])],
            lines: vec![3, 4],
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

    #[test]
    fn plan_files_say_unit_cost_only_when_every_operator_costs_one() {
        let steps = [Step::new("pick-up", ["b"]), Step::new("stack", ["b", "a"])];
        assert_eq!(CostKind::of_costs([1, 1, 1]), CostKind::Unit);
        assert_eq!(CostKind::of_costs([]), CostKind::Unit);
        assert_eq!(CostKind::of_costs([1, 0, 1]), CostKind::General);
        assert_eq!(CostKind::of_costs([2]), CostKind::General);
        assert_eq!(
            write_plan(&steps, 2, CostKind::of_costs([1, 1])),
            "(pick-up b)\n(stack b a)\n; cost = 2 (unit cost)\n"
        );
        assert_eq!(
            write_plan(&steps, 7, CostKind::of_costs([1, 6])),
            "(pick-up b)\n(stack b a)\n; cost = 7 (general cost)\n"
        );
        // What the writer writes reads back as the same steps.
        let text = write_plan(&steps, 7, CostKind::General);
        assert_eq!(parse_plan(&text).map(|p| p.steps), Ok(steps.to_vec()));
    }

    #[test]
    fn operator_names_are_the_steps_words() {
        let step = Step::new("stack", ["b", "a"]);
        assert_eq!(step.words(), "stack b a");
        assert_eq!(Step::from_words("stack  b a"), Some(step));
        assert_eq!(
            Step::from_words("noop"),
            Some(Step::new("noop", [] as [&str; 0]))
        );
        assert_eq!(Step::from_words("  "), None);
    }
}
