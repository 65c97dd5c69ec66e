//! Downward Lab's `properties`: the JSON object Lab keeps per run (in the run's folder)
//! and combined per experiment (in its evaluation folder, keyed by the run's `id`
//! joined with `-`), so that Lab's reports (`AbsoluteReport`, ...) read demoplan's grids.
//!
//! Attributes, as Lab's Fast Downward parsers name them: `id` (`[algorithm, domain,
//! problem]`), `run_dir`, `domain`, `problem`, `algorithm`; `coverage` (1 when solved),
//! `unsolvable` (1 when the task was proved to have no plan), `cost`, `expansions`,
//! `generated`; `search_time` and `total_time` (seconds), `memory` (peak, KB);
//! `error` with Lab's words (`success`, `search-unsolvable`, `search-out-of-time`,
//! `search-out-of-memory`, `search-critical-error`), `unexplained_errors` (the message of
//! a run that failed, which Lab's reports list), and `planner_time_limit` (seconds).
//! demoplan's own id is `demoplan_id`.

use serde_json::{json, Map, Value};
use slim::Outcome;

use crate::cell::{Cell, DEFAULT_PARAMS};
use crate::record::RunRecord;

use super::RunLayout;

/// A cell's (domain, problem, algorithm), unique per cell of a grid: the domain holds
/// the library's conditions and the level (`seed7-h1-prio2`), the problem the scene
/// and goal (`tower-6`), the algorithm the planner (`demoplan-lmcut`). Conditions at
/// their defaults are left out of the names.
#[derive(Debug, Clone, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct LabNames {
    pub domain: String,
    pub problem: String,
    pub algorithm: String,
}

impl LabNames {
    pub fn of(cell: &Cell) -> LabNames {
        Self::from_parts(
            &cell.conditions,
            &cell.level.name(),
            cell.planner,
            cell.repeat,
        )
    }

    fn from_parts(
        c: &crate::cell::Conditions,
        level: &str,
        planner: crate::cell::Planner,
        repeat: u32,
    ) -> LabNames {
        let mut domain = format!("seed{}-h{}", c.seed, c.hands);
        if (c.participants, c.per_participant)
            != (
                simulate::DEFAULT_PARTICIPANTS,
                simulate::DEFAULT_PER_PARTICIPANT,
            )
        {
            domain.push_str(&format!("-p{}x{}", c.participants, c.per_participant));
        }
        if c.params != DEFAULT_PARAMS {
            domain.push_str(&format!("-{}", c.params));
        }
        if c.activities != learn::Grouping::Settled.name() {
            domain.push_str(&format!("-{}", c.activities));
        }
        if c.keep_without_effects {
            domain.push_str("-keep");
        }
        if c.generalised {
            domain.push_str("-general");
        }
        domain.push_str(&format!("-{}", level.replace("prio-", "prio")));
        let mut problem = format!("tower-{}", c.height);
        if c.towers != 1 {
            problem.push_str(&format!("-x{}", c.towers));
        }
        if c.distractors != 0 {
            problem.push_str(&format!("-d{}", c.distractors));
        }
        if repeat != 0 {
            problem.push_str(&format!("-r{repeat}"));
        }
        let algorithm = if planner.is_fast_downward() {
            planner.name().to_string()
        } else {
            format!("demoplan-{}", planner.name())
        };
        LabNames {
            domain,
            problem,
            algorithm,
        }
    }

    fn of_record(r: &RunRecord) -> LabNames {
        Self::from_parts(&r.conditions, &r.level.name(), r.planner, r.repeat)
    }

    /// Lab's `id` of the run, and the key of the combined properties (`-`-joined).
    pub fn id(&self) -> [&str; 3] {
        [&self.algorithm, &self.domain, &self.problem]
    }
}

/// Lab's `error` word for an outcome.
pub fn lab_error(outcome: Outcome) -> &'static str {
    match outcome {
        Outcome::Solved => "success",
        Outcome::RelaxedUnreachable | Outcome::Unsolvable => "search-unsolvable",
        Outcome::TimeLimit => "search-out-of-time",
        Outcome::MemoryLimit => "search-out-of-memory",
        Outcome::Cancelled | Outcome::Error => "search-critical-error",
    }
}

