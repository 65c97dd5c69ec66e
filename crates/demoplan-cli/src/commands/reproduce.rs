//! `demoplan reproduce [-o DIR]`: the paper's experiment in one command
//! (`experiment::reproduce`); this parses the options, shows progress and maps the
//! outcome to an exit code.

use slim::FastDownward;

use std::path::Path;

use crate::cli::{FastDownwardArgs, ReproduceArgs, SlurmArgs};
use crate::commands::plan::parse_run_memory_limit;
use crate::diagnostic::Failure;
use crate::progress::Bar;
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

/// With `jobs` above 1, how the grid's cells run in child processes: this program
/// again, with this command line, `--cell ID` and the memory limit this process resolved
/// (the last `--memory-limit` wins: `auto` again in a child would count its siblings).
pub fn cell_command(
    jobs: usize,
    memory_limit: Option<u64>,
) -> Result<Option<experiment::CellCommand>, Failure> {
    if jobs <= 1 {
        return Ok(None);
    }
    let bytes = memory_limit.map_or("infinity".to_string(), |b| b.to_string());
    let program = std::env::current_exe().map_err(|e| {
        Failure::plain(
            ExitCode::USAGE,
            format!("-j {jobs}: cannot find this program to run its cells: {e}"),
        )
    })?;
    Ok(Some(experiment::CellCommand {
        program,
        args: std::env::args_os()
            .skip(1)
            .chain(["--memory-limit".into(), bytes.into()])
            .collect(),
        jobs,
    }))
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
) -> Result<ExitCode, Failure> {
    use experiment::grid::slurm::{write_job, GridCommand, SlurmOptions};
    let here = |e: std::io::Error| Failure::plain(ExitCode::USAGE, format!("--slurm: {e}"));
    let command = GridCommand {
        program: std::env::current_exe().map_err(here)?,
        args: std::env::args_os().skip(1).collect(),
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

/// A child process's cell record on standard output, as [`experiment::CellCommand`]
/// reads it.
pub fn print_cell(
    record: Result<experiment::RunRecord, experiment::ExperimentError>,
) -> Result<ExitCode, Failure> {
    println!("{}", record.map_err(experiment_failure)?.to_json_line());
    Ok(ExitCode::SUCCESS)
}

pub fn run(args: ReproduceArgs) -> Result<ExitCode, Failure> {
    let started = std::time::Instant::now();
    let memory_limit =
        grid_memory_limit(&args.limits.memory_limit, args.jobs as usize, &args.slurm)?;
    let options = experiment::ReproduceOptions {
        out: args.out,
        time_limit: time_limit(args.limits.time_limit.as_deref())?,
        repeat: args.repeat,
        goals: args.goals,
        prios: args.prios,
        fast_downward: fast_downward(&args.fast_downward)?,
        seed: args.seed,
        hands: args.hands as usize,
        memory: Some(crate::memory::probe()),
        memory_limit,
        children: cell_command(args.jobs as usize, memory_limit)?,
        force: false,
        collect_only: args.slurm.collect,
    };
    if let Some(id) = &args.cell {
        return print_cell(experiment::reproduce_cell(&options, id));
    }
    if let (Some(dir), false) = (&args.slurm.slurm, args.slurm.collect) {
        let cells = experiment::reproduce_cells(&options);
        return write_slurm(&args.slurm, dir, "reproduce", cells, memory_limit);
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
