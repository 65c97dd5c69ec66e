//! What `demoplan solve` prints of the execution loop, as text: a note under an
//! attempt's row of the level table, and the operators set aside.

use crate::{Attempt, Check, Solved};

/// The lines under an attempt's row of the level table (with their line endings), or
/// `None` when execution did not run: a failing step in the words of `demoplan execute`
/// and the operator set aside, a goal the final geometry misses, or that the plan
/// executed.
pub fn attempt_note(attempt: &Attempt) -> Option<String> {
    match &attempt.check {
        Check::NotRun => None,
        Check::Executed => Some(format!(
            "      executed in the cube world: every step and the goal check pass ({:.3} s)\n",
            attempt.execution_time.as_secs_f64()
        )),
        Check::StepFailed(s) => Some(format!(
            "      step {} {}: FAILED: {}\n      set aside {} (operator {}); searching priority {} \
             again without it\n",
            s.step, s.action, s.why, s.name, s.id, s.prio
        )),
        Check::GoalNotReached { unsatisfied } => Some(format!(
            "      every step executed, but goal not reached: {} not in the final grounded \
             state; nothing set aside, widening\n",
            unsatisfied.join(" ")
        )),
    }
}

/// An attempt's row of the level table ([`slim::level_row`]) and its note
/// ([`attempt_note`]), with their line endings: what `demoplan solve` prints as each
/// attempt ends.
pub fn attempt_lines(attempt: &Attempt) -> String {
    let mut out = slim::level_row(&attempt.level);
    out.push_str(&attempt_note(attempt).unwrap_or_default());
    out
}

impl Attempt {
    /// The line of a plan found (without line ending): its level, operators, steps and
    /// cost, and where it was written.
    pub fn solution_line(&self, plan_file: &std::path::Path) -> String {
        let level = &self.level;
        format!(
            "Solution found at priority {} ({} operators): {} step(s), cost {}; plan written to {}",
            level.prio,
            level.operators,
            level.run.plan.len(),
            level.run.cost.unwrap_or(0),
            plan_file.display()
        )
    }

    /// The line `demoplan solve` prints on standard error for a run that failed (with
    /// its line ending); empty for any other.
    pub fn error_line(&self) -> String {
        match &self.level.run.error {
            Some(e) => format!("error at priority {}: {e}\n", self.level.prio),
            None => String::new(),
        }
    }
}

/// The operators set aside, one line each (with its line ending): name, id, the level
/// and step that failed and why; `"nothing\n"`-free: empty when none was.
pub fn set_aside_list(solved: &Solved) -> String {
    solved
        .set_aside()
        .iter()
        .map(|s| {
            format!(
                "  {} (operator {}): priority {}, step {} {}: {}\n",
                s.name, s.id, s.prio, s.step, s.action, s.why
            )
        })
        .collect()
}

impl Solved {
    /// The sentence of a solve without an executable plan (with its line ending), the
    /// operators set aside listed after it.
    pub fn no_executable_plan_text(&self) -> String {
        let plans = self.replans();
        let mut out = format!(
            "No executable plan: the cube world executed none of the {plans} plan(s) found \
             (exit {}).\n",
            crate::NO_EXECUTABLE_PLAN.0
        );
        let list = set_aside_list(self);
        if list.is_empty() {
            out.push_str("Nothing set aside: every failing plan missed the goal, not a step.\n");
        } else {
            out.push_str("Set aside for this problem:\n");
            out.push_str(&list);
        }
        if let Some(which) = self.limits_reached() {
            out.push_str(&format!("Some level also reached {which}.\n"));
        }
        out
    }

    /// What a solve without a plan says (with its line ending): the operators set aside
    /// when no plan executed, else which limit some level reached, else that every level
    /// is unsolvable (the sentences of Algorithm 1 alone).
    pub fn no_plan_text(&self) -> String {
        match self.verdict() {
            crate::Verdict::Plan(_) => String::new(),
            crate::Verdict::NoExecutablePlan => self.no_executable_plan_text(),
            crate::Verdict::LimitReached => format!(
                "No plan: some level reached {} (exit 12).\n",
                self.limits_reached().unwrap_or("its limit")
            ),
            crate::Verdict::Unsolvable => {
                "No plan on any level: every level is unsolvable.\n".to_string()
            }
        }
    }

    /// The line after the table: the time over every attempt, and with execution the
    /// part spent executing plans and the number of replans.
    pub fn cumulative_line(&self) -> String {
        let mut line = self.levels().cumulative_line();
        if self.execution == crate::Execution::On {
            line.pop();
            line.push_str(&format!(
                "; executing plans: {:.3} s, {} replan(s)\n",
                self.execution_time.as_secs_f64(),
                self.replans()
            ));
        }
        line
    }
}
