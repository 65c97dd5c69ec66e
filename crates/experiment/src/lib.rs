//! demoplan's experiments as a library: the paper's grid ([`reproduce()`]) and the study
//! over conditions ([`study()`]).
//!
//! An experiment is a list of [`Cell`]s, one planning run each. A cell holds its
//! [`Conditions`] (simulated study, grouping, scene and goal), its level (a priority,
//! the full domain, or the paper's Algorithm 1), its [`Planner`], its time limit and its
//! repeat, so it can be computed alone ([`Lab::run`]); its id is a stable hash of all
//! of that ([`Cell::id`]). A cell gives one [`RunRecord`] (outcome, the four times,
//! expansions, generated states, plan cost, peak memory, execution check), written as
//! one JSON line, so grids resume by skipping the ids already in their results and can
//! be split over processes or cluster jobs. [`ratio`] and [`quartiles`] turn records
//! into slimming ratios, bounds where a run hit its limit; [`findings()`] writes what
//! the results say, from the results alone.
//!
//! The crate writes files (results, tables, figures, pages) but never touches the
//! terminal: progress goes to a callback ([`Progress`]).
//!
//! ```
//! use experiment::{Cell, Conditions, LevelChoice, Planner};
//! use std::time::Duration;
//! let cell = Cell {
//!     conditions: Conditions::paper_goal(7, 5, 1),
//!     level: LevelChoice::Full,
//!     planner: Planner::Lmcut,
//!     time_limit: Duration::from_secs(60),
//!     repeat: 0,
//! };
//! assert_eq!(cell.conditions.cubes(), 6);
//! assert_eq!(cell.id().len(), 16);
//! ```

mod cell;
mod closing;
mod findings;
pub mod grid;
mod lab;
mod memory_limit;
mod numbers;
mod output;
mod ratio;
mod record;
mod reproduce;
mod study;

use std::path::PathBuf;
use std::time::Duration;

/// The paper's published numbers (its Tables 3 and 4, library statistics, ratios).
pub use report::paper;

pub use cell::{params_key, Cell, Conditions, LevelChoice, Planner, DEFAULT_PARAMS};
pub use findings::findings;
pub use grid::{cell_list, CellCommand, GridRun, RunLayout, Runner};
pub use lab::{execute, learn_study, learn_study_as, tower_problem, towers, Known, Lab};
pub use memory_limit::auto_memory_limit;
pub use numbers::{numbers, sizes};
pub use ratio::{quartiles, ratio, ratio_text, Quartiles};
pub use record::{
    append_record, parse_records, read_records, RunRecord, SetAsideRecord, Times, WideningStep,
};
pub use reproduce::{reproduce, reproduce_cell, reproduce_cells, ReproduceOptions, Reproduction};
pub use study::{
    study, study_cell, study_cells, study_grid, StudyConditionArgs, StudyOptions, StudyOutcome,
};

/// Where a grid is: cells done (reused ones among them) and failed of the total, the
/// cell now running, time since start.
#[derive(Debug, Clone, Copy)]
pub struct Progress<'a> {
    pub done: usize,
    /// Of `done`, the cells whose process crashed.
    pub failed: usize,
    /// Of `done`, the cells whose results were there already (they took no time).
    pub reused: usize,
    pub total: usize,
    /// What runs now, for people: e.g. `lmcut full height 5 seed 3`.
    pub current: &'a str,
    pub elapsed: Duration,
}

impl Progress<'_> {
    /// Cells not done yet.
    pub fn remaining(&self) -> usize {
        self.total.saturating_sub(self.done)
    }

    /// The time left, from the rate of the cells computed so far (reused ones took no
    /// time; cells at once are in the rate): `None` before the first is done.
    pub fn time_left(&self) -> Option<Duration> {
        let computed = self.done.saturating_sub(self.reused);
        (computed > 0).then(|| {
            self.elapsed
                .mul_f64(self.remaining() as f64 / computed as f64)
        })
    }
}

/// What can go wrong in an experiment. "No plan" and "out of time" are outcomes in the
/// records, not errors.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum ExperimentError {
    /// An option the experiment cannot run with (the command line's fault).
    #[error("{0}")]
    Options(String),
    /// A cell's conditions cannot be set up.
    #[error("{0}")]
    Condition(String),
    /// A cell names other simulator parameters than the lab has.
    #[error("the cell wants simulator parameters {wanted}, the lab has {have}")]
    Params { wanted: String, have: String },
    /// The grid runs Fast Downward and none was given.
    #[error("the grid runs Fast Downward, and none was located")]
    FastDownwardMissing,
    /// A results file with a line that is not a record.
    #[error("{}:{line}: not a result record: {message}", file.display())]
    Results {
        file: PathBuf,
        line: usize,
        message: String,
    },
    /// Cells without a result, when a grid's results are collected.
    #[error(
        "{}: {} of {total} cells have no result, so the report is not written; run the \
         grid again to compute them: {}",
        out.display(),
        missing.len(),
        missing.join(", ")
    )]
    Incomplete {
        out: PathBuf,
        missing: Vec<String>,
        total: usize,
    },
    /// A file could not be read or written.
    #[error("{}: {message}", path.display())]
    Io { path: PathBuf, message: String },
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_time_left_comes_from_the_cells_computed_so_far() {
        let at = |done, reused, secs| Progress {
            done,
            failed: 0,
            reused,
            total: 10,
            current: "",
            elapsed: Duration::from_secs(secs),
        };
        // Nothing computed yet (reused cells took no time): no estimate.
        assert_eq!(at(4, 4, 3).time_left(), None);
        // 2 computed in 10 s, 4 to go: 20 s.
        let p = at(6, 4, 10);
        assert_eq!(p.remaining(), 4);
        assert_eq!(p.time_left(), Some(Duration::from_secs(20)));
        assert_eq!(at(10, 4, 10).time_left(), Some(Duration::ZERO));
    }
}
