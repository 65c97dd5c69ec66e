//! Cells: one planning run each, computable from its conditions alone, with a stable id.

use std::time::Duration;

use serde::{Deserialize, Serialize};

/// Who plans, with which heuristic: the report crate's type, the lowest crate that shows
/// planners, re-exported as `experiment::Planner`.
pub use report::Planner;

/// The search string of a planner's run under `time_limit`. The paper ran Fast
/// Downward's `ipdb()`, whose hill climbing has no time limit of its own; demoplan's
/// default gives the climb half of a run's time (see the search crate's ipdb module),
/// so demoplan's iPDB here may climb for the whole run, as Fast Downward's does.
pub fn search_string(planner: Planner, time_limit: Duration) -> String {
    match planner {
        Planner::Ipdb => format!("astar(ipdb(max_time={}))", time_limit.as_secs().max(1)),
        Planner::Lmcut | Planner::FdLmcut => "astar(lmcut())".to_string(),
        Planner::FdIpdb => "astar(ipdb())".to_string(),
    }
}

/// Which domain a cell plans on. Written in results as its [`name`](LevelChoice::name).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize, Deserialize)]
#[serde(try_from = "String", into = "String")]
pub enum LevelChoice {
    /// The domain of this priority level (`learn::levels`).
    Prio(usize),
    /// The full domain: the last level, every operator with effects.
    Full,
    /// The paper's Algorithm 1: priority 1, 2, ... until a plan; its time is the
    /// cumulative time, failed levels included.
    Algorithm1,
}

impl LevelChoice {
    /// `prio-N`, `full` or `alg1`.
    pub fn name(self) -> String {
        match self {
            LevelChoice::Prio(n) => format!("prio-{n}"),
            LevelChoice::Full => "full".to_string(),
            LevelChoice::Algorithm1 => "alg1".to_string(),
        }
    }

    /// The choice of a [`name`](Self::name).
    pub fn from_name(name: &str) -> Option<LevelChoice> {
        match name {
            "full" => Some(LevelChoice::Full),
            "alg1" => Some(LevelChoice::Algorithm1),
            _ => name
                .strip_prefix("prio-")?
                .parse()
                .ok()
                .filter(|n| *n > 0)
                .map(LevelChoice::Prio),
        }
    }
}

impl std::fmt::Display for LevelChoice {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.name())
    }
}

impl From<LevelChoice> for String {
    fn from(level: LevelChoice) -> String {
        level.name()
    }
}

impl TryFrom<String> for LevelChoice {
    type Error = String;

    /// A name read back from a results file; an unknown one names the field and the
    /// names it may be.
    fn try_from(name: String) -> Result<LevelChoice, String> {
        LevelChoice::from_name(&name)
            .ok_or_else(|| format!("level `{name}` is none of prio-N (N >= 1), full, alg1"))
    }
}

/// What decides a cell's library and problem: the simulated study, how it is learned,
/// and the scene and goal. Cubes on the table = `height * towers + distractors`.
#[derive(Debug, Clone, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize, Deserialize)]
pub struct Conditions {
    /// The simulator's seed.
    pub seed: u64,
    /// Simulated participants.
    pub participants: u32,
    /// Demonstrations per participant.
    pub per_participant: u32,
    /// `default`, or a hash of the simulator's parameters (see [`params_key`]).
    pub params: String,
    /// Hands in the problem's scene (1 or 2).
    pub hands: usize,
    /// Cubes per tower of the goal.
    pub height: usize,
    /// Towers of the goal, built side by side from distinct cubes.
    pub towers: usize,
    /// Cubes on the table that no tower uses.
    pub distractors: usize,
    /// How segments become activities: `settled` or `runs` ([`learn::Grouping`]).
    pub activities: String,
    /// Whether operators that change nothing stay in the domains.
    pub keep_without_effects: bool,
    /// Whether the library's operators are generalised ([`learn::OperatorForm`]).
    /// Absent from records written before it existed, and written only when true.
    #[serde(default, skip_serializing_if = "std::ops::Not::not")]
    pub generalised: bool,
}

