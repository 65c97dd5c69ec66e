//! What `demoplan check` says about a domain and a problem: counts in rows of a key and
//! a value, in a fixed order.

use crate::{Domain, InitEntry, Problem};

/// A summary row: what is counted, and its value as text.
pub type SummaryRow = (&'static str, String);

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
