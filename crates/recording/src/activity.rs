//! The paper's hand activities (Table 1): what a demonstration's frames are labelled
//! with, what the segmenter classifies, and the types of the operators learned from them.

use std::fmt;

use serde::{Deserialize, Serialize};

/// The paper's hand activities (Table 1).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize, Deserialize)]
pub enum Activity {
    /// Moving, acting on an object, holding an object.
    Stack,
    /// Nothing acted on, nothing in hand (moving or not); also any tuple no rule matches.
    Idle,
    /// Moving, acting on an object, nothing in hand.
    Reach,
    /// Moving, nothing acted on, holding an object.
    Put,
    /// Not moving, nothing acted on, holding an object.
    Take,
}

impl Activity {
    /// Every activity, in the order of the paper's Table 1.
    pub const ALL: [Activity; 5] = [
        Activity::Stack,
        Activity::Idle,
        Activity::Reach,
        Activity::Put,
        Activity::Take,
    ];

    /// The order in which tables, domains, cards and figures list operator types: the
    /// order of a demonstration (reach, take, put, stack), then idle.
    pub const OPERATOR_ORDER: [Activity; 5] = [
        Activity::Reach,
        Activity::Take,
        Activity::Put,
        Activity::Stack,
        Activity::Idle,
    ];

    /// The paper's Table 1: (handMove, actedOn is an object, inHand is an object) to an
    /// activity; a tuple that matches no row (not moving but acting on an object) is Idle.
    pub fn classify(moving: bool, acted_on: bool, in_hand: bool) -> Activity {
        match (moving, acted_on, in_hand) {
            (true, true, true) => Activity::Stack,
            (true, true, false) => Activity::Reach,
            (true, false, true) => Activity::Put,
            (false, false, true) => Activity::Take,
            _ => Activity::Idle,
        }
    }

    /// The name in files and tables: `Stack`, `Idle`, `Reach`, `Put`, `Take`.
    pub fn name(self) -> &'static str {
        match self {
            Activity::Stack => "Stack",
            Activity::Idle => "Idle",
            Activity::Reach => "Reach",
            Activity::Put => "Put",
            Activity::Take => "Take",
        }
    }

    /// The activity with this name, ignoring case.
    pub fn from_name(name: &str) -> Option<Activity> {
        Activity::ALL
            .into_iter()
            .find(|a| a.name().eq_ignore_ascii_case(name))
    }

    /// Position in [`Activity::ALL`].
    pub fn index(self) -> usize {
        self as usize
    }

    /// The stem of its operators' PDDL names: `stack`, `idle`, `reach`, `put`, `take`
    /// (the operators themselves are `put`, `put2`, ... by rank).
    pub fn operator_name(self) -> &'static str {
        match self {
            Activity::Stack => "stack",
            Activity::Idle => "idle",
            Activity::Reach => "reach",
            Activity::Put => "put",
            Activity::Take => "take",
        }
    }

    /// The type of an operator by its PDDL name, its trailing digits left out (`put2` is
    /// a Put), if it is one of the five.
    pub fn of_operator_name(name: &str) -> Option<Activity> {
        let stem = name.trim_end_matches(|c: char| c.is_ascii_digit());
        Activity::ALL
            .into_iter()
            .find(|a| a.operator_name() == stem)
    }
}

impl fmt::Display for Activity {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_read_back() {
        for a in Activity::ALL {
            assert_eq!(Activity::from_name(a.name()), Some(a));
            assert_eq!(Activity::from_name(&a.name().to_uppercase()), Some(a));
            assert_eq!(Activity::of_operator_name(a.operator_name()), Some(a));
            assert_eq!(Activity::ALL[a.index()], a);
        }
        assert_eq!(Activity::of_operator_name("put12"), Some(Activity::Put));
        assert_eq!(Activity::of_operator_name("pick-up"), None);
        assert_eq!(Activity::of_operator_name("Put"), None);
        assert_eq!(Activity::from_name("Pour"), None);
    }

    #[test]
    fn table_one() {
        use Activity::*;
        let rows = [
            ((true, true, true), Stack),
            ((true, false, false), Idle),
            ((false, false, false), Idle),
            ((true, true, false), Reach),
            ((true, false, true), Put),
            ((false, false, true), Take),
            // No row: not moving but acting on an object.
            ((false, true, false), Idle),
            ((false, true, true), Idle),
        ];
        for ((moving, acted_on, in_hand), a) in rows {
            assert_eq!(Activity::classify(moving, acted_on, in_hand), a);
        }
    }
}
