//! What Fast Downward's translator prints about a translation, in its words
//! ("Translator variables: N", ...), so that scripts that read its log read ours.

use crate::Translation;

impl Translation {
    /// The `output.sas` text Fast Downward's translator would write for this result: the
    /// task, or for an unsolvable one [`crate::unsolvable_task`], with
    /// [`sas_comment`](Self::sas_comment) on its first variable's line; `None` for a
    /// translation stopped at a limit, which writes nothing.
    pub fn sas_file(&self) -> Option<String> {
        let write = |task: &task::Task| task::sas_file::write_commented(task, &self.sas_comment());
        match self {
            Translation::Task(t) => Some(write(&t.task)),
            Translation::Unsolvable { .. } => Some(write(&crate::unsolvable_task())),
            Translation::Stopped { .. } => None,
        }
    }

    /// The comment `output.sas` carries ([`task::sas_file::write_commented`]) when the
    /// translation is not Fast Downward's: the options on, and what h² removed. Empty
    /// with the default options.
    pub fn sas_comment(&self) -> String {
        let stats = match self {
            Translation::Task(t) => &t.stats,
            Translation::Unsolvable { stats, .. } | Translation::Stopped { stats, .. } => stats,
        };
        let options = stats.options;
        let mut on = Vec::new();
        if options.h2_mutexes {
            on.push("--h2-mutexes");
        }
        if options.remove_dominated_operators {
            on.push("--remove-dominated-operators");
        }
        if on.is_empty() {
            return String::new();
        }
        let mut comment = format!("translated by demoplan with {}", on.join(" "));
        if let Some(h2) = &stats.h2 {
            comment.push_str(&format!(
                "; h2 removed {} operator(s), {} fact(s), {} variable(s) and added {} mutex pair(s)",
                h2.operators_removed, h2.facts_removed, h2.variables_removed, h2.mutexes_added
            ));
        }
        comment
    }

    /// The translator's size lines for this result, each ending in a newline.
    pub fn log(&self) -> String {
        let mut lines: Vec<String> = Vec::new();
        match self {
            Translation::Unsolvable { reason, stats } => {
                lines.push(format!("{} relevant atoms", stats.reachable_atoms));
                lines.push(format!("{} ground actions", stats.ground_actions));
                lines.push(format!("Goal violated by relaxed reachability: {reason}"));
            }
            Translation::Stopped { limit, .. } => {
                lines.push(format!("Translation stopped: {limit} reached"));
            }
            Translation::Task(t) => {
                let s = &t.stats;
                let sizes = t.task.sizes();
                let mutex_size: usize = t.task.mutexes.iter().map(Vec::len).sum();
                lines.extend([
                    format!("{} relevant atoms", s.reachable_atoms),
                    format!("{} fluent atoms", s.fluent_atoms),
                    format!("{} ground actions", s.ground_actions),
                    format!("Found {} mutex groups", s.mutex_groups),
                    format!(
                        "{} variables before goal relevance",
                        s.variables_before_relevance
                    ),
                    format!("Translator variables: {}", sizes.variables),
                    format!("Translator facts: {}", sizes.facts),
                    format!("Translator goal facts: {}", sizes.goal_facts),
                    format!("Translator mutex groups: {}", sizes.mutex_groups),
                    format!("Translator total mutex groups size: {mutex_size}"),
                ]);
                let options = s.options;
                if options != crate::TranslateOptions::default() {
                    lines.extend(options.log_lines());
                }
                if let Some(h2) = &s.h2 {
                    lines.extend(h2.log_lines());
                }
                if let Some(n) = s.dominated_operators_removed {
                    lines.push(format!("Removed {n} dominated operator(s)"));
                }
                lines.push(format!("Translator operators: {}", sizes.operators));
            }
        }
        lines.iter().map(|l| format!("{l}\n")).collect()
    }
}
