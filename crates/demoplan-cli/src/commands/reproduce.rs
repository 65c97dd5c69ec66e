//! `demoplan reproduce [-o DIR]`: the paper's experiment in one command
//! (`experiment::reproduce`); this parses the options, shows progress and maps the
//! outcome to an exit code.

use slim::FastDownward;

use std::path::Path;

use crate::cli::{FastDownwardArgs, GridArgs, ReproduceArgs, SlurmArgs};
use crate::commands::plan::parse_run_memory_limit;
use crate::diagnostic::Failure;
use crate::progress::Bar;
use crate::Invocation;
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

/// The grid's cells at once: `-j N`, else the number of cores.
pub fn jobs(grid: &GridArgs) -> usize {
    grid.jobs.map_or_else(
        || std::thread::available_parallelism().map_or(1, usize::from),
        |n| n as usize,
    )
}

/// How the grid's cells run, each in a child process: `this` (the command that runs
/// demoplan again) with the grid's command line `argv`, `--cell ID` and the memory limit
/// this process resolved (the last `--memory-limit` wins: `auto` again in a child would
/// count its siblings).
pub fn cell_command(
    jobs: usize,
    memory_limit: Option<u64>,
    this: &Invocation,
) -> experiment::CellCommand {
    let bytes = memory_limit.map_or("infinity".to_string(), |b| b.to_string());
    experiment::CellCommand {
        program: this.program[0].clone().into(),
        args: (this.program[1..].iter().chain(&this.argv).cloned())
            .chain(["--memory-limit".into(), bytes.into()])
            .collect(),
        jobs,
    }
}

/// The memory limit per cell: `--memory-limit`, where `auto` on a grid written for
/// Slurm is [`experiment::grid::slurm::AUTO_MEMORY_LIMIT`].
pub fn grid_memory_limit(
    text: &str,
    jobs: usize,
    slurm: &SlurmArgs,
) -> Result<Option<u64>, Failure> {
    match slurm.slurm {
        Some(_) if !slurm.collect && text.trim().eq_ignore_ascii_case("auto") => {
            Ok(Some(experiment::grid::slurm::AUTO_MEMORY_LIMIT))
        }
        _ => parse_run_memory_limit(text, jobs),
    }
}

/// `--slurm DIR`: writes the grid `cells` as Slurm jobs into DIR and runs nothing.
pub fn write_slurm(
    args: &SlurmArgs,
    dir: &Path,
    name: &str,
    cells: Result<Vec<experiment::Cell>, experiment::ExperimentError>,
    memory_limit: Option<u64>,
    this: &Invocation,
) -> Result<ExitCode, Failure> {
    use experiment::grid::slurm::{write_job, GridCommand, SlurmOptions};
    let here = |e: std::io::Error| Failure::plain(ExitCode::USAGE, format!("--slurm: {e}"));
    let command = GridCommand {
        program: this.program[0].clone().into(),
        args: (this.program[1..].iter().chain(&this.argv).cloned()).collect(),
        workdir: std::env::current_dir().map_err(here)?,
        name: name.into(),
        memory_limit,
    };
    let options = SlurmOptions {
        partition: args.slurm_partition.clone(),
        cpus_per_task: args.slurm_cpus_per_task,
        mem: args.slurm_mem,
        time: args.slurm_time,
        cells_per_task: args.slurm_cells_per_task.map(|n| n as usize),
        max_running: args.slurm_max_running as usize,
        seed: args.slurm_seed,
        sbatch: args.slurm_sbatch.clone(),
        ..SlurmOptions::new(dir)
    };
    let job = cells.and_then(|cells| write_job(&cells, &command, &options));
    print!("{}", job.map_err(experiment_failure)?.summary());
    Ok(ExitCode::SUCCESS)
}

/// What a grid command does before its grid: `--list-cells` prints the cells, `--cell
/// ID` computes one (printing its record as one JSON line); `None` runs the grid.
pub fn cell_or_list(
    grid: &GridArgs,
    cells: impl FnOnce() -> Result<Vec<experiment::Cell>, experiment::ExperimentError>,
    cell: impl FnOnce(&str) -> Result<experiment::RunRecord, experiment::ExperimentError>,
) -> Option<Result<ExitCode, Failure>> {
    let print = |text: Result<String, experiment::ExperimentError>| {
        print!("{}", text.map_err(experiment_failure)?);
        Ok(ExitCode::SUCCESS)
    };
    if grid.list_cells {
        return Some(print(cells().map(|c| experiment::cell_list(&c))));
    }
    let id = grid.cell.as_deref()?;
    Some(print(cell(id).map(|r| r.to_json_line() + "\n")))
}

pub fn run(args: ReproduceArgs, this: &Invocation) -> Result<ExitCode, Failure> {
    let started = std::time::Instant::now();
    let jobs = jobs(&args.grid);
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
        children: Some(cell_command(jobs, memory_limit, this)),
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
