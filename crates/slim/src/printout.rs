//! What `demoplan solve` prints, as text: a row per level of Algorithm 1 as it ends, the
//! sentence for a solve without a plan, and the full domain's optimum beside the slim
//! plan's cost.

use std::time::Duration;

use learn::{DomainOptions, Library};

use crate::{Backend, LevelResult, Outcome, RunLimits, Solved};

fn seconds(d: Duration) -> String {
    format!("{:.3}", d.as_secs_f64())
}

/// The header of the table of levels, with its line ending.
pub fn level_header() -> String {
    format!(
        "{:>5} {:>9}  {:<19} {:>9} {:>11} {:>6}\n",
        "prio", "operators", "outcome", "time (s)", "expansions", "cost"
    )
}

/// A level's row of the table, with its line ending.
pub fn level_row(level: &LevelResult) -> String {
    let run = &level.run;
    format!(
        "{:>5} {:>9}  {:<19} {:>9} {:>11} {:>6}\n",
        level.prio,
        level.operators,
        run.outcome.word(),
        seconds(run.total_time),
        run.expansions.map_or("-".to_string(), |e| e.to_string()),
        run.cost.map_or("-".to_string(), |c| c.to_string())
    )
}

impl Solved {
    /// The line after the table: the time over every level.
    pub fn cumulative_line(&self) -> String {
        format!(
            "Cumulative time over {} level(s), failed ones included: {} s\n",
            self.levels.len(),
            seconds(self.cumulative)
        )
    }

    /// Which limit stopped some level of a solve without a plan (`its time limit`, ...),
    /// or `None` when no level reached one.
    pub fn limits_reached(&self) -> Option<&'static str> {
        let reached = |o: Outcome| self.levels.iter().any(|l| l.run.outcome == o);
        match (reached(Outcome::TimeLimit), reached(Outcome::MemoryLimit)) {
            (true, true) => Some("its time or memory limit"),
            (false, true) => Some("its memory limit"),
            (true, false) => Some("its time limit"),
            (false, false) => None,
        }
    }
}

/// Plans on the full domain of `library` and says its optimal cost beside `slim_cost`,
/// the plan of Algorithm 1 (the price of slimming), or why there is no optimum to compare
/// with. `None` for a library without levels.
pub fn compare_full(
    library: &Library,
    options: DomainOptions,
    problem: &pddl::Problem,
    backend: &Backend,
    limits: &RunLimits,
    slim_cost: u64,
) -> Option<String> {
    let full = learn::levels(library, options).pop()?;
    let domain = learn::domain("demoplan", &full.operators);
    let run = backend.plan(&domain, problem, limits);
    Some(match (&run.outcome, run.cost) {
        (Outcome::Solved, Some(optimum)) => format!(
            "Full domain ({} operators): optimal cost {optimum} in {} s; the slim plan costs \
             {slim_cost} (price of slimming: {})\n",
            full.operators.len(),
            seconds(run.total_time),
            slim_cost.saturating_sub(optimum)
        ),
        (outcome, _) => format!(
            "Full domain ({} operators): {} after {} s; no optimum to compare with\n",
            full.operators.len(),
            outcome.word(),
            seconds(run.total_time)
        ),
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::PlanRun;

    fn level(prio: usize, outcome: Outcome) -> LevelResult {
        let mut run = PlanRun::ended(outcome);
        run.total_time = Duration::from_millis(1500);
        LevelResult {
            prio,
            operators: 5 * prio,
            domain: learn::domain("demoplan", &[]),
            run,
        }
    }

    fn solved(outcomes: &[Outcome]) -> Solved {
        Solved {
            levels: (1..).zip(outcomes).map(|(p, o)| level(p, *o)).collect(),
            cumulative: Duration::from_secs(3),
        }
    }

    #[test]
    fn rows_line_up_under_the_header() {
        let header = level_header();
        let row = level_row(&level(2, Outcome::TimeLimit));
        assert_eq!(row.len(), header.len(), "{header}{row}");
        assert!(row.starts_with("    2        10  limit "), "{row}");
        assert!(
            row.trim_end().ends_with("1.500           -      -"),
            "{row}"
        );
        assert_eq!(
            solved(&[Outcome::Unsolvable]).cumulative_line(),
            "Cumulative time over 1 level(s), failed ones included: 3.000 s\n"
        );
    }

    #[test]
    fn a_solve_without_a_plan_names_the_limits_its_levels_reached() {
        use Outcome::*;
        let reached = |o: &[Outcome]| solved(o).limits_reached();
        assert_eq!(reached(&[Unsolvable, RelaxedUnreachable]), None);
        assert_eq!(reached(&[TimeLimit, Unsolvable]), Some("its time limit"));
        assert_eq!(reached(&[MemoryLimit]), Some("its memory limit"));
        assert_eq!(
            reached(&[MemoryLimit, TimeLimit]),
            Some("its time or memory limit")
        );
    }
}
