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

    /// Plans with `search` under `time_limit` and `memory_limit` bytes (Fast Downward's
    /// `--overall-time-limit` and `--overall-memory-limit`, which its driver sets as the
    /// process's limits).
    pub fn plan(
        &self,
        domain: &str,
        problem: &str,
        search: &str,
        time_limit: Option<Duration>,
        memory_limit: Option<u64>,
    ) -> PlanRun {
        let start = Instant::now();
        let mut run = PlanRun::ended(Outcome::Error);
        let dir = std::env::temp_dir().join(format!(
            "demoplan-fd-{}-{}",
            std::process::id(),
            RUNS.fetch_add(1, Ordering::Relaxed)
        ));
        let result = self.run_in(&dir, domain, problem, search, time_limit, memory_limit);
        let _ = std::fs::remove_dir_all(&dir);
        match result {
            Ok((code, log, plan)) => {
                match code {
                    Some(0..=3) => run.outcome = Outcome::Solved,
                    Some(10..=13) => run.outcome = Outcome::Unsolvable,
                    Some(20 | 22) => run.outcome = Outcome::MemoryLimit,
                    Some(21 | 23 | 24) => run.outcome = Outcome::TimeLimit,
                    other => run.fail(format!(
                        "Fast Downward exited with {}; its log ends: {}",
                        other.map_or("a signal".to_string(), |c| c.to_string()),
                        log.lines().rev().take(3).collect::<Vec<_>>().join(" / ")
                    )),
                }
                let parsed = parse_log(&log);
                run.translate_time = parsed.translate;
                run.heuristic_time = parsed.heuristic;
                run.search_time = parsed.search;
                run.expansions = parsed.expansions;
                run.generated = parsed.generated;
                run.cost = parsed.cost;
                run.peak_memory_kb = parsed.peak_memory_kb;
                if run.outcome == Outcome::Solved {
                    match pddl::parse_plan(&plan) {
                        Ok(read) => run.plan = read.steps,
                        Err(e) => run.fail(format!("Fast Downward's sas_plan, {e}")),
                    }
                    // Fast Downward's own verdict, from its cost line.
                    if plan.contains("(unit cost)") {
                        run.cost_kind = pddl::CostKind::Unit;
                    }
                }
            }
            Err(e) => run.fail(e),
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
        memory_limit: Option<u64>,
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
        if let Some(bytes) = memory_limit {
            // In KiB, with its unit, so that no default unit of the driver applies.
            command.arg("--overall-memory-limit");
            command.arg(format!("{}K", bytes.div_ceil(1024).max(1)));
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

/// What a Fast Downward log says about one run.
#[derive(Debug, Clone, Default, PartialEq, Eq)]
pub struct FdLog {
    /// The translator's wall-clock time, from its last line "Done! [0.1s CPU, 0.1s
    /// wall-clock]".
    pub translate: Duration,
    /// The search component's "Total time" minus its "Search time": reading the task
    /// and building the heuristic (iPDB's hill climbing, LM-cut's relaxed task).
    pub heuristic: Duration,
    /// The search component's "Search time".
    pub search: Duration,
    /// "Expanded N state(s)." (not the count until the last jump).
    pub expansions: Option<u64>,
    /// "Generated N state(s)."
    pub generated: Option<u64>,
    /// "Plan cost: N".
    pub cost: Option<u64>,
    /// "Peak memory: N KB", the search component's peak resident set.
    pub peak_memory_kb: Option<u64>,
}

/// Reads the times and counts out of a Fast Downward log (the driver's standard
/// output: translator and search component one after the other). Lines it does not
/// know are skipped; a missing line leaves its field at zero or `None`.
pub fn parse_log(log: &str) -> FdLog {
    let mut out = FdLog::default();
    let mut search_total = None;
    let mut search_time = None;
    for line in log.lines() {
        // The search component prefixes its lines with "[t=0.01s, 9788 KB] ".
        let text = line.rsplit("] ").next().unwrap_or(line).trim();
        if let Some(rest) = text.strip_prefix("Total time: ") {
            search_total = Some(seconds(rest));
        } else if let Some(rest) = text.strip_prefix("Search time: ") {
            search_time = Some(seconds(rest));
        } else if let Some(rest) = line.split("Done! [").nth(1) {
            if let Some(wall) = rest.split(", ").nth(1) {
                out.translate = seconds(wall);
            }
        } else if let Some(rest) = text.strip_prefix("Expanded ") {
            if text.ends_with("state(s).") && !text.contains("until last jump") {
                out.expansions = rest.split(' ').next().and_then(|n| n.parse().ok());
            }
        } else if let Some(rest) = text.strip_prefix("Generated ") {
            // Not the translator's "Generated 24 rules.".
            if text.ends_with("state(s).") && !text.contains("until last jump") {
                out.generated = rest.split(' ').next().and_then(|n| n.parse().ok());
            }
        } else if let Some(rest) = text.strip_prefix("Plan cost: ") {
            out.cost = rest.trim().parse().ok();
        } else if let Some(rest) = text.strip_prefix("Peak memory: ") {
            out.peak_memory_kb = rest.split(' ').next().and_then(|n| n.parse().ok());
        }
    }
    out.search = search_time.unwrap_or(Duration::ZERO);
    out.heuristic = search_total.map_or(Duration::ZERO, |t| t.saturating_sub(out.search));
    out
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

    fn fixture(name: &str) -> String {
        let path = Path::new(env!("CARGO_MANIFEST_DIR"))
            .join("tests/fixtures/fast-downward")
            .join(name);
        std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display()))
    }

    /// Logs of Fast Downward 26.6 (`up-fast-downward` 1.0.0) planning goal 3 on the
    /// widening library's full domain.
    #[test]
    fn the_four_times_come_from_a_real_ipdb_log() {
        let log = parse_log(&fixture("astar-ipdb.log"));
        assert_eq!(log.translate, Duration::from_secs_f64(0.031));
        assert_eq!(log.search, Duration::from_secs_f64(0.000505));
        // "Total time: 0.009395s" less the search time: reading the task and the climb.
        assert_eq!(
            log.heuristic,
            Duration::from_secs_f64(0.009395) - Duration::from_secs_f64(0.000505)
        );
        assert_eq!(log.expansions, Some(7));
        assert_eq!(log.generated, Some(60));
        assert_eq!(log.cost, Some(240));
        assert_eq!(log.peak_memory_kb, Some(10676));
    }

    #[test]
    fn the_four_times_come_from_a_real_lmcut_log() {
        let log = parse_log(&fixture("astar-lmcut.log"));
        assert!(log.translate > Duration::ZERO);
        assert!(log.search > Duration::ZERO);
        assert!(log.heuristic > Duration::ZERO);
        assert_eq!(log.cost, Some(240));
        assert!(log.expansions.is_some_and(|e| e > 0));
        assert!(log.peak_memory_kb.is_some());
    }

    #[test]
    fn a_log_cut_short_leaves_what_it_did_not_say_empty() {
        let log = parse_log("Done! [0.1s CPU, 0.2s wall-clock]\nGenerated 24 rules.\n");
        assert_eq!(log.translate, Duration::from_millis(200));
        assert_eq!(log.generated, None);
        assert_eq!(log.search, Duration::ZERO);
        assert_eq!(log.heuristic, Duration::ZERO);
    }

    #[test]
    fn a_missing_driver_is_a_clear_error() {
        let e = FastDownward::locate(Some(Path::new("/nonexistent/fast-downward.py")))
            .err()
            .unwrap_or_default();
        assert!(e.contains("not a file"), "{e}");
    }
}
