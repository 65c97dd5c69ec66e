//! `demoplan reproduce [-o DIR]`: the paper's experiment in one command
//! (`experiment::reproduce`); this parses the options, shows progress and maps the
//! outcome to an exit code.

use crate::cli::ReproduceArgs;
use crate::diagnostic::Failure;
use crate::progress::Bar;
use experiment::grid::{GridArgs, GridExperiment, Relaunch, SlurmArgs};
use experiment::ExperimentError;
use slim::ExitCode;

/// An experiment's error as a failure with its exit code
/// ([`ExperimentError::exit_code`]).
pub fn experiment_failure(e: ExperimentError) -> Failure {
    Failure::plain(e.exit_code(), e)
}

/// `--list-cells`, `--cell ID` or `--slurm DIR` ([`GridArgs::instead_of_grid`]), done and
/// printed; `None` runs the grid.
pub fn instead_of_grid(
    grid: &GridArgs,
    slurm: &SlurmArgs,
    experiment: &impl GridExperiment,
    this: &Relaunch,
) -> Option<Result<ExitCode, Failure>> {
    let done = grid.instead_of_grid(slurm, experiment, this)?;
    Some(done.map_err(experiment_failure).map(|text| {
        print!("{text}");
        ExitCode::SUCCESS
    }))
}

/// Runs a grid (`experiment::reproduce` or `study`) with the progress bar up.
pub fn with_bar<T>(
    grid: impl FnOnce(&mut dyn FnMut(experiment::Progress<'_>)) -> Result<T, ExperimentError>,
) -> Result<T, Failure> {
    let bar = Bar::new();
    let result = grid(&mut |p| bar.update(p));
    bar.finish();
    result.map_err(experiment_failure)
}

/// What every grid command prints when its grid is done: the closing line, and what
/// failed on standard error.
pub fn closing(
    line: String,
    failures: Option<String>,
    code: ExitCode,
) -> Result<ExitCode, Failure> {
    print!("{line}");
    if let Some(failures) = failures {
        eprint!("{failures}");
    }
    Ok(code)
}

pub fn run(args: ReproduceArgs, this: &Relaunch) -> Result<ExitCode, Failure> {
    let started = std::time::Instant::now();
    let (limits, fast_downward) = (&args.limits, &args.fast_downward);
    let grid = (args.grid.settings(&args.slurm, fast_downward, limits, this))
        .map_err(experiment_failure)?;
    let options = experiment::ReproduceOptions {
        out: args.out,
        repeat: args.repeat,
        goals: args.goals,
        prios: args.prios,
        seed: args.seed,
        hands: args.hands as usize,
        grid,
    };
    if let Some(done) = instead_of_grid(&args.grid, &args.slurm, &options, this) {
        return done;
    }
    let done = with_bar(|progress| experiment::reproduce(&options, progress))?;
    print!("{}{}", done.summary, done.tables);
    let line = done.closing_line(&options.out, started.elapsed());
    closing(line, done.failures(), done.exit_code())
}
