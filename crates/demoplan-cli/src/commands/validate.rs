//! `demoplan validate DOMAIN PROBLEM PLAN...`: VAL's `validate`, with VAL's wording and
//! exit status (the number of invalid plans), on the independent `validate` crate.

use std::path::{Path, PathBuf};

use validate::{GroundLiteral, Reason, Report, Verdict};

use crate::diagnostic::Failure;
use crate::exit::ExitCode;
use crate::input;

pub fn run(domain: &Path, problem: &Path, plans: &[PathBuf]) -> Result<ExitCode, Failure> {
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
                    render(&mut out, &report);
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

/// VAL's report of one plan, with its repair advice.
fn render(out: &mut String, report: &Report) {
    match &report.verdict {
        Verdict::Valid => {
            out.push_str("Plan executed successfully - checking goal\n");
            out.push_str("Plan valid\n");
            out.push_str(&format!("Final value: {}\n", report.value));
        }
        Verdict::StepFailed(failure) => {
            out.push_str("Plan failed to execute\n");
            match &failure.reason {
                Reason::UnsatisfiedPrecondition { unsatisfied } => {
                    out.push_str("Plan Repair Advice:\n");
                    out.push_str(&format!(
                        "{} has an unsatisfied precondition at time {}\n",
                        failure.action, failure.step
                    ));
                    advice(out, unsatisfied);
                }
                other => out.push_str(&format!(
                    "{} at time {} (line {}): {other}\n",
                    failure.action, failure.step, failure.line
                )),
            }
            out.push_str("Plan invalid\n");
        }
        Verdict::GoalNotSatisfied { unsatisfied } => {
            out.push_str("Plan executed successfully - checking goal\n");
            out.push_str("Goal not satisfied\n");
            out.push_str("Plan Repair Advice:\n");
            advice(out, unsatisfied);
            out.push_str("Plan invalid\n");
        }
    }
}

/// `(Set (p a) to true)` for one literal; `(Follow each of: ...)` around several.
fn advice(out: &mut String, literals: &[GroundLiteral]) {
    let set = |l: &GroundLiteral| format!("(Set {} to {})", l.atom, l.positive);
    match literals {
        [one] => out.push_str(&format!("{}\n", set(one))),
        _ => {
            out.push_str("(Follow each of:\n");
            for (i, l) in literals.iter().enumerate() {
                let and = if i == 0 { "" } else { "and " };
                out.push_str(&format!("    {and}{}\n", set(l)));
            }
            out.push_str(")\n");
        }
    }
}
