//! `demoplan translate [DOMAIN] PROBLEM`: PDDL to a finite-domain task in output.sas.

use std::path::{Path, PathBuf};
use std::time::Instant;

use crate::cli::TranslateArgs;
use crate::diagnostic::Failure;
use crate::{input, output};
use slim::ExitCode;

/// Resolves `[DOMAIN] PROBLEM` (Fast Downward's rules when the domain is omitted).
pub fn domain_and_problem(files: &[PathBuf]) -> Result<(PathBuf, PathBuf), Failure> {
    match files {
        [domain, problem] => Ok((domain.clone(), problem.clone())),
        [problem] => Ok((input::find_domain_file(problem)?, problem.clone())),
        _ => Err(Failure::plain(ExitCode::USAGE, "expected [DOMAIN] PROBLEM")),
    }
}

/// Reads, parses and checks the PDDL files, with Fast Downward's `Parsing...` lines.
pub fn read_parsed(domain: &Path, problem: &Path) -> Result<input::Task, Failure> {
    let start = Instant::now();
    println!("Parsing...");
    let parsed = input::read_task(domain, problem)?;
    println!(
        "Parsing: [{:.3}s wall-clock]",
        start.elapsed().as_secs_f64()
    );
    Ok(parsed)
}

pub fn run(args: TranslateArgs) -> Result<ExitCode, Failure> {
    let start = Instant::now();
    let (domain, problem) = domain_and_problem(&args.files)?;
    let parsed = read_parsed(&domain, &problem)?;
    let (d, p, limits) = (&parsed.domain, &parsed.problem, task::Limits::default());
    let translation =
        translate::translate_with_options(d, p, &limits, &args.translator).map_err(|e| {
            Failure::plain(ExitCode::INPUT_ERROR, format!("{}: {e}", problem.display()))
        })?;
    print!("{}", translation.log());
    println!(
        "Translation done! [{:.3}s wall-clock]",
        start.elapsed().as_secs_f64()
    );
    let code = match translation {
        translate::Translation::Task(_) => ExitCode::SUCCESS,
        translate::Translation::Unsolvable { .. } => ExitCode::UNSOLVABLE,
        // Without limits nothing stops translation; were it stopped, nothing is written.
        translate::Translation::Stopped { limit, .. } => {
            return Err(Failure::plain(
                ExitCode::CRITICAL_ERROR,
                format!("translation stopped at a {limit} it does not have"),
            ))
        }
    };
    let sas_file = &args.sas_file;
    output::write_atomically(sas_file, &translation.sas_file().unwrap_or_default())?;
    println!("Wrote {}", sas_file.display());
    Ok(code)
}
