//! The paper's published numbers, in one place: its Tables 3 and 4, the sizes of its
//! domains (Figure 3), the statistics of its operator library (Section V) and the
//! slimming ratios it reports for goal 5. Everything that compares demoplan with the
//! paper reads them from here (the `experiment` crate re-exports this module).
//!
//! Source: Diehl, Paxton and Ramirez-Amaro, "Optimizing robot planning domains to
//! reduce search time for long-horizon planning", the `.tex` in `shared/paper/`.

/// The paper's title.
pub const PAPER_TITLE: &str =
    "Optimizing robot planning domains to reduce search time for long-horizon planning";

/// Operators of the paper's five domains, priority 1 to 5 (its Figure 3).
pub const PAPER_OPERATORS: [usize; 5] = [5, 11, 18, 23, 30];

/// The paper's Table 3 (A* with iPDB), search time in seconds as printed, domain by
/// goal.
pub const PAPER_IPDB: [[&str; 5]; 5] = [
    ["0.0005", "0.00066", "0.0011", "0.0013", "2.499"],
    ["0.00042", "0.00065", "0.0011", "0.1626", "11.2901"],
    ["0.0005", "0.00061", "0.0011", "1.6405", "124.2"],
    ["0.00042", "0.00064", "0.0011", "1.0601", "144.769"],
    ["0.0005", "0.00093", "0.00081", "1.2987", "180.652"],
];

/// The paper's Table 4 (A* with LM-cut), search time in seconds as printed, domain by
/// goal.
pub const PAPER_LMCUT: [[&str; 5]; 5] = [
    ["0.00048", "0.0015", "0.0046", "0.2877", "14.30"],
    ["0.00085", "0.0028", "0.0103", "0.977", "47.415"],
    ["0.00072", "0.0093", "0.0751", "13.081", "882.75"],
    ["0.0008", "0.01135", "0.0890", "15.96", "1295.11"],
    ["0.0018", "0.01348", "0.1588", "23.186", "1725.18"],
];

/// Demonstrations of the paper's study.
pub const DEMONSTRATIONS: usize = 12;

/// Participants of the paper's study.
pub const PARTICIPANTS: usize = 3;

/// Activities the paper retrieved from its 12 demonstrations.
pub const ACTIVITIES: usize = 115;

/// Distinct operators the paper learned from them.
pub const DISTINCT_OPERATORS: usize = 30;

/// Operator types (reach, take, put, stack, idle).
pub const OPERATOR_TYPES: usize = 5;

/// Distinct Put operators the paper learned.
pub const PUT_OPERATORS: usize = 5;

/// How often the most frequent Put operator was seen ("Put, Count: 12").
pub const PUT_COUNT: usize = 12;

/// How often the second Put operator was seen ("Put2, Count: 4").
pub const PUT2_COUNT: usize = 4;

/// Goal 5, full domain over priority 1, with iPDB: "around 72 times (2.499s vs.
/// 180.652s)", search time.
pub const RATIO_IPDB: f64 = 72.0;

/// Goal 5, full domain over priority 1, with LM-cut: "even 120 times (14.3s vs.
/// 1725.18s)", search time.
pub const RATIO_LMCUT: f64 = 120.0;

/// The paper's goal-5 search time (seconds) on the domain of `prio` (1 to 5) with the
/// heuristic of `table` ([`PAPER_IPDB`] or [`PAPER_LMCUT`]).
pub fn goal_five(table: &[[&str; 5]; 5], prio: usize) -> Option<f64> {
    table.get(prio.checked_sub(1)?)?[4].parse().ok()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_published_ratios_follow_from_the_tables() {
        let ratio = |t| goal_five(t, 5).unwrap_or(0.0) / goal_five(t, 1).unwrap_or(1.0);
        // "around 72 times" and "even 120 times", as the text rounds them.
        assert!((ratio(&PAPER_IPDB) - RATIO_IPDB).abs() < 1.0);
        assert!((ratio(&PAPER_LMCUT) - RATIO_LMCUT).abs() < 1.0);
        assert_eq!(PAPER_OPERATORS[4], DISTINCT_OPERATORS);
        assert_eq!(goal_five(&PAPER_IPDB, 6), None);
    }
}
