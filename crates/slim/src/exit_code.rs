//! Exit codes. A planning run ends with Fast Downward's code for its outcome, so that
//! scripts written for Fast Downward read demoplan's results; the command line uses the
//! same codes for the same kinds of failure in its other commands. The README lists them.
//! Here, in the crate of the planning runs, so that every caller of a run (the command
//! line, the Python package) maps its outcome and errors one way.

/// A process exit code.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct ExitCode(pub i32);

impl ExitCode {
    /// Success (for `plan`: a plan was found).
    pub const SUCCESS: ExitCode = ExitCode(0);
    /// A check that found a difference: `fmt --check` on a file that is not canonical.
    pub const CHECK_FAILED: ExitCode = ExitCode(1);
    /// Fast Downward's SEARCH_UNSOLVABLE: the task has no plan.
    pub const UNSOLVABLE: ExitCode = ExitCode(11);
    /// Fast Downward's SEARCH_OUT_OF_MEMORY: the memory limit was reached.
    pub const OUT_OF_MEMORY: ExitCode = ExitCode(22);
    /// Fast Downward's SEARCH_OUT_OF_TIME: the time limit was reached.
    pub const OUT_OF_TIME: ExitCode = ExitCode(23);
    /// Fast Downward's TRANSLATE_INPUT_ERROR: the PDDL is malformed or inconsistent.
    pub const INPUT_ERROR: ExitCode = ExitCode(31);
    /// Fast Downward's SEARCH_CRITICAL_ERROR: a plan failed validation (a bug).
    pub const CRITICAL_SEARCH_ERROR: ExitCode = ExitCode(32);
    /// Fast Downward's SEARCH_INPUT_ERROR: a bad search string or output.sas file.
    pub const SEARCH_INPUT_ERROR: ExitCode = ExitCode(33);
    /// Fast Downward's SEARCH_UNSUPPORTED: valid PDDL outside the supported fragment.
    pub const UNSUPPORTED: ExitCode = ExitCode(34);
    /// Fast Downward's DRIVER_CRITICAL_ERROR: an I/O failure writing output.
    pub const CRITICAL_ERROR: ExitCode = ExitCode(35);
    /// Fast Downward's DRIVER_INPUT_ERROR: a bad command line, a missing input file, no
    /// domain file found by the naming rules.
    pub const USAGE: ExitCode = ExitCode(36);
    /// Not Fast Downward's (it has no such case): another process held the lock of the
    /// file to write for longer than the wait allowed. A temporary failure, worth trying
    /// again: the code is `EX_TEMPFAIL` of BSD's sysexits.h.
    pub const LOCKED: ExitCode = ExitCode(75);
    /// Not Fast Downward's: the reader of standard output closed it early (`demoplan
    /// operators LIB | head`). 141 is what a shell reports for a program killed by
    /// SIGPIPE (128 + 13), as C programs like Fast Downward are; demoplan stops quietly
    /// with the same code.
    pub const OUTPUT_CLOSED: ExitCode = ExitCode(141);
}

impl From<ExitCode> for std::process::ExitCode {
    /// Exit codes are 0 to 255 (the validator's count of invalid plans is capped there).
    fn from(code: ExitCode) -> std::process::ExitCode {
        std::process::ExitCode::from(u8::try_from(code.0).unwrap_or(u8::MAX))
    }
}

impl crate::Outcome {
    /// The exit code of a run that ended so: Fast Downward's for a plan, no plan and the
    /// two limits. A cancelled run has no code of Fast Downward's: nothing cancels the
    /// command line (Ctrl-C kills it), so it is a critical search error there.
    pub fn exit_code(self) -> ExitCode {
        match self {
            crate::Outcome::Solved => ExitCode::SUCCESS,
            crate::Outcome::TimeLimit => ExitCode::OUT_OF_TIME,
            crate::Outcome::MemoryLimit => ExitCode::OUT_OF_MEMORY,
            crate::Outcome::Unsolvable | crate::Outcome::RelaxedUnreachable => ExitCode::UNSOLVABLE,
            crate::Outcome::Cancelled | crate::Outcome::Error => ExitCode::CRITICAL_SEARCH_ERROR,
        }
    }
}

impl crate::RunError {
    /// The exit code of a run that could not be made: a task that does not translate is
    /// an input error (31), a plan cost beyond the search's range is unsupported (34),
    /// and a heuristic that cannot be built for the task a search input error (33).
    pub fn exit_code(&self) -> ExitCode {
        match self {
            crate::RunError::Translate(_) => ExitCode::INPUT_ERROR,
            crate::RunError::Search(search::SearchError::CostTooLarge { .. }) => {
                ExitCode::UNSUPPORTED
            }
            crate::RunError::Search(_) => ExitCode::SEARCH_INPUT_ERROR,
        }
    }

    /// The message, naming the problem file where the task is at fault.
    pub fn message(&self, problem: &std::path::Path) -> String {
        match self {
            crate::RunError::Translate(e) => format!("{}: {e}", problem.display()),
            crate::RunError::Search(e) => e.to_string(),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::ExitCode;
    use crate::Outcome;

    #[test]
    fn outcomes_exit_with_fast_downwards_codes() {
        let codes: Vec<(Outcome, i32)> =
            Outcome::ALL.iter().map(|o| (*o, o.exit_code().0)).collect();
        assert_eq!(
            codes,
            [
                (Outcome::Solved, 0),
                (Outcome::RelaxedUnreachable, 11),
                (Outcome::Unsolvable, 11),
                (Outcome::TimeLimit, 23),
                (Outcome::MemoryLimit, 22),
                (Outcome::Cancelled, 32),
                (Outcome::Error, 32),
            ]
        );
        assert_eq!(
            std::process::ExitCode::from(ExitCode(300)),
            std::process::ExitCode::from(255)
        );
    }
}
