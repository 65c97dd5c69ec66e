//! Fast Downward's `output.sas` format (version 3): the translator's output and the search
//! component's input.
//!
//! The file is line based, in this order:
//!
//! ```text
//! begin_version / 3 / end_version
//! begin_metric / 0 or 1 / end_metric
//! N, then N × (begin_variable / name / axiom layer (-1) / domain size / one value name
//!              per line / end_variable)
//! M, then M × (begin_mutex_group / K / K lines `VAR VALUE` / end_mutex_group)
//! begin_state / one value per variable, one per line / end_state
//! begin_goal / K / K lines `VAR VALUE` / end_goal
//! O, then O × (begin_operator / name / P / P prevail lines `VAR VALUE` /
//!              E / E effect lines `0 VAR PRE POST` / cost / end_operator)
//! 0 (the number of axioms)
//! ```
//!
//! A prevail condition is a precondition on a variable the operator does not change; an
//! effect line carries the precondition on its own variable as `PRE`, or `-1` for none.
//! [`read`] merges both into [`Operator::preconditions`]; [`write`] splits them again.
//!
//! Axioms (derived variables, whose axiom layer is not `-1`, and `begin_rule` blocks) and
//! conditional effects (an effect line whose leading condition count is not `0`) are valid
//! Fast Downward input that demoplan does not support: [`read`] reports them as
//! [`SasError::Unsupported`], every other problem as a different variant, so a command line
//! can tell them apart (Fast Downward's exit codes 34 and 33).
//!
//! ```
//! use task::*;
//! let task = Task {
//!     variables: vec![Variable::binary("var0")],
//!     mutexes: vec![],
//!     initial_state: vec![1],
//!     goal: vec![Fact::new(VarId(0), 0)],
//!     operators: vec![Operator {
//!         name: "go".into(),
//!         preconditions: vec![Fact::new(VarId(0), 1)],
//!         effects: vec![Fact::new(VarId(0), 0)],
//!         cost: 1,
//!     }],
//!     use_costs: false,
//! };
//! let text = sas_file::write(&task);
//! assert!(text.contains("begin_operator\ngo\n0\n1\n0 0 1 0\n1\nend_operator\n"));
//! assert_eq!(sas_file::read(&text)?, task);
//! # Ok::<(), sas_file::SasError>(())
//! ```
//!
//! Reading takes time linear in the size of the file, plus sorting each partial
//! assignment by variable; writing takes `O(n log n)` for an operator with `n` facts.

// A reader of untrusted input (issue 23): no arithmetic that can wrap or panic, no
// cast that can truncate; each such operation is checked, saturating or proved in range.
#![deny(clippy::arithmetic_side_effects, clippy::cast_possible_truncation)]

use std::fmt;

use crate::{Fact, Operator, Task, TaskError, VarId, Variable};

/// The only version of the format there is.
const VERSION: u32 = 3;

