//! Result records: one per cell, one JSON line each, appended as cells finish and read
//! back to resume a grid or to report on it.

use std::io::Write as _;
use std::path::Path;

use report::{Bound, Measure};
use serde::{Deserialize, Serialize};

use slim::Outcome;

use crate::cell::{Cell, Conditions, LevelChoice, Planner};
use crate::ExperimentError;

/// A run's time in four parts, in seconds.
#[derive(Debug, Clone, Copy, Default, PartialEq, Serialize, Deserialize)]
pub struct Times {
    /// Parse and translate (Fast Downward: its translator's wall-clock "Done!" time).
    pub translate_s: f64,
    /// Heuristic construction: iPDB's hill climbing, LM-cut's setup (Fast Downward:
    /// "Total time" minus "Search time").
    pub heuristic_s: f64,
    /// The search proper ("Search time", the paper's measure).
    pub search_s: f64,
    /// Wall time of the whole run (Fast Downward: its whole process tree).
    pub total_s: f64,
}

impl Times {
    /// The time by `measure`.
    pub fn get(&self, measure: Measure) -> f64 {
        match measure {
            Measure::Search => self.search_s,
            Measure::Total => self.total_s,
        }
    }

    pub(crate) fn of(run: &slim::PlanRun) -> Times {
        Times {
            translate_s: run.translate_time.as_secs_f64(),
            heuristic_s: run.heuristic_time.as_secs_f64(),
            search_s: run.search_time.as_secs_f64(),
            total_s: run.total_time.as_secs_f64(),
        }
    }

    /// What a run with these times had spent when stopped after `limit` seconds: its
    /// phases run in order (translate, heuristic, search), so each keeps what fits.
    pub(crate) fn truncated(&self, limit: f64) -> Times {
        let translate_s = self.translate_s.min(limit);
        let heuristic_s = self.heuristic_s.min(limit - translate_s);
        let search_s = self.search_s.min(limit - translate_s - heuristic_s);
        Times {
            translate_s,
            heuristic_s,
            search_s,
            total_s: limit.min(self.total_s),
        }
    }

    pub(crate) fn add(&mut self, other: &Times) {
        self.translate_s += other.translate_s;
        self.heuristic_s += other.heuristic_s;
        self.search_s += other.search_s;
        self.total_s += other.total_s;
    }
}

fn is_zero(n: &u32) -> bool {
    *n == 0
}

/// One level tried by Algorithm 1 (a level searched again after the execution loop set
/// an operator aside is tried again, with fewer operators).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct WideningStep {
    pub prio: usize,
    pub operators: usize,
    pub outcome: Outcome,
    pub times: Times,
}

/// An operator an Algorithm 1 cell set aside: the execution loop found a step of its
/// in a plan that the cube world did not execute (`closed_loop::SetAside`, as a record).
#[derive(Debug, Clone, PartialEq, Eq, Serialize, Deserialize)]
pub struct SetAsideRecord {
    /// The operator's display name (`stack2`).
    pub name: String,
    /// Its stable id.
    pub id: String,
    /// The level whose plan failed.
    pub prio: usize,
    /// The failing step's 1-based position in that plan.
    pub step: usize,
    /// The step, `(stack2 left_hand cube_2 cube_1)`.
    pub action: String,
    /// Why, in the words of `demoplan execute`: the effects promised against the
    /// grounded facts, collisions.
    pub why: String,
}

impl SetAsideRecord {
    /// The record of what the loop set aside.
    pub fn of(s: &closed_loop::SetAside) -> SetAsideRecord {
        SetAsideRecord {
            name: s.name.clone(),
            id: s.id.clone(),
            prio: s.prio,
            step: s.step,
            action: s.action.clone(),
            why: s.why.clone(),
        }
    }
}

