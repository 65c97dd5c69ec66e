//! `demoplan study`: the slimming effect over seeds and conditions
//! (`experiment::study`); this parses the options, shows progress and maps the outcome
//! to an exit code.

use crate::cli::StudyArgs;
use crate::commands::reproduce::{
    cell_or_list, experiment_failure, fast_downward, grid_memory_limit, time_limit, write_slurm,
};
use crate::diagnostic::Failure;
use crate::input;
use crate::progress::Bar;
use experiment::grid::Relaunch;
use slim::ExitCode;

fn usage(option: &str, message: String) -> Failure {
    Failure::plain(ExitCode::USAGE, format!("{option}: {message}"))
}

/// A list option of numbers (`--seeds 1-20`, `--heights 2,4`), read by
/// [`experiment::numbers`].
fn numbers(option: &str, text: &str) -> Result<Vec<u64>, Failure> {
    experiment::numbers(text).map_err(|e| usage(option, e))
}

fn sizes(option: &str, text: &str) -> Result<Vec<usize>, Failure> {
    experiment::sizes(text).map_err(|e| usage(option, e))
}

pub fn run(args: StudyArgs, this: &Relaunch) -> Result<ExitCode, Failure> {
    let started = std::time::Instant::now();
    let params = input::sim_params(args.params.as_deref())?;
    let mut activities: Vec<String> = args
        .activities
        .split(',')
        .map(|a| a.trim().to_string())
        .collect();
    activities.dedup();
    let jobs = experiment::grid::jobs(args.grid.jobs);
    let memory_limit = grid_memory_limit(&args.limits.memory_limit, jobs, &args.slurm)?;
    let options = experiment::StudyOptions {
        out: args.out,
        seeds: numbers("--seeds", &args.seeds)?,
        participants: args.participants,
        per_participant: args.per_participant,
        hands: sizes("--hands", &args.hands)?,
        distractors: sizes("--distractors", &args.distractors)?,
        heights: sizes("--heights", &args.heights)?,
        towers: sizes("--towers", &args.towers)?,
        activities,
        keep_without_effects: args.keep_without_effects,
        params,
        time_limit: time_limit(args.limits.time_limit.as_deref())?,
        fast_downward: fast_downward(&args.fast_downward)?,
        memory: Some(slim::MemoryProbe::counting()),
        memory_limit,
        children: Some(this.cells(jobs, memory_limit)),
        force: args.grid.force,
        collect_only: args.slurm.collect,
    };
    let cells = || experiment::study_cells(&options);
    if let Some(done) = cell_or_list(&args.grid, cells, |id| experiment::study_cell(&options, id)) {
        return done;
    }
    if let (Some(dir), false) = (&args.slurm.slurm, args.slurm.collect) {
        let cells = experiment::study_cells(&options);
        return write_slurm(&args.slurm, dir, "study", cells, memory_limit, this);
    }
    let bar = Bar::new();
    let result = experiment::study(&options, &mut |p| bar.update(p));
    bar.finish();
    let done = result.map_err(experiment_failure)?;
    print!("{}", done.closing_line(&options.out, started.elapsed()));
    if let Some(failures) = done.failures() {
        eprint!("{failures}");
    }
    Ok(done.exit_code())
}