/// A file [`read`] cannot turn into a [`Task`].
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum SasError {
    /// The text does not follow the format: a missing keyword, a line that is not the
    /// number or fact expected, a premature end, trailing text.
    #[error("line {line}: expected {expected}, found {found}")]
    Syntax {
        /// 1-based line number; one past the last line for a premature end of file.
        line: usize,
        /// What the format requires here.
        expected: String,
        /// What the line holds.
        found: String,
    },
    /// The text follows the format but does not describe a task: a fact naming a variable
    /// or value that does not exist, a variable twice in one partial assignment, an empty
    /// domain.
    #[error("line {line}: {message}")]
    Invalid {
        /// 1-based line number.
        line: usize,
        /// What is wrong.
        message: String,
    },
    /// Valid Fast Downward input that demoplan does not support: axioms, derived variables,
    /// conditional effects.
    #[error("line {line}: {what} are not supported")]
    Unsupported {
        /// 1-based line number.
        line: usize,
        /// The construct, in the plural: `axioms`, `conditional effects`.
        what: String,
    },
    /// The task read breaks one of [`Task::validate`]'s invariants. The line-by-line
    /// checks of [`read`] report every such problem with its line first; this variant
    /// guards against the two drifting apart.
    #[error("{0}")]
    Task(#[from] TaskError),
}

impl SasError {
    /// The 1-based line the error points at, if any.
    pub fn line(&self) -> Option<usize> {
        match self {
            SasError::Syntax { line, .. }
            | SasError::Invalid { line, .. }
            | SasError::Unsupported { line, .. } => Some(*line),
            SasError::Task(_) => None,
        }
    }
}

/// Writes `task` as Fast Downward's translator would.
///
/// Every variable gets axiom layer `-1`; an operator's effects are written in the order of
/// [`Operator::effects`] (sorted by variable), each with the operator's precondition on
/// that variable or `-1`, and its other preconditions as prevail conditions. The output is
/// what [`read`] turns back into `task`, provided the task is valid ([`Task::validate`]),
/// no name contains a line break, and variable names are single words (Fast Downward
/// reads them as such); names are written as they are, never altered.
pub fn write(task: &Task) -> String {
    Sas(task, None).to_string()
}

/// Like [`write`], with `comment` (its line breaks made spaces) on the first variable's
/// name line: `var0 ; COMMENT`. The format has no comment lines, and Fast Downward
/// (26.6) rejects any text after the axioms; it takes a variable's whole name line as
/// its name (a name only its logs show), and [`read`] takes the word before ` ; `. An
/// empty comment, or a task without variables, is written as [`write`] writes it.
pub fn write_commented(task: &Task, comment: &str) -> String {
    let comment = comment.replace(['\n', '\r'], " ");
    Sas(task, Some(comment.as_str()).filter(|c| !c.is_empty())).to_string()
}

/// [`write`]'s formatter, with [`write_commented`]'s comment.
struct Sas<'a>(&'a Task, Option<&'a str>);

impl fmt::Display for Sas<'_> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let task = self.0;
        writeln!(f, "begin_version\n{VERSION}\nend_version")?;
        writeln!(f, "begin_metric\n{}\nend_metric", u8::from(task.use_costs))?;
        writeln!(f, "{}", task.variables.len())?;
        for (i, var) in task.variables.iter().enumerate() {
            let comment = self.1.filter(|_| i == 0).map(|c| format!(" ; {c}"));
            writeln!(
                f,
                "begin_variable\n{}{}\n-1\n{}",
                var.name,
                comment.unwrap_or_default(),
                var.value_names.len()
            )?;
            for value in &var.value_names {
                writeln!(f, "{value}")?;
            }
            writeln!(f, "end_variable")?;
        }
        writeln!(f, "{}", task.mutexes.len())?;
        for group in &task.mutexes {
            writeln!(f, "begin_mutex_group\n{}", group.len())?;
            write_facts(f, group)?;
            writeln!(f, "end_mutex_group")?;
        }
        writeln!(f, "begin_state")?;
        for value in &task.initial_state {
            writeln!(f, "{value}")?;
        }
        writeln!(f, "end_state")?;
        writeln!(f, "begin_goal\n{}", task.goal.len())?;
        write_facts(f, &task.goal)?;
        writeln!(f, "end_goal")?;
        writeln!(f, "{}", task.operators.len())?;
        for op in &task.operators {
            write_operator(f, op)?;
        }
        // No axioms.
        writeln!(f, "0")
    }
}

fn write_facts(f: &mut fmt::Formatter<'_>, facts: &[Fact]) -> fmt::Result {
    for fact in facts {
        writeln!(f, "{} {}", fact.var.0, fact.value)?;
    }
    Ok(())
}

/// Relies on the operator's facts being sorted by variable (it looks them up by binary
/// search), as [`Task::validate`] requires.
fn write_operator(f: &mut fmt::Formatter<'_>, op: &Operator) -> fmt::Result {
    let find = |facts: &[Fact], var: VarId| {
        let i = facts.binary_search_by_key(&var, |fact| fact.var).ok()?;
        facts.get(i).copied()
    };
    let prevail: Vec<Fact> = op
        .preconditions
        .iter()
        .copied()
        .filter(|p| find(&op.effects, p.var).is_none())
        .collect();
    writeln!(f, "begin_operator\n{}\n{}", op.name, prevail.len())?;
    write_facts(f, &prevail)?;
    writeln!(f, "{}", op.effects.len())?;
    for effect in &op.effects {
        match find(&op.preconditions, effect.var) {
            Some(pre) => writeln!(f, "0 {} {} {}", effect.var.0, pre.value, effect.value)?,
            None => writeln!(f, "0 {} -1 {}", effect.var.0, effect.value)?,
        }
    }
    writeln!(f, "{}\nend_operator", op.cost)
}