/// The properties of cell `task`'s run.
pub fn run_properties(r: &RunRecord, task: usize, planner_time_limit: f64) -> Value {
    let names = LabNames::of_record(r);
    let solved = r.outcome == Outcome::Solved;
    let mut p = Map::new();
    p.insert("id".into(), json!(names.id()));
    p.insert("run_dir".into(), json!(RunLayout::run_dir_name(task)));
    p.insert("domain".into(), json!(names.domain));
    p.insert("problem".into(), json!(names.problem));
    p.insert("algorithm".into(), json!(names.algorithm));
    p.insert("coverage".into(), json!(u8::from(solved)));
    p.insert(
        "unsolvable".into(),
        json!(u8::from(matches!(
            r.outcome,
            Outcome::Unsolvable | Outcome::RelaxedUnreachable
        ))),
    );
    if solved {
        if let Some(cost) = r.cost {
            p.insert("cost".into(), json!(cost));
        }
        p.insert("plan_length".into(), json!(r.length));
    }
    if let Some(n) = r.expansions {
        p.insert("expansions".into(), json!(n));
    }
    if let Some(n) = r.generated {
        p.insert("generated".into(), json!(n));
    }
    // Lab's parsers give times only of runs that got there; a run that hit its limit
    // has its total as a lower bound, which Lab does not know, so it is left out.
    if solved {
        p.insert("search_time".into(), json!(r.times.search_s));
        p.insert("total_time".into(), json!(r.times.total_s));
    }
    if let Some(kb) = r.peak_memory_kb {
        p.insert("memory".into(), json!(kb));
    }
    p.insert("error".into(), json!(lab_error(r.outcome)));
    if matches!(r.outcome, Outcome::Error | Outcome::Cancelled) || r.crashed {
        let why = r.error.clone().unwrap_or_else(|| r.outcome.to_string());
        p.insert("unexplained_errors".into(), json!([why]));
    }
    p.insert("planner_time_limit".into(), json!(planner_time_limit));
    p.insert("demoplan_id".into(), json!(r.id));
    p.insert("demoplan_level".into(), json!(r.level));
    p.insert("demoplan_outcome".into(), json!(r.outcome.to_string()));
    if let Some(executed) = r.executed {
        p.insert("demoplan_executed".into(), json!(executed));
    }
    // Algorithm 1's execution loop: plans that failed execution and the operators set
    // aside for them (by display name), 0 and [] when none.
    if r.level == crate::cell::LevelChoice::Algorithm1 {
        p.insert("demoplan_replans".into(), json!(r.replans));
        let names: Vec<&str> = r.set_aside.iter().map(|s| s.name.as_str()).collect();
        p.insert("demoplan_set_aside".into(), json!(names));
    }
    Value::Object(p)
}

/// The combined properties of an evaluation folder: each run's, keyed by its `id`.
pub fn combined<'a>(runs: impl Iterator<Item = (&'a RunRecord, usize, f64)>) -> Value {
    let mut all = Map::new();
    for (r, task, limit) in runs {
        let key = LabNames::of_record(r).id().join("-");
        all.insert(key, run_properties(r, task, limit));
    }
    Value::Object(all)
}

