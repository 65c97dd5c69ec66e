//! An [`ExecutionReport`] as people read it (`demoplan execute`): one line per step (ok,
//! or what failed: the expected facts against the grounded state, collisions), the
//! first failing step with its motion, and whether the goal was reached.

use crate::execute::ExecutionReport;

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
            if s.ok() {
                out.push_str(&format!("{head}: ok\n"));
            } else {
                let expected: Vec<String> = s
                    .failed
                    .iter()
                    .map(|f| {
                        if f.expected {
                            f.fact.clone()
                        } else {
                            format!("(not {})", f.fact)
                        }
                    })
                    .collect();
                let mut why = Vec::new();
                if !expected.is_empty() {
                    why.push(format!(
                        "expected {}, grounded state has {}",
                        expected.join(" "),
                        if s.grounded.is_empty() {
                            "nothing over its objects".to_string()
                        } else {
                            s.grounded.join(" ")
                        }
                    ));
                }
                if !s.collisions.is_empty() {
                    why.push(format!(
                        "its motion moves things through each other: {}",
                        s.collisions.join(" ")
                    ));
                }
                out.push_str(&format!("{head}: FAILED: {}\n", why.join("; ")));
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
