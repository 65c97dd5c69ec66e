//! Grids: a list of cells run as independent runs, each with its own folder in Downward
//! Lab's run layout, collected afterwards.
//!
//! A grid's cells are numbered 1, 2, ... in their order (Lab's task ids); cell `n`'s
//! folder is `runs-00001-00100/0000n` under the grid's output folder ([`RunLayout`]).
//! A cell computed in any process (this one, a child process of `-j N`, a Slurm array
//! task) writes there, each file atomically: `started` when it begins, then its
//! `record.json` ([`RunRecord`]) and Lab's `properties` ([`properties`]). A cell whose
//! folder holds its record is done, and is reused unless the grid is forced
//! ([`reusable`]); a record of a crash ([`RunRecord::crashed`]) is not a result, so
//! its cell runs again. [`collect`] reads every cell's record, writes `results.jsonl`
//! and Lab's combined `eval/properties`, and is what every report is built from.

mod children;
pub mod properties;
mod relaunch;
mod settings;
pub mod slurm;

use std::path::{Path, PathBuf};
use std::time::Instant;

pub use children::CellCommand;
pub use relaunch::{cell_or_list, jobs, memory_limit, Relaunch};
pub(crate) use settings::named_option;
pub use settings::{
    FastDownwardArgs, GridArgs, GridExperiment, GridSettings, RunLimitArgs, SlurmArgs,
};

use crate::cell::{Cell, LevelChoice};
use crate::lab::{Known, Lab};
use crate::output::{create_dir, write_text};
use crate::record::{parse_records, RunRecord};
use crate::{ExperimentError, Progress};

/// Cells per `runs-*` folder, as Lab's.
const SHARD: usize = 100;

/// Where a grid's runs live: Lab's layout under the grid's output folder.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct RunLayout {
    root: PathBuf,
}

impl RunLayout {
    pub fn new(root: &Path) -> RunLayout {
        RunLayout {
            root: root.to_path_buf(),
        }
    }

    /// The grid's output folder.
    pub fn root(&self) -> &Path {
        &self.root
    }

    /// Cell `task`'s folder, relative to the root: `runs-00001-00100/00001` for task 1
    /// (tasks count from 1, as Lab's).
    pub fn run_dir_name(task: usize) -> String {
        let lower = (task.saturating_sub(1) / SHARD) * SHARD + 1;
        format!("runs-{lower:05}-{:05}/{task:05}", lower + SHARD - 1)
    }

    pub fn run_dir(&self, task: usize) -> PathBuf {
        self.root.join(Self::run_dir_name(task))
    }

    /// The cell's result record, one JSON line.
    pub fn record(&self, task: usize) -> PathBuf {
        self.run_dir(task).join("record.json")
    }

    /// Lab's properties of the run.
    pub fn properties(&self, task: usize) -> PathBuf {
        self.run_dir(task).join("properties")
    }

    /// Written when the cell begins (the process id and the host), so that a watcher
    /// knows a cell has started without guessing from the time.
    pub fn started(&self, task: usize) -> PathBuf {
        self.run_dir(task).join("started")
    }

    /// The combined properties of every run (Lab's evaluation folder).
    pub fn eval_properties(&self) -> PathBuf {
        self.root.join("eval").join("properties")
    }

    /// Every cell's record, one JSON line each (what [`collect`] writes).
    pub fn results(&self) -> PathBuf {
        self.root.join("results.jsonl")
    }

    /// The record in cell `task`'s folder, if there is a whole one of `cell`: a missing
    /// file, a record of another cell (the folder of an earlier, different grid) or a
    /// file that is not one record are `None`, so that the cell runs again.
    pub fn read_record(&self, task: usize, cell: &Cell) -> Option<RunRecord> {
        let path = self.record(task);
        let text = std::fs::read_to_string(&path).ok()?;
        let mut records = parse_records(&text, &path).ok()?;
        match (records.pop(), records.is_empty()) {
            (Some(r), true) if r.is_of(cell) => Some(r),
            _ => None,
        }
    }
}

