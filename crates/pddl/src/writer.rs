//! The canonical writer: deterministic, readable, lowercase PDDL.
//!
//! Layout: one section per line group, one fact or literal per line, typed lists grouped
//! by runs of equal types. `parse(write(x)) == x` for every AST the parser can produce.
//! An untyped run that precedes a typed one is written with `- object`, since PDDL would
//! otherwise give it the later type.

use std::fmt::{self, Write};

use crate::ast::*;

const INDENT: &str = "  ";

impl fmt::Display for Domain {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        writeln!(f, "(define (domain {})", self.name.text)?;
        write_requirements(f, &self.requirements)?;
        if !self.types.is_empty() {
            write_typed_section(f, ":types", &self.types)?;
        }
        if !self.constants.is_empty() {
            write_typed_section(f, ":constants", &self.constants)?;
        }
        if !self.predicates.is_empty() {
            writeln!(f, "{INDENT}(:predicates")?;
            for (i, p) in self.predicates.iter().enumerate() {
                let close = if i + 1 == self.predicates.len() {
                    ")"
                } else {
                    ""
                };
                writeln!(
                    f,
                    "{INDENT}{INDENT}({}{}){close}",
                    p.name.text,
                    params_suffix(&p.params)
                )?;
            }
        }
        if !self.functions.is_empty() {
            writeln!(f, "{INDENT}(:functions")?;
            for (i, func) in self.functions.iter().enumerate() {
                let close = if i + 1 == self.functions.len() {
                    ")"
                } else {
                    ""
                };
                writeln!(
                    f,
                    "{INDENT}{INDENT}({}{}) - number{close}",
                    func.name.text,
                    params_suffix(&func.params)
                )?;
            }
        }
        for a in &self.actions {
            write_action(f, a)?;
        }
        writeln!(f, ")")
    }
}

impl fmt::Display for Problem {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        writeln!(f, "(define (problem {})", self.name.text)?;
        writeln!(f, "{INDENT}(:domain {})", self.domain.text)?;
        write_requirements(f, &self.requirements)?;
        if !self.objects.is_empty() {
            write_typed_section(f, ":objects", &self.objects)?;
        }
        writeln!(f, "{INDENT}(:init")?;
        for entry in &self.init {
            match entry {
                InitEntry::Fact(a) => writeln!(f, "{INDENT}{INDENT}{}", atom(a))?,
                InitEntry::FunctionValue { term, value } => writeln!(
                    f,
                    "{INDENT}{INDENT}(= {} {})",
                    function_term(term),
                    value.value
                )?,
            }
        }
        writeln!(f, "{INDENT})")?;
        write!(f, "{INDENT}(:goal ")?;
        write_conjunction(f, &self.goal, 2)?;
        writeln!(f, ")")?;
        if self.metric.is_some() {
            writeln!(f, "{INDENT}(:metric minimize (total-cost))")?;
        }
        writeln!(f, ")")
    }
}

fn write_requirements(f: &mut fmt::Formatter<'_>, reqs: &[Requirement]) -> fmt::Result {
    if reqs.is_empty() {
        return Ok(());
    }
    let names: Vec<&str> = reqs.iter().map(|r| r.name.as_str()).collect();
    writeln!(f, "{INDENT}(:requirements {})", names.join(" "))
}

/// Runs of consecutive items with equal types.
fn type_runs(items: &[Typed]) -> Vec<(&[Typed], Option<&Type>)> {
    let mut runs = Vec::new();
    let mut start = 0;
    for i in 1..=items.len() {
        if i == items.len() || items[i].ty != items[start].ty {
            runs.push((&items[start..i], items[start].ty.as_ref()));
            start = i;
        }
    }
    runs
}

fn type_text(ty: &Type) -> String {
    match ty {
        Type::Named(n) => n.text.clone(),
        Type::Either(ns) => {
            let names: Vec<&str> = ns.iter().map(|n| n.as_str()).collect();
            format!("(either {})", names.join(" "))
        }
    }
}