/// Reads a task from Fast Downward's `output.sas` text.
///
/// Keywords and numbers may carry surrounding spaces; names and value names are taken
/// verbatim from their lines (a variable's name line may end in a comment, ` ; ...`,
/// which is dropped: see [`write_commented`]). Preconditions (prevail conditions and the `PRE` of effect
/// lines) are merged and sorted by variable, as are effects and the goal; mutex groups
/// keep the file's order. Blank lines may follow the axiom count, nothing else.
///
/// Never panics; every error but [`SasError::Task`] carries the line it concerns. A
/// returned task satisfies [`Task::validate`].
pub fn read(text: &str) -> Result<Task, SasError> {
    let mut c = Cursor::new(text);
    c.keyword("begin_version")?;
    let version = c.number::<u32>("the format version")?;
    if version != VERSION {
        return Err(c.syntax(format!("version {VERSION}")));
    }
    c.keyword("end_version")?;
    c.keyword("begin_metric")?;
    let use_costs = match c
        .next_line("0 or 1 (whether the task has action costs)")?
        .trim()
    {
        "0" => false,
        "1" => true,
        _ => return Err(c.syntax("0 or 1 (whether the task has action costs)")),
    };
    c.keyword("end_metric")?;

    let count = c.number::<u32>("the number of variables")?;
    let mut variables = Vec::new();
    for _ in 0..count {
        variables.push(read_variable(&mut c)?);
    }

    let count = c.number::<u32>("the number of mutex groups")?;
    let mut mutexes = Vec::new();
    for _ in 0..count {
        c.keyword("begin_mutex_group")?;
        let size = c.number::<u32>("the number of facts in the mutex group")?;
        let mut group = Vec::new();
        for _ in 0..size {
            group.push(c.fact(&variables, "a fact `VARIABLE VALUE` of the mutex group")?);
        }
        c.keyword("end_mutex_group")?;
        mutexes.push(group);
    }

    c.keyword("begin_state")?;
    let mut init = Vec::new();
    for (i, var) in variables.iter().enumerate() {
        let value = c.number::<u32>(&format!("the initial value of variable {i}"))?;
        if value >= var.domain_size() {
            return Err(c.invalid(format!(
                "initial value {value} of variable {i} ({}) is out of range: it has {} values",
                var.name,
                var.domain_size()
            )));
        }
        init.push(value);
    }
    c.keyword("end_state")?;

    c.keyword("begin_goal")?;
    let size = c.number::<u32>("the number of goal facts")?;
    let mut goal = Vec::new();
    for _ in 0..size {
        let fact = c.fact(&variables, "a goal fact `VARIABLE VALUE`")?;
        goal.push((c.line, fact));
    }
    let goal = sorted_partial(goal, "the goal")?
        .into_iter()
        .map(|(_, fact)| fact)
        .collect();
    c.keyword("end_goal")?;

    let count = c.number::<u32>("the number of operators")?;
    let mut operators = Vec::new();
    for _ in 0..count {
        operators.push(read_operator(&mut c, &variables)?);
    }

    let axioms = c.number::<u32>("the number of axioms")?;
    if axioms > 0 {
        return Err(c.unsupported("axioms"));
    }
    c.end()?;

    let task = Task::new(variables, mutexes, init, goal, operators, use_costs);
    task.validate()?;
    Ok(task)
}

/// A name line without trailing carriage returns. Lines are split at `\n` and one `\r`
/// of a CRLF ending is dropped; a name ending in more of them (the fuzzer wrote one)
/// would lose one more on every write and read, so none are kept: a written task reads
/// back unchanged.
fn without_carriage_returns(line: &str) -> String {
    line.trim_end_matches('\r').to_string()
}

fn read_variable(c: &mut Cursor<'_>) -> Result<Variable, SasError> {
    c.keyword("begin_variable")?;
    let line = c.next_line("a variable name")?;
    // `NAME ; COMMENT`, as `write_commented` writes the first variable.
    let name = line.split_once(" ; ").map_or(line, |(name, _)| name);
    if name.is_empty() || name.contains(char::is_whitespace) {
        return Err(c.syntax("a variable name (one word)"));
    }
    let expected = "an axiom layer (-1)";
    match c.next_line(expected)?.trim().parse::<i64>() {
        Ok(-1) => {}
        Ok(layer) if layer >= 0 => return Err(c.unsupported("derived variables (axiom layers)")),
        _ => return Err(c.syntax(expected)),
    }
    let size = c.number::<u32>("the domain size")?;
    if size == 0 {
        return Err(c.invalid(format!("variable {name} has an empty domain")));
    }
    let mut value_names = Vec::new();
    for _ in 0..size {
        value_names.push(without_carriage_returns(c.next_line("a value name")?));
    }
    c.keyword("end_variable")?;
    Ok(Variable {
        name: name.to_string(),
        value_names,
    })
}

