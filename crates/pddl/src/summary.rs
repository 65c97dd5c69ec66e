//! What `demoplan check` says about a domain and a problem: counts in rows of a key and
//! a value, in a fixed order.

use crate::{Domain, InitEntry, Problem};

/// A summary row: what is counted, and its value as text.
pub type SummaryRow = (&'static str, String);

/// What `demoplan check` prints: the domain (named with `domain_file`) and its rows, then
/// the problem (named with its file) and its rows, a key padded to 22 columns a line.
pub fn summary_text(
    domain: &Domain,
    domain_file: &str,
    problem: Option<(&Problem, &str)>,
) -> String {
    let mut out = String::new();
    let mut line = |key: &str, value: &str| out.push_str(&format!("{key:<22} {value}\n"));
    line("domain", &format!("{} ({domain_file})", domain.name.text));
    for (key, value) in domain.summary(problem.map(|(p, _)| p)) {
        line(key, &value);
    }
    if let Some((problem, file)) = problem {
        line("problem", &format!("{} ({file})", problem.name.text));
        for (key, value) in problem.summary() {
            line(key, &value);
        }
    }
    out
}

impl Domain {
    /// Requirements declared and used (with `problem`, what the pair uses), then the
    /// number of distinct types, constants, predicates, functions and actions.
    pub fn summary(&self, problem: Option<&Problem>) -> Vec<SummaryRow> {
        let declared: Vec<&str> = self.requirements.iter().map(|r| r.name.as_str()).collect();
        let mut types: Vec<&str> = self.types.iter().map(|t| t.name.as_str()).collect();
        types.sort_unstable();
        types.dedup();
        vec![
            (
                "requirements declared",
                if declared.is_empty() {
                    "(none)".into()
                } else {
                    declared.join(" ")
                },
            ),
            (
                "requirements used",
                self.used_requirements(problem).join(" "),
            ),
            ("types", types.len().to_string()),
            ("constants", self.constants.len().to_string()),
            ("predicates", self.predicates.len().to_string()),
            ("functions", self.functions.len().to_string()),
            ("actions", self.actions.len().to_string()),
        ]
    }
}

impl Problem {
    /// Objects, initial facts and function values, goal literals (how many negative)
    /// and the metric.
    pub fn summary(&self) -> Vec<SummaryRow> {
        let facts = self
            .init
            .iter()
            .filter(|e| matches!(e, InitEntry::Fact(_)))
            .count();
        let negative = self.goal.iter().filter(|l| !l.positive).count();
        vec![
            ("objects", self.objects.len().to_string()),
            (
                "init",
                format!(
                    "{facts} facts, {} function values",
                    self.init.len().saturating_sub(facts)
                ),
            ),
            (
                "goal",
                format!("{} literals ({negative} negative)", self.goal.len()),
            ),
            (
                "metric",
                if self.metric.is_some() {
                    "minimize (total-cost)"
                } else {
                    "(none)"
                }
                .into(),
            ),
        ]
    }
}

#[cfg(test)]
mod tests {
    use crate::{parse_domain, parse_problem};

    #[test]
    fn a_summary_counts_what_the_files_declare() {
        let domain = parse_domain(
            "(define (domain d) (:requirements :strips :typing) (:types a b)
             (:predicates (p ?x - a) (q)) (:action go :parameters (?x - a)
             :precondition (p ?x) :effect (q)))",
        )
        .unwrap();
        let problem = parse_problem(
            "(define (problem p) (:domain d) (:objects o - a) (:init (p o))
             (:goal (and (q) (not (p o)))))",
        )
        .unwrap();
        let rows = domain.summary(Some(&problem));
        let value = |key: &str| rows.iter().find(|r| r.0 == key).map(|r| r.1.as_str());
        assert_eq!(value("requirements declared"), Some(":strips :typing"));
        assert_eq!(value("types"), Some("2"));
        assert_eq!(value("predicates"), Some("2"));
        assert_eq!(value("actions"), Some("1"));
        assert_eq!(
            problem.summary(),
            vec![
                ("objects", "1".to_string()),
                ("init", "1 facts, 0 function values".to_string()),
                ("goal", "2 literals (1 negative)".to_string()),
                ("metric", "(none)".to_string()),
            ]
        );
    }
}
