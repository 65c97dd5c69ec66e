//! `demoplan plan`: translate (or read output.sas), search, write the plan; Fast
//! Downward's log lines, plan file and exit codes.

use std::path::Path;
use std::time::{Duration, Instant};

use crate::cli::PlanArgs;
use crate::commands::translate::{domain_and_problem, translate_files, Translated};
use crate::diagnostic::Failure;
use crate::exit::ExitCode;
use crate::{input, memory, output};

/// `30s`, `5m`, `1h`, `90` (seconds), `1e3`, `infinity`. A limit too large for a
/// `Duration` (over about 5.8e11 years, `1e20`) is no limit, as `infinity` is; negative,
/// NaN and infinite numbers are refused.
pub fn parse_time_limit(text: &str) -> Result<Option<Duration>, String> {
    let t = text.trim().to_ascii_lowercase();
    if t == "infinity" {
        return Ok(None);
    }
    let (number, unit) = match t.char_indices().last() {
        Some((i, 's')) => (&t[..i], 1.0),
        Some((i, 'm')) => (&t[..i], 60.0),
        Some((i, 'h')) => (&t[..i], 3600.0),
        _ => (t.as_str(), 1.0),
    };
    match number.parse::<f64>() {
        Ok(v) if v.is_finite() && v >= 0.0 => Ok(Duration::try_from_secs_f64(v * unit).ok()),
        _ => Err(format!(
            "invalid time limit `{text}`: expected e.g. 30s, 5m, 1h or infinity"
        )),
    }
}

/// `512M`, `3G`, `100K`, `1048576` (bytes), `infinity`; units are powers of 1024.
pub fn parse_memory_limit(text: &str) -> Result<Option<u64>, String> {
    let t = text.trim().to_ascii_lowercase();
    if t == "infinity" {
        return Ok(None);
    }
    let (number, unit) = match t.char_indices().last() {
        Some((i, 'k')) => (&t[..i], 1u64 << 10),
        Some((i, 'm')) => (&t[..i], 1 << 20),
        Some((i, 'g')) => (&t[..i], 1 << 30),
        _ => (t.as_str(), 1),
    };
    match number.parse::<u64>() {
        Ok(v) => v
            .checked_mul(unit)
            .map(Some)
            .ok_or_else(|| format!("memory limit `{text}` is too large")),
        Err(_) => Err(format!(
            "invalid memory limit `{text}`: expected e.g. 512M, 3G or infinity"
        )),
    }
}

/// `--memory-limit` of `solve`, `reproduce`, `study`: as [`parse_memory_limit`], or
/// `auto` ([`experiment::auto_memory_limit`]).
pub fn parse_run_memory_limit(text: &str, runs_at_once: usize) -> Result<Option<u64>, Failure> {
    if text.trim().eq_ignore_ascii_case("auto") {
        return Ok(experiment::auto_memory_limit(runs_at_once));
    }
    parse_memory_limit(text)
        .map_err(|e| Failure::plain(ExitCode::USAGE, format!("--memory-limit: {e}")))
}

fn is_sas_file(path: &Path) -> bool {
    path.extension().is_some_and(|e| e == "sas")
}