fn read_operator(c: &mut Cursor<'_>, variables: &[Variable]) -> Result<Operator, SasError> {
    c.keyword("begin_operator")?;
    let name = without_carriage_returns(c.next_line("an operator name")?);
    let count = c.number::<u32>("the number of prevail conditions")?;
    let mut prevail = Vec::new();
    for _ in 0..count {
        let fact = c.fact(variables, "a prevail condition `VARIABLE VALUE`")?;
        prevail.push((c.line, fact));
    }
    let count = c.number::<u32>("the number of effects")?;
    let mut effect_preconditions = Vec::new();
    let mut effects = Vec::new();
    for _ in 0..count {
        let (pre, post) = c.effect(variables)?;
        effect_preconditions.extend(pre);
        effects.push((c.line, post));
    }
    let cost = c.number::<u64>("the operator cost (a non-negative integer)")?;
    c.keyword("end_operator")?;

    let prevail = sorted_partial(prevail, &format!("the prevail conditions of `{name}`"))?;
    let effects = sorted_partial(effects, &format!("the effects of `{name}`"))?;
    // A prevail condition is on a variable the operator leaves alone.
    let changed = |var| prevail.binary_search_by_key(&var, |(_, p)| p.var).is_ok();
    if let Some(&(line, effect)) = effects.iter().find(|(_, e)| changed(e.var)) {
        return Err(SasError::Invalid {
            line,
            message: format!(
                "variable {} has both a prevail condition and an effect in `{name}`",
                effect.var.0
            ),
        });
    }
    // Disjoint variables now: prevail ones are unchanged, effect ones distinct.
    let mut preconditions: Vec<Fact> = prevail.iter().map(|&(_, fact)| fact).collect();
    preconditions.extend(effect_preconditions);
    preconditions.sort_by_key(|fact| fact.var);
    Ok(Operator {
        name,
        preconditions,
        effects: effects.into_iter().map(|(_, fact)| fact).collect(),
        cost,
    })
}

/// Sorts facts (with their lines) by variable; a variable twice is an error at the later
/// of its lines.
fn sorted_partial(
    mut facts: Vec<(usize, Fact)>,
    what: &str,
) -> Result<Vec<(usize, Fact)>, SasError> {
    facts.sort_by_key(|&(line, fact)| (fact.var, line));
    for pair in facts.windows(2) {
        if let [(_, a), (line, b)] = pair {
            if a.var == b.var {
                return Err(SasError::Invalid {
                    line: *line,
                    message: format!("variable {} appears twice in {what}", b.var.0),
                });
            }
        }
    }
    Ok(facts)
}

/// The lines of the file, with the number of the line last taken.
struct Cursor<'a> {
    lines: std::str::Lines<'a>,
    /// 1-based number of the line last taken; 0 before the first.
    line: usize,
    /// The line last taken, or `None` after the end of the text.
    current: Option<&'a str>,
}

impl<'a> Cursor<'a> {
    fn new(text: &'a str) -> Cursor<'a> {
        Cursor {
            lines: text.lines(),
            line: 0,
            current: None,
        }
    }

    /// Takes the next line; at the end of the text, an error expecting `expected`.
    fn next_line(&mut self, expected: &str) -> Result<&'a str, SasError> {
        self.line = self.line.saturating_add(1);
        self.current = self.lines.next();
        match self.current {
            Some(line) => Ok(line),
            None => Err(self.syntax(expected)),
        }
    }

    /// A syntax error at the line last taken.
    fn syntax(&self, expected: impl Into<String>) -> SasError {
        let found = match self.current {
            None => "end of file".to_string(),
            Some(line) if line.trim().is_empty() => "an empty line".to_string(),
            Some(line) => {
                const SHOWN: usize = 60;
                let mut shown: String = line.chars().take(SHOWN).collect();
                if line.chars().nth(SHOWN).is_some() {
                    shown.push('…');
                }
                format!("`{shown}`")
            }
        };
        SasError::Syntax {
            line: self.line,
            expected: expected.into(),
            found,
        }
    }

    fn invalid(&self, message: String) -> SasError {
        SasError::Invalid {
            line: self.line,
            message,
        }
    }

    fn unsupported(&self, what: &str) -> SasError {
        SasError::Unsupported {
            line: self.line,
            what: what.to_string(),
        }
    }

