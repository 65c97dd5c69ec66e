//! What `demoplan reproduce` and `demoplan study` say when a grid ends, and the exit code
//! of an experiment that could not run, so that the command line only prints them.

use std::path::Path;
use std::time::Duration;

use slim::ExitCode;

use crate::grid::GridRun;
use crate::{ExperimentError, Reproduction, StudyOutcome};

impl ExperimentError {
    /// A bad option is a command line error (36), a cell that cannot be set up or a
    /// damaged results file an input error (31), cells without a result when a grid is
    /// collected a failed check (1: running the grid again computes them), a file that
    /// cannot be read or written an I/O error (35).
    pub fn exit_code(&self) -> ExitCode {
        match self {
            ExperimentError::Options(_)
            | ExperimentError::FastDownwardMissing
            | ExperimentError::Params { .. } => ExitCode::USAGE,
            ExperimentError::Condition(_) | ExperimentError::Results { .. } => {
                ExitCode::INPUT_ERROR
            }
            ExperimentError::Incomplete { .. } => ExitCode::CHECK_FAILED,
            ExperimentError::Io { .. } => ExitCode::CRITICAL_ERROR,
        }
    }
}

/// A grid whose cells all ran and whose plans all passed the execution check succeeded;
/// a crashed cell or a failed check is a failed check (1).
fn checked(grid: &GridRun) -> ExitCode {
    if grid.crashed > 0 || grid.failed_executions() > 0 {
        ExitCode::CHECK_FAILED
    } else {
        ExitCode::SUCCESS
    }
}

/// What failed, for standard error: cells whose process crashed (their records say why,
/// and the next run computes them again) and plans that failed the execution check.
fn failures(crashed: usize, failed_executions: usize) -> Option<String> {
    let mut text = String::new();
    if crashed > 0 {
        text.push_str(&format!(
            "error: {crashed} cell(s) crashed (their records in results.jsonl say why; run \
             again to compute them)\n"
        ));
    }
    if failed_executions > 0 {
        text.push_str(&format!(
            "error: {failed_executions} plan(s) failed the execution check (see tables.md)\n"
        ));
    }
    (!text.is_empty()).then_some(text)
}

impl Reproduction {
    /// The last line: where the results are, how many runs in how long (`elapsed`).
    pub fn closing_line(&self, out: &Path, elapsed: Duration) -> String {
        format!(
            "Wrote {} ({} runs in {:.0} s): open {}\n",
            out.display(),
            self.grid.records.len(),
            elapsed.as_secs_f64(),
            self.report.display()
        )
    }

    /// What failed, for standard error: crashed cells and plans that failed the
    /// execution check.
    pub fn failures(&self) -> Option<String> {
        failures(self.grid.crashed, self.grid.failed_executions())
    }

    /// [`ExitCode::CHECK_FAILED`] if a cell crashed or a plan failed the execution check.
    pub fn exit_code(&self) -> ExitCode {
        checked(&self.grid)
    }
}

impl StudyOutcome {
    /// The last line: runs computed now and found in earlier results, how many at a
    /// time (when any ran: not after `--collect` or with every result reused), in
    /// `elapsed`, failed execution checks, and where the results are.
    pub fn closing_line(&self, out: &Path, elapsed: Duration) -> String {
        let grid = &self.grid;
        let at_once = if grid.computed > 0 {
            format!(", {} at a time", grid.jobs)
        } else {
            String::new()
        };
        format!(
            "Study: {} runs ({} computed now, {} from earlier results{at_once}) in {:.0} s; \
             {} plan(s) failed the execution check. Wrote {}: open {}\n",
            grid.records.len(),
            grid.computed,
            grid.records.len().saturating_sub(grid.computed),
            elapsed.as_secs_f64(),
            grid.failed_executions(),
            out.display(),
            self.report.display()
        )
    }

    /// What failed, for standard error: crashed cells (the closing line counts the
    /// plans that failed the execution check).
    pub fn failures(&self) -> Option<String> {
        failures(self.grid.crashed, 0)
    }

