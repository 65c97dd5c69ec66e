//! `demoplan study`: the slimming effect over seeds and conditions
//! (`experiment::study`); this parses the options, shows progress and maps the outcome
//! to an exit code.

use crate::cli::StudyArgs;
use crate::commands::plan::parse_run_memory_limit;
use crate::commands::reproduce::{
    cell_command, experiment_failure, fast_downward, print_cell, time_limit,
};
use crate::diagnostic::Failure;
use crate::exit::ExitCode;
use crate::input;
use crate::progress::Bar;

fn usage(option: &str, message: String) -> Failure {
    Failure::plain(ExitCode::USAGE, format!("{option}: {message}"))
}

/// `1-20` (inclusive), `7`, or `1,4,9` (each part a number or a range).
fn numbers(option: &str, text: &str) -> Result<Vec<u64>, Failure> {
    let mut out = Vec::new();
    for part in text.split(',').map(str::trim) {
        let number = |t: &str| {
            t.trim().parse::<u64>().map_err(|_| {
                usage(
                    option,
                    format!("{t:?} is not a number (give e.g. 1-20, 3 or 1,4,9)"),
                )
            })
        };
        match part.split_once('-') {
            Some((a, b)) => {
                let (a, b) = (number(a)?, number(b)?);
                if a > b {
                    return Err(usage(option, format!("the range {a}-{b} is empty")));
                }
                if b - a > 100_000 {
                    return Err(usage(option, format!("the range {a}-{b} is too long")));
                }
                out.extend(a..=b);
            }
            None => out.push(number(part)?),
        }
    }
    out.sort_unstable();
    out.dedup();
    Ok(out)
}

fn sizes(option: &str, text: &str) -> Result<Vec<usize>, Failure> {
    numbers(option, text)?
        .into_iter()
        .map(|n| usize::try_from(n).map_err(|_| usage(option, format!("{n} is too large"))))
        .collect()
}

pub fn run(args: StudyArgs) -> Result<ExitCode, Failure> {
    let started = std::time::Instant::now();
    let params = match &args.params {
        None => simulate::SimParams::default(),
        Some(path) => {
            let text = input::read_text(path)?;
            serde_json::from_str(&text).map_err(|e| {
                usage(
                    "--params",
                    format!("{}: not a parameter file: {e}", path.display()),
                )
            })?
        }
    };
    let mut activities: Vec<String> = args
        .activities
        .split(',')
        .map(|a| a.trim().to_string())
        .collect();
    activities.dedup();
    let jobs = match args.jobs {
        Some(n) => n as usize,
        None => std::thread::available_parallelism().map_or(1, usize::from),
    };
    let memory_limit = parse_run_memory_limit(&args.memory_limit, jobs)?;
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
        time_limit: time_limit(&args.time_limit)?,
        fast_downward: fast_downward(args.with_fd, args.fd.as_deref())?,
        memory: Some(crate::memory::probe()),
        memory_limit,
        children: None,
    };
    if let Some(id) = &args.cell {
        return print_cell(experiment::study_cell(&options, id));
    }
    let options = experiment::StudyOptions {
        children: cell_command(jobs, memory_limit)?,
        ..options
    };
    let bar = Bar::new();
    let result = experiment::study(&options, &mut |p| bar.update(p));
    bar.finish();
    let done = result.map_err(experiment_failure)?;
    println!(
        "Study: {} runs ({} computed now, {} from earlier results, {jobs} at a time) in \
         {:.0} s; {} plan(s) failed the execution check. Wrote {}: open {}",
        done.records.len(),
        done.computed,
        done.records.len() - done.computed,
        started.elapsed().as_secs_f64(),
        done.failed_executions,
        options.out.display(),
        done.report.display()
    );
    if done.failed_executions > 0 {
        return Ok(ExitCode::CHECK_FAILED);
    }
    Ok(ExitCode::SUCCESS)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn seeds_read_as_ranges_and_lists() {
        assert_eq!(numbers("--seeds", "1-3").ok(), Some(vec![1, 2, 3]));
        assert_eq!(numbers("--seeds", "5, 1,2-3").ok(), Some(vec![1, 2, 3, 5]));
        for bad in ["3-1", "x", "1-", ""] {
            let e = numbers("--seeds", bad).err().map(|f| (f.code, f.text));
            assert!(
                matches!(&e, Some((code, text)) if *code == ExitCode::USAGE && text.contains("--seeds")),
                "{bad}: {e:?}"
            );
        }
    }
}