/// What one cell gave.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct RunRecord {
    /// [`Cell::id`].
    pub id: String,
    pub conditions: Conditions,
    /// Written as [`LevelChoice::name`]: `prio-N`, `full`, `alg1`.
    pub level: LevelChoice,
    pub planner: Planner,
    pub time_limit_s: f64,
    pub repeat: u32,
    /// The priority planned on: the level's, the full domain's, or for Algorithm 1 the
    /// level that gave the plan (else the last tried).
    pub prio: usize,
    /// Operators in that domain.
    pub operators: usize,
    /// Written as [`Outcome::word`]: `solved`, `relaxed-unreachable`, `unsolvable`,
    /// `limit`, `memory`, `error`.
    pub outcome: Outcome,
    /// For Algorithm 1 the cumulative times over every level tried.
    pub times: Times,
    pub expansions: Option<u64>,
    pub generated: Option<u64>,
    pub cost: Option<u64>,
    pub length: Option<usize>,
    pub peak_memory_kb: Option<u64>,
    /// The plan executed in the cube world: its effects and goal held.
    pub executed: Option<bool>,
    /// The plan's steps, written as their words (`"reach left_hand cube_2"`).
    #[serde(default, with = "plan_words")]
    pub plan: Vec<pddl::Step>,
    /// Whether every operator of the task costs 1, so that the plan file says `unit
    /// cost` (absent from the line when false: `general cost`).
    #[serde(default, skip_serializing_if = "std::ops::Not::not")]
    pub unit_cost: bool,
    /// Algorithm 1 only: every level tried, in order.
    #[serde(default)]
    pub widening: Vec<WideningStep>,
    /// Algorithm 1 only: the operators the execution loop set aside, in order (absent
    /// from the line when none was, and in records written before the loop).
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub set_aside: Vec<SetAsideRecord>,
    /// Algorithm 1 only: plans that failed the execution check, each followed by another
    /// search (absent from the line when 0).
    #[serde(default, skip_serializing_if = "is_zero")]
    pub replans: u32,
    /// Why the run is an error, if it is one.
    #[serde(default)]
    pub error: Option<String>,
    /// The cell's process crashed (died, hung, or exited with an unexpected code): the
    /// record says so in `error` and is no result, so the grid computes the cell again
    /// when run again. Absent from the line when false.
    #[serde(default, skip_serializing_if = "std::ops::Not::not")]
    pub crashed: bool,
}

impl RunRecord {
    /// `cell`'s record before its run: no times, nothing found, and the outcome
    /// [`Outcome::Error`] until the run gives its own.
    pub fn blank(cell: &Cell) -> RunRecord {
        RunRecord {
            id: cell.id(),
            conditions: cell.conditions.clone(),
            level: cell.level,
            planner: cell.planner,
            time_limit_s: cell.time_limit.as_secs_f64(),
            repeat: cell.repeat,
            prio: 0,
            operators: 0,
            outcome: Outcome::Error,
            times: Times::default(),
            expansions: None,
            generated: None,
            cost: None,
            length: None,
            peak_memory_kb: None,
            executed: None,
            plan: Vec::new(),
            unit_cost: false,
            widening: Vec::new(),
            set_aside: Vec::new(),
            replans: 0,
            error: None,
            crashed: false,
        }
    }

    /// The record of a cell that could not be computed (its process crashed, say):
    /// outcome `error`, with why.
    pub fn failed(cell: &Cell, message: String) -> RunRecord {
        RunRecord {
            outcome: Outcome::Error,
            error: Some(message),
            ..RunRecord::blank(cell)
        }
    }

    /// Whether a plan was found.
    pub fn solved(&self) -> bool {
        self.outcome == Outcome::Solved
    }

    /// Whether the run stopped at its time or memory limit: its times are lower bounds.
    pub fn hit_limit(&self) -> bool {
        self.outcome.hit_limit()
    }

    /// The time by `measure` and whether it is exact or a lower bound (the run hit its
    /// limit); `None` for a run that gave no time worth comparing (no plan exists in
    /// its domain, or an error), and for the search time of a run that hit its limit
    /// before its search expanded a state (iPDB's hill climbing took the whole limit):
    /// its search never began, so nothing is known of it, not even a bound.
    pub fn time(&self, measure: Measure) -> Option<(f64, Bound)> {
        if self.solved() {
            Some((self.times.get(measure), Bound::Exact))
        } else if self.hit_limit() {
            // Fast Downward stopped at its limit prints no expansions and no search
            // time: whether its search began is unknown, so no bound either.
            let searched = match self.expansions {
                Some(n) => n > 0,
                None => self.times.search_s > 0.0,
            };
            if measure == Measure::Search && !searched {
                return None;
            }
            Some((self.times.get(measure), Bound::AtLeast))
        } else {
            None
        }
    }

    /// Whether this record is `cell`'s.
    pub fn is_of(&self, cell: &Cell) -> bool {
        self.id == cell.id()
    }

    /// One JSON line, without the newline.
    pub fn to_json_line(&self) -> String {
        serde_json::to_string(self).unwrap_or_default()
    }
}

