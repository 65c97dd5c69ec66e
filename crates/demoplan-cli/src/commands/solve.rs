//! `demoplan solve LIBRARY PROBLEM`: the paper's Algorithm 1 on the command line.

use std::path::Path;

use learn::DomainOptions;
use slim::Backend;

use crate::cli::SolveArgs;
use crate::commands::library::read_library;
use crate::commands::reproduce::experiment_failure;
use crate::diagnostic::Failure;
use crate::input;
use crate::output::write_atomically;
use slim::ExitCode;

fn read_problem(path: &Path) -> Result<pddl::Problem, Failure> {
    let text = input::read_text(path)?;
    pddl::parse_problem(&text).map_err(|e| Failure::pddl(path, &text, &e))
}

pub fn run(args: SolveArgs) -> Result<ExitCode, Failure> {
    let limits = slim::RunLimits {
        time: args.limits.time().map_err(experiment_failure)?,
        memory_bytes: args.limits.memory(1, false).map_err(experiment_failure)?,
        memory: Some(slim::MemoryProbe::counting()),
    };
    let library = read_library(&args.library)?;
    let problem = read_problem(&args.problem)?;
    let (alias, fd) = (args.alias.as_deref(), args.fd.as_deref());
    let search = Some(args.search.as_str()).filter(|_| alias.is_none());
    let backend = Backend::new(args.planner, search, alias, fd)
        .map_err(|e| Failure::plain(e.exit_code(), e))?;
    let options = DomainOptions {
        keep_without_effects: args.keep_without_effects,
    };
    print!("{}", slim::level_header());
    let solved = slim::solve(&library, options, &problem, &backend, limits, |level| {
        print!("{}", slim::level_row(level));
        if let Some(e) = &level.run.error {
            eprintln!("error at priority {}: {e}", level.prio);
        }
    });
    print!("{}", solved.cumulative_line());
    let Some(level) = solved.plan_level() else {
        if let Some(which) = solved.limits_reached() {
            println!("No plan: some level reached {which} (exit 12).");
            return Ok(ExitCode(12));
        }
        println!("No plan on any level: every level is unsolvable.");
        return Ok(ExitCode::UNSOLVABLE);
    };
    write_atomically(&args.plan_file, &level.run.plan_text().unwrap_or_default())?;
    println!(
        "Solution found at priority {} ({} operators): {} step(s), cost {}; plan written to {}",
        level.prio,
        level.operators,
        level.run.plan.len(),
        level.run.cost.unwrap_or(0),
        args.plan_file.display()
    );
    if args.compare_full {
        let slim_cost = level.run.cost.unwrap_or(0);
        let full = slim::compare_full(&library, options, &problem, &backend, &limits, slim_cost);
        print!("{}", full.unwrap_or_default());
    }
    Ok(ExitCode::SUCCESS)
}
