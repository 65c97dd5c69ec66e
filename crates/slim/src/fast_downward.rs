//! Fast Downward as an external backend: an installed `fast-downward.py`, run as a
//! separate process in a fresh folder, its log and plan file read back.

use std::path::{Path, PathBuf};
use std::process::Command;
use std::sync::atomic::{AtomicU64, Ordering};
use std::time::{Duration, Instant};

use crate::run::{Outcome, PlanRun};

/// The environment variable that names `fast-downward.py`.
pub const FD_VARIABLE: &str = "DEMOPLAN_FD";

/// An installed Fast Downward.
#[derive(Debug, Clone)]
pub struct FastDownward {
    /// The driver script (`fast-downward.py`) or an executable.
    pub driver: PathBuf,
    /// The Python that runs the script: the one beside it in a virtual environment when
    /// there is one, else `python3`.
    pub python: Option<PathBuf>,
}

static RUNS: AtomicU64 = AtomicU64::new(0);

impl FastDownward {
    /// Fast Downward from a path given on the command line, else from `DEMOPLAN_FD`; an
    /// error says how to install it when neither names an existing file.
    pub fn locate(explicit: Option<&Path>) -> Result<FastDownward, String> {
        let from_env = std::env::var_os(FD_VARIABLE).map(PathBuf::from);
        let Some(driver) = explicit.map(Path::to_path_buf).or(from_env) else {
            return Err(format!(
                "Fast Downward not found: give --fd PATH or set {FD_VARIABLE} to its \
                 fast-downward.py (install: python3 -m venv .venv-fd && .venv-fd/bin/pip \
                 install up-fast-downward; the script is in \
                 .venv-fd/lib/python3*/site-packages/up_fast_downward/downward/)"
            ));
        };
        if !driver.is_file() {
            return Err(format!(
                "Fast Downward not found: {} is not a file (from --fd or {FD_VARIABLE})",
                driver.display()
            ));
        }
        let python = if driver.extension().is_some_and(|e| e == "py") {
            // .venv/lib/python3.X/site-packages/.../fast-downward.py: the venv's python.
            let venv_python = driver
                .ancestors()
                .find(|a| a.join("bin/python").is_file() && a.join("pyvenv.cfg").is_file())
                .map(|a| a.join("bin/python"));
            Some(venv_python.unwrap_or_else(|| PathBuf::from("python3")))
        } else {
            None
        };
        Ok(FastDownward { driver, python })
    }

    /// Plans with `search` under `time_limit` (Fast Downward's `--overall-time-limit`).
    pub fn plan(
        &self,
        domain: &str,
        problem: &str,
        search: &str,
        time_limit: Option<Duration>,
    ) -> PlanRun {
        let start = Instant::now();
        let mut run = PlanRun::ended(Outcome::Error(String::new()));
        let dir = std::env::temp_dir().join(format!(
            "demoplan-fd-{}-{}",
            std::process::id(),
            RUNS.fetch_add(1, Ordering::Relaxed)
        ));
        let result = self.run_in(&dir, domain, problem, search, time_limit);
        let _ = std::fs::remove_dir_all(&dir);
        match result {
            Ok((code, log, plan)) => {
                run.outcome = match code {
                    Some(0..=3) => Outcome::Solved,
                    Some(10..=13) => Outcome::Unsolvable,
                    Some(20 | 22) => Outcome::MemoryLimit,
                    Some(21 | 23 | 24) => Outcome::TimeLimit,
                    other => Outcome::Error(format!(
                        "Fast Downward exited with {}; its log ends: {}",
                        other.map_or("a signal".to_string(), |c| c.to_string()),
                        log.lines().rev().take(3).collect::<Vec<_>>().join(" / ")
                    )),
                };
                // The search component's "Total time" includes building the heuristic
                // (iPDB's hill climbing), which its "Search time" leaves out; demoplan's
                // search time includes it, so that is the one to compare.
                let mut search_total = None;
                for line in log.lines() {
                    if let Some(rest) = line.split("Total time: ").nth(1) {
                        search_total = Some(seconds(rest));
                    } else if let Some(rest) = line.split("Search time: ").nth(1) {
                        run.search_time = seconds(rest);
                    } else if let Some(rest) = line.split("Done! [").nth(1) {
                        // The translator's last line: "Done! [0.1s CPU, 0.1s wall-clock]".
                        if let Some(wall) = rest.split(", ").nth(1) {
                            run.translate_time = seconds(wall);
                        }
                    } else if let Some(rest) = line.split("Expanded ").nth(1) {
                        if line.contains("until last jump") {
                            continue;
                        }
                        run.expansions = rest.split(' ').next().and_then(|n| n.parse().ok());
                    } else if let Some(rest) = line.split("Plan cost: ").nth(1) {
                        run.cost = rest.trim().parse().ok();
                    }
                }
                if let Some(total) = search_total {
                    run.search_time = total;
                }
                if run.outcome == Outcome::Solved {
                    run.plan = plan
                        .lines()
                        .map(str::trim)
                        .filter(|l| l.starts_with('('))
                        .map(|l| l.trim_start_matches('(').trim_end_matches(')').to_string())
                        .collect();
                }
            }
            Err(e) => run.outcome = Outcome::Error(e),
        }
        run.total_time = start.elapsed();
        run
    }

    fn run_in(
        &self,
        dir: &Path,
        domain: &str,
        problem: &str,
        search: &str,
        time_limit: Option<Duration>,
    ) -> Result<(Option<i32>, String, String), String> {
        std::fs::create_dir_all(dir)
            .map_err(|e| format!("cannot create {}: {e}", dir.display()))?;
        let write = |name: &str, text: &str| {
            std::fs::write(dir.join(name), text)
                .map_err(|e| format!("cannot write {}: {e}", dir.join(name).display()))
        };
        write("domain.pddl", domain)?;
        write("problem.pddl", problem)?;
        let mut command = match &self.python {
            Some(python) => {
                let mut c = Command::new(python);
                c.arg(&self.driver);
                c
            }
            None => Command::new(&self.driver),
        };
        if let Some(limit) = time_limit {
            command.arg("--overall-time-limit");
            command.arg(format!("{}s", limit.as_secs().max(1)));
        }
        command
            .args(["domain.pddl", "problem.pddl", "--search", search])
            .current_dir(dir);
        let output = command
            .output()
            .map_err(|e| format!("cannot run Fast Downward ({}): {e}", self.driver.display()))?;
        let log = String::from_utf8_lossy(&output.stdout).into_owned();
        let plan = std::fs::read_to_string(dir.join("sas_plan")).unwrap_or_default();
        Ok((output.status.code(), log, plan))
    }
}

/// `0.0123s` (or `0.0123s]`) in seconds.
fn seconds(text: &str) -> Duration {
    let number: String = text
        .trim()
        .chars()
        .take_while(|c| c.is_ascii_digit() || *c == '.')
        .collect();
    number
        .parse::<f64>()
        .ok()
        .filter(|s| s.is_finite() && *s >= 0.0)
        .map(Duration::from_secs_f64)
        .unwrap_or(Duration::ZERO)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn seconds_read_fast_downwards_numbers() {
        assert_eq!(seconds("0.5s"), Duration::from_millis(500));
        assert_eq!(seconds("1.25s wall-clock]"), Duration::from_millis(1250));
        assert_eq!(seconds("garbage"), Duration::ZERO);
    }

    #[test]
    fn a_missing_driver_is_a_clear_error() {
        let e = FastDownward::locate(Some(Path::new("/nonexistent/fast-downward.py")))
            .err()
            .unwrap_or_default();
        assert!(e.contains("not a file"), "{e}");
    }
}