/// Reads records written one JSON object per line. A last line without its newline is
/// an append that was cut short (the process was killed while writing it): it is left
/// out, so that its cell runs again. Any other line that is not a record is an error
/// naming its line.
pub fn parse_records(text: &str, file: &Path) -> Result<Vec<RunRecord>, ExperimentError> {
    let mut out = Vec::new();
    let complete = if text.ends_with('\n') || text.is_empty() {
        text
    } else {
        match text.rfind('\n') {
            Some(i) => &text[..=i],
            None => "",
        }
    };
    for (i, line) in complete.lines().enumerate() {
        if line.trim().is_empty() {
            continue;
        }
        let record: RunRecord =
            serde_json::from_str(line).map_err(|e| ExperimentError::Results {
                file: file.to_path_buf(),
                line: i + 1,
                message: e.to_string(),
            })?;
        out.push(record);
    }
    Ok(out)
}

/// Reads a results file; a missing one has no records.
pub fn read_records(path: &Path) -> Result<Vec<RunRecord>, ExperimentError> {
    match std::fs::read_to_string(path) {
        Ok(text) => parse_records(&text, path),
        Err(e) if e.kind() == std::io::ErrorKind::NotFound => Ok(Vec::new()),
        Err(e) => Err(ExperimentError::Io {
            path: path.to_path_buf(),
            message: e.to_string(),
        }),
    }
}

/// Appends one record as one line, in one write, and flushes it to the disk: a crash
/// loses at most the line being written, which [`parse_records`] then leaves out.
pub fn append_record(path: &Path, record: &RunRecord) -> Result<(), ExperimentError> {
    let io = |e: std::io::Error| ExperimentError::Io {
        path: path.to_path_buf(),
        message: e.to_string(),
    };
    let mut file = std::fs::OpenOptions::new()
        .create(true)
        .append(true)
        .open(path)
        .map_err(io)?;
    let mut line = record.to_json_line();
    line.push('\n');
    file.write_all(line.as_bytes()).map_err(io)?;
    file.sync_data().map_err(io)
}

/// A plan in a record: each step as its words, `"reach left_hand cube_2"`, the form
/// results files have always had.
mod plan_words {
    use serde::{Deserialize, Deserializer, Serializer};

    pub fn serialize<S: Serializer>(plan: &[pddl::Step], s: S) -> Result<S::Ok, S::Error> {
        s.collect_seq(plan.iter().map(pddl::Step::words))
    }

