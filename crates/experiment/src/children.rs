//! Cells in child processes, several at a time.
//!
//! Each cell runs as `PROGRAM ARGS... --cell ID`: the grid's own command again, asked
//! for one cell. The child computes it in-process and prints its record as one JSON
//! line on standard output. A process per cell gives each run its own memory counter
//! (peak heap is counted per process) and its own limits, and a crash loses one cell,
//! whose record then says why.

use std::ffi::OsString;
use std::io::Read;
use std::path::PathBuf;
use std::process::{Child, Command, Stdio};
use std::sync::mpsc;
use std::sync::Mutex;
use std::time::{Duration, Instant};

use crate::cell::Cell;
use crate::record::RunRecord;
use crate::ExperimentError;

/// How to run one cell of this grid in a child process.
#[derive(Debug, Clone)]
pub struct CellCommand {
    /// The executable (the CLI passes its own).
    pub program: PathBuf,
    /// The grid's arguments; `--cell ID` is appended.
    pub args: Vec<OsString>,
    /// Children at once (at least 1).
    pub jobs: usize,
}

/// What the workers tell the thread that records results.
pub(crate) enum Event {
    Started(usize),
    Finished(usize, Box<RunRecord>),
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
                    let record = self.run_one(&cells[i]);
                    if tx.send(Event::Finished(i, Box::new(record))).is_err() {
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

    /// One cell in a child; a child that fails, hangs or prints no record gives an
    /// error record saying so.
    fn run_one(&self, cell: &Cell) -> RunRecord {
        let id = cell.id();
        let mut command = Command::new(&self.program);
        command
            .args(&self.args)
            .arg("--cell")
            .arg(&id)
            .stdin(Stdio::null())
            .stdout(Stdio::piped())
            .stderr(Stdio::piped());
        let mut child = match command.spawn() {
            Ok(child) => child,
            Err(e) => {
                return RunRecord::failed(
                    cell,
                    format!("could not start {}: {e}", self.program.display()),
                )
            }
        };
        let (status, stdout, stderr) = match wait(&mut child, watchdog(cell)) {
            Ok(done) => done,
            Err(message) => return RunRecord::failed(cell, message),
        };
        let line = stdout.lines().rev().find(|l| !l.trim().is_empty());
        let parsed = line.map(serde_json::from_str::<RunRecord>);
        match (status.success(), parsed) {
            (true, Some(Ok(record))) if record.id == id => record,
            (true, Some(Ok(record))) => RunRecord::failed(
                cell,
                format!("the child computed cell {} instead", record.id),
            ),
            (true, Some(Err(e))) => {
                RunRecord::failed(cell, format!("the child printed no record: {e}"))
            }
            (true, None) => RunRecord::failed(cell, "the child printed nothing".to_string()),
            (false, _) => {
                let tail: Vec<&str> = stderr.lines().rev().take(5).collect();
                let tail: Vec<&str> = tail.into_iter().rev().collect();
                RunRecord::failed(
                    cell,
                    format!("the child process failed ({status}): {}", tail.join(" / ")),
                )
            }
        }
    }
}

/// Waits for `child` (reading its output as it comes, so that a full pipe never blocks
/// it), killing it after `limit`.
fn wait(
    child: &mut Child,
    limit: Duration,
) -> Result<(std::process::ExitStatus, String, String), String> {
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
    let out = reader(
        child
            .stdout
            .take()
            .map(|p| Box::new(p) as Box<dyn Read + Send>),
    );
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
    let stdout = out.join().unwrap_or_default();
    let stderr = err.join().unwrap_or_default();
    Ok((status, stdout, stderr))
}
