//! Cells in child processes, several at a time.
//!
//! Each cell runs as `PROGRAM ARGS... --cell ID`: the grid's own command again, asked
//! for one cell. The child computes it in-process and writes its record into its run
//! folder ([`super::run_cell`]). A process per cell gives each run its own memory
//! counter (peak heap is counted per process) and its own limits, and a crash loses one
//! cell, whose folder then gets a record saying why ([`RunRecord::crashed`]).

use std::ffi::OsString;
use std::io::Read;
use std::path::PathBuf;
use std::process::{Child, Command, Stdio};
use std::sync::mpsc;
use std::sync::Mutex;
use std::time::{Duration, Instant};

use super::RunLayout;
use crate::cell::Cell;
use crate::record::RunRecord;
use crate::ExperimentError;

/// How to run one cell of this grid in a child process.
#[derive(Debug, Clone)]
pub struct CellCommand {
    /// The executable (the CLI passes its own).
    pub program: PathBuf,
    /// The grid's arguments (its output folder among them); `--cell ID` is appended.
    pub args: Vec<OsString>,
    /// Children at once (at least 1).
    pub jobs: usize,
}

/// What the workers tell the thread that records results.
pub(crate) enum Event {
    Started(usize),
    Finished(Box<RunRecord>),
}

/// How much longer than its limit a child may take before it is killed: its limit
/// covers the planning, not the start-up (simulating and learning) or Fast Downward's
/// driver. Only a hung child ever gets near it.
fn watchdog(cell: &Cell) -> Duration {
    cell.time_limit * 3 + Duration::from_secs(120)
}

impl CellCommand {
    /// Runs the cells `which` (indices into `cells`), `jobs` at a time, calling
    /// `on_event` on this thread as each starts and finishes. Stops at the first error
    /// `on_event` returns, after the running children end.
    pub(crate) fn run_all(
        &self,
        cells: &[Cell],
        which: &[usize],
        layout: &RunLayout,
        on_event: &mut dyn FnMut(Event) -> Result<(), ExperimentError>,
    ) -> Result<(), ExperimentError> {
        let queue = Mutex::new(which.iter().copied());
        let stop = std::sync::atomic::AtomicBool::new(false);
        let (tx, rx) = mpsc::channel();
        std::thread::scope(|scope| {
            for _ in 0..self.jobs.max(1).min(which.len()) {
                let tx = tx.clone();
                let (queue, stop) = (&queue, &stop);
                scope.spawn(move || loop {
                    if stop.load(std::sync::atomic::Ordering::Relaxed) {
                        break;
                    }
                    let next = queue.lock().ok().and_then(|mut q| q.next());
                    let Some(i) = next else { break };
                    if tx.send(Event::Started(i)).is_err() {
                        break;
                    }
                    let record = self.run_one(&cells[i], i + 1, layout);
                    if tx.send(Event::Finished(Box::new(record))).is_err() {
                        break;
                    }
                });
            }
            drop(tx);
            let mut first_error = None;
            for event in rx {
                if first_error.is_some() {
                    continue;
                }
                if let Err(e) = on_event(event) {
                    stop.store(true, std::sync::atomic::Ordering::Relaxed);
                    first_error = Some(e);
                }
            }
            first_error.map_or(Ok(()), Err)
        })
    }

    /// One cell in a child, which writes its record into the cell's folder. A child
    /// that fails, hangs or leaves no record of its cell gives a record of the crash,
    /// written there in its place (the result of a failing write is the record alone).
    fn run_one(&self, cell: &Cell, task: usize, layout: &RunLayout) -> RunRecord {
        let outcome = self.spawn_one(cell, task, layout);
        match outcome {
            Ok(record) => record,
            Err(message) => {
                let record = RunRecord {
                    crashed: true,
                    ..RunRecord::failed(cell, message)
                };
                let _ = super::write_result(layout, task, &record, cell.time_limit.as_secs_f64());
                record
            }
        }
    }

    fn spawn_one(&self, cell: &Cell, task: usize, layout: &RunLayout) -> Result<RunRecord, String> {
        let id = cell.id();
        let mut command = Command::new(&self.program);
        command
            .args(&self.args)
            .arg("--cell")
            .arg(&id)
            .stdin(Stdio::null())
            .stdout(Stdio::null())
            .stderr(Stdio::piped());
        let mut child = command
            .spawn()
            .map_err(|e| format!("could not start {}: {e}", self.program.display()))?;
        let (status, stderr) = wait(&mut child, watchdog(cell))?;
        if !status.success() {
            let tail: Vec<&str> = stderr.lines().rev().take(5).collect();
            let tail: Vec<&str> = tail.into_iter().rev().collect();
            return Err(format!(
                "the child process failed ({status}): {}",
                tail.join(" / ")
            ));
        }
        layout.read_record(task, cell).ok_or_else(|| {
            format!(
                "the child process ended without writing the record of cell {id} into {}",
                layout.run_dir(task).display()
            )
        })
    }
}

/// Waits for `child` (reading its standard error as it comes, so that a full pipe never
/// blocks it), killing it after `limit`.
fn wait(child: &mut Child, limit: Duration) -> Result<(std::process::ExitStatus, String), String> {
    let reader = |pipe: Option<Box<dyn Read + Send>>| {
        std::thread::spawn(move || {
            let mut text = String::new();
            if let Some(mut pipe) = pipe {
                let mut bytes = Vec::new();
                let _ = pipe.read_to_end(&mut bytes);
                text = String::from_utf8_lossy(&bytes).into_owned();
            }
            text
        })
    };
    let err = reader(
        child
            .stderr
            .take()
            .map(|p| Box::new(p) as Box<dyn Read + Send>),
    );
    let start = Instant::now();
    let status = loop {
        match child.try_wait() {
            Ok(Some(status)) => break status,
            Ok(None) if start.elapsed() > limit => {
                let _ = child.kill();
                let _ = child.wait();
                return Err(format!(
                    "the child process ran {:.0} s and was killed",
                    limit.as_secs_f64()
                ));
            }
            Ok(None) => std::thread::sleep(Duration::from_millis(5)),
            Err(e) => return Err(format!("could not wait for the child process: {e}")),
        }
    };
    let stderr = err.join().unwrap_or_default();
    Ok((status, stderr))
}
