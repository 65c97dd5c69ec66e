//! `demoplan study`: the slimming effect over seeds and conditions
//! (`experiment::study`); this parses the options, shows progress and maps the outcome
//! to an exit code.

use crate::cli::StudyArgs;
use crate::commands::reproduce::{closing, experiment_failure, instead_of_grid, with_bar};
use crate::diagnostic::Failure;
use crate::input;
use experiment::grid::Relaunch;
use slim::ExitCode;

pub fn run(args: StudyArgs, this: &Relaunch) -> Result<ExitCode, Failure> {
    let started = std::time::Instant::now();
    let params = input::sim_params(args.params.as_deref(), args.conditions.style)?;
    let (limits, fast_downward) = (&args.limits, &args.fast_downward);
    let grid = (args.grid.settings(&args.slurm, fast_downward, limits, this))
        .map_err(experiment_failure)?;
    let options = (args.conditions.options(args.out, params, grid)).map_err(experiment_failure)?;
    if let Some(done) = instead_of_grid(&args.grid, &args.slurm, &options, this) {
        return done;
    }
    let done = with_bar(|progress| experiment::study(&options, progress))?;
    let line = done.closing_line(&options.out, started.elapsed());
    closing(line, done.failures(), done.exit_code())
}