    pub fn deserialize<'de, D: Deserializer<'de>>(d: D) -> Result<Vec<pddl::Step>, D::Error> {
        Vec::<String>::deserialize(d)?
            .iter()
            .map(|words| {
                pddl::Step::from_words(words)
                    .ok_or_else(|| serde::de::Error::custom("a plan step without an action"))
            })
            .collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn record(id: &str) -> RunRecord {
        RunRecord {
            id: id.to_string(),
            conditions: Conditions::paper_goal(7, 1, 1),
            level: LevelChoice::Prio(1),
            planner: Planner::Lmcut,
            time_limit_s: 20.0,
            repeat: 0,
            prio: 1,
            operators: 5,
            outcome: Outcome::Solved,
            times: Times {
                translate_s: 0.01,
                heuristic_s: 0.002,
                search_s: 0.003,
                total_s: 0.015,
            },
            expansions: Some(10),
            generated: Some(40),
            cost: Some(190),
            length: Some(5),
            peak_memory_kb: Some(1024),
            executed: Some(true),
            plan: vec![pddl::Step::new("reach", ["left_hand", "cube_2"])],
            unit_cost: false,
            widening: vec![],
            set_aside: vec![],
            replans: 0,
            error: None,
            crashed: false,
        }
    }

    #[test]
    fn what_the_execution_loop_set_aside_reads_back_and_older_lines_read_without_it() {
        let mut a = record("a");
        let plain = a.to_json_line();
        assert!(
            !plain.contains("set_aside") && !plain.contains("replans"),
            "{plain}"
        );
        a.set_aside.push(SetAsideRecord {
            name: "stack2".into(),
            id: "f9f44c129737eb4a".into(),
            prio: 1,
            step: 3,
            action: "(stack2 left_hand cube_2 cube_1)".into(),
            why: "expected (ontop cube_2 cube_1), grounded state has (handopen left_hand)".into(),
        });
        a.replans = 1;
        let line = a.to_json_line();
        assert!(line.contains(r#""replans":1"#), "{line}");
        let path = Path::new("results.jsonl");
        let read = parse_records(&format!("{line}\n"), path).unwrap();
        assert_eq!(read, vec![a.clone()]);
        // A line written before the loop: no set-aside list, no replans.
        let old = plain.replace(r#","widening":[]"#, "");
        let read = parse_records(&format!("{old}\n"), path).unwrap();
        assert_eq!((read[0].replans, read[0].set_aside.len()), (0, 0));
    }

    #[test]
    fn records_read_back_and_a_cut_line_is_left_out() {
        let a = record("a");
        let b = record("b");
        let text = format!("{}\n{}\n", a.to_json_line(), b.to_json_line());
        let path = Path::new("results.jsonl");
        assert_eq!(parse_records(&text, path).ok(), Some(vec![a.clone(), b]));
        let cut = format!(
            "{}\n{}",
            a.to_json_line(),
            &record("c").to_json_line()[..40]
        );
        assert_eq!(parse_records(&cut, path).ok(), Some(vec![a]));
    }

    #[test]
    fn a_damaged_line_is_an_error_naming_it() {
        let text = format!("{}\n{{\"id\": 3}}\n", record("a").to_json_line());
        let e = parse_records(&text, Path::new("out/results.jsonl"))
            .err()
            .map(|e| e.to_string())
            .unwrap_or_default();
        assert!(e.contains("out/results.jsonl:2"), "{e}");
    }

    #[test]
    fn outcomes_planners_and_levels_are_written_as_their_words() {
        let mut r = record("a");
        r.outcome = Outcome::MemoryLimit;
        r.planner = Planner::FdIpdb;
        r.level = LevelChoice::Prio(12);
        let line = r.to_json_line();
        assert!(line.contains(r#""level":"prio-12""#), "{line}");
        assert!(line.contains(r#""planner":"fd-ipdb""#), "{line}");
        assert!(line.contains(r#""outcome":"memory""#), "{line}");
        assert_eq!(
            parse_records(&format!("{line}\n"), Path::new("r")).ok(),
            Some(vec![r])
        );
    }

    #[test]
    fn an_unknown_outcome_planner_or_level_is_an_error_naming_the_file_line_and_field() {
        let good = record("a").to_json_line();
        for (from, to, says) in [
            (
                r#""outcome":"solved""#,
                r#""outcome":"won""#,
                "outcome `won` is none of solved, relaxed-unreachable, unsolvable, limit, \
                 memory, cancelled, error",
            ),
            (
                r#""planner":"lmcut""#,
                r#""planner":"lm-cut""#,
                "planner `lm-cut` is none of ipdb, lmcut, fd-ipdb, fd-lmcut",
            ),
            (
                r#""level":"prio-1""#,
                r#""level":"prio-0""#,
                "level `prio-0` is none of prio-N (N >= 1), full, alg1",
            ),
        ] {
            assert!(good.contains(from), "{good}");
            let text = format!("{good}\n{}\n", good.replace(from, to));
            let e = parse_records(&text, Path::new("out/results.jsonl"))
                .err()
                .map(|e| e.to_string())
                .unwrap_or_default();
            assert!(
                e.starts_with("out/results.jsonl:2: not a result record: "),
                "{e}"
            );
            assert!(e.contains(says), "{e}");
        }
    }

    #[test]
    fn a_limit_run_gives_a_lower_bound() {
        let mut r = record("a");
        assert_eq!(r.time(Measure::Total), Some((0.015, Bound::Exact)));
        r.outcome = Outcome::TimeLimit;
        assert_eq!(r.time(Measure::Search), Some((0.003, Bound::AtLeast)));
        // Stopped in the hill climbing: the search never began.
        r.expansions = Some(0);
        assert_eq!(r.time(Measure::Search), None);
        assert_eq!(r.time(Measure::Total), Some((0.015, Bound::AtLeast)));
        // Fast Downward killed at its limit: no expansions, no search time printed.
        r.expansions = None;
        r.times.search_s = 0.0;
        assert_eq!(r.time(Measure::Search), None);
        assert_eq!(r.time(Measure::Total), Some((0.015, Bound::AtLeast)));
        r.outcome = Outcome::Unsolvable;
        assert_eq!(r.time(Measure::Search), None);
    }
}
