//! The results of one reproduce run, as the report reads them, and the number formats
//! shared by the figures, the HTML tables and (through the public API) the Markdown
//! tables of the reproduce command.

use serde::{Deserialize, Serialize};

use crate::Planner;

/// One planner run: one planner on one domain and one goal (medians over repeats).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Run {
    pub planner: Planner,
    /// The domain's priority level.
    pub prio: usize,
    /// Operators in that domain.
    pub operators: usize,
    /// 1..=5.
    pub goal: usize,
    pub outcome: Outcome,
    /// Seconds, median over repeats (for [`Outcome::Limit`]: the limit).
    pub search_time: f64,
    pub total_time: f64,
    /// Every repeat's search time.
    pub times: Vec<f64>,
    pub expansions: Option<u64>,
    pub cost: Option<u64>,
    pub length: Option<usize>,
    /// The plan checked in the cube world.
    pub executed: Option<bool>,
}

/// Which of a run's times a table, figure or ratio shows.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Measure {
    /// The search proper, without translation or heuristic construction: what Fast
    /// Downward prints as "Search time" and the paper's Tables 3 and 4 report.
    Search,
    /// The whole run: translation, heuristic construction (iPDB's hill climbing) and
    /// search.
    Total,
}

impl Measure {
    /// Both, the paper's first.
    pub const ALL: [Measure; 2] = [Measure::Search, Measure::Total];

    /// `"search"` or `"total"`, as in file names and CSV columns.
    pub fn name(self) -> &'static str {
        match self {
            Measure::Search => "search",
            Measure::Total => "total",
        }
    }

    /// `"Search time"` or `"Total time"`.
    pub fn title(self) -> &'static str {
        match self {
            Measure::Search => "Search time",
            Measure::Total => "Total time",
        }
    }
}

impl Run {
    /// The run's time by `measure`, in seconds.
    pub fn time(&self, measure: Measure) -> f64 {
        match measure {
            Measure::Search => self.search_time,
            Measure::Total => self.total_time,
        }
    }
}

/// How a run ended.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Outcome {
    Solved,
    /// Proven unsolvable on this domain.
    Unsolvable,
    /// Hit the time limit, or the memory limit (a bound too: with more memory it would
    /// have taken longer).
    Limit,
    Error,
}

/// One priority level's domain: its operator count, per type in the order of
/// [`recording::Activity::OPERATOR_ORDER`] (reach, take, put, stack, idle).
#[derive(Debug, Clone, PartialEq, Eq, Serialize, Deserialize)]
pub struct Level {
    pub prio: usize,
    pub operators: usize,
    pub per_type: [usize; 5],
}

/// One planning goal: a tower, bottom first (e.g. `["cube_1", "cube_2"]`).
#[derive(Debug, Clone, PartialEq, Eq, Serialize, Deserialize)]
pub struct Goal {
    pub number: usize,
    pub tower: Vec<String>,
}

/// Everything the report shows.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Experiment {
    pub runs: Vec<Run>,
    pub levels: Vec<Level>,
    pub goals: Vec<Goal>,
    /// Per-run time limit in seconds.
    pub time_limit: f64,
    pub repeat: usize,
    pub seed: u64,
    /// e.g. `"2 cores, 24 GB, Linux x86_64"`.
    pub machine: String,
    /// e.g. `"demoplan 0.1.0; Fast Downward 26.6 (not run)"`.
    pub versions: String,
    /// Findings written by reproduce (ratios, honest statements), shown in the report.
    pub notes: Vec<String>,
    /// Cubes on the table in the problems' scene (0: the highest `cube_N` of the goals).
    #[serde(default)]
    pub cubes: usize,
    /// Hands in the problems' scene (0: not said).
    #[serde(default)]
    pub hands: usize,
}

