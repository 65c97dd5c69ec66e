//! Exit codes. Planning commands use Fast Downward's table so that scripts written for
//! Fast Downward read demoplan's results; other commands use the same codes for the same
//! kinds of failure. The README lists them.

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
