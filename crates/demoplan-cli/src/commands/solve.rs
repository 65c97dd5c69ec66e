//! `demoplan solve LIBRARY PROBLEM`: the paper's Algorithm 1 on the command line.

use std::path::Path;
use std::time::Duration;

use learn::DomainOptions;
use slim::{Backend, FastDownward, Outcome, PlannerName};

use crate::cli::SolveArgs;
use crate::commands::library::read_library;
use crate::diagnostic::Failure;
use crate::exit::ExitCode;
use crate::input;
use crate::output::write_atomically;

fn read_problem(path: &Path) -> Result<pddl::Problem, Failure> {
    let text = input::read_text(path)?;
    pddl::parse_problem(&text).map_err(|e| Failure::pddl(path, &text, &e))
}

fn seconds(d: Duration) -> String {
    format!("{:.3}", d.as_secs_f64())
}

pub fn run(args: SolveArgs) -> Result<ExitCode, Failure> {
    let time_limit = match &args.time_limit {
        Some(text) => crate::commands::plan::parse_time_limit(text)
            .map_err(|e| Failure::plain(ExitCode::USAGE, format!("--time-limit: {e}")))?,
        None => None,
    };
    let memory_limit = crate::commands::plan::parse_run_memory_limit(&args.memory_limit, 1)?;
    let limits = slim::RunLimits {
        time: time_limit,
        memory_bytes: memory_limit,
        memory: Some(crate::memory::probe()),
    };
    let library = read_library(&args.library)?;
    let problem = read_problem(&args.problem)?;
    let backend = match PlannerName::from_name(&args.planner) {
        Some(PlannerName::Demoplan) => {
            Backend::Demoplan(search::parse_search(&args.search).map_err(|e| {
                Failure::plain(
                    ExitCode::SEARCH_INPUT_ERROR,
                    format!("--search {}: {e}", args.search),
                )
            })?)
        }
        Some(PlannerName::FastDownward) => Backend::FastDownward(
            FastDownward::locate(args.fd.as_deref())
                .map_err(|e| Failure::plain(ExitCode::USAGE, e))?,
            args.search.clone(),
        ),
        None => {
            let names: Vec<&str> = PlannerName::ALL.iter().map(|p| p.name()).collect();
            return Err(Failure::plain(
                ExitCode::USAGE,
                format!(
                    "--planner {}: expected {}",
                    args.planner,
                    names.join(" or ")
                ),
            ));
        }
    };
    let options = DomainOptions {
        keep_without_effects: args.keep_without_effects,
    };
    println!(
        "{:>5} {:>9}  {:<19} {:>9} {:>11} {:>6}",
        "prio", "operators", "outcome", "time (s)", "expansions", "cost"
    );
    let solved = slim::solve(&library, options, &problem, &backend, limits, |level| {
        let run = &level.run;
        println!(
            "{:>5} {:>9}  {:<19} {:>9} {:>11} {:>6}",
            level.prio,
            level.operators,
            run.outcome.word(),
            seconds(run.total_time),
            run.expansions.map_or("-".to_string(), |e| e.to_string()),
            run.cost.map_or("-".to_string(), |c| c.to_string())
        );
        if let Some(e) = &run.error {
            eprintln!("error at priority {}: {e}", level.prio);
        }
    });
    println!(
        "Cumulative time over {} level(s), failed ones included: {} s",
        solved.levels.len(),
        seconds(solved.cumulative)
    );
    let Some(level) = solved.plan_level() else {
        if solved.any_limit() {
            let reached = |o: Outcome| solved.levels.iter().any(|l| l.run.outcome == o);
            let which = match (reached(Outcome::TimeLimit), reached(Outcome::MemoryLimit)) {
                (true, true) => "its time or memory limit",
                (false, true) => "its memory limit",
                _ => "its time limit",
            };
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
        let all = learn::levels(&library, options);
        if let Some(full) = all.last() {
            let domain = learn::domain("demoplan", &full.operators);
            let run = backend.plan(&domain, &problem, &limits);
            match (&run.outcome, run.cost) {
                (Outcome::Solved, Some(optimum)) => println!(
                    "Full domain ({} operators): optimal cost {optimum} in {} s; the slim plan \
                     costs {} (price of slimming: {})",
                    full.operators.len(),
                    seconds(run.total_time),
                    level.run.cost.unwrap_or(0),
                    level.run.cost.unwrap_or(0).saturating_sub(optimum)
                ),
                (outcome, _) => println!(
                    "Full domain ({} operators): {} after {} s; no optimum to compare with",
                    full.operators.len(),
                    outcome.word(),
                    seconds(run.total_time)
                ),
            }
        }
    }
    Ok(ExitCode::SUCCESS)
}