    /// [`ExitCode::CHECK_FAILED`] if a cell crashed or a plan failed the execution check.
    pub fn exit_code(&self) -> ExitCode {
        checked(&self.grid)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A grid of `runs` records, the first `failed` of them plans that failed the
    /// execution check.
    fn grid(runs: usize, failed: usize, computed: usize, crashed: usize, jobs: usize) -> GridRun {
        let mut records = vec![crate::RunRecord::blank(&crate::grid::tests::cell(1)); runs];
        for r in &mut records[..failed] {
            r.executed = Some(false);
        }
        GridRun {
            records,
            computed,
            crashed,
            jobs,
        }
    }

    #[test]
    fn a_failed_execution_check_fails_the_grid_and_says_so() {
        let mut done = StudyOutcome {
            grid: grid(0, 0, 0, 0, 3),
            report: "out/report.html".into(),
        };
        assert_eq!(done.exit_code(), ExitCode::SUCCESS);
        done.grid = grid(2, 2, 0, 0, 3);
        assert_eq!(done.exit_code(), ExitCode::CHECK_FAILED);
        let line = done.closing_line(Path::new("out"), Duration::from_secs(7));
        assert_eq!(
            line,
            "Study: 2 runs (0 computed now, 2 from earlier results) in 7 s; 2 \
             plan(s) failed the execution check. Wrote out: open out/report.html\n"
        );
        // Only runs computed now ran at a time (not those collected or reused).
        done.grid = grid(4, 0, 1, 0, 3);
        let line = done.closing_line(Path::new("out"), Duration::from_secs(7));
        assert!(
            line.starts_with("Study: 4 runs (1 computed now, 3 from earlier results, 3 at a time)"),
            "{line}"
        );
        let reproduction = Reproduction {
            summary: String::new(),
            tables: String::new(),
            grid: grid(1, 1, 0, 0, 1),
            report: "r/report.html".into(),
        };
        assert_eq!(reproduction.exit_code(), ExitCode::CHECK_FAILED);
        assert_eq!(
            reproduction.failures().as_deref(),
            Some("error: 1 plan(s) failed the execution check (see tables.md)\n")
        );
    }

    #[test]
    fn a_crashed_cell_fails_the_grid_and_says_so() {
        let mut done = StudyOutcome {
            grid: grid(4, 0, 4, 0, 2),
            report: "out/report.html".into(),
        };
        assert_eq!(done.failures(), None);
        done.grid.crashed = 1;
        assert_eq!(done.exit_code(), ExitCode::CHECK_FAILED);
        assert_eq!(
            done.failures().as_deref(),
            Some(
                "error: 1 cell(s) crashed (their records in results.jsonl say why; run again \
                 to compute them)\n"
            )
        );
        let reproduction = Reproduction {
            summary: String::new(),
            tables: String::new(),
            grid: grid(4, 1, 4, 2, 2),
            report: "r/report.html".into(),
        };
        assert_eq!(reproduction.exit_code(), ExitCode::CHECK_FAILED);
        let text = reproduction.failures().unwrap();
        assert!(text.starts_with("error: 2 cell(s) crashed"), "{text}");
        assert!(text.ends_with("error: 1 plan(s) failed the execution check (see tables.md)\n"));
    }

    #[test]
    fn experiment_errors_exit_by_whose_fault_they_are() {
        let results = ExperimentError::Results {
            file: "r".into(),
            line: 1,
            message: String::new(),
        };
        assert_eq!(results.exit_code(), ExitCode::INPUT_ERROR);
        assert_eq!(
            ExperimentError::FastDownwardMissing.exit_code(),
            ExitCode::USAGE
        );
        let io = ExperimentError::Io {
            path: "r".into(),
            message: String::new(),
        };
        assert_eq!(io.exit_code(), ExitCode::CRITICAL_ERROR);
        let incomplete = ExperimentError::Incomplete {
            out: "r".into(),
            missing: vec!["abc".into()],
            total: 3,
        };
        assert_eq!(incomplete.exit_code(), ExitCode::CHECK_FAILED);
    }
}
