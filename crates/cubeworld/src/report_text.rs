//! An [`ExecutionReport`] as people read it (`demoplan execute`): one line per step (ok,
//! or what failed: the expected facts against the grounded state, collisions), the
//! first failing step with its motion, and whether the goal was reached.

use crate::execute::{ExecutionReport, StepReport};

impl StepReport {
    /// Why the step failed, as [`ExecutionReport::text`] says it after `FAILED: `: the
    /// effects expected (`(not ...)` for a delete) against the grounded facts over the
    /// step's objects, and what its motion moved through each other; `None` for a step
    /// that is ok. The execution loop (`closed-loop`) reports a set-aside operator in
    /// these words.
    pub fn failure_text(&self) -> Option<String> {
        if self.ok() {
            return None;
        }
        let mut why = Vec::new();
        if !self.failed.is_empty() {
            why.push(format!(
                "expected {}, grounded state has {}",
                self.promised().join(" "),
                if self.grounded.is_empty() {
                    "nothing over its objects".to_string()
                } else {
                    self.grounded.join(" ")
                }
            ));
        }
        if !self.collisions.is_empty() {
            why.push(format!(
                "its motion moves things through each other: {}",
                self.collisions.join(" ")
            ));
        }
        Some(why.join("; "))
    }

    /// The effects the grounded state did not give, as atoms: `(inhand left_hand
    /// cube_2)` for an add effect, `(not (handopen left_hand))` for a delete effect.
    pub fn promised(&self) -> Vec<String> {
        self.failed
            .iter()
            .map(|f| {
                if f.expected {
                    f.fact.clone()
                } else {
                    format!("(not {})", f.fact)
                }
            })
            .collect()
    }
}

impl ExecutionReport {
    /// The report as text, a line per step and then the goal.
    pub fn text(&self) -> String {
        let mut out = String::new();
        if !self.initial_missing.is_empty() {
            out.push_str(&format!(
                "warning: the cube world's initial state lacks {}\n",
                self.initial_missing.join(" ")
            ));
        }
        for s in &self.steps {
            let head = format!("step {} {}", s.index, s.action_text());
            for u in &s.unmet_preconditions {
                out.push_str(&format!(
                    "{head}: warning: precondition {u} does not hold in the plan's state\n"
                ));
            }
            match s.failure_text() {
                None => out.push_str(&format!("{head}: ok\n")),
                Some(why) => out.push_str(&format!("{head}: FAILED: {why}\n")),
            }
        }
        if let Some(i) = self.first_failure() {
            let s = &self.steps[i];
            out.push_str(&format!(
                "first failing step: {} {} ({} to {} s; motion: {})\n",
                s.index,
                s.action_text(),
                s.start,
                s.end,
                s.primitives.join(", ")
            ));
        }
        if self.goal.reached {
            out.push_str("goal reached\n");
        } else {
            out.push_str(&format!(
                "goal not reached: {} not in the final grounded state\n",
                self.goal.unsatisfied.join(" ")
            ));
        }
        out
    }
}
