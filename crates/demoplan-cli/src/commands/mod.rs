//! One module per subcommand, each a `run` taking its `Args` struct from `cli`.

pub mod check;
pub mod classify;
pub mod demo_input;
pub mod execute;
pub mod fmt;
pub mod import;
pub mod inspect;
pub mod library;
pub mod plan;
pub mod reproduce;
pub mod segment;
pub mod simulate;
pub mod solve;
pub mod study;
pub mod timeline;
pub mod translate;
pub mod validate;

use crate::cli::Command;
use crate::diagnostic::Failure;
use experiment::grid::Relaunch;
use slim::ExitCode;

/// Runs a parsed command.
pub fn run(command: Command, this: &Relaunch) -> Result<ExitCode, Failure> {
    match command {
        Command::Check(args) => check::run(args),
        Command::Fmt(args) => fmt::run(args),
        Command::Plan(args) => plan::run(args),
        Command::Translate(args) => translate::run(args),
        Command::Validate(args) => validate::run(args),
        Command::Simulate(args) => simulate::run(args),
        Command::Inspect(args) => inspect::run(args),
        Command::Import(args) => import::run(args),
        Command::Segment(args) => segment::run(args),
        Command::Classify(args) => classify::run(args),
        Command::Timeline(args) => timeline::run(args),
        Command::Learn(args) => library::learn(args),
        Command::Operators(args) => library::operators(args),
        Command::Domain(args) => library::domain(args),
        Command::Problem(args) => library::problem(args),
        Command::Solve(args) => solve::run(args),
        Command::Reproduce(args) => reproduce::run(args, this),
        Command::Study(args) => study::run(args, this),
        Command::Execute(args) => execute::run(args),
    }
}
