//! `demoplan validate DOMAIN PROBLEM PLAN...`: VAL's `validate`, with VAL's wording and
//! exit status (the number of invalid plans), on the independent `validate` crate.

use std::path::{Path, PathBuf};

use crate::cli::ValidateArgs;
use crate::diagnostic::Failure;
use crate::input;
use slim::ExitCode;

pub fn run(args: ValidateArgs) -> Result<ExitCode, Failure> {
    validate_plans(&args.domain, &args.problem, &args.plans)
}

/// Validates each plan file, printing VAL's report; the exit code counts invalid plans.
pub fn validate_plans(
    domain: &Path,
    problem: &Path,
    plans: &[PathBuf],
) -> Result<ExitCode, Failure> {
    let task = input::read_task(domain, problem)?;
    // Every plan file is read before any is judged: a missing one is a command line
    // mistake (36), not an invalid plan.
    let texts = plans
        .iter()
        .map(|p| input::read_text(p))
        .collect::<Result<Vec<_>, _>>()?;
    let mut invalid: i32 = 0;
    for (index, (path, text)) in plans.iter().zip(&texts).enumerate() {
        let blank = if index == 0 { "" } else { "\n" };
        println!("{blank}Checking plan: {}", path.display());
        let name = path.display().to_string();
        let (report, valid) = validate::val_text_of_file(&task.domain, &task.problem, &name, text)
            .map_err(|e| {
                Failure::plain(ExitCode::INPUT_ERROR, format!("{}: {e}", problem.display()))
            })?;
        print!("{report}");
        invalid += i32::from(!valid);
    }
    // VAL exits with the number of invalid plans; beyond 255 it would wrap to success.
    Ok(ExitCode(invalid.min(255)))
}
