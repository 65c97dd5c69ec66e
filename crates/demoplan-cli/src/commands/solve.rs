//! `demoplan solve LIBRARY PROBLEM`: Algorithm 1 with execution in the loop (`closed_loop`).

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
    let solved = closed_loop::solve(
        &library,
        options,
        &problem,
        &backend,
        limits,
        args.execution.execution(),
        |a| {
            print!("{}", closed_loop::attempt_lines(a));
            eprint!("{}", a.error_line());
        },
    )
    .map_err(|e| Failure::plain(e.exit_code(), format!("{}: {e}", args.problem.display())))?;
    print!("{}", solved.cumulative_line());
    let closed_loop::Verdict::Plan(attempt) = solved.verdict() else {
        print!("{}", solved.no_plan_text());
        return Ok(solved.exit_code());
    };
    write_atomically(
        &args.plan_file,
        &attempt.level.run.plan_text().unwrap_or_default(),
    )?;
    println!("{}", attempt.solution_line(&args.plan_file));
    if args.compare_full {
        let cost = attempt.level.run.cost.unwrap_or(0);
        let full = slim::compare_full(&library, options, &problem, &backend, &limits, cost);
        print!("{}", full.unwrap_or_default());
    }
    Ok(ExitCode::SUCCESS)
}