pub fn run(args: PlanArgs) -> Result<ExitCode, Failure> {
    let start = Instant::now();
    let usage = |m: String| Failure::plain(ExitCode::USAGE, m);
    let time_limit = args
        .overall_time_limit
        .as_deref()
        .map(parse_time_limit)
        .transpose()
        .map_err(usage)?
        .flatten();
    let memory_limit = args
        .overall_memory_limit
        .as_deref()
        .map(parse_memory_limit)
        .transpose()
        .map_err(usage)?
        .flatten();
    let search_string = match (&args.search, &args.alias) {
        (Some(s), _) => s.clone(),
        (None, Some(a)) => search::alias(a).map(str::to_string).ok_or_else(|| {
            let known: Vec<&str> = search::ALIASES.iter().map(|(name, _)| *name).collect();
            usage(format!(
                "unknown alias `{a}`; known aliases: {}",
                known.join(", ")
            ))
        })?,
        (None, None) => return Err(usage("give a search with --search or --alias".into())),
    };
    let config = search::parse_search(&search_string)
        .map_err(|e| Failure::plain(ExitCode::SEARCH_INPUT_ERROR, format!("--search: {e}")))?;
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
    };
    let mut pddl_files = None;
    let task = match args.files.as_slice() {
        [single] if is_sas_file(single) => read_sas(single)?,
        files => {
            let (domain, problem) = domain_and_problem(files)?;
            let translated = translate_files(&domain, &problem, &limits)?;
            pddl_files = Some((domain, problem));
            match translated {
                Translated::Task(task) => task,
                Translated::Unsolvable => {
                    println!("Search stopped without finding a solution.");
                    let report = Report::unsolvable_before_search(start);
                    report.print();
                    write_stats(&args, &report)?;
                    return Ok(ExitCode::UNSOLVABLE);
                }
                Translated::Stopped(limit) => return stopped_before_search(&args, start, limit),
            }
        }
    };
    let translate_time = start.elapsed();

    println!("Search: {config}");
    let mut observer = |p: search::Progress| {
        println!(
            "f = {}, {} evaluated, {} expanded [t={:.3}s]",
            p.f,
            p.evaluated,
            p.expanded,
            start.elapsed().as_secs_f64()
        );
    };
    // The heuristic first, so that what building it did (the hill climbing of ipdb())
    // is reported before the search, as Fast Downward does.
    let mut heuristic = match config
        .heuristic
        .build_with_limits(&task, &limits)
        .map_err(|e| Failure::plain(ExitCode::SEARCH_INPUT_ERROR, e.to_string()))?
    {
        search::Built::Heuristic(h) => h,
        search::Built::Stopped(limit) => return stopped_before_search(&args, start, limit),
    };
    if let Some(s) = heuristic.pdb_statistics() {
        println!("{s}");
    }
    let result = match config.engine {
        search::Engine::AStar => search::astar(&task, &mut heuristic, &limits, Some(&mut observer)),
    }
    .map_err(|e| {
        let code = match e {
            search::SearchError::CostTooLarge { .. } => ExitCode::UNSUPPORTED,
            _ => ExitCode::SEARCH_INPUT_ERROR,
        };
        Failure::plain(code, e.to_string())
    })?;
    let stats = &result.statistics;
    if let Some(h) = stats.initial_h {
        println!("Initial heuristic value: {h}");
    }
    let (code, plan) = match &result.outcome {
        search::Outcome::Solved(plan) => {
            println!("Solution found!");
            (ExitCode::SUCCESS, Some(plan))
        }
        search::Outcome::Unsolvable => {
            println!("Completely explored state space -- no solution!");
            (ExitCode::UNSOLVABLE, None)
        }
        search::Outcome::TimeLimit => {
            println!("Time limit reached. Abort search.");
            (ExitCode::OUT_OF_TIME, None)
        }
        search::Outcome::MemoryLimit => {
            println!("Memory limit has been reached.");
            (ExitCode::OUT_OF_MEMORY, None)
        }
    };
    if let Some(plan) = plan {
        for op in &plan.operators {
            let o = &task.operators[op.index()];
            println!("{} ({})", o.name, task.cost(o));
        }
        let steps = translate::plan_steps(&task, &plan.operators);
        let text = pddl::write_plan(&steps, plan.cost, translate::cost_kind(&task));
        output::write_atomically(&args.plan_file, &text)?;
        println!("Plan length: {} step(s).", plan.operators.len());
        println!("Plan cost: {}", plan.cost);
    }
    let report = Report {
        outcome: match code {
            ExitCode::SUCCESS => "solved",
            ExitCode::UNSOLVABLE => "unsolvable",
            ExitCode::OUT_OF_TIME => "out_of_time",
            _ => "out_of_memory",
        },
        plan: plan.map(|p| (p.operators.len(), p.cost)),
        statistics: Some(result.statistics),
        translate_time,
        total_time: start.elapsed(),
        sizes: Some(task.sizes()),
    };
    report.print();
    if plan.is_some() {
        println!("Solution found.");
    }
    write_stats(&args, &report)?;
    if let (Some(_), true, Some((domain, problem))) = (plan, args.validate, &pddl_files) {
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
    Ok(code)
}