/// Properties as Lab writes them: JSON, indented by 2, keys sorted.
pub fn to_text(value: &Value) -> String {
    let mut text = serde_json::to_string_pretty(value).unwrap_or_default();
    text.push('\n');
    text
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::cell::{Conditions, LevelChoice, Planner};
    use std::time::Duration;

    fn cell() -> Cell {
        Cell {
            conditions: Conditions::paper_goal(7, 5, 1),
            level: LevelChoice::Prio(2),
            planner: Planner::Lmcut,
            time_limit: Duration::from_secs(60),
            repeat: 0,
        }
    }

    #[test]
    fn names_read_as_the_issue_gives_them() {
        let n = LabNames::of(&cell());
        assert_eq!(n.domain, "seed7-h1-prio2");
        assert_eq!(n.problem, "tower-6");
        assert_eq!(n.algorithm, "demoplan-lmcut");
        let fd = LabNames::of(&Cell {
            planner: Planner::FdIpdb,
            ..cell()
        });
        assert_eq!(fd.algorithm, "fd-ipdb");
    }

    #[test]
    fn every_cell_of_a_varied_grid_has_its_own_names() {
        let mut names = std::collections::BTreeSet::new();
        let mut n = 0;
        for seed in [1, 2] {
            for hands in [1, 2] {
                for (participants, per) in [(3, 4), (2, 4), (3, 2)] {
                    for activities in ["settled", "runs"] {
                        for keep in [false, true] {
                            for (height, towers, distractors) in
                                [(2, 1, 0), (3, 1, 0), (2, 2, 0), (2, 1, 1)]
                            {
                                for level in [
                                    LevelChoice::Prio(1),
                                    LevelChoice::Full,
                                    LevelChoice::Algorithm1,
                                ] {
                                    for planner in Planner::ALL {
                                        for repeat in [0, 1] {
                                            let c = Cell {
                                                conditions: Conditions {
                                                    seed,
                                                    participants,
                                                    per_participant: per,
                                                    params: DEFAULT_PARAMS.into(),
                                                    hands,
                                                    height,
                                                    towers,
                                                    distractors,
                                                    activities: activities.into(),
                                                    keep_without_effects: keep,
                                                    generalised: false,
                                                },
                                                level,
                                                planner,
                                                time_limit: Duration::from_secs(5),
                                                repeat,
                                            };
                                            names.insert(LabNames::of(&c));
                                            n += 1;
                                        }
                                    }
                                }
                            }
                        }
                    }
                }
            }
        }
        assert_eq!(names.len(), n);
    }

    #[test]
    fn outcomes_take_labs_error_words() {
        let mut r = RunRecord::blank(&cell());
        r.outcome = Outcome::Solved;
        r.cost = Some(1395);
        r.expansions = Some(12);
        let p = run_properties(&r, 7, 60.0);
        assert_eq!(p["error"], "success");
        assert_eq!(p["coverage"], 1);
        assert_eq!(p["cost"], 1395);
        assert_eq!(p["run_dir"], "runs-00001-00100/00007");
        assert_eq!(
            p["id"],
            json!(["demoplan-lmcut", "seed7-h1-prio2", "tower-6"])
        );
        assert!(p.get("unexplained_errors").is_none());
        for (outcome, word) in [
            (Outcome::TimeLimit, "search-out-of-time"),
            (Outcome::MemoryLimit, "search-out-of-memory"),
            (Outcome::Unsolvable, "search-unsolvable"),
            (Outcome::RelaxedUnreachable, "search-unsolvable"),
        ] {
            r.outcome = outcome;
            let p = run_properties(&r, 1, 60.0);
            assert_eq!(p["error"], word);
            assert_eq!(p["coverage"], 0);
            assert!(p.get("cost").is_none());
        }
        let crash = RunRecord {
            crashed: true,
            ..RunRecord::failed(&cell(), "the child process was killed".into())
        };
        let p = run_properties(&crash, 1, 60.0);
        assert_eq!(p["error"], "search-critical-error");
        assert_eq!(
            p["unexplained_errors"],
            json!(["the child process was killed"])
        );
    }

    #[test]
    fn algorithm1_runs_say_what_the_execution_loop_set_aside() {
        let mut r = RunRecord::blank(&cell());
        let p = run_properties(&r, 1, 60.0);
        assert!(p.get("demoplan_replans").is_none() && p.get("demoplan_set_aside").is_none());
        r.level = LevelChoice::Algorithm1;
        let p = run_properties(&r, 1, 60.0);
        assert_eq!(
            (&p["demoplan_replans"], &p["demoplan_set_aside"]),
            (&json!(0), &json!([]))
        );
        r.replans = 2;
        r.set_aside.push(crate::record::SetAsideRecord {
            name: "stack2".into(),
            id: "0123456789abcdef".into(),
            prio: 4,
            step: 21,
            action: "(stack2 left_hand cube_2 cube_1)".into(),
            why: "expected (ontop cube_2 cube_1), grounded state has (handopen left_hand)".into(),
        });
        let p = run_properties(&r, 1, 60.0);
        assert_eq!(p["demoplan_replans"], 2);
        assert_eq!(p["demoplan_set_aside"], json!(["stack2"]));
    }
}