/// `a b - t c - u d`, one string.
fn typed_list_text(items: &[Typed]) -> Vec<String> {
    let runs = type_runs(items);
    let last = runs.len().saturating_sub(1);
    runs.iter()
        .enumerate()
        .map(|(i, (run, ty))| {
            let names: Vec<&str> = run.iter().map(|t| t.name.as_str()).collect();
            match ty {
                Some(ty) => format!("{} - {}", names.join(" "), type_text(ty)),
                None if i == last => names.join(" "),
                None => format!("{} - object", names.join(" ")),
            }
        })
        .collect()
}

fn params_suffix(params: &[Typed]) -> String {
    let text = typed_list_text(params).join(" ");
    if text.is_empty() {
        text
    } else {
        format!(" {text}")
    }
}

fn write_typed_section(f: &mut fmt::Formatter<'_>, keyword: &str, items: &[Typed]) -> fmt::Result {
    let groups = typed_list_text(items);
    if groups.len() == 1 {
        return writeln!(f, "{INDENT}({keyword} {})", groups[0]);
    }
    writeln!(f, "{INDENT}({keyword}")?;
    for (i, g) in groups.iter().enumerate() {
        let close = if i + 1 == groups.len() { ")" } else { "" };
        writeln!(f, "{INDENT}{INDENT}{g}{close}")?;
    }
    Ok(())
}

fn term_text(t: &Term) -> &str {
    t.name().as_str()
}

fn atom(a: &Atom) -> String {
    let mut s = format!("({}", a.predicate.text);
    for t in &a.args {
        s.push(' ');
        s.push_str(term_text(t));
    }
    s.push(')');
    s
}

fn literal(l: &Literal) -> String {
    if l.positive {
        atom(&l.atom)
    } else {
        format!("(not {})", atom(&l.atom))
    }
}

fn function_term(t: &FunctionTerm) -> String {
    let mut s = format!("({}", t.function.text);
    for a in &t.args {
        let _ = write!(s, " {}", term_text(a));
    }
    s.push(')');
    s
}

/// `(and\n  lit\n  lit)` at the given indentation depth; a single literal stands alone.
fn write_conjunction_of(f: &mut fmt::Formatter<'_>, lines: &[String], depth: usize) -> fmt::Result {
    match lines {
        [] => write!(f, "(and)"),
        [only] => write!(f, "{only}"),
        _ => {
            write!(f, "(and")?;
            for l in lines {
                write!(f, "\n{}{l}", INDENT.repeat(depth))?;
            }
            write!(f, ")")
        }
    }
}

fn write_conjunction(f: &mut fmt::Formatter<'_>, lits: &[Literal], depth: usize) -> fmt::Result {
    let lines: Vec<String> = lits.iter().map(literal).collect();
    write_conjunction_of(f, &lines, depth)
}

fn write_action(f: &mut fmt::Formatter<'_>, a: &Action) -> fmt::Result {
    writeln!(f, "{INDENT}(:action {}", a.name.text)?;
    writeln!(
        f,
        "{INDENT}{INDENT}:parameters ({})",
        typed_list_text(&a.params).join(" ")
    )?;
    write!(f, "{INDENT}{INDENT}:precondition ")?;
    write_conjunction(f, &a.precondition, 3)?;
    writeln!(f)?;
    write!(f, "{INDENT}{INDENT}:effect ")?;
    let lines: Vec<String> = a
        .effects
        .iter()
        .map(|e| match e {
            Effect::Add(x) => atom(x),
            Effect::Delete(x) => format!("(not {})", atom(x)),
            Effect::IncreaseCost(CostExpr::Constant(n)) => {
                format!("(increase (total-cost) {})", n.value)
            }
            Effect::IncreaseCost(CostExpr::Function(t)) => {
                format!("(increase (total-cost) {})", function_term(t))
            }
        })
        .collect();
    write_conjunction_of(f, &lines, 3)?;
    writeln!(f, ")")
}