impl Conditions {
    /// The paper's setting for its goal `goal` (1 to 5): the default study (3 x 4,
    /// `seed`), a tower of `goal + 1` cubes from 6 on the table, `hands` hands.
    pub fn paper_goal(seed: u64, goal: usize, hands: usize) -> Conditions {
        let height = goal + 1;
        Conditions {
            seed,
            participants: simulate::DEFAULT_PARTICIPANTS,
            per_participant: simulate::DEFAULT_PER_PARTICIPANT,
            params: DEFAULT_PARAMS.to_string(),
            hands,
            height,
            towers: 1,
            distractors: learn::DEFAULT_CUBES.saturating_sub(height),
            activities: learn::Grouping::Settled.name().to_string(),
            keep_without_effects: false,
            generalised: false,
        }
    }

    /// Cubes on the table.
    pub fn cubes(&self) -> usize {
        self.height * self.towers + self.distractors
    }

    /// The text the id hashes: every condition, named, in a fixed order. `generalised`
    /// is named only when true, so that the ids of cells from before it stay.
    pub fn canonical(&self) -> String {
        let generalised = if self.generalised {
            ";generalised=true"
        } else {
            ""
        };
        format!(
            "seed={};participants={};per_participant={};params={};hands={};height={};\
             towers={};distractors={};activities={};keep_without_effects={}{}",
            self.seed,
            self.participants,
            self.per_participant,
            self.params,
            self.hands,
            self.height,
            self.towers,
            self.distractors,
            self.activities,
            self.keep_without_effects,
            generalised
        )
    }

    /// The conditions that decide the library (not the scene).
    pub(crate) fn library_key(&self) -> String {
        format!(
            "{};{};{};{};{};{}",
            self.seed,
            self.participants,
            self.per_participant,
            self.params,
            self.activities,
            self.generalised
        )
    }

    /// The same conditions without the seed: what a distribution over seeds is of.
    pub fn without_seed(&self) -> Conditions {
        Conditions {
            seed: 0,
            ..self.clone()
        }
    }
}

/// [`Conditions::params`] of the simulator's default parameters.
pub const DEFAULT_PARAMS: &str = "default";

/// [`Conditions::params`] for a parameter set: `default` for the defaults, a style's
/// name (`two-handed`) for that style's parameters ([`simulate::Style::params`]), else
/// `params-` and the FNV-1a hash of their JSON (which names the style when it is not the
/// paper's).
pub fn params_key(params: &simulate::SimParams) -> String {
    if *params == simulate::SimParams::default() {
        return DEFAULT_PARAMS.to_string();
    }
    if *params == params.style.params() {
        return params.style.name().to_string();
    }
    format!(
        "params-{:016x}",
        learn::stable_hash(params.to_json().to_string().as_bytes())
    )
}

/// One planning run: conditions, level, planner, limit and repeat. Everything a run
/// needs is here (and in the simulator parameters its `params` names), so a cell can be
/// computed alone: in this process, in a child process given its id, or on a cluster.
#[derive(Debug, Clone, PartialEq, Eq, Hash)]
pub struct Cell {
    pub conditions: Conditions,
    pub level: LevelChoice,
    pub planner: Planner,
    pub time_limit: Duration,
    /// 0 for the first run of a repeated cell, 1 for the second, ...
    pub repeat: u32,
}

impl Cell {
    /// The text the id hashes.
    pub fn canonical(&self) -> String {
        format!(
            "{};level={};planner={};time_limit_ms={};repeat={}",
            self.conditions.canonical(),
            self.level.name(),
            self.planner.name(),
            self.time_limit.as_millis(),
            self.repeat
        )
    }