impl Experiment {
    /// The run of `planner` on level `prio` for goal `goal` (the first, if several).
    pub fn run(&self, planner: Planner, prio: usize, goal: usize) -> Option<&Run> {
        self.runs
            .iter()
            .find(|r| r.planner == planner && r.prio == prio && r.goal == goal)
    }

    /// The planners that have runs, in the report's order ([`Planner::ALL`]).
    pub fn planners(&self) -> Vec<Planner> {
        let mut planners: Vec<Planner> = self.runs.iter().map(|r| r.planner).collect();
        planners.sort_unstable();
        planners.dedup();
        planners
    }

    /// `(prio, operators)` of every level, from `levels` and from the runs, sorted by
    /// priority.
    pub fn domains(&self) -> Vec<(usize, usize)> {
        let mut out: Vec<(usize, usize)> =
            self.levels.iter().map(|l| (l.prio, l.operators)).collect();
        for r in &self.runs {
            if !out.iter().any(|(p, _)| *p == r.prio) {
                out.push((r.prio, r.operators));
            }
        }
        out.sort_unstable();
        out.dedup_by_key(|d| d.0);
        out
    }

    /// The goal numbers, from `goals` and from the runs, sorted.
    pub fn goal_numbers(&self) -> Vec<usize> {
        let mut out: Vec<usize> = self.goals.iter().map(|g| g.number).collect();
        out.extend(self.runs.iter().map(|r| r.goal));
        out.sort_unstable();
        out.dedup();
        out
    }
}

impl Experiment {
    /// A made-up experiment shaped like the paper's, for examples and tests: its five
    /// domains, towers of 2 to 6 cubes, the paper's Tables 3 and 4 as demoplan's
    /// `ipdb` and `lmcut` times under a 60 s limit (so the slowest runs of goal 5 hit
    /// the limit), three repeats each.
    pub fn example() -> Experiment {
        let per_type = [
            [1, 1, 1, 1, 1],
            [2, 2, 3, 2, 2],
            [4, 3, 5, 3, 3],
            [5, 4, 6, 4, 4],
            [6, 5, 8, 6, 5],
        ];
        let levels: Vec<Level> = per_type
            .iter()
            .enumerate()
            .map(|(i, t)| Level {
                prio: i + 1,
                operators: t.iter().sum(),
                per_type: *t,
            })
            .collect();
        let goals: Vec<Goal> = (1..=5)
            .map(|n| Goal {
                number: n,
                tower: (1..=n + 1).map(|c| format!("cube_{c}")).collect(),
            })
            .collect();
        let limit = 60.0;
        let mut runs = Vec::new();
        for (planner, table) in [
            (Planner::Ipdb, &crate::html::PAPER_IPDB),
            (Planner::Lmcut, &crate::html::PAPER_LMCUT),
        ] {
            for (d, level) in levels.iter().enumerate() {
                for (g, text) in table[d].iter().enumerate() {
                    let t: f64 = text.parse().unwrap_or(f64::NAN);
                    let at_limit = t > limit;
                    let times = if at_limit {
                        vec![limit; 3]
                    } else {
                        vec![t * 0.93, t, t * 1.12]
                    };
                    let length = 4 * (g + 1);
                    runs.push(Run {
                        planner,
                        prio: level.prio,
                        operators: level.operators,
                        goal: g + 1,
                        outcome: if at_limit {
                            Outcome::Limit
                        } else {
                            Outcome::Solved
                        },
                        search_time: if at_limit { limit } else { t },
                        total_time: if at_limit { limit } else { t + 0.02 },
                        times,
                        expansions: (!at_limit).then(|| (t * 40_000.0) as u64 + 5),
                        cost: (!at_limit).then_some(length as u64 * 10),
                        length: (!at_limit).then_some(length),
                        executed: (!at_limit).then_some(true),
                    });
                }
            }
        }
        Experiment {
            runs,
            levels,
            goals,
            time_limit: limit,
            repeat: 3,
            seed: 7,
            machine: "2 cores, 24 GB, Linux x86_64 (made up)".to_string(),
            versions: "demoplan 0.1.0; Fast Downward 26.6 (not run)".to_string(),
            notes: vec![
                "A made-up experiment: the paper's Tables 3 and 4 under a 60 s limit.".to_string(),
                "Goal 5, largest over smallest domain: >= 24x (iPDB), >= 4.2x (LM-cut); the paper reports 72x and 120x.".to_string(),
            ],
            cubes: 6,
            hands: 1,
        }
    }
}

