//! A library as text for people: the per-type summary `learn` prints, the operator
//! cards of `operators` (the paper's Figure 2, as text and as Markdown), and a domain
//! file with a comment block saying what it holds. Formatting only, no I/O.

use std::fmt::Write as _;

use segment::Activity;

use crate::{domain, per_type, Level, Library, Ranked};

/// The priority levels, a line each: the priority, its operators, and how many of each
/// type (what `domain` lists without an output file).
pub fn levels_table(levels: &[Level<'_>]) -> String {
    let mut s = format!(
        "{:>5} {:>9}  per type (reach, take, put, stack, idle)\n",
        "prio", "operators"
    );
    for l in levels {
        let counts = per_type(&l.operators);
        let _ = writeln!(s, "{:>5} {:>9}  {:?}", l.prio, l.operators.len(), counts);
    }
    s
}

/// Per type: activities, operators, and each operator's count and cost; in a library of
/// generalised operators, a line says from how many demonstrated ones; last, what mending
/// did and the changes no hand caused.
pub fn summary_table(library: &Library) -> String {
    let mut s = String::new();
    let _ = writeln!(
        s,
        "{:<6} {:>10} {:>9}  operators (name count/cost)",
        "type", "activities", "operators"
    );
    for a in Activity::OPERATOR_ORDER {
        let ranked = library.ranked_type(a);
        let list: Vec<String> = ranked
            .iter()
            .map(|r| {
                let mark = if r.operator().has_effects() { "" } else { "*" };
                format!("{}{mark} {}/{}", r.name(), r.count(), r.cost)
            })
            .collect();
        let _ = writeln!(
            s,
            "{:<6} {:>10} {:>9}  {}",
            a.name(),
            library.type_count(a),
            ranked.len(),
            list.join(", ")
        );
    }
    let _ = writeln!(
        s,
        "{:<6} {:>10} {:>9}  (* changes nothing: left out of domains)",
        "all",
        library.segments(),
        library.len()
    );
    if library.form() == crate::OperatorForm::Generalised {
        let _ = writeln!(
            s,
            "generalised: {} operators from {} demonstrated ones (docs/operators.md)",
            library.len(),
            library.specific_entries().count()
        );
    }
    s.push_str(&library.mend_counts().line(library.uncaused()));
    s
}

/// Every fact an operator mentions, with its value in the precondition and effect:
/// `Some(true)`, `Some(false)` or `None` (not mentioned).
fn card_rows(r: &Ranked<'_>) -> Vec<(String, Option<bool>, Option<bool>)> {
    let op = r.operator();
    let names = op.param_names();
    let mut facts: Vec<crate::LiftedFact> = op
        .pre_positive
        .iter()
        .chain(&op.pre_negative)
        .chain(&op.add)
        .chain(&op.delete)
        .copied()
        .collect();
    facts.sort_unstable();
    facts.dedup();
    facts
        .iter()
        .map(|f| {
            let pre = if op.pre_positive.contains(f) {
                Some(true)
            } else if op.pre_negative.contains(f) {
                Some(false)
            } else {
                None
            };
            let eff = if op.add.contains(f) {
                Some(true)
            } else if op.delete.contains(f) {
                Some(false)
            } else {
                None
            };
            (crate::fact_text(f, &names), pre, eff)
        })
        .collect()
}

fn value(v: Option<bool>) -> &'static str {
    match v {
        Some(true) => "true",
        Some(false) => "false",
        None => "",
    }
}

fn header_line(r: &Ranked<'_>) -> String {
    let op = r.operator();
    let params: Vec<String> = op
        .param_names()
        .iter()
        .zip(&op.params)
        .map(|(n, t)| format!("{n} - {}", t.name()))
        .collect();
    format!(
        "{} ({}, count {}, cost {}, id {}): {}",
        r.name(),
        op.activity.name(),
        r.count(),
        r.cost,
        op.id(),
        params.join(", ")
    )
}

fn supporters(r: &Ranked<'_>) -> String {
    let list: Vec<String> = r
        .entry
        .provenance
        .iter()
        .map(|p| format!("{} {} {:.2}-{:.2} s", p.recording, p.hand, p.start, p.end))
        .collect();
    list.join("; ")
}

/// Operator cards as text: preconditions and effects side by side.
pub fn cards_text(library: &Library) -> String {
    let mut s = String::new();
    for r in library.ranked() {
        let _ = writeln!(s, "{}", header_line(&r));
        if !r.operator().has_effects() {
            let _ = writeln!(s, "  (changes nothing: left out of domains by default)");
        }
        let rows = card_rows(&r);
        let width = rows.iter().map(|x| x.0.len()).max().unwrap_or(4).max(4);
        let _ = writeln!(s, "  {:<width$}  {:<12}  effect", "fact", "precondition");
        for (fact, pre, eff) in rows {
            let _ = writeln!(s, "  {fact:<width$}  {:<12}  {}", value(pre), value(eff));
        }
        let _ = writeln!(s, "  seen in: {}\n", supporters(&r));
    }
    s
}

/// Operator cards as Markdown, like the paper's Figure 2.
pub fn cards_markdown(library: &Library) -> String {
    let mut s = String::from("# Operator cards\n\n");
    let _ = writeln!(
        s,
        "{} operators from {} activities of {} recordings; cost = ceil({} * (1 - count / \
         type count)).\n",
        library.len(),
        library.segments(),
        library.recordings().count(),
        library.lambda
    );
    for r in library.ranked() {
        let op = r.operator();
        let _ = writeln!(
            s,
            "## {} ({}, count {}, cost {})\n",
            r.name(),
            op.activity.name(),
            r.count(),
            r.cost
        );
        let params: Vec<String> = op
            .param_names()
            .iter()
            .zip(&op.params)
            .map(|(n, t)| format!("`{n} - {}`", t.name()))
            .collect();
        let _ = writeln!(s, "Parameters: {}. Id `{}`.\n", params.join(", "), op.id());
        if !op.has_effects() {
            let _ = writeln!(s, "Changes nothing: left out of domains by default.\n");
        }
        let _ = writeln!(s, "| fact | precondition | effect |\n|---|---|---|");
        for (fact, pre, eff) in card_rows(&r) {
            let _ = writeln!(s, "| `{fact}` | {} | {} |", value(pre), value(eff));
        }
        let _ = writeln!(s, "\nSeen in: {}.\n", supporters(&r));
    }
    s
}

/// A domain file's text with a comment block saying what it is.
pub fn domain_text(library: &Library, operators: &[Ranked<'_>], what: &str) -> String {
    let counts = per_type(operators);
    let per: Vec<String> = Activity::OPERATOR_ORDER
        .iter()
        .zip(counts)
        .map(|(a, n)| format!("{} {n}", a.operator_name()))
        .collect();
    format!(
        "; demoplan domain: {what}, {} operators ({}), from {} activities of {} recordings.\n\
         ; Costs: ceil({} * (1 - count / type count)).\n{}",
        operators.len(),
        per.join(", "),
        library.segments(),
        library.recordings().count(),
        library.lambda,
        domain("demoplan", operators)
    )
}