/// Which cells already have a result: per cell (in order), its record when it is done
/// and can be reused. Nothing is reused when `force` is set, nor a record of a crash.
pub fn reusable(layout: &RunLayout, cells: &[Cell], force: bool) -> Vec<Option<RunRecord>> {
    cells
        .iter()
        .enumerate()
        .map(|(i, cell)| {
            if force {
                return None;
            }
            layout.read_record(i + 1, cell).filter(|r| !r.crashed)
        })
        .collect()
}

/// The task number (from 1) of the cell with id `id`.
pub fn task_of(cells: &[Cell], id: &str) -> Result<usize, ExperimentError> {
    cells
        .iter()
        .position(|c| c.id() == id)
        .map(|i| i + 1)
        .ok_or_else(|| {
            ExperimentError::Options(format!("--cell {id}: no cell of this grid has that id"))
        })
}

/// Writes cell `task`'s record and Lab's properties into its folder, each atomically.
pub fn write_result(
    layout: &RunLayout,
    task: usize,
    record: &RunRecord,
    limit_s: f64,
) -> Result<(), ExperimentError> {
    create_dir(&layout.run_dir(task))?;
    let props = properties::run_properties(record, task, limit_s);
    write_text(&layout.properties(task), &properties::to_text(&props))?;
    write_text(
        &layout.record(task),
        &format!("{}\n", record.to_json_line()),
    )
}

/// What a cell's process does: computes cell `id` of `cells` (unless its result is
/// there and `force` is not set) and writes it into its folder. Algorithm 1 cells reuse
/// the grid's records of the levels they try, when those are done.
pub fn run_cell(
    lab: &mut Lab,
    cells: &[Cell],
    id: &str,
    layout: &RunLayout,
    force: bool,
) -> Result<RunRecord, ExperimentError> {
    let task = task_of(cells, id)?;
    let cell = &cells[task - 1];
    if !force {
        if let Some(done) = layout.read_record(task, cell).filter(|r| !r.crashed) {
            return Ok(done);
        }
    }
    create_dir(&layout.run_dir(task))?;
    write_text(
        &layout.started(task),
        &format!("pid {}\ncell {id}\n", std::process::id()),
    )?;
    let known: Known = if cell.level == LevelChoice::Algorithm1 {
        reusable(layout, cells, false)
            .into_iter()
            .flatten()
            .map(|r| (r.id.clone(), r))
            .collect()
    } else {
        Known::new()
    };
    let record = lab.run(cell, &known)?;
    write_result(layout, task, &record, cell.time_limit.as_secs_f64())?;
    Ok(record)
}

/// How a grid's cells are computed.
#[derive(Debug)]
pub enum Runner<'a> {
    /// In this process, one after another (each run's peak heap measured alone).
    InProcess(&'a mut Lab),
    /// In child processes, several at a time ([`CellCommand`]).
    Children(&'a CellCommand),
}

impl Runner<'_> {
    /// Cells computed at once.
    pub fn jobs(&self) -> usize {
        match self {
            Runner::InProcess(_) => 1,
            Runner::Children(c) => c.jobs.max(1),
        }
    }
}

/// What a grid run did.
#[derive(Debug, Clone)]
pub struct GridRun {
    /// Every cell's record, in the order of the cells.
    pub records: Vec<RunRecord>,
    /// Cells computed now (the others were reused).
    pub computed: usize,
    /// Cells whose process crashed now (each has a record saying why).
    pub crashed: usize,
    /// Cells computed at once.
    pub jobs: usize,
}

impl GridRun {
    /// Plans that failed the execution check.
    pub fn failed_executions(&self) -> usize {
        self.records
            .iter()
            .filter(|r| r.executed == Some(false))
            .count()
    }
}