/// A run stopped at `limit` before its search began (in translation, or building a
/// pattern database that does not fit): Fast Downward's line and exit code, the closing
/// statistics, `--stats-json`.
fn stopped_before_search(
    args: &PlanArgs,
    start: Instant,
    limit: task::Limit,
) -> Result<ExitCode, Failure> {
    let (line, outcome, code) = match limit {
        task::Limit::Time => (
            "Time limit reached. Abort search.",
            "out_of_time",
            ExitCode::OUT_OF_TIME,
        ),
        task::Limit::Memory => (
            "Memory limit has been reached.",
            "out_of_memory",
            ExitCode::OUT_OF_MEMORY,
        ),
    };
    println!("{line}");
    let report = Report {
        outcome,
        ..Report::unsolvable_before_search(start)
    };
    report.print();
    write_stats(args, &report)?;
    Ok(code)
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

/// What a run reports at its end, on the terminal and in `--stats-json`.
struct Report {
    outcome: &'static str,
    plan: Option<(usize, u64)>,
    statistics: Option<search::Statistics>,
    translate_time: Duration,
    total_time: Duration,
    sizes: Option<task::TaskSizes>,
}

impl Report {
    fn unsolvable_before_search(start: Instant) -> Report {
        Report {
            outcome: "unsolvable",
            plan: None,
            statistics: None,
            translate_time: start.elapsed(),
            total_time: start.elapsed(),
            sizes: None,
        }
    }

    /// Fast Downward's closing statistics lines.
    fn print(&self) {
        if let Some(s) = &self.statistics {
            println!("Expanded {} state(s).", s.expanded);
            println!("Reopened {} state(s).", s.reopened);
            println!("Evaluated {} state(s).", s.evaluated);
            println!("Generated {} state(s).", s.generated);
            println!("Dead ends: {} state(s).", s.dead_ends);
            println!(
                "Expanded until last jump: {} state(s).",
                s.expanded_until_last_jump
            );
            println!(
                "Evaluated until last jump: {} state(s).",
                s.evaluated_until_last_jump
            );
            println!(
                "Generated until last jump: {} state(s).",
                s.generated_until_last_jump
            );
            println!("Number of registered states: {}", s.registered_states);
            println!("Search time: {:.6}s", s.search_time.as_secs_f64());
        }
        println!("Total time: {:.6}s", self.total_time.as_secs_f64());
        if let Some(kb) = memory::peak_rss_kb() {
            println!("Peak memory: {kb} KB");
        }
    }

    fn to_json(&self) -> serde_json::Value {
        let s = self.statistics.as_ref();
        serde_json::json!({
            "outcome": self.outcome,
            "plan_length": self.plan.map(|p| p.0),
            "plan_cost": self.plan.map(|p| p.1),
            "expanded": s.map(|s| s.expanded),
            "reopened": s.map(|s| s.reopened),
            "evaluated": s.map(|s| s.evaluated),
            "generated": s.map(|s| s.generated),
            "dead_ends": s.map(|s| s.dead_ends),
            "expanded_until_last_jump": s.map(|s| s.expanded_until_last_jump),
            "registered_states": s.map(|s| s.registered_states),
            "initial_h": s.and_then(|s| s.initial_h),
            "search_time_s": s.map(|s| s.search_time.as_secs_f64()),
            "translate_time_s": self.translate_time.as_secs_f64(),
            "total_time_s": self.total_time.as_secs_f64(),
            "peak_memory_kb": memory::peak_rss_kb(),
            "variables": self.sizes.map(|z| z.variables),
            "facts": self.sizes.map(|z| z.facts),
            "operators": self.sizes.map(|z| z.operators),
        })
    }
}

fn write_stats(args: &PlanArgs, report: &Report) -> Result<(), Failure> {
    if let Some(path) = &args.stats_json {
        let text = serde_json::to_string_pretty(&report.to_json())
            .map_err(|e| Failure::plain(ExitCode::CRITICAL_ERROR, e.to_string()))?;
        output::write_atomically(path, &format!("{text}\n"))?;
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn time_limits_take_fast_downward_units() {
        assert_eq!(parse_time_limit("30s"), Ok(Some(Duration::from_secs(30))));
        assert_eq!(parse_time_limit("5m"), Ok(Some(Duration::from_secs(300))));
        assert_eq!(parse_time_limit("1h"), Ok(Some(Duration::from_secs(3600))));
        assert_eq!(parse_time_limit("90"), Ok(Some(Duration::from_secs(90))));
        assert_eq!(parse_time_limit("infinity"), Ok(None));
        assert!(parse_time_limit("10x").is_err());
        assert!(parse_time_limit("-1s").is_err());
        assert!(parse_time_limit("nan").is_err());
        assert!(parse_time_limit("inf").is_err());
        // Beyond what a deadline can be: no limit, never a panic.
        assert_eq!(parse_time_limit("1e20"), Ok(None));
        assert_eq!(parse_time_limit("1e300h"), Ok(None));
        assert_eq!(parse_time_limit("1e3"), Ok(Some(Duration::from_secs(1000))));
    }

    #[test]
    fn memory_limits_take_binary_units() {
        assert_eq!(parse_memory_limit("512M"), Ok(Some(512 << 20)));
        assert_eq!(parse_memory_limit("3G"), Ok(Some(3 << 30)));
        assert_eq!(parse_memory_limit("100k"), Ok(Some(100 << 10)));
        assert_eq!(parse_memory_limit("4096"), Ok(Some(4096)));
        assert!(parse_memory_limit("lots").is_err());
        assert!(parse_memory_limit("99999999999999999999G").is_err());
    }
}