/// The paper's domain name: `dom{prio}({operators})`, e.g. `dom1(5)`.
pub fn domain_label(prio: usize, operators: usize) -> String {
    format!("dom{prio}({operators})")
}

/// Seconds with three significant digits and no exponent: `0.000512`, `0.0123`,
/// `2.50`, `14.3`, `181`. Non-finite or negative values print as `-`.
pub fn format_seconds(s: f64) -> String {
    if !s.is_finite() || s < 0.0 {
        return "-".to_string();
    }
    if s == 0.0 {
        return "0".to_string();
    }
    if s >= 100.0 {
        return format!("{s:.0}");
    }
    let decimals = (2 - s.log10().floor() as i32).clamp(0, 9) as usize;
    // Rounding may carry into the next decade (9.996 -> "10.00"); recompute then.
    let text = format!("{s:.decimals$}");
    match text.parse::<f64>() {
        Ok(v) if v >= 10f64.powi(3 - decimals as i32) && decimals > 0 => {
            format!("{s:.prec$}", prec = decimals - 1)
        }
        _ => text,
    }
}

/// A time limit: whole seconds without decimals (`60`), else as [`format_seconds`].
pub fn format_limit(limit: f64) -> String {
    if limit.fract() == 0.0 && limit.abs() < 1e9 {
        format!("{limit:.0}")
    } else {
        format_seconds(limit)
    }
}

/// The table cell for a run's search time: the seconds, `> limit`, `unsolvable` or
/// `error`.
pub fn time_cell(run: &Run) -> String {
    time_cell_by(run, Measure::Search)
}

/// [`time_cell`] by any [`Measure`].
pub fn time_cell_by(run: &Run, measure: Measure) -> String {
    match run.outcome {
        Outcome::Solved => format_seconds(run.time(measure)),
        Outcome::Limit => "> limit".to_string(),
        Outcome::Unsolvable => "unsolvable".to_string(),
        Outcome::Error => "error".to_string(),
    }
}

/// Whether a [`Ratio`] is exact or a bound (because a run hit the time limit).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Bound {
    Exact,
    /// The numerator hit the limit: the true ratio is at least the value.
    AtLeast,
    /// The denominator hit the limit: the true ratio is at most the value.
    AtMost,
}

/// A search-time ratio between two runs.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Ratio {
    pub value: f64,
    pub bound: Bound,
}

impl std::fmt::Display for Ratio {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let prefix = match self.bound {
            Bound::Exact => "",
            Bound::AtLeast => ">= ",
            Bound::AtMost => "<= ",
        };
        let v = self.value;
        let digits = if v >= 10.0 {
            format!("{v:.0}")
        } else {
            format!("{v:.2}")
        };
        write!(f, "{prefix}{digits}x")
    }
}

/// `slow.search_time / fast.search_time` (the paper's "72 times": largest domain over
/// smallest). A run at the limit counts with the limit as its time, which makes the
/// ratio a bound; `None` when either run is unsolvable or an error, both hit the limit,
/// or the denominator is zero.
pub fn ratio(slow: &Run, fast: &Run) -> Option<Ratio> {
    ratio_by(slow, fast, Measure::Search)
}

