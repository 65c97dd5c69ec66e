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
        let mut out = format!("{blank}Checking plan: {}\n", path.display());
        let valid = match pddl::parse_plan(text) {
            Err(e) => {
                out.push_str("Bad plan description!\n");
                out.push_str(&format!("{}:{}: {}\n", path.display(), e.line, e.kind));
                out.push_str("Plan invalid\n");
                false
            }
            Ok(plan) => match validate::validate(&task.domain, &task.problem, &plan) {
                Ok(report) => {
                    out.push_str(&report.val_text());
                    report.is_valid()
                }
                Err(e) => {
                    print!("{out}");
                    return Err(Failure::plain(
                        ExitCode::INPUT_ERROR,
                        format!("{}: {e}", problem.display()),
                    ));
                }
            },
        };
        if !valid {
            invalid += 1;
        }
        print!("{out}");
    }
    // VAL exits with the number of invalid plans; beyond 255 it would wrap to success.
    Ok(ExitCode(invalid.min(255)))
}
