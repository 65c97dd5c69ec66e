//! `demoplan translate [DOMAIN] PROBLEM`: PDDL to a finite-domain task in output.sas.

use std::path::{Path, PathBuf};
use std::time::Instant;

use crate::cli::TranslateArgs;
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
    print!("{}", result.log());
    let translated = match result {
        translate::Translation::Unsolvable { .. } => Translated::Unsolvable,
        translate::Translation::Stopped { limit, .. } => Translated::Stopped(limit),
        translate::Translation::Task(t) => Translated::Task(t.task),
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

pub fn run(args: TranslateArgs) -> Result<ExitCode, Failure> {
    let (domain, problem) = domain_and_problem(&args.files)?;
    let sas_file = &args.sas_file;
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
