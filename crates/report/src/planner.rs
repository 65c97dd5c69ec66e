//! The planners of an experiment: who plans (demoplan or Fast Downward) with which of
//! the paper's two heuristics. The one type of the concept: the experiment's cells and
//! records use it (`experiment::Planner` is this type), and this crate, the lowest that
//! shows them, orders, labels and matches them to the paper's tables with it.

use serde::{Deserialize, Serialize};

/// Who plans, with which heuristic. Written in results as its [`name`](Planner::name);
/// ordered as the report shows them: the paper's Table 3 (iPDB) before Table 4
/// (LM-cut), demoplan's own planner before Fast Downward.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize, Deserialize)]
#[serde(try_from = "String", into = "&'static str")]
pub enum Planner {
    /// demoplan's `astar(ipdb())`.
    Ipdb,
    /// demoplan's `astar(lmcut())`.
    Lmcut,
    /// Fast Downward's `astar(ipdb())`.
    FdIpdb,
    /// Fast Downward's `astar(lmcut())`.
    FdLmcut,
}

impl Planner {
    /// Every planner, in the report's order.
    pub const ALL: [Planner; 4] = [
        Planner::Ipdb,
        Planner::Lmcut,
        Planner::FdIpdb,
        Planner::FdLmcut,
    ];

    /// demoplan's two planners, the paper's Table 3 (iPDB) first.
    pub const DEMOPLAN: [Planner; 2] = [Planner::Ipdb, Planner::Lmcut];

    /// The name in results and file names: `ipdb`, `lmcut`, `fd-ipdb`, `fd-lmcut`.
    pub fn name(self) -> &'static str {
        match self {
            Planner::Ipdb => "ipdb",
            Planner::Lmcut => "lmcut",
            Planner::FdIpdb => "fd-ipdb",
            Planner::FdLmcut => "fd-lmcut",
        }
    }

    /// The planner of a [`name`](Planner::name).
    pub fn from_name(name: &str) -> Option<Planner> {
        Planner::ALL.into_iter().find(|p| p.name() == name)
    }

    /// The name for people: `lmcut` is `demoplan astar(lmcut())`, `fd-ipdb` is `Fast
    /// Downward astar(ipdb())`.
    pub fn label(self) -> &'static str {
        match self {
            Planner::Ipdb => "demoplan astar(ipdb())",
            Planner::Lmcut => "demoplan astar(lmcut())",
            Planner::FdIpdb => "Fast Downward astar(ipdb())",
            Planner::FdLmcut => "Fast Downward astar(lmcut())",
        }
    }

    /// Whether Fast Downward plans.
    pub fn is_fast_downward(self) -> bool {
        matches!(self, Planner::FdIpdb | Planner::FdLmcut)
    }

    /// The same heuristic with Fast Downward.
    pub fn with_fast_downward(self) -> Planner {
        match self {
            Planner::Ipdb | Planner::FdIpdb => Planner::FdIpdb,
            Planner::Lmcut | Planner::FdLmcut => Planner::FdLmcut,
        }
    }

    /// Whether the heuristic is iPDB, the paper's Table 3 (else LM-cut, Table 4).
    pub fn is_ipdb(self) -> bool {
        matches!(self, Planner::Ipdb | Planner::FdIpdb)
    }

    /// The paper's table of this planner's heuristic: `Table 3` (iPDB) or `Table 4`
    /// (LM-cut).
    pub fn paper_table(self) -> &'static str {
        if self.is_ipdb() {
            "Table 3"
        } else {
            "Table 4"
        }
    }

    /// The paper's slimming ratio for goal 5 with this planner's heuristic
    /// ([`crate::paper::RATIO_IPDB`] or [`crate::paper::RATIO_LMCUT`]).
    pub fn paper_ratio(self) -> f64 {
        if self.is_ipdb() {
            crate::paper::RATIO_IPDB
        } else {
            crate::paper::RATIO_LMCUT
        }
    }
}

impl std::fmt::Display for Planner {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.name())
    }
}

impl From<Planner> for &'static str {
    fn from(planner: Planner) -> &'static str {
        planner.name()
    }
}

impl TryFrom<String> for Planner {
    type Error = String;

    /// A name read back from a results file; an unknown one names the field and the
    /// names it may be.
    fn try_from(name: String) -> Result<Planner, String> {
        Planner::from_name(&name).ok_or_else(|| {
            let names: Vec<&str> = Planner::ALL.iter().map(|p| p.name()).collect();
            format!("planner `{name}` is none of {}", names.join(", "))
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_read_back_and_others_are_refused_by_name() {
        for p in Planner::ALL {
            assert_eq!(Planner::from_name(p.name()), Some(p));
            assert_eq!(Planner::try_from(p.to_string()), Ok(p));
        }
        assert_eq!(Planner::from_name("astar"), None);
        assert_eq!(
            Planner::try_from("blind".to_string()),
            Err("planner `blind` is none of ipdb, lmcut, fd-ipdb, fd-lmcut".to_string())
        );
    }

    #[test]
    fn the_order_is_the_reports() {
        let mut shuffled = [
            Planner::FdLmcut,
            Planner::Lmcut,
            Planner::FdIpdb,
            Planner::Ipdb,
        ];
        shuffled.sort();
        assert_eq!(shuffled, Planner::ALL);
        assert!(Planner::FdIpdb.is_ipdb() && !Planner::Lmcut.is_ipdb());
        assert_eq!(Planner::Lmcut.with_fast_downward(), Planner::FdLmcut);
    }
}