    /// The stable id: FNV-1a (`learn::stable_hash`) of [`canonical`](Self::canonical),
    /// 16 hex digits. The same on every machine and in every version that keeps the
    /// canonical text.
    pub fn id(&self) -> String {
        format!("{:016x}", learn::stable_hash(self.canonical().as_bytes()))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn cell() -> Cell {
        Cell {
            conditions: Conditions::paper_goal(7, 5, 1),
            level: LevelChoice::Full,
            planner: Planner::Lmcut,
            time_limit: Duration::from_secs(60),
            repeat: 0,
        }
    }

    #[test]
    fn a_cell_id_is_stable() {
        // Pinned on purpose: results written by one version are found by the next. If
        // this changes, every study's results are run again.
        assert_eq!(
            cell().canonical(),
            "seed=7;participants=3;per_participant=4;params=default;hands=1;height=6;\
             towers=1;distractors=0;activities=settled;keep_without_effects=false;\
             level=full;planner=lmcut;time_limit_ms=60000;repeat=0"
        );
        assert_eq!(cell().id(), cell().id());
        assert_eq!(cell().id().len(), 16);
        assert_eq!(
            cell().id(),
            format!("{:016x}", learn::stable_hash(cell().canonical().as_bytes()))
        );
    }

    #[test]
    fn a_cell_id_differs_when_any_condition_differs() {
        let base = cell();
        let mut variants = Vec::new();
        let with = |f: &dyn Fn(&mut Cell)| {
            let mut c = cell();
            f(&mut c);
            c
        };
        variants.push(with(&|c| c.conditions.seed = 8));
        variants.push(with(&|c| c.conditions.participants = 4));
        variants.push(with(&|c| c.conditions.per_participant = 5));
        variants.push(with(&|c| c.conditions.params = "params-1".into()));
        variants.push(with(&|c| c.conditions.hands = 2));
        variants.push(with(&|c| c.conditions.height = 5));
        variants.push(with(&|c| c.conditions.towers = 2));
        variants.push(with(&|c| c.conditions.distractors = 1));
        variants.push(with(&|c| c.conditions.activities = "runs".into()));
        variants.push(with(&|c| c.conditions.keep_without_effects = true));
        variants.push(with(&|c| c.conditions.generalised = true));
        variants.push(with(&|c| c.level = LevelChoice::Prio(1)));
        variants.push(with(&|c| c.level = LevelChoice::Algorithm1));
        variants.push(with(&|c| c.planner = Planner::Ipdb));
        variants.push(with(&|c| c.planner = Planner::FdLmcut));
        variants.push(with(&|c| c.time_limit = Duration::from_secs(20)));
        variants.push(with(&|c| c.repeat = 1));
        let mut ids: Vec<String> = variants.iter().map(Cell::id).collect();
        ids.push(base.id());
        let n = ids.len();
        ids.sort();
        ids.dedup();
        assert_eq!(ids.len(), n, "two different cells share an id");
    }

    #[test]
    fn names_read_back() {
        for l in [
            LevelChoice::Prio(3),
            LevelChoice::Full,
            LevelChoice::Algorithm1,
        ] {
            assert_eq!(LevelChoice::from_name(&l.name()), Some(l));
        }
        assert_eq!(LevelChoice::from_name("prio-0"), None);
    }

    #[test]
    fn paper_goals_keep_six_cubes() {
        for goal in 1..=5 {
            let c = Conditions::paper_goal(7, goal, 1);
            assert_eq!(c.cubes(), 6);
            assert_eq!(c.height, goal + 1);
        }
        assert_eq!(params_key(&simulate::SimParams::default()), "default");
    }

    #[test]
    fn a_style_is_its_own_params_key_and_a_changed_one_a_hash() {
        let two = simulate::Style::TwoHanded.params();
        assert_eq!(params_key(&two), "two-handed");
        let changed = simulate::SimParams { cubes: 4, ..two };
        assert!(params_key(&changed).starts_with("params-"));
        let paper_changed = simulate::SimParams {
            cubes: 4,
            ..simulate::SimParams::default()
        };
        assert_ne!(params_key(&changed), params_key(&paper_changed));
    }
}
