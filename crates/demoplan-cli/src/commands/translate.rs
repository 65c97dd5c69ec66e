//! `demoplan translate [DOMAIN] PROBLEM`: PDDL to a finite-domain task in output.sas.

use std::path::{Path, PathBuf};
use std::time::Instant;

use crate::diagnostic::Failure;
use crate::exit::ExitCode;
use crate::{input, output};

/// A translated task, or the verdict that the goal is unreachable.
pub enum Translated {
    /// The task.
    Task(task::Task),
    /// Unsolvable even in the relaxation (the reason was printed).
    Unsolvable,
    /// Stopped at the run's time or memory limit (`plan`'s limits).
    Stopped(task::Limit),
}

/// Resolves `[DOMAIN] PROBLEM` (Fast Downward's rules when the domain is omitted).
pub fn domain_and_problem(files: &[PathBuf]) -> Result<(PathBuf, PathBuf), Failure> {
    match files {
        [domain, problem] => Ok((domain.clone(), problem.clone())),
        [problem] => Ok((input::find_domain_file(problem)?, problem.clone())),
        _ => Err(Failure::plain(ExitCode::USAGE, "expected [DOMAIN] PROBLEM")),
    }
}

/// Parses, checks and translates under the run's `limits`, printing Fast Downward's
/// translator statistics.
pub fn translate_files(
    domain: &Path,
    problem: &Path,
    limits: &task::Limits,
) -> Result<Translated, Failure> {
    let start = Instant::now();
    println!("Parsing...");
    let parsed = input::read_task(domain, problem)?;
    println!(
        "Parsing: [{:.3}s wall-clock]",
        start.elapsed().as_secs_f64()
    );
    let result =
        translate::translate_within(&parsed.domain, &parsed.problem, limits).map_err(|e| {
            Failure::plain(ExitCode::INPUT_ERROR, format!("{}: {e}", problem.display()))
        })?;
    let translated = match result {
        translate::Translation::Unsolvable { reason, stats } => {
            println!("{} relevant atoms", stats.reachable_atoms);
            println!("{} ground actions", stats.ground_actions);
            println!("Goal violated by relaxed reachability: {reason}");
            Translated::Unsolvable
        }
        translate::Translation::Stopped { limit, .. } => {
            println!("Translation stopped: {limit} reached");
            Translated::Stopped(limit)
        }
        translate::Translation::Task(t) => {
            let s = &t.stats;
            println!("{} relevant atoms", s.reachable_atoms);
            println!("{} fluent atoms", s.fluent_atoms);
            println!("{} ground actions", s.ground_actions);
            println!("Found {} mutex groups", s.mutex_groups);
            println!(
                "{} variables before goal relevance",
                s.variables_before_relevance
            );
            let task = t.task;
            let sizes = task.sizes();
            println!("Translator variables: {}", sizes.variables);
            println!("Translator facts: {}", sizes.facts);
            println!("Translator goal facts: {}", sizes.goal_facts);
            println!("Translator mutex groups: {}", sizes.mutex_groups);
            println!(
                "Translator total mutex groups size: {}",
                task.mutexes.iter().map(Vec::len).sum::<usize>()
            );
            println!("Translator operators: {}", sizes.operators);
            Translated::Task(task)
        }
    };
    println!(
        "Translation done! [{:.3}s wall-clock]",
        start.elapsed().as_secs_f64()
    );
    Ok(translated)
}

/// A task with one variable whose goal value no operator reaches: what Fast Downward's
/// translator writes for a task it found unsolvable.
pub fn trivially_unsolvable_task() -> task::Task {
    task::Task {
        variables: vec![task::Variable {
            name: "var0".into(),
            value_names: vec!["Atom dummy(val1)".into(), "Atom dummy(val2)".into()],
        }],
        mutexes: Vec::new(),
        initial_state: vec![0],
        goal: vec![task::Fact::new(task::VarId(0), 1)],
        operators: Vec::new(),
        use_costs: false,
    }
}

pub fn run(files: &[PathBuf], sas_file: &Path) -> Result<ExitCode, Failure> {
    let (domain, problem) = domain_and_problem(files)?;
    let (task, code) = match translate_files(&domain, &problem, &task::Limits::default())? {
        Translated::Task(task) => (task, ExitCode::SUCCESS),
        Translated::Unsolvable => (trivially_unsolvable_task(), ExitCode::UNSOLVABLE),
        // Without limits nothing stops translation; were it stopped, nothing is written.
        Translated::Stopped(limit) => {
            return Err(Failure::plain(
                ExitCode::CRITICAL_ERROR,
                format!("translation stopped at a {limit} it does not have"),
            ))
        }
    };
    output::write_atomically(sas_file, &task::sas_file::write(&task))?;
    println!("Wrote {}", sas_file.display());
    Ok(code)
}