/// [`ratio`] by any [`Measure`].
pub fn ratio_by(slow: &Run, fast: &Run, measure: Measure) -> Option<Ratio> {
    // A run stopped before its search expanded a state (the hill climbing took the whole
    // limit) has no search time at all, not even a bound.
    let usable = |r: &Run| match r.outcome {
        Outcome::Solved => true,
        Outcome::Limit => measure == Measure::Total || r.expansions != Some(0),
        _ => false,
    };
    let (s, f) = (slow.time(measure), fast.time(measure));
    if !usable(slow) || !usable(fast) || f.is_nan() || f <= 0.0 || !s.is_finite() {
        return None;
    }
    let bound = match (slow.outcome, fast.outcome) {
        (Outcome::Limit, Outcome::Limit) => return None,
        (Outcome::Limit, _) => Bound::AtLeast,
        (_, Outcome::Limit) => Bound::AtMost,
        _ => Bound::Exact,
    };
    Some(Ratio {
        value: s / f,
        bound,
    })
}

/// For `planner` and `goal`: the search-time ratio of the largest domain (highest
/// priority level with a run) over the smallest (lowest).
pub fn slimming_ratio(exp: &Experiment, planner: Planner, goal: usize) -> Option<Ratio> {
    slimming_ratio_by(exp, planner, goal, Measure::Search)
}

/// [`slimming_ratio`] by any [`Measure`].
pub fn slimming_ratio_by(
    exp: &Experiment,
    planner: Planner,
    goal: usize,
    measure: Measure,
) -> Option<Ratio> {
    let mut runs: Vec<&Run> = exp
        .runs
        .iter()
        .filter(|r| r.planner == planner && r.goal == goal)
        .collect();
    runs.sort_by_key(|r| r.prio);
    let (first, last) = (runs.first()?, runs.last()?);
    if first.prio == last.prio {
        return None;
    }
    ratio_by(last, first, measure)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn seconds_have_three_significant_digits() {
        assert_eq!(format_seconds(0.000512), "0.000512");
        assert_eq!(format_seconds(0.0123456), "0.0123");
        assert_eq!(format_seconds(2.499), "2.50");
        assert_eq!(format_seconds(14.3), "14.3");
        assert_eq!(format_seconds(180.652), "181");
        assert_eq!(format_seconds(9.9996), "10.0");
        assert_eq!(format_seconds(0.0), "0");
        assert_eq!(format_seconds(f64::NAN), "-");
    }

    /// LM-cut's run of goal 5 at `prio`.
    fn run(prio: usize, outcome: Outcome, t: f64) -> Run {
        crate::test_common::run(Planner::Lmcut, prio, 5, outcome, t)
    }

    #[test]
    fn ratios_at_the_limit_are_bounds() {
        let fast = run(1, Outcome::Solved, 2.0);
        let slow = run(5, Outcome::Limit, 60.0);
        let r = ratio(&slow, &fast);
        assert_eq!(
            r,
            Some(Ratio {
                value: 30.0,
                bound: Bound::AtLeast
            })
        );
        assert_eq!(r.map(|r| r.to_string()), Some(">= 30x".to_string()));
        assert_eq!(ratio(&slow, &run(1, Outcome::Limit, 60.0)), None);
        // Stopped before the search expanded a state: no search time, so no ratio by
        // it; by total time still a bound.
        let climbed = Run {
            expansions: Some(0),
            ..slow.clone()
        };
        assert_eq!(ratio(&climbed, &fast), None);
        assert_eq!(
            ratio_by(&climbed, &fast, Measure::Total).map(|r| r.bound),
            Some(Bound::AtLeast)
        );
        assert_eq!(ratio(&slow, &run(1, Outcome::Unsolvable, 1.0)), None);
        let exp = crate::test_common::experiment(vec![slow, fast]);
        assert_eq!(
            slimming_ratio(&exp, Planner::Lmcut, 5).map(|r| r.bound),
            Some(Bound::AtLeast)
        );
        assert_eq!(slimming_ratio(&exp, Planner::Ipdb, 5), None);
    }
}