/// Runs the grid `cells` into `out`: every cell without a reusable result (all of them
/// when `force` is set), Algorithm 1 cells after every other so that they reuse the
/// runs of the levels the grid has as cells; then [`collect`]s them. A cell whose
/// process crashed gets a record with its error and counts in [`GridRun::crashed`].
pub fn run_grid(
    runner: Runner<'_>,
    cells: &[Cell],
    out: &Path,
    force: bool,
    progress: &mut dyn FnMut(Progress<'_>),
    describe: &dyn Fn(&Cell) -> String,
) -> Result<GridRun, ExperimentError> {
    let start = Instant::now();
    let layout = RunLayout::new(out);
    create_dir(out)?;
    let done = reusable(&layout, cells, force);
    let (levels, widenings): (Vec<usize>, Vec<usize>) = (0..cells.len())
        .filter(|&i| done[i].is_none())
        .partition(|&i| cells[i].level != LevelChoice::Algorithm1);
    let total = cells.len();
    let reused = total - levels.len() - widenings.len();
    let jobs = runner.jobs();
    let mut finished = reused;
    let mut crashed = 0;
    let mut report = |finished: usize, crashed: usize, current: &str| {
        progress(Progress {
            done: finished,
            failed: crashed,
            reused,
            total,
            current,
            elapsed: start.elapsed(),
        })
    };
    let mut runner = runner;
    for phase in [levels, widenings] {
        match &mut runner {
            Runner::InProcess(lab) => {
                for i in phase {
                    report(finished, crashed, &describe(&cells[i]));
                    run_cell(lab, cells, &cells[i].id(), &layout, force)?;
                    finished += 1;
                }
            }
            Runner::Children(command) => {
                let mut running = String::new();
                command.run_all(cells, &phase, &layout, &mut |event| {
                    match event {
                        children::Event::Started(i) => running = describe(&cells[i]),
                        children::Event::Finished(record) => {
                            finished += 1;
                            if record.crashed {
                                crashed += 1;
                            }
                        }
                    }
                    report(finished, crashed, &running);
                    Ok(())
                })?;
            }
        }
    }
    report(total, crashed, "done");
    let records = collect(out, cells)?;
    Ok(GridRun {
        records,
        computed: total - reused,
        crashed,
        jobs,
    })
}

/// Reads every cell's record from its folder and writes `results.jsonl` and Lab's
/// combined `eval/properties`. A cell without a record is an error listing the cells
/// missing (run the grid again: it computes them).
pub fn collect(out: &Path, cells: &[Cell]) -> Result<Vec<RunRecord>, ExperimentError> {
    let layout = RunLayout::new(out);
    let mut records = Vec::with_capacity(cells.len());
    let mut missing = Vec::new();
    for (i, cell) in cells.iter().enumerate() {
        match layout.read_record(i + 1, cell) {
            Some(r) => records.push(r),
            None => missing.push(format!(
                "{} ({})",
                cell.id(),
                RunLayout::run_dir_name(i + 1)
            )),
        }
    }
    if !missing.is_empty() {
        return Err(ExperimentError::Incomplete {
            out: out.to_path_buf(),
            missing,
            total: cells.len(),
        });
    }
    let mut jsonl = String::new();
    for r in &records {
        jsonl.push_str(&r.to_json_line());
        jsonl.push('\n');
    }
    write_text(&layout.results(), &jsonl)?;
    create_dir(&out.join("eval"))?;
    let combined = properties::combined(
        records
            .iter()
            .enumerate()
            .map(|(i, r)| (r, i + 1, cells[i].time_limit.as_secs_f64())),
    );
    write_text(&layout.eval_properties(), &properties::to_text(&combined))?;
    Ok(records)
}

/// `--list-cells`: one line per cell, its task number, id, Lab names and conditions,
/// tab-separated, with a header line.
pub fn cell_list(cells: &[Cell]) -> String {
    let mut s = String::from("task\tid\talgorithm\tdomain\tproblem\tconditions\n");
    for (i, cell) in cells.iter().enumerate() {
        let names = properties::LabNames::of(cell);
        s.push_str(&format!(
            "{}\t{}\t{}\t{}\t{}\t{}\n",
            i + 1,
            cell.id(),
            names.algorithm,
            names.domain,
            names.problem,
            cell.canonical()
        ));
    }
    s
}

#[cfg(test)]
pub(crate) mod tests {
    use super::*;
    use crate::cell::{Conditions, Planner};
    use std::time::Duration;

    #[test]
    fn run_folders_follow_labs_layout() {
        assert_eq!(RunLayout::run_dir_name(1), "runs-00001-00100/00001");
        assert_eq!(RunLayout::run_dir_name(100), "runs-00001-00100/00100");
        assert_eq!(RunLayout::run_dir_name(101), "runs-00101-00200/00101");
        assert_eq!(RunLayout::run_dir_name(12345), "runs-12301-12400/12345");
    }

    pub(crate) fn cell(seed: u64) -> Cell {
        Cell {
            conditions: Conditions::paper_goal(seed, 1, 1),
            level: LevelChoice::Prio(1),
            planner: Planner::Lmcut,
            time_limit: Duration::from_secs(10),
            repeat: 0,
        }
    }

    fn scratch(name: &str) -> PathBuf {
        let dir = std::env::temp_dir().join(format!(
            "demoplan-grid-{name}-{}-{:?}",
            std::process::id(),
            std::thread::current().id()
        ));
        let _ = std::fs::remove_dir_all(&dir);
        dir
    }

    #[test]
    fn only_whole_records_of_the_same_cell_are_reused() {
        let dir = scratch("reuse");
        let layout = RunLayout::new(&dir);
        let cells = [cell(1), cell(2), cell(3), cell(4)];
        // 1: its own record; 2: another cell's; 3: a crash; 4: half a record.
        write_result(&layout, 1, &RunRecord::blank(&cells[0]), 10.0).unwrap();
        write_result(&layout, 2, &RunRecord::blank(&cells[0]), 10.0).unwrap();
        let mut crash = RunRecord::failed(&cells[2], "killed".into());
        crash.crashed = true;
        write_result(&layout, 3, &crash, 10.0).unwrap();
        let line = RunRecord::blank(&cells[3]).to_json_line();
        std::fs::create_dir_all(layout.run_dir(4)).unwrap();
        std::fs::write(layout.record(4), &line[..line.len() / 2]).unwrap();
        let reused: Vec<bool> = reusable(&layout, &cells, false)
            .iter()
            .map(Option::is_some)
            .collect();
        assert_eq!(reused, [true, false, false, false]);
        assert!(reusable(&layout, &cells, true).iter().all(Option::is_none));
        // Collecting names what is missing.
        let e = collect(&dir, &cells).unwrap_err().to_string();
        // A crash is a result of this run (failed), not a missing one.
        assert!(e.contains("2 of 4 cells have no result"), "{e}");
        assert!(e.contains("runs-00001-00100/00002"), "{e}");
        let _ = std::fs::remove_dir_all(&dir);
    }

    #[test]
    fn collect_writes_the_results_and_labs_combined_properties() {
        let dir = scratch("collect");
        let layout = RunLayout::new(&dir);
        let cells = [cell(1), cell(2)];
        for (i, c) in cells.iter().enumerate() {
            write_result(&layout, i + 1, &RunRecord::blank(c), 10.0).unwrap();
        }
        let records = collect(&dir, &cells).unwrap();
        assert_eq!(records.len(), 2);
        let text = std::fs::read_to_string(layout.results()).unwrap();
        assert_eq!(text.lines().count(), 2);
        let eval: serde_json::Value =
            serde_json::from_str(&std::fs::read_to_string(layout.eval_properties()).unwrap())
                .unwrap();
        let runs = eval.as_object().unwrap();
        assert_eq!(runs.len(), 2);
        for (key, run) in runs {
            let id: Vec<&str> = run["id"]
                .as_array()
                .unwrap()
                .iter()
                .map(|v| v.as_str().unwrap())
                .collect();
            assert_eq!(*key, id.join("-"));
        }
        let _ = std::fs::remove_dir_all(&dir);
    }

    #[test]
    fn the_cell_list_has_a_line_per_cell() {
        let cells = [cell(1), cell(2)];
        let list = cell_list(&cells);
        let lines: Vec<&str> = list.lines().collect();
        assert_eq!(lines.len(), 3);
        assert!(lines[1].starts_with(&format!("1\t{}\tdemoplan-lmcut\t", cells[0].id())));
        assert!(lines[2].contains("seed=2;"), "{}", lines[2]);
    }
}