    fn keyword(&mut self, keyword: &str) -> Result<(), SasError> {
        let expected = format!("`{keyword}`");
        if self.next_line(&expected)?.trim() == keyword {
            Ok(())
        } else {
            Err(self.syntax(expected))
        }
    }

    /// A line holding one number.
    fn number<T: std::str::FromStr>(&mut self, expected: &str) -> Result<T, SasError> {
        self.next_line(expected)?
            .trim()
            .parse()
            .map_err(|_| self.syntax(expected))
    }

    /// A line `VARIABLE VALUE` naming a value of one of `variables`.
    fn fact(&mut self, variables: &[Variable], expected: &str) -> Result<Fact, SasError> {
        let line = self.next_line(expected)?;
        match parse_numbers::<2>(line) {
            Some([var, value]) => self.check_fact(variables, var, value),
            None => Err(self.syntax(expected)),
        }
    }

    /// An effect line `0 VARIABLE PRE POST`: the precondition on the variable (`PRE`, or
    /// none for `-1`) and the effect.
    fn effect(&mut self, variables: &[Variable]) -> Result<(Option<Fact>, Fact), SasError> {
        let expected = "an effect `0 VARIABLE PRE POST` (PRE a value or -1)";
        let line = self.next_line(expected)?;
        let mut tokens = line.split_whitespace();
        match tokens.next().map(str::parse::<u32>) {
            Some(Ok(0)) => {}
            Some(Ok(_)) => return Err(self.unsupported("conditional effects")),
            _ => return Err(self.syntax(expected)),
        }
        let rest: Vec<&str> = tokens.collect();
        let [var, pre, post] = rest.as_slice() else {
            return Err(self.syntax(expected));
        };
        let (Ok(var), Ok(post)) = (var.parse::<u32>(), post.parse::<u32>()) else {
            return Err(self.syntax(expected));
        };
        let pre = match *pre {
            "-1" => None,
            pre => match pre.parse::<u32>() {
                Ok(value) => Some(self.check_fact(variables, var, value)?),
                Err(_) => return Err(self.syntax(expected)),
            },
        };
        let post = self.check_fact(variables, var, post)?;
        Ok((pre, post))
    }

    fn check_fact(&self, variables: &[Variable], var: u32, value: u32) -> Result<Fact, SasError> {
        let Some(variable) = variables.get(var as usize) else {
            return Err(self.invalid(format!(
                "variable {var} does not exist: the task has {} variables",
                variables.len()
            )));
        };
        if value >= variable.domain_size() {
            return Err(self.invalid(format!(
                "value {value} of variable {var} ({}) is out of range: it has {} values",
                variable.name,
                variable.domain_size()
            )));
        }
        Ok(Fact::new(VarId(var), value))
    }

    /// Only blank lines may remain.
    fn end(&mut self) -> Result<(), SasError> {
        for line in self.lines.by_ref() {
            self.line = self.line.saturating_add(1);
            if !line.trim().is_empty() {
                self.current = Some(line);
                return Err(self.syntax("the end of the file"));
            }
        }
        Ok(())
    }
}

/// Exactly `N` whitespace-separated non-negative numbers.
fn parse_numbers<const N: usize>(line: &str) -> Option<[u32; N]> {
    let mut numbers = [0; N];
    let mut tokens = line.split_whitespace();
    for slot in &mut numbers {
        *slot = tokens.next()?.parse().ok()?;
    }
    match tokens.next() {
        Some(_) => None,
        None => Some(numbers),
    }
}

#[cfg(test)]
#[allow(clippy::arithmetic_side_effects, clippy::cast_possible_truncation)] // tests, not readers
mod tests {
    use super::*;
    use proptest::prelude::*;

    /// A small task in the translator's layout, with every section used. Line numbers
    /// matter to the malformed cases below.
    const SMALL: &str = "\
begin_version
3
end_version
begin_metric
1
end_metric
2
begin_variable
var0
-1
2
Atom p()
NegatedAtom p()
end_variable
begin_variable
var1
-1
3
Atom q(a)
Atom q(b)
<none of those>
end_variable
1
begin_mutex_group
2
1 0
1 1
end_mutex_group
begin_state
1
2
end_state
begin_goal
1
0 0
end_goal
2
begin_operator
make-p a
1
1 0
1
0 0 -1 0
5
end_operator
begin_operator
move b a
0
2
0 0 0 1
0 1 1 0
0
end_operator
0
";

