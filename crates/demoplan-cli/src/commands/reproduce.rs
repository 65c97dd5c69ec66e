//! `demoplan reproduce [-o DIR]`: the paper's experiment in one command
//! (`experiment::reproduce`); this parses the options, shows progress and maps the
//! outcome to an exit code.

use slim::FastDownward;

use std::path::Path;

use crate::cli::{FastDownwardArgs, GridArgs, ReproduceArgs, SlurmArgs};
use crate::commands::plan::parse_run_memory_limit;
use crate::diagnostic::Failure;
use crate::progress::Bar;
use experiment::grid::Relaunch;
use slim::ExitCode;

/// An experiment's error as a failure with its exit code
/// ([`experiment::ExperimentError::exit_code`]).
pub fn experiment_failure(e: experiment::ExperimentError) -> Failure {
    Failure::plain(e.exit_code(), e)
}

/// A `--time-limit`: Fast Downward's units; `infinity` (or none) is no limit worth the
/// name.
pub fn time_limit(text: Option<&str>) -> Result<std::time::Duration, Failure> {
    task::units::parse_time_limit(text.unwrap_or("infinity"))
        .map(|t| t.unwrap_or(std::time::Duration::from_secs(u64::from(u32::MAX))))
        .map_err(|e| Failure::plain(ExitCode::USAGE, format!("--time-limit: {e}")))
}

/// Fast Downward when `--with-fd` asks for it.
pub fn fast_downward(args: &FastDownwardArgs) -> Result<Option<FastDownward>, Failure> {
    if !args.with_fd {
        return Ok(None);
    }
    FastDownward::locate(args.fd.as_deref())
        .map(Some)
        .map_err(|e| Failure::plain(ExitCode::USAGE, e))
}

/// The memory limit per cell: `--memory-limit` ([`parse_run_memory_limit`]).
pub fn grid_memory_limit(
    text: &str,
    jobs: usize,
    slurm: &SlurmArgs,
) -> Result<Option<u64>, Failure> {
    parse_run_memory_limit(text, jobs, slurm.slurm.is_some() && !slurm.collect)
}

/// `--slurm DIR`: writes the grid `cells` as Slurm jobs into DIR and runs nothing.
pub fn write_slurm(
    args: &SlurmArgs,
    dir: &Path,
    name: &str,
    cells: Result<Vec<experiment::Cell>, experiment::ExperimentError>,
    memory_limit: Option<u64>,
    this: &Relaunch,
) -> Result<ExitCode, Failure> {
    let options = experiment::grid::slurm::SlurmOptions {
        partition: args.slurm_partition.clone(),
        cpus_per_task: args.slurm_cpus_per_task,
        mem: args.slurm_mem,
        time: args.slurm_time,
        cells_per_task: args.slurm_cells_per_task.map(|n| n as usize),
        max_running: args.slurm_max_running as usize,
        seed: args.slurm_seed,
        sbatch: args.slurm_sbatch.clone(),
        ..experiment::grid::slurm::SlurmOptions::new(dir)
    };
    let job = cells.and_then(|cells| this.write_slurm(name, &cells, memory_limit, &options));
    print!("{}", job.map_err(experiment_failure)?.summary());
    Ok(ExitCode::SUCCESS)
}

/// `--list-cells` or `--cell ID` (`experiment::grid::cell_or_list`), printed; `None`
/// runs the grid.
pub fn cell_or_list(
    grid: &GridArgs,
    cells: impl FnOnce() -> Result<Vec<experiment::Cell>, experiment::ExperimentError>,
    cell: impl FnOnce(&str) -> Result<experiment::RunRecord, experiment::ExperimentError>,
) -> Option<Result<ExitCode, Failure>> {
    let text = experiment::grid::cell_or_list(grid.list_cells, grid.cell.as_deref(), cells, cell)?;
    Some(text.map_err(experiment_failure).map(|text| {
        print!("{text}");
        ExitCode::SUCCESS
    }))
}

pub fn run(args: ReproduceArgs, this: &Relaunch) -> Result<ExitCode, Failure> {
    let started = std::time::Instant::now();
    let jobs = experiment::grid::jobs(args.grid.jobs);
    let memory_limit = grid_memory_limit(&args.limits.memory_limit, jobs, &args.slurm)?;
    let options = experiment::ReproduceOptions {
        out: args.out,
        time_limit: time_limit(args.limits.time_limit.as_deref())?,
        repeat: args.repeat,
        goals: args.goals,
        prios: args.prios,
        fast_downward: fast_downward(&args.fast_downward)?,
        seed: args.seed,
        hands: args.hands as usize,
        memory: Some(slim::MemoryProbe::counting()),
        memory_limit,
        children: Some(this.cells(jobs, memory_limit)),
        force: args.grid.force,
        collect_only: args.slurm.collect,
    };
    let cells = || experiment::reproduce_cells(&options);
    if let Some(done) = cell_or_list(&args.grid, cells, |id| {
        experiment::reproduce_cell(&options, id)
    }) {
        return done;
    }
    if let (Some(dir), false) = (&args.slurm.slurm, args.slurm.collect) {
        let cells = experiment::reproduce_cells(&options);
        return write_slurm(&args.slurm, dir, "reproduce", cells, memory_limit, this);
    }
    let bar = Bar::new();
    let result = experiment::reproduce(&options, &mut |p| bar.update(p));
    bar.finish();
    let done = result.map_err(experiment_failure)?;
    print!("{}", done.summary);
    print!("{}", done.tables);
    print!("{}", done.closing_line(&options.out, started.elapsed()));
    if let Some(failures) = done.failures() {
        eprint!("{failures}");
    }
    Ok(done.exit_code())
}
