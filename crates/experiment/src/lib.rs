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
mod children;
mod closing;
mod findings;
mod lab;
mod memory_limit;
mod numbers;
mod output;
mod ratio;
mod record;
mod reproduce;
pub mod slurm;
mod study;

use std::path::PathBuf;
use std::time::{Duration, Instant};

/// The paper's published numbers (its Tables 3 and 4, library statistics, ratios).
pub use report::paper;

pub use cell::{params_key, Cell, Conditions, LevelChoice, Planner, DEFAULT_PARAMS};
pub use children::CellCommand;
pub use findings::findings;
pub use lab::{execute, learn_study, tower_problem, towers, Known, Lab};
pub use memory_limit::auto_memory_limit;
pub use numbers::{numbers, sizes};
pub use ratio::{quartiles, ratio, ratio_text, Quartiles};
pub use record::{append_record, parse_records, read_records, RunRecord, Times, WideningStep};
pub use reproduce::{reproduce, reproduce_cell, ReproduceOptions, Reproduction};
pub use study::{study, study_cell, study_grid, StudyOptions, StudyOutcome};

/// Where a grid is: cells done of the total, the cell now running, time since start.
#[derive(Debug, Clone, Copy)]
pub struct Progress<'a> {
    pub done: usize,
    pub total: usize,
    /// What runs now, for people: e.g. `lmcut full height 5 seed 3`.
    pub current: &'a str,
    pub elapsed: Duration,
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
    /// A file could not be read or written.
    #[error("{}: {message}", path.display())]
    Io { path: PathBuf, message: String },
}

/// How a grid's cells are computed.
#[derive(Debug)]
pub enum Runner<'a> {
    /// In this process, one after another (each run's peak heap measured alone).
    InProcess(&'a mut Lab),
    /// In child processes, several at a time ([`CellCommand`]); needs a results file,
    /// where the children of Algorithm 1 cells find the runs they reuse.
    Children(&'a CellCommand),
}

/// Runs `cells`, skipping those whose id has a record in `done`, appending each new
/// record to `results` (when given) as it finishes. Algorithm 1 cells run after every
/// other cell, so that they reuse the runs of the levels the grid has as cells
/// ([`Lab::run`]). Returns the records of every cell, `done`'s and the new ones, in
/// the order of `cells`.
pub fn run_cells(
    runner: Runner<'_>,
    cells: &[Cell],
    done: &[RunRecord],
    results: Option<&std::path::Path>,
    progress: &mut dyn FnMut(Progress<'_>),
    describe: &dyn Fn(&Cell) -> String,
) -> Result<Vec<RunRecord>, ExperimentError> {
    let start = Instant::now();
    let ids: Vec<String> = cells.iter().map(Cell::id).collect();
    let mut known: Known = done.iter().map(|r| (r.id.clone(), r.clone())).collect();
    let (levels, widenings): (Vec<usize>, Vec<usize>) = (0..cells.len())
        .filter(|&i| !known.contains_key(&ids[i]))
        .partition(|&i| cells[i].level != LevelChoice::Algorithm1);
    let total = cells.len();
    let mut finished = total - levels.len() - widenings.len();
    let record = |i: usize, r: RunRecord, known: &mut Known| {
        if let Some(path) = results {
            append_record(path, &r)?;
        }
        known.insert(ids[i].clone(), r);
        Ok::<(), ExperimentError>(())
    };
    let mut runner = runner;
    for phase in [levels, widenings] {
        match &mut runner {
            Runner::InProcess(lab) => {
                for i in phase {
                    let what = describe(&cells[i]);
                    progress(Progress {
                        done: finished,
                        total,
                        current: &what,
                        elapsed: start.elapsed(),
                    });
                    let r = lab.run(&cells[i], &known)?;
                    record(i, r, &mut known)?;
                    finished += 1;
                }
            }
            Runner::Children(command) => {
                if results.is_none() {
                    return Err(ExperimentError::Options(
                        "cells in child processes need a results file".into(),
                    ));
                }
                let mut running = String::new();
                command.run_all(cells, &phase, &mut |event| {
                    match event {
                        children::Event::Started(i) => running = describe(&cells[i]),
                        children::Event::Finished(i, r) => {
                            record(i, *r, &mut known)?;
                            finished += 1;
                        }
                    }
                    progress(Progress {
                        done: finished,
                        total,
                        current: &running,
                        elapsed: start.elapsed(),
                    });
                    Ok(())
                })?;
            }
        }
    }
    progress(Progress {
        done: total,
        total,
        current: "done",
        elapsed: start.elapsed(),
    });
    ids.iter()
        .map(|id| {
            known
                .get(id)
                .cloned()
                .ok_or_else(|| ExperimentError::Condition(format!("cell {id} has no record")))
        })
        .collect()
}

/// Computes the cell of `cells` whose id is `id`, as a child process of
/// [`CellCommand`] does: Algorithm 1 reuses the records already in `results`.
pub fn run_cell(
    lab: &mut Lab,
    cells: &[Cell],
    id: &str,
    results: &std::path::Path,
) -> Result<RunRecord, ExperimentError> {
    let cell = cells.iter().find(|c| c.id() == id).ok_or_else(|| {
        ExperimentError::Options(format!("--cell {id}: no cell of this grid has that id"))
    })?;
    let known: Known = if cell.level == LevelChoice::Algorithm1 {
        read_records(results)?
            .into_iter()
            .map(|r| (r.id.clone(), r))
            .collect()
    } else {
        Known::new()
    };
    lab.run(cell, &known)
}