    fn small_task() -> Task {
        let f = |var, value| Fact::new(VarId(var), value);
        Task {
            variables: vec![
                Variable {
                    name: "var0".into(),
                    value_names: vec!["Atom p()".into(), "NegatedAtom p()".into()],
                },
                Variable {
                    name: "var1".into(),
                    value_names: vec![
                        "Atom q(a)".into(),
                        "Atom q(b)".into(),
                        "<none of those>".into(),
                    ],
                },
            ],
            mutexes: vec![vec![f(1, 0), f(1, 1)]],
            initial_state: vec![1, 2],
            goal: vec![f(0, 0)],
            operators: vec![
                Operator {
                    name: "make-p a".into(),
                    preconditions: vec![f(1, 0)],
                    effects: vec![f(0, 0)],
                    cost: 5,
                },
                Operator {
                    name: "move b a".into(),
                    preconditions: vec![f(0, 0), f(1, 1)],
                    effects: vec![f(0, 1), f(1, 0)],
                    cost: 0,
                },
            ],
            use_costs: true,
        }
    }

    /// `SMALL` with its 1-based line `line` replaced by `text` (which may span lines).
    fn edit(line: usize, text: &str) -> String {
        let mut lines: Vec<&str> = SMALL.lines().collect();
        lines[line - 1] = text;
        lines.join("\n") + "\n"
    }

    #[derive(Debug, PartialEq)]
    enum Kind {
        Syntax,
        Invalid,
        Unsupported,
    }

    /// `read(input)` fails with an error of `kind` at `line`.
    fn check_error(input: &str, kind: Kind, line: usize) {
        let error = read(input).expect_err("input should be rejected");
        let found = match error {
            SasError::Syntax { .. } => Kind::Syntax,
            SasError::Invalid { .. } => Kind::Invalid,
            SasError::Unsupported { .. } => Kind::Unsupported,
            SasError::Task(_) => panic!("error without a line: {error}"),
        };
        assert_eq!((found, error.line()), (kind, Some(line)), "{error}");
    }

    #[test]
    fn reads_the_small_task() {
        assert_eq!(read(SMALL), Ok(small_task()));
    }

    #[test]
    fn writes_the_small_task_as_the_translator_does() {
        assert_eq!(write(&small_task()), SMALL);
    }

    #[test]
    fn sorts_effects_and_merges_preconditions() {
        // The translator may list effects out of variable order (after reordering).
        let text = edit(50, "0 1 1 0").replacen("0 1 1 0\n0 1 1 0", "0 1 1 0\n0 0 0 1", 1);
        assert!(text.contains("2\n0 1 1 0\n0 0 0 1\n0\nend_operator"));
        assert_eq!(read(&text), Ok(small_task()));
    }

    #[test]
    fn mutex_groups_keep_their_order() {
        let text = edit(26, "1 1").replacen("1 1\n1 1", "1 1\n1 0", 1);
        let task = read(&text).unwrap();
        let f = |var, value| Fact::new(VarId(var), value);
        assert_eq!(task.mutexes, vec![vec![f(1, 1), f(1, 0)]]);
        assert_eq!(write(&task), text);
    }

    #[test]
    fn tolerates_spaces_crlf_and_trailing_blank_lines() {
        let text = SMALL
            .replace("end_goal", "  end_goal ")
            .replace('\n', "\r\n")
            + "\n \n";
        assert_eq!(read(&text), Ok(small_task()));
    }

    #[test]
    fn a_comment_on_the_first_name_line_reads_back_as_the_task() {
        let task = small_task();
        let text = write_commented(&task, "translator options: h2_mutexes\nmore");
        let first = text.lines().position(|l| l == "begin_variable").unwrap() + 1;
        let name_line = text.lines().nth(first).unwrap();
        assert_eq!(
            name_line,
            format!(
                "{} ; translator options: h2_mutexes more",
                task.variables[0].name
            )
        );
        assert_eq!(
            text.matches(" ; ").count(),
            1,
            "only the first variable's line"
        );
        assert_eq!(read(&text), Ok(task.clone()));
        assert_eq!(write_commented(&task, ""), write(&task));
        assert!(
            read(&SMALL.replacen("var0", "var0 ;x", 1)).is_err(),
            "` ; ` with its spaces"
        );
    }

    /// Found by fuzzing (`fuzz/run`, target `sas_file`): an operator name ending in
    /// several carriage returns lost one on every write and read.
    #[test]
    fn names_ending_in_carriage_returns_read_back_unchanged() {
        let lines: Vec<&str> = SMALL.lines().collect();
        let at = lines.iter().position(|l| *l == "begin_operator").unwrap() + 1;
        let name = lines[at];
        let text = SMALL.replacen(&format!("\n{name}\n"), &format!("\n{name}\r\r\r\n"), 1);
        assert_ne!(text, SMALL);
        let task = read(&text).unwrap();
        assert_eq!(task.operators[0].name, name);
        assert_eq!(read(&write(&task)), Ok(task));
    }

