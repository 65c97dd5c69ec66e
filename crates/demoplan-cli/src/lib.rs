//! The `demoplan` command line as a library: [`run`] parses an argument vector and runs
//! the command, as the executable does (`main.rs` only calls it), so that the Python
//! package runs the very same command line in its own process.
//!
//! The crate is the shell around the library crates and nothing more: it parses
//! arguments (`cli`, one clap `Args` struct per command), reads and writes files,
//! renders diagnostics and maps outcomes to exit codes. Each command module in
//! `commands` turns its `Args` into calls to the library crates.
//!
//! ```no_run
//! let code = demoplan_cli::run(["demoplan", "check", "domain.pddl", "problem.pddl"]);
//! assert_eq!(code, demoplan_cli::ExitCode::SUCCESS);
//! ```

use std::ffi::OsString;
use std::io::Write;

use clap::Parser;

mod cli;
mod commands;
mod diagnostic;
mod input;
mod output;
mod progress;
mod recording_input;

pub use slim::ExitCode;
// For the Python extension's in-process calls: failures rendered as the command line
// renders them.
pub use diagnostic::Failure;
// For the Python extension's `learn`, `simulate` and `tower_problem`, which call the
// library crates as the commands do: bad demonstration files reported as the command
// line reports them (file, line, field), and files written whole or not at all.
pub use commands::demo_input::file_failure;
pub use output::{write_atomically, write_atomically_with};
pub use recording_input::open as open_recording;

/// Counts the heap in use for `--overall-memory-limit` and the experiments' peak memory
/// ([`task::memory`]; `slim::MemoryProbe::counting` reads it). Declared by the library, so that whoever calls [`run`] (the executable,
/// the Python extension) gets the limits; a program linking this crate cannot declare
/// another global allocator.
#[global_allocator]
static ALLOCATOR: task::memory::CountingAllocator = task::memory::CountingAllocator;

/// Runs the command line `argv` (its first item is the program's name) and returns the
/// exit code the executable would exit with, after printing what it prints. A grid's
/// cells run this executable again.
pub fn run<I, T>(argv: I) -> ExitCode
where
    I: IntoIterator<Item = T>,
    T: Into<OsString> + Clone,
{
    let program = std::env::current_exe().map_or_else(|_| "demoplan".into(), OsString::from);
    run_as(vec![program], argv.into_iter().map(Into::into).collect())
}

/// [`run`], with `program` as the command that runs demoplan again (a grid runs each
/// cell as `program... argv... --cell ID`, docs/grids.md). An empty `program` is a usage
/// error (exit 36), not a panic.
pub fn run_as(program: Vec<OsString>, argv: Vec<OsString>) -> ExitCode {
    stop_cleanly_when_stdout_fails();
    let this = match experiment::grid::Relaunch::new(&program, argv.get(1..).unwrap_or(&[])) {
        Ok(this) => this,
        Err(e) => {
            eprintln!("error: {e}");
            return ExitCode::USAGE;
        }
    };
    match cli::Cli::try_parse_from(argv) {
        Ok(cli) => commands::run(cli.command, &this).unwrap_or_else(|failure| {
            let _ = std::io::stdout().flush();
            eprint!("{}", failure.text);
            failure.code
        }),
        Err(e) => {
            // Help and version are not errors. Anything else is Fast Downward's "driver
            // input error" (36): clap's own code 2 means "plan found, out of time" there.
            let _ = e.print();
            if e.use_stderr() {
                ExitCode::USAGE
            } else {
                ExitCode::SUCCESS
            }
        }
    }
}

/// Rust ignores SIGPIPE, so printing to a closed pipe or a full disk panics inside
/// `println!`. A reader that stops early (`| head`) is no error: exit quietly with the
/// code a shell shows for SIGPIPE. Any other failure to write standard output is an I/O
/// error (35) with a message, not a panic report. Installed once per process.
fn stop_cleanly_when_stdout_fails() {
    static INSTALLED: std::sync::Once = std::sync::Once::new();
    INSTALLED.call_once(|| {
        let default_hook = std::panic::take_hook();
        std::panic::set_hook(Box::new(move |info| {
            let text = info.to_string();
            if let Some(at) = text.find("failed printing to stdout: ") {
                if text.contains("Broken pipe") {
                    std::process::exit(ExitCode::OUTPUT_CLOSED.0);
                }
                let cause = &text[at + "failed printing to stdout: ".len()..];
                eprintln!("error: cannot write to standard output: {}", cause.trim());
                std::process::exit(ExitCode::CRITICAL_ERROR.0);
            }
            default_hook(info);
        }));
    });
}
