//! `demoplan plan`: translate (or read output.sas), search, write the plan; Fast
//! Downward's log lines, plan file and exit codes.

use std::path::Path;
use std::time::Instant;

use crate::cli::PlanArgs;
use crate::commands::translate::{domain_and_problem, read_parsed};
use crate::diagnostic::Failure;
use crate::{input, output};
use slim::ExitCode;
use task::memory;
use task::units::{parse_memory_limit, parse_time_limit};

fn is_sas_file(path: &Path) -> bool {
    path.extension().is_some_and(|e| e == "sas")
}

/// A limit option: absent and `infinity` both mean none; a bad one is a usage error.
fn limit<T>(
    given: Option<&str>,
    parse: fn(&str) -> Result<Option<T>, String>,
) -> Result<Option<T>, Failure> {
    let parsed = given.map(parse).transpose();
    Ok(parsed
        .map_err(|m| Failure::plain(ExitCode::USAGE, m))?
        .flatten())
}

pub fn run(args: PlanArgs) -> Result<ExitCode, Failure> {
    let start = Instant::now();
    let time_limit = limit(args.overall_time_limit.as_deref(), parse_time_limit)?;
    let memory_limit = limit(args.overall_memory_limit.as_deref(), parse_memory_limit)?;
    let (search, alias) = (args.search.as_deref(), args.alias.as_deref());
    let config = slim::PlannerConfig::resolve(search, alias, args.translator)
        .map_err(|e| Failure::plain(e.exit_code(), e.to_string()))?;
    // Like Fast Downward, never leave an old plan behind that could be mistaken for this
    // run's.
    if args.plan_file.exists() {
        std::fs::remove_file(&args.plan_file).map_err(|e| {
            Failure::plain(
                ExitCode::CRITICAL_ERROR,
                format!("cannot remove old {}: {e}", args.plan_file.display()),
            )
        })?;
    }

    // One deadline from the process start for every phase: translation, heuristic
    // construction and search.
    let limits = task::Limits {
        deadline: task::deadline_after(start, time_limit),
        memory_limit_bytes: memory_limit,
        memory_usage: Some(memory::heap_in_use),
        cancel: None,
    };
    let mut log = |line: &str| println!("{line}");
    let (logged, problem_path, pddl_files) = match args.files.as_slice() {
        [single] if is_sas_file(single) => {
            if args.translator != translate::TranslateOptions::default() {
                let what = "the translator options act on PDDL, not on a translated task";
                return Err(Failure::plain(
                    ExitCode::USAGE,
                    format!("{}: {what}", single.display()),
                ));
            }
            if config.translator != translate::TranslateOptions::default() {
                log("Translator options of the alias not applied: the task is translated");
            }
            let task = read_sas(single)?;
            let logged = slim::plan_logged(
                slim::PlanInput::Task(&task),
                &config.search,
                &limits,
                start,
                &mut log,
            );
            (logged, single.clone(), None)
        }
        files => {
            let (domain_path, problem_path) = domain_and_problem(files)?;
            let parsed = read_parsed(&domain_path, &problem_path)?;
            let input = slim::PlanInput::Pddl {
                domain: &parsed.domain,
                problem: &parsed.problem,
                options: config.translator,
            };
            let logged = slim::plan_logged(input, &config.search, &limits, start, &mut log);
            (
                logged,
                problem_path.clone(),
                Some((domain_path, problem_path)),
            )
        }
    };
    let logged = logged.map_err(|e| Failure::plain(e.exit_code(), e.message(&problem_path)))?;
    let solved = logged.run.plan_text();
    if let Some(text) = &solved {
        output::write_atomically(&args.plan_file, text)?;
        println!("Plan length: {} step(s).", logged.run.plan.len());
        println!("Plan cost: {}", logged.run.cost.unwrap_or(0));
    }
    let peak_memory_kb = memory::peak_rss_kb();
    print!("{}", logged.closing_statistics(peak_memory_kb));
    if let Some(path) = &args.stats_json {
        let record = logged.statistics_record(peak_memory_kb);
        let text = serde_json::to_string_pretty(&record)
            .map_err(|e| Failure::plain(ExitCode::CRITICAL_ERROR, e.to_string()))?;
        output::write_atomically(path, &format!("{text}\n"))?;
    }
    if let (Some(_), true, Some((domain, problem))) = (&solved, args.validate, &pddl_files) {
        let invalid = crate::commands::validate::validate_plans(
            domain,
            problem,
            std::slice::from_ref(&args.plan_file),
        )?;
        if invalid != ExitCode::SUCCESS {
            return Err(Failure::plain(
                ExitCode::CRITICAL_SEARCH_ERROR,
                "the plan found does not validate: this is a bug in demoplan, please report it",
            ));
        }
    }
    Ok(logged.run.outcome.exit_code())
}

fn read_sas(path: &Path) -> Result<task::Task, Failure> {
    let text = input::read_text(path)?;
    task::sas_file::read(&text).map_err(|e| {
        let code = match e {
            task::sas_file::SasError::Unsupported { .. } => ExitCode::UNSUPPORTED,
            _ => ExitCode::SEARCH_INPUT_ERROR,
        };
        let location = e.line().map_or(String::new(), |l| format!(":{l}"));
        Failure::plain(code, format!("{}{location}: {e}", path.display()))
    })
}