    #[test]
    fn unit_cost_and_empty_task() {
        let task = Task {
            variables: vec![],
            mutexes: vec![],
            initial_state: vec![],
            goal: vec![],
            operators: vec![],
            use_costs: false,
        };
        let text = write(&task);
        assert_eq!(
            text,
            "begin_version\n3\nend_version\nbegin_metric\n0\nend_metric\n0\n0\n\
             begin_state\nend_state\nbegin_goal\n0\nend_goal\n0\n0\n"
        );
        assert_eq!(read(&text), Ok(task));
    }

    #[test]
    fn messages_say_what_was_expected_and_found() {
        let costs =
            "line 5: expected 0 or 1 (whether the task has action costs), found an empty line";
        let range = "line 27: value 3 of variable 1 (var1) is out of range: it has 3 values";
        for (input, message) in [
            (
                String::new(),
                "line 1: expected `begin_version`, found end of file",
            ),
            (edit(2, "2"), "line 2: expected version 3, found `2`"),
            (edit(5, ""), costs),
            (edit(27, "1 3"), range),
            (
                edit(43, "1 1 0 0 -1 0"),
                "line 43: conditional effects are not supported",
            ),
            (edit(54, "1"), "line 54: axioms are not supported"),
        ] {
            assert_eq!(read(&input).unwrap_err().to_string(), message);
        }
    }

    #[test]
    fn malformed_inputs() {
        use Kind::*;
        // A case a line: the line of `SMALL` edited, its new text, the kind of error and
        // the line it names, and what the case is. "variable count too large": a huge
        // count must not allocate; the file ends long before.
        let edits = "
1  | begin_versio | syntax      | 1  | misspelt keyword
2  | 2            | syntax      | 2  | old version
5  | 2            | syntax      | 5  | metric 2
7  | x            | syntax      | 7  | variable count not a number
7  | 99999999999  | syntax      | 7  | variable count overflows
7  | 4294967295   | syntax      | 23 | variable count too large
9  | var 0        | syntax      | 9  | variable name with a space
10 | 0            | unsupported | 10 | derived variable
10 | none         | syntax      | 10 | axiom layer not a number
11 | 0            | invalid     | 11 | empty domain
18 | 4            | syntax      | 23 | domain size too large
26 | 2 0          | invalid     | 26 | mutex fact of a missing variable
27 | 1 3          | invalid     | 27 | mutex fact out of range
27 | 1 1 1        | syntax      | 27 | mutex fact with three numbers
30 | 1 0          | syntax      | 30 | two numbers in the state
31 | 3            | invalid     | 31 | initial value out of range
31 | end_state    | syntax      | 31 | state too short
43 | 1 1 0 0 -1 0 | unsupported | 43 | conditional effect
43 | 0 0 -2 0     | syntax      | 43 | effect precondition -2
43 | 0 0 0        | syntax      | 43 | effect with three numbers
51 | 0 1 1 3      | invalid     | 51 | effect post out of range
51 | 0 1 3 0      | invalid     | 51 | effect pre out of range
41 | 0 1          | invalid     | 43 | prevail on a changed variable
44 | -5           | syntax      | 44 | negative cost
45 | end_op       | syntax      | 45 | missing end_operator
54 | 1            | unsupported | 54 | axioms
";
        for case in edits.lines().filter(|l| !l.is_empty()) {
            let fields: Vec<&str> = case.split('|').map(str::trim).collect();
            let [line, text, kind, at, name] = fields[..] else {
                panic!("not a case: {case}")
            };
            let kind = match kind {
                "syntax" => Syntax,
                "invalid" => Invalid,
                "unsupported" => Unsupported,
                other => panic!("{name}: no kind {other}"),
            };
            eprintln!("case: {name}");
            check_error(
                &edit(line.parse().unwrap(), text),
                kind,
                at.parse().unwrap(),
            );
        }
        // The empty file, edits that add a line, a cut file and one with more after it.
        let cases: Vec<(&str, String, Kind, usize)> = vec![
            ("empty input", String::new(), Syntax, 1),
            (
                "goal variable twice",
                edit(34, "2").replacen("0 0\nend_goal", "0 0\n0 1\nend_goal", 1),
                Invalid,
                36,
            ),
            (
                "prevail twice",
                edit(40, "2").replacen("1 0\n1\n0 0", "1 0\n1 1\n1\n0 0", 1),
                Invalid,
                42,
            ),
            (
                "effect twice",
                edit(49, "3").replacen("0 1 1 0\n0", "0 1 1 0\n0 1 -1 2\n0", 1),
                Invalid,
                52,
            ),
            (
                "truncated",
                SMALL.lines().take(40).collect::<Vec<_>>().join("\n"),
                Syntax,
                41,
            ),
            ("trailing text", format!("{SMALL}\njunk\n"), Syntax, 56),
        ];
        for (name, input, kind, line) in cases {
            eprintln!("case: {name}");
            check_error(&input, kind, line);
        }
    }

