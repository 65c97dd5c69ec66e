//! A [`Report`] in VAL's words (`demoplan validate`): "Plan valid" and "Final value: N",
//! or the failing step with VAL's repair advice, or the unsatisfied goal, and "Plan
//! invalid", so that scripts written for VAL read demoplan's output.

use pddl::{Domain, Problem};

use crate::execute::{validate, GroundLiteral, Reason, Report, ValidateError, Verdict};

/// What VAL prints after "Checking plan" for the plan file `name` holding `text`, and
/// whether the plan is valid: "Bad plan description!" with the line at fault for a plan
/// that does not parse, the [`Report::val_text`] of [`validate`] otherwise.
pub fn val_text_of_file(
    domain: &Domain,
    problem: &Problem,
    name: &str,
    text: &str,
) -> Result<(String, bool), ValidateError> {
    match pddl::parse_plan(text) {
        Err(e) => Ok((
            format!(
                "Bad plan description!\n{name}:{}: {}\nPlan invalid\n",
                e.line, e.kind
            ),
            false,
        )),
        Ok(plan) => validate(domain, problem, &plan).map(|r| (r.val_text(), r.is_valid())),
    }
}

impl Report {
    /// The lines VAL's `validate` prints for this plan, after its "Checking plan" line.
    pub fn val_text(&self) -> String {
        let mut out = String::new();
        match &self.verdict {
            Verdict::Valid => {
                out.push_str("Plan executed successfully - checking goal\n");
                out.push_str("Plan valid\n");
                out.push_str(&format!("Final value: {}\n", self.value));
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
                        advice(&mut out, unsatisfied);
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
                advice(&mut out, unsatisfied);
                out.push_str("Plan invalid\n");
            }
        }
        out
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