    /// A partial assignment over variables with these domain sizes, sorted by variable.
    fn partial(domains: &[u32]) -> impl Strategy<Value = Vec<Fact>> {
        let values: Vec<_> = domains
            .iter()
            .map(|&d| proptest::option::of(0..d))
            .collect();
        values.prop_map(|values| {
            values
                .into_iter()
                .enumerate()
                .filter_map(|(var, value)| Some(Fact::new(VarId(var as u32), value?)))
                .collect()
        })
    }

    /// Mutex groups: any facts, in any order.
    fn mutexes(domains: &[u32]) -> BoxedStrategy<Vec<Vec<Fact>>> {
        if domains.is_empty() {
            return Just(vec![]).boxed();
        }
        let domains = domains.to_vec();
        let fact = (0..domains.len()).prop_flat_map(move |var| {
            (0..domains[var]).prop_map(move |value| Fact::new(VarId(var as u32), value))
        });
        proptest::collection::vec(proptest::collection::vec(fact, 0..4), 0..3).boxed()
    }

    /// Valid tasks whose names the format can carry: no line breaks, one-word variable
    /// names.
    fn task() -> impl Strategy<Value = Task> {
        proptest::collection::vec(1u32..5, 0..6).prop_flat_map(|domains| {
            let variables: Vec<_> = domains
                .iter()
                .map(|&d| {
                    (
                        "[a-z][a-z0-9_-]{0,6}",
                        proptest::collection::vec("\\PC{0,10}", d as usize),
                    )
                        .prop_map(|(name, value_names)| Variable { name, value_names })
                })
                .collect();
            let initial_state: Vec<_> = domains.iter().map(|&d| 0..d).collect();
            let operator = (
                "\\PC{0,16}",
                partial(&domains),
                partial(&domains),
                any::<u64>(),
            )
                .prop_map(|(name, preconditions, effects, cost)| Operator {
                    name,
                    preconditions,
                    effects,
                    cost,
                });
            (
                variables,
                mutexes(&domains),
                initial_state,
                partial(&domains),
                proptest::collection::vec(operator, 0..5),
                any::<bool>(),
            )
                .prop_map(|(v, m, i, g, o, u)| Task::new(v, m, i, g, o, u))
        })
    }

    proptest! {
        #[test]
        fn read_inverts_write(task in task()) {
            prop_assert_eq!(task.validate(), Ok(()));
            let text = write(&task);
            prop_assert_eq!(read(&text), Ok(task));
        }

        /// Damaged files never panic the reader, and whatever it accepts is valid and
        /// written back the same way.
        #[test]
        fn damaged_files_do_not_panic(
            task in task(),
            edits in proptest::collection::vec(
                (any::<prop::sample::Index>(), 0..4u8, "-?[0-9]{1,3}( -?[0-9]{1,3}){0,4}|[a-z_]{0,12}"),
                1..4,
            ),
        ) {
            let text = write(&task);
            let mut lines: Vec<String> = text.lines().map(str::to_string).collect();
            for (at, action, replacement) in edits {
                let i = at.index(lines.len() + 1);
                match action {
                    0 if i < lines.len() => { lines.remove(i); }
                    1 if i < lines.len() => lines[i] = replacement,
                    2 if i < lines.len() => lines.insert(i, lines[i].clone()),
                    _ => lines.insert(i, replacement),
                }
            }
            let damaged = lines.join("\n");
            if let Ok(read_back) = read(&damaged) {
                prop_assert_eq!(read_back.validate(), Ok(()));
                prop_assert_eq!(read(&write(&read_back)), Ok(read_back));
            }
        }

        #[test]
        fn arbitrary_text_does_not_panic(text in "\\PC{0,200}") {
            let _ = read(&text);
        }
    }
}
