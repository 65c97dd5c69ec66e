//! Fast Downward-style search strings: `astar(blind())`, `astar(hmax())`,
//! `astar(ipdb(max_time=30))`.
//!
//! A string is first read as a generic term, `name(arg, key=value, ...)`, where a value is
//! a term, a bare word (a number such as `10`, `1.5`, `2M` or `infinity`, or a name) or a
//! list `[a, b]`; then the term is interpreted. Adding a heuristic is one match arm in
//! [`HeuristicConfig`]'s interpretation.

use std::fmt;
use std::time::Duration;

use task::{Limit, Task};

use crate::astar::{SearchError, SearchLimits};
use crate::cpdbs::{systematic_patterns, CanonicalPdbs};
use crate::heuristic::{Blind, Heuristic};
use crate::hmax::HMax;
use crate::ipdb::{hill_climbing, ipdb, IpdbConfig};
use crate::lmcut::LmCut;
use crate::pdb::build_collection_within;
use crate::pruning::{
    AtomSelectionStrategy, LimitedPruningConfig, PruningConfig, Ratio, StubbornSetsConfig,
};
use crate::scp::{PatternGenerator, Scp, ScpConfig, SysScpConfig};

/// The search engines demoplan runs.
pub const SEARCH_ENGINES: &[&str] = &["astar"];

/// A heuristic demoplan computes, by its name in search strings: the one type of the
/// concept (a [`HeuristicConfig`] adds its settings, [`HeuristicConfig::kind`]).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum HeuristicName {
    /// `blind()`.
    Blind,
    /// `hmax()`.
    HMax,
    /// `lmcut()`.
    LmCut,
    /// `pdb()`.
    Pdb,
    /// `ipdb()`.
    Ipdb,
    /// `cpdbs()`.
    Cpdbs,
    /// `scp()`.
    Scp,
    /// `scp_online()`.
    ScpOnline,
}

impl HeuristicName {
    /// Every heuristic, in the order error messages list them.
    pub const ALL: [HeuristicName; 8] = [
        HeuristicName::Blind,
        HeuristicName::HMax,
        HeuristicName::LmCut,
        HeuristicName::Pdb,
        HeuristicName::Ipdb,
        HeuristicName::Cpdbs,
        HeuristicName::Scp,
        HeuristicName::ScpOnline,
    ];

    /// Its name in search strings: `blind`, `hmax`, `lmcut`, `pdb`, `ipdb`, `cpdbs`,
    /// `scp`, `scp_online`.
    pub fn name(self) -> &'static str {
        match self {
            HeuristicName::Blind => "blind",
            HeuristicName::HMax => "hmax",
            HeuristicName::LmCut => "lmcut",
            HeuristicName::Pdb => "pdb",
            HeuristicName::Ipdb => "ipdb",
            HeuristicName::Cpdbs => "cpdbs",
            HeuristicName::Scp => "scp",
            HeuristicName::ScpOnline => "scp_online",
        }
    }

    /// The heuristic of a name in a search string, if there is one.
    pub fn from_name(name: &str) -> Option<HeuristicName> {
        HeuristicName::ALL.into_iter().find(|h| h.name() == name)
    }
}

/// A parsed search string.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct SearchConfig {
    /// The search engine.
    pub engine: Engine,
    /// The heuristic it is guided by.
    pub heuristic: HeuristicConfig,
    /// Partial-order reduction (`pruning=...`; default `null()`, none).
    pub pruning: PruningConfig,
}

/// A search engine.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Engine {
    /// Optimal eager A* with reopening ([`crate::astar`]).
    AStar,
}

/// A heuristic, as the search string names it.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum HeuristicConfig {
    /// [`Blind`].
    Blind,
    /// [`HMax`].
    HMax,
    /// [`LmCut`].
    LmCut,
    /// One [`PatternDatabase`](crate::PatternDatabase): `pdb(pattern=[0, 1])` (variable
    /// indices of the task).
    Pdb {
        /// The pattern as given.
        pattern: Vec<u32>,
    },
    /// The canonical heuristic over the hill climbing's collection ([`ipdb`]).
    Ipdb(IpdbConfig),
    /// The canonical heuristic ([`CanonicalPdbs`]) over a pattern collection:
    /// `cpdbs(patterns=systematic(2))`.
    Cpdbs {
        /// Where the patterns come from.
        patterns: PatternCollectionConfig,
        /// Time limit of the dominance pruning of cliques (`None`: unlimited; zero: no
        /// pruning).
        max_time_dominance_pruning: Option<Duration>,
    },
    /// Saturated cost partitioning over projections ([`Scp`]): `scp([projections(
    /// sys_scp())], orders=greedy_orders())`, or `scp_online(...)` when
    /// `online_interval` is set.
    Scp(ScpConfig),
}

/// A pattern collection generator of `cpdbs(patterns=...)`.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum PatternCollectionConfig {
    /// `manual_patterns([[0, 1], [2]])` (or just the list): these patterns.
    Manual(Vec<Vec<u32>>),
    /// `systematic(n)`: every interesting pattern of at most `n` variables (`n` is 1 or
    /// 2; Pommerening, Röger and Helmert, IJCAI 2013): of one variable the goal
    /// variables, of two a goal variable with one of its causal-graph predecessors.
    Systematic(u32),
    /// `hillclimbing(...)`, with the options of `ipdb()` (whose
    /// `max_time_dominance_pruning` is ignored here: `cpdbs`' own option counts).
    HillClimbing(IpdbConfig),
}

impl HeuristicConfig {
    /// Which heuristic it configures.
    pub fn kind(&self) -> HeuristicName {
        match self {
            HeuristicConfig::Blind => HeuristicName::Blind,
            HeuristicConfig::HMax => HeuristicName::HMax,
            HeuristicConfig::LmCut => HeuristicName::LmCut,
            HeuristicConfig::Pdb { .. } => HeuristicName::Pdb,
            HeuristicConfig::Ipdb(_) => HeuristicName::Ipdb,
            HeuristicConfig::Cpdbs { .. } => HeuristicName::Cpdbs,
            HeuristicConfig::Scp(c) if c.online_interval.is_some() => HeuristicName::ScpOnline,
            HeuristicConfig::Scp(_) => HeuristicName::Scp,
        }
    }

    /// Its name in search strings.
    pub fn name(&self) -> &'static str {
        self.kind().name()
    }

    /// The heuristic for `task` under `limits`; fails if the task is invalid or a pattern
    /// does not fit it.
    ///
    /// The limits hold during construction: `pdb()` and `cpdbs()` with a collection the
    /// user fixed (manual or systematic patterns) give [`Built::Stopped`] with
    /// [`Limit::Memory`] before any database is allocated when building them would take
    /// memory use beyond `limits.memory_limit_bytes` (by [`crate::construction_bytes`]),
    /// and with [`Limit::Time`] when the deadline passes between databases. The hill
    /// climbing of `ipdb()` and `cpdbs(hillclimbing())` stops at the limits instead,
    /// rejecting a candidate whose database does not fit, and keeps the collection found
    /// so far; the clique enumeration and dominance pruning after it stop at the
    /// deadline, keeping the cliques found (any set of additive cliques is admissible).
    /// `scp()` and `scp_online()` stop each phase (patterns, projections, orders) at the
    /// limits likewise and keep what they have.
    /// Then the search reports a limit that has passed at its first check.
    pub fn build_with_limits(
        &self,
        task: &Task,
        limits: &SearchLimits,
    ) -> Result<Built, SearchError> {
        let fixed = |patterns: &[Vec<u32>]| build_collection_within(task, patterns, limits);
        Ok(Built::Heuristic(match self {
            HeuristicConfig::Blind => Box::new(Blind::new(task)),
            HeuristicConfig::HMax => Box::new(HMax::new(task)?),
            HeuristicConfig::LmCut => Box::new(LmCut::new(task)?),
            HeuristicConfig::Pdb { pattern } => match fixed(std::slice::from_ref(pattern))? {
                Ok(pdbs) => Box::new(CanonicalPdbs::new(task, pdbs, None, "pdb")),
                Err(limit) => return Ok(Built::Stopped(limit)),
            },
            HeuristicConfig::Ipdb(config) => Box::new(ipdb(task, config, limits)?),
            HeuristicConfig::Scp(config) => Box::new(Scp::new(task, config, limits)?),
            HeuristicConfig::Cpdbs {
                patterns,
                max_time_dominance_pruning,
            } => {
                let start = std::time::Instant::now();
                let pruning = match max_time_dominance_pruning {
                    Some(t) if t.is_zero() => None,
                    Some(t) => Some(*t),
                    None => Some(Duration::MAX),
                };
                let collection = match patterns {
                    PatternCollectionConfig::Manual(patterns) => {
                        fixed(patterns)?.map(|p| (p, None))
                    }
                    PatternCollectionConfig::Systematic(size) => {
                        task.validate()?;
                        fixed(&systematic_patterns(task, *size as usize))?.map(|p| (p, None))
                    }
                    PatternCollectionConfig::HillClimbing(config) => {
                        task.validate()?;
                        let (pdbs, climb) = hill_climbing(task, config, limits);
                        Ok((pdbs, Some(climb)))
                    }
                };
                let (pdbs, climb) = match collection {
                    Ok(built) => built,
                    Err(limit) => return Ok(Built::Stopped(limit)),
                };
                let mut h = CanonicalPdbs::within(task, pdbs, pruning, "cpdbs", limits.clock());
                let statistics = h.statistics_mut();
                statistics.hill_climbing = climb;
                statistics.total_time = start.elapsed();
                Box::new(h)
            }
        }))
    }
}

/// A heuristic built under limits ([`HeuristicConfig::build_with_limits`]), or the limit
/// that stopped its construction before it was complete.
pub enum Built {
    /// The heuristic, ready for the search.
    Heuristic(Box<dyn Heuristic>),
    /// Construction stopped at this limit; nothing is left to search with.
    Stopped(Limit),
}

impl Built {
    /// The heuristic, or `None` if construction stopped at a limit.
    pub fn into_heuristic(self) -> Option<Box<dyn Heuristic>> {
        match self {
            Built::Heuristic(h) => Some(h),
            Built::Stopped(_) => None,
        }
    }
}

impl fmt::Debug for Built {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Built::Heuristic(h) => write!(f, "Heuristic({})", h.name()),
            Built::Stopped(limit) => write!(f, "Stopped({limit:?})"),
        }
    }
}

impl fmt::Display for SearchConfig {
    /// The canonical search string: `astar(hmax())`, `astar(ipdb(max_time=30))`.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self.engine {
            Engine::AStar => write!(f, "astar({}", self.heuristic)?,
        }
        if self.pruning != PruningConfig::Null {
            write!(f, ", pruning={}", self.pruning)?;
        }
        write!(f, ")")
    }
}

impl fmt::Display for HeuristicConfig {
    /// The canonical form: `hmax()`, `pdb(pattern=[0, 1])`, `ipdb(max_time=30)` (options
    /// at their defaults left out).
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            HeuristicConfig::Pdb { pattern } => write!(f, "pdb(pattern={})", List(pattern)),
            HeuristicConfig::Ipdb(config) => {
                write!(f, "ipdb(")?;
                write_ipdb_options(f, config, true)?;
                write!(f, ")")
            }
            HeuristicConfig::Cpdbs {
                patterns,
                max_time_dominance_pruning,
            } => {
                write!(f, "cpdbs(patterns=")?;
                match patterns {
                    PatternCollectionConfig::Manual(patterns) => {
                        write!(f, "manual_patterns([")?;
                        for (i, p) in patterns.iter().enumerate() {
                            let comma = if i > 0 { ", " } else { "" };
                            write!(f, "{comma}{}", List(p))?;
                        }
                        write!(f, "])")?;
                    }
                    PatternCollectionConfig::Systematic(size) => write!(f, "systematic({size})")?,
                    PatternCollectionConfig::HillClimbing(config) => {
                        write!(f, "hillclimbing(")?;
                        write_ipdb_options(f, config, false)?;
                        write!(f, ")")?;
                    }
                }
                if let Some(t) = max_time_dominance_pruning {
                    write!(f, ", max_time_dominance_pruning={}", t.as_secs_f64())?;
                }
                write!(f, ")")
            }
            HeuristicConfig::Scp(config) => write_scp(f, config),
            other => write!(f, "{}()", other.name()),
        }
    }
}

impl fmt::Display for PruningConfig {
    /// The canonical form: `atom_centric_stubborn_sets()`,
    /// `limited_pruning(pruning=atom_centric_stubborn_sets())` (options at their defaults
    /// left out).
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            PruningConfig::Null => write!(f, "null()"),
            PruningConfig::AtomCentricStubbornSets(config) => {
                let default = StubbornSetsConfig::default();
                let mut options = Vec::new();
                if config.use_sibling_shortcut != default.use_sibling_shortcut {
                    options.push(format!(
                        "use_sibling_shortcut={}",
                        config.use_sibling_shortcut
                    ));
                }
                if config.atom_selection_strategy != default.atom_selection_strategy {
                    options.push(format!(
                        "atom_selection_strategy={}",
                        config.atom_selection_strategy.name()
                    ));
                }
                write!(f, "atom_centric_stubborn_sets({})", options.join(", "))
            }
            PruningConfig::Limited(config) => {
                let default = LimitedPruningConfig::new(PruningConfig::Null);
                write!(f, "limited_pruning(pruning={}", config.pruning)?;
                if config.min_required_pruning_ratio != default.min_required_pruning_ratio {
                    write!(
                        f,
                        ", min_required_pruning_ratio={}",
                        config.min_required_pruning_ratio.0
                    )?;
                }
                let n = config.expansions_before_checking_pruning_ratio;
                if n != default.expansions_before_checking_pruning_ratio {
                    let n = if n == u64::MAX {
                        "infinity".to_string()
                    } else {
                        n.to_string()
                    };
                    write!(f, ", expansions_before_checking_pruning_ratio={n}")?;
                }
                write!(f, ")")
            }
        }
    }
}

/// `[0, 1]`.
struct List<'a>(&'a [u32]);

impl fmt::Display for List<'_> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "[")?;
        for (i, v) in self.0.iter().enumerate() {
            let comma = if i > 0 { ", " } else { "" };
            write!(f, "{comma}{v}")?;
        }
        write!(f, "]")
    }
}

/// The options of `config` that differ from the defaults, as `key=value, ...`.
fn write_ipdb_options(
    f: &mut fmt::Formatter<'_>,
    config: &IpdbConfig,
    with_pruning: bool,
) -> fmt::Result {
    let default = IpdbConfig::default();
    let mut options: Vec<String> = Vec::new();
    let int = |v: u64| {
        if v == u64::MAX {
            "infinity".to_string()
        } else {
            v.to_string()
        }
    };
    let seconds =
        |t: Option<Duration>| t.map_or("infinity".to_string(), |t| t.as_secs_f64().to_string());
    if config.pdb_max_size != default.pdb_max_size {
        options.push(format!("pdb_max_size={}", int(config.pdb_max_size)));
    }
    if config.collection_max_size != default.collection_max_size {
        options.push(format!(
            "collection_max_size={}",
            int(config.collection_max_size)
        ));
    }
    if config.num_samples != default.num_samples {
        options.push(format!("num_samples={}", config.num_samples));
    }
    if config.min_improvement != default.min_improvement {
        options.push(format!("min_improvement={}", config.min_improvement));
    }
    if config.max_time != default.max_time {
        options.push(format!("max_time={}", seconds(config.max_time)));
    }
    if config.random_seed != default.random_seed {
        options.push(format!("random_seed={}", config.random_seed));
    }
    if config.max_generated_patterns != default.max_generated_patterns {
        options.push(format!(
            "max_generated_patterns={}",
            int(config.max_generated_patterns.unwrap_or(u64::MAX))
        ));
    }
    if with_pruning && config.max_time_dominance_pruning != default.max_time_dominance_pruning {
        options.push(format!(
            "max_time_dominance_pruning={}",
            seconds(config.max_time_dominance_pruning)
        ));
    }
    write!(f, "{}", options.join(", "))
}

/// What is wrong with a search string. Every message ends with the known search engines
/// and heuristics.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum ConfigError {
    /// The string is not a well-formed term.
    #[error(
        "syntax error at byte {position} of the search string: {message}\n{}",
        known()
    )]
    Syntax {
        /// Byte offset of the problem.
        position: usize,
        /// What was expected.
        message: String,
    },
    /// The outermost name is not a search engine.
    #[error("unknown search engine `{name}`\n{}", known())]
    UnknownEngine {
        /// The name given.
        name: String,
    },
    /// A heuristic name demoplan does not know.
    #[error("unknown heuristic `{name}`\n{}", known())]
    UnknownHeuristic {
        /// The name given.
        name: String,
    },
    /// A required argument is missing.
    #[error("`{function}` needs the argument `{argument}`\n{}", known())]
    MissingArgument {
        /// The search engine or heuristic.
        function: String,
        /// The argument.
        argument: String,
    },
    /// An argument the function does not take, or takes once.
    #[error("`{function}` does not take the argument {argument}\n{}", known())]
    UnexpectedArgument {
        /// The search engine or heuristic.
        function: String,
        /// The argument as written: `pruning=...` or `the 2nd positional argument`.
        argument: String,
    },
    /// An argument of the wrong kind, e.g. a number where a heuristic belongs.
    #[error("`{function}`: {message}\n{}", known())]
    InvalidArgument {
        /// The search engine or heuristic.
        function: String,
        /// What is wrong.
        message: String,
    },
}

/// The list of known names that ends every error message.
fn known() -> String {
    format!(
        "known search engines: {}\nknown heuristics: {}",
        SEARCH_ENGINES.join(", "),
        HeuristicName::ALL.map(HeuristicName::name).join(", "),
    )
}

/// Parses a Fast Downward-style search string such as `astar(hmax())`. Whitespace
/// between tokens is ignored. O(length).
pub fn parse_search(s: &str) -> Result<SearchConfig, ConfigError> {
    let term = Parser::new(s).parse()?;
    interpret_search(&term)
}

fn interpret_search(term: &Term) -> Result<SearchConfig, ConfigError> {
    match term.name.as_str() {
        "astar" => {
            // `pruning` only by keyword: Fast Downward's second positional parameter is
            // another (`lazy_evaluator`).
            if let Some(i) = term.args.iter().skip(1).position(|a| a.key.is_none()) {
                return Err(ConfigError::UnexpectedArgument {
                    function: term.name.clone(),
                    argument: format!("number {} (positional)", i + 2),
                });
            }
            let mut args = Args::new(term, &["eval", "pruning"])?;
            let eval = args
                .take("eval")?
                .ok_or_else(|| ConfigError::MissingArgument {
                    function: term.name.clone(),
                    argument: "eval".into(),
                })?;
            let pruning = args.take("pruning")?;
            args.finish()?;
            let heuristic = interpret_heuristic(eval)?;
            let pruning = match pruning {
                Some(value) => interpret_pruning(value, 0)?,
                None => PruningConfig::Null,
            };
            Ok(SearchConfig {
                engine: Engine::AStar,
                heuristic,
                pruning,
            })
        }
        _ => Err(ConfigError::UnknownEngine {
            name: term.name.clone(),
        }),
    }
}

fn interpret_heuristic(value: &Value) -> Result<HeuristicConfig, ConfigError> {
    let term = match value {
        Value::Term(term) => term,
        Value::List(_) => {
            return Err(ConfigError::InvalidArgument {
                function: "astar".into(),
                message: "a list is not a heuristic".into(),
            })
        }
    };
    let name = term.name.as_str();
    let Some(kind) = HeuristicName::from_name(name) else {
        if SEARCH_ENGINES.contains(&name) {
            return Err(ConfigError::InvalidArgument {
                function: "astar".into(),
                message: format!("`{name}` is a search engine, not a heuristic"),
            });
        }
        return Err(ConfigError::UnknownHeuristic {
            name: name.to_string(),
        });
    };
    let heuristic = match kind {
        HeuristicName::Blind => HeuristicConfig::Blind,
        HeuristicName::HMax => HeuristicConfig::HMax,
        HeuristicName::LmCut => HeuristicConfig::LmCut,
        HeuristicName::Pdb => return interpret_pdb(term),
        HeuristicName::Ipdb => return Ok(HeuristicConfig::Ipdb(interpret_ipdb(term, true)?)),
        HeuristicName::Cpdbs => return interpret_cpdbs(term),
        HeuristicName::Scp | HeuristicName::ScpOnline => {
            return Ok(HeuristicConfig::Scp(interpret_scp(term)?))
        }
    };
    Args::new(term, &[])?.finish()?;
    Ok(heuristic)
}

/// The pruning methods of `pruning=...`.
const PRUNING_METHODS: &str = "null, atom_centric_stubborn_sets, limited_pruning";

/// `null()`, `atom_centric_stubborn_sets(...)` or `limited_pruning(...)`.
fn interpret_pruning(value: &Value, depth: usize) -> Result<PruningConfig, ConfigError> {
    let Value::Term(term) = value else {
        return Err(invalid(
            "astar",
            &format!("`pruning` must be a pruning method, not a list (known: {PRUNING_METHODS})"),
        ));
    };
    let function = term.name.as_str();
    match function {
        "null" => {
            Args::new(term, &[])?.finish()?;
            Ok(PruningConfig::Null)
        }
        "atom_centric_stubborn_sets" => {
            let mut args = Args::new(term, &["use_sibling_shortcut", "atom_selection_strategy"])?;
            let mut config = StubbornSetsConfig::default();
            if let Some(v) = args.take("use_sibling_shortcut")? {
                config.use_sibling_shortcut = match word(v) {
                    Some("true") => true,
                    Some("false") => false,
                    _ => {
                        return Err(invalid(
                            function,
                            &format!(
                                "`use_sibling_shortcut` must be true or false, not {}",
                                shown(v)
                            ),
                        ))
                    }
                };
            }
            if let Some(v) = args.take("atom_selection_strategy")? {
                config.atom_selection_strategy = word(v)
                    .and_then(AtomSelectionStrategy::from_name)
                    .ok_or_else(|| {
                        let known = AtomSelectionStrategy::ALL.map(AtomSelectionStrategy::name);
                        invalid(
                            function,
                            &format!(
                                "`atom_selection_strategy` must be one of {}, not {}",
                                known.join(", "),
                                shown(v)
                            ),
                        )
                    })?;
            }
            args.finish()?;
            Ok(PruningConfig::AtomCentricStubbornSets(config))
        }
        "limited_pruning" => {
            if depth >= 4 {
                return Err(invalid(function, "`pruning` is nested too deeply"));
            }
            let mut args = Args::new(
                term,
                &[
                    "pruning",
                    "min_required_pruning_ratio",
                    "expansions_before_checking_pruning_ratio",
                ],
            )?;
            let inner = args
                .take("pruning")?
                .ok_or_else(|| ConfigError::MissingArgument {
                    function: function.into(),
                    argument: "pruning".into(),
                })?;
            let mut config = LimitedPruningConfig::new(interpret_pruning(inner, depth + 1)?);
            if let Some(v) = args.take("min_required_pruning_ratio")? {
                let ratio = word(v)
                    .and_then(|w| w.parse::<f64>().ok())
                    .filter(|r| (0.0..=1.0).contains(r))
                    .ok_or_else(|| {
                        invalid(
                            function,
                            &format!(
                                "`min_required_pruning_ratio` must be a number from 0 to 1, not {}",
                                shown(v)
                            ),
                        )
                    })?;
                config.min_required_pruning_ratio = Ratio(ratio);
            }
            if let Some(v) = args.take("expansions_before_checking_pruning_ratio")? {
                config.expansions_before_checking_pruning_ratio = integer(function, v, true)
                    .map_err(|_| {
                        invalid(
                            function,
                            &format!(
                                "`expansions_before_checking_pruning_ratio` must be a non-negative integer or infinity, not {}",
                                shown(v)
                            ),
                        )
                    })?;
            }
            args.finish()?;
            Ok(PruningConfig::Limited(config))
        }
        name => Err(invalid(
            "astar",
            &format!("unknown pruning method `{name}` (known: {PRUNING_METHODS})"),
        )),
    }
}

/// A value as an error message quotes it: `` `foo` `` for a word, else its kind.
fn shown(value: &Value) -> String {
    match (word(value), value) {
        (Some(w), _) => format!("`{w}`"),
        (None, Value::List(_)) => "a list".into(),
        (None, Value::Term(t)) => format!("`{}(...)`", t.name),
    }
}

/// `pdb(pattern=[0, 1])` or `pdb(pattern=manual_pattern([0, 1]))`.
fn interpret_pdb(term: &Term) -> Result<HeuristicConfig, ConfigError> {
    let mut args = Args::new(term, &["pattern"])?;
    let value = args
        .take("pattern")?
        .ok_or_else(|| ConfigError::MissingArgument {
            function: "pdb".into(),
            argument: "pattern".into(),
        })?;
    args.finish()?;
    let list = match value {
        Value::Term(t) if t.name == "manual_pattern" => {
            let mut args = Args::new(t, &["pattern"])?;
            let list = args
                .take("pattern")?
                .ok_or_else(|| ConfigError::MissingArgument {
                    function: "manual_pattern".into(),
                    argument: "pattern".into(),
                })?;
            args.finish()?;
            list
        }
        Value::Term(t) if t.args.is_empty() && !t.name.starts_with(|c: char| c.is_alphabetic()) => {
            return Err(invalid("pdb", "`pattern` must be a list of variables such as [0, 1]"))
        }
        Value::Term(t) => {
            return Err(ConfigError::InvalidArgument {
                function: "pdb".into(),
                message: format!("the pattern generator `{}` is not supported; give a list of variables such as [0, 1]", t.name),
            })
        }
        list => list,
    };
    Ok(HeuristicConfig::Pdb {
        pattern: variables("pdb", list)?,
    })
}

/// The options of `ipdb(...)` (with `max_time_dominance_pruning`) or `hillclimbing(...)`.
fn interpret_ipdb(term: &Term, with_pruning: bool) -> Result<IpdbConfig, ConfigError> {
    const PARAMS: &[&str] = &[
        "pdb_max_size",
        "collection_max_size",
        "num_samples",
        "min_improvement",
        "max_time",
        "random_seed",
        "max_generated_patterns",
        "max_time_dominance_pruning",
    ];
    let params = if with_pruning {
        PARAMS
    } else {
        &PARAMS[..PARAMS.len() - 1]
    };
    let function = term.name.as_str();
    let mut args = Args::new(term, params)?;
    let mut config = IpdbConfig::default();
    if let Some(v) = args.take("pdb_max_size")? {
        config.pdb_max_size = positive(function, "pdb_max_size", integer(function, v, true)?)?;
    }
    if let Some(v) = args.take("collection_max_size")? {
        config.collection_max_size =
            positive(function, "collection_max_size", integer(function, v, true)?)?;
    }
    if let Some(v) = args.take("num_samples")? {
        let n = positive(function, "num_samples", integer(function, v, false)?)?;
        config.num_samples =
            u32::try_from(n).map_err(|_| invalid(function, "`num_samples` is too large"))?;
    }
    if let Some(v) = args.take("min_improvement")? {
        let n = positive(function, "min_improvement", integer(function, v, false)?)?;
        config.min_improvement =
            u32::try_from(n).map_err(|_| invalid(function, "`min_improvement` is too large"))?;
    }
    if let Some(v) = args.take("max_time")? {
        config.max_time = seconds(function, v)?;
    }
    if let Some(v) = args.take("random_seed")? {
        // Fast Downward's bounds: -1 (its global generator, seeded 2011) or an int.
        config.random_seed = seed(function, v)?;
    }
    if let Some(v) = args.take("max_generated_patterns")? {
        config.max_generated_patterns = match integer(function, v, true)? {
            u64::MAX => None,
            n => Some(n),
        };
    }
    if with_pruning {
        if let Some(v) = args.take("max_time_dominance_pruning")? {
            config.max_time_dominance_pruning = seconds(function, v)?;
        }
    }
    args.finish()?;
    Ok(config)
}

/// `cpdbs(patterns=..., max_time_dominance_pruning=...)`.
fn interpret_cpdbs(term: &Term) -> Result<HeuristicConfig, ConfigError> {
    let mut args = Args::new(term, &["patterns", "max_time_dominance_pruning"])?;
    let patterns = args.take("patterns")?;
    let pruning = args.take("max_time_dominance_pruning")?;
    args.finish()?;
    let patterns = match patterns {
        // Fast Downward's default: systematic(1).
        None => PatternCollectionConfig::Systematic(1),
        Some(Value::List(items)) => PatternCollectionConfig::Manual(
            items
                .iter()
                .map(|p| variables("cpdbs", p))
                .collect::<Result<_, _>>()?,
        ),
        Some(Value::Term(t)) => match t.name.as_str() {
            "manual_patterns" => PatternCollectionConfig::Manual(manual_patterns(t)?),
            "systematic" => {
                let size = systematic_size(t)?;
                if !(1..=2).contains(&size) {
                    return Err(invalid(
                        "systematic",
                        "`pattern_max_size` must be 1 or 2 (larger sizes are not supported)",
                    ));
                }
                PatternCollectionConfig::Systematic(size as u32)
            }
            "hillclimbing" => PatternCollectionConfig::HillClimbing(interpret_ipdb(t, false)?),
            name => {
                return Err(ConfigError::InvalidArgument {
                    function: "cpdbs".into(),
                    message: format!(
                        "unknown pattern collection generator `{name}` (known: manual_patterns, systematic, hillclimbing)"
                    ),
                })
            }
        },
    };
    let max_time_dominance_pruning = match pruning {
        Some(v) => seconds("cpdbs", v)?,
        None => None,
    };
    Ok(HeuristicConfig::Cpdbs {
        patterns,
        max_time_dominance_pruning,
    })
}

/// The pattern generators of `projections(...)`.
const PATTERN_GENERATORS: &str = "manual_patterns, systematic, hillclimbing, sys_scp";

/// `scp([projections(...), ...], orders=greedy_orders(), max_orders=..., max_time=...,
/// diversify=..., samples=..., random_seed=...)` or `scp_online([...], orders=...,
/// interval=..., max_time=..., random_seed=...)`, with Scorpion's names and defaults.
fn interpret_scp(term: &Term) -> Result<ScpConfig, ConfigError> {
    let function = term.name.as_str();
    let online = function == "scp_online";
    let params: &[&str] = if online {
        &[
            "abstractions",
            "orders",
            "interval",
            "max_time",
            "random_seed",
        ]
    } else {
        &[
            "abstractions",
            "orders",
            "max_orders",
            "max_time",
            "diversify",
            "samples",
            "random_seed",
        ]
    };
    let mut args = Args::new(term, params)?;
    let mut config = ScpConfig::default();
    let abstractions = args
        .take("abstractions")?
        .ok_or_else(|| ConfigError::MissingArgument {
            function: function.into(),
            argument: "abstractions".into(),
        })?;
    let Value::List(items) = abstractions else {
        return Err(invalid(
            function,
            "`abstractions` must be a list such as [projections(sys_scp())]",
        ));
    };
    config.abstractions = items
        .iter()
        .map(|item| interpret_abstraction(function, item))
        .collect::<Result<_, _>>()?;
    if let Some(v) = args.take("orders")? {
        let Value::Term(t) = v else {
            return Err(invalid(function, "`orders` must be greedy_orders(...)"));
        };
        if t.name != "greedy_orders" {
            return Err(invalid(
                function,
                &format!(
                    "unknown order generator `{}` (known: greedy_orders)",
                    t.name
                ),
            ));
        }
        let mut args = Args::new(t, &["random_seed"])?;
        if let Some(v) = args.take("random_seed")? {
            config.orders_seed = seed("greedy_orders", v)?;
        }
        args.finish()?;
    }
    if let Some(v) = args.take("max_time")? {
        config.max_time = seconds(function, v)?;
    }
    if let Some(v) = args.take("random_seed")? {
        config.random_seed = seed(function, v)?;
    }
    if online {
        let interval = match args.take("interval")? {
            Some(v) => positive(function, "interval", integer(function, v, false)?)?,
            None => 10_000,
        };
        config.online_interval = Some(interval);
    } else {
        if let Some(v) = args.take("max_orders")? {
            config.max_orders = positive(function, "max_orders", integer(function, v, true)?)?;
        }
        if let Some(v) = args.take("diversify")? {
            config.diversify = boolean(function, "diversify", v)?;
        }
        if let Some(v) = args.take("samples")? {
            let n = positive(function, "samples", integer(function, v, false)?)?;
            config.samples =
                u32::try_from(n).map_err(|_| invalid(function, "`samples` is too large"))?;
        }
    }
    args.finish()?;
    Ok(config)
}

/// `projections(systematic(2))` and the other pattern generators.
fn interpret_abstraction(function: &str, value: &Value) -> Result<PatternGenerator, ConfigError> {
    let term = match value {
        Value::Term(t) if t.name == "projections" => t,
        Value::Term(t) if t.name == "cartesian" => {
            return Err(invalid(
                function,
                "Cartesian abstractions (`cartesian`) are not supported; use projections(...)",
            ))
        }
        Value::Term(t) => {
            return Err(invalid(
                function,
                &format!(
                    "unknown abstraction generator `{}` (known: projections)",
                    t.name
                ),
            ))
        }
        Value::List(_) => {
            return Err(invalid(
                function,
                "an abstraction must be projections(...), not a list",
            ))
        }
    };
    let mut args = Args::new(term, &["patterns"])?;
    let patterns = args.take("patterns")?;
    args.finish()?;
    let generator = match patterns {
        None => {
            return Err(ConfigError::MissingArgument {
                function: "projections".into(),
                argument: "patterns".into(),
            })
        }
        Some(Value::List(items)) => PatternGenerator::Manual(
            items
                .iter()
                .map(|p| variables("projections", p))
                .collect::<Result<_, _>>()?,
        ),
        Some(Value::Term(t)) => match t.name.as_str() {
            "manual_patterns" => PatternGenerator::Manual(manual_patterns(t)?),
            "systematic" => {
                let size = systematic_size(t)?;
                let size = u32::try_from(positive("systematic", "pattern_max_size", size)?)
                    .map_err(|_| invalid("systematic", "`pattern_max_size` is too large"))?;
                PatternGenerator::Systematic(size)
            }
            "hillclimbing" => PatternGenerator::HillClimbing(interpret_ipdb(t, false)?),
            "sys_scp" => PatternGenerator::SysScp(interpret_sys_scp(t)?),
            name => {
                return Err(invalid(
                    "projections",
                    &format!(
                    "unknown pattern collection generator `{name}` (known: {PATTERN_GENERATORS})"
                ),
                ))
            }
        },
    };
    Ok(generator)
}

/// `sys_scp(max_pattern_size=..., max_pdb_size=..., max_collection_size=...,
/// max_patterns=..., max_time=..., max_time_per_restart=...)`.
fn interpret_sys_scp(term: &Term) -> Result<SysScpConfig, ConfigError> {
    let f = "sys_scp";
    let mut args = Args::new(
        term,
        &[
            "max_pattern_size",
            "max_pdb_size",
            "max_collection_size",
            "max_patterns",
            "max_time",
            "max_time_per_restart",
        ],
    )?;
    let mut config = SysScpConfig::default();
    for (name, slot) in [
        ("max_pattern_size", &mut config.max_pattern_size),
        ("max_pdb_size", &mut config.max_pdb_size),
        ("max_collection_size", &mut config.max_collection_size),
        ("max_patterns", &mut config.max_patterns),
    ] {
        if let Some(v) = args.take(name)? {
            *slot = positive(f, name, integer(f, v, true)?)?;
        }
    }
    if let Some(v) = args.take("max_time")? {
        config.max_time = seconds(f, v)?;
    }
    if let Some(v) = args.take("max_time_per_restart")? {
        config.max_time_per_restart = seconds(f, v)?;
    }
    args.finish()?;
    Ok(config)
}

/// `true` or `false`.
fn boolean(function: &str, param: &str, value: &Value) -> Result<bool, ConfigError> {
    match word(value) {
        Some("true") => Ok(true),
        Some("false") => Ok(false),
        _ => Err(invalid(
            function,
            &format!("`{param}` must be true or false, not {}", shown(value)),
        )),
    }
}

/// A seed as Fast Downward bounds it: -1 (the default, [`crate::ipdb::DEFAULT_SEED`])
/// or an integer up to 2147483647.
fn seed(function: &str, value: &Value) -> Result<u32, ConfigError> {
    match word(value) {
        Some("-1") => Ok(crate::ipdb::DEFAULT_SEED),
        _ => u32::try_from(integer(function, value, false)?)
            .ok()
            .filter(|&seed| seed <= i32::MAX as u32)
            .ok_or_else(|| invalid(function, "`random_seed` must be -1 or at most 2147483647")),
    }
}

/// The canonical form of `scp(...)` or `scp_online(...)`: options at their defaults
/// left out.
fn write_scp(f: &mut fmt::Formatter<'_>, config: &ScpConfig) -> fmt::Result {
    let default = ScpConfig::default();
    let name = if config.online_interval.is_some() {
        "scp_online"
    } else {
        "scp"
    };
    let int = |v: u64| {
        if v == u64::MAX {
            "infinity".to_string()
        } else {
            v.to_string()
        }
    };
    let secs =
        |t: Option<Duration>| t.map_or("infinity".to_string(), |t| t.as_secs_f64().to_string());
    let mut items = Vec::new();
    for g in &config.abstractions {
        let inner = match g {
            PatternGenerator::Manual(patterns) => {
                let lists: Vec<String> = patterns.iter().map(|p| List(p).to_string()).collect();
                format!("manual_patterns([{}])", lists.join(", "))
            }
            PatternGenerator::Systematic(k) => format!("systematic({k})"),
            PatternGenerator::HillClimbing(c) => {
                struct Options<'a>(&'a IpdbConfig);
                impl fmt::Display for Options<'_> {
                    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
                        write_ipdb_options(f, self.0, false)
                    }
                }
                format!("hillclimbing({})", Options(c))
            }
            PatternGenerator::SysScp(c) => {
                let d = SysScpConfig::default();
                let mut o = Vec::new();
                for (n, a, b) in [
                    ("max_pattern_size", c.max_pattern_size, d.max_pattern_size),
                    ("max_pdb_size", c.max_pdb_size, d.max_pdb_size),
                    (
                        "max_collection_size",
                        c.max_collection_size,
                        d.max_collection_size,
                    ),
                    ("max_patterns", c.max_patterns, d.max_patterns),
                ] {
                    if a != b {
                        o.push(format!("{n}={}", int(a)));
                    }
                }
                if c.max_time != d.max_time {
                    o.push(format!("max_time={}", secs(c.max_time)));
                }
                if c.max_time_per_restart != d.max_time_per_restart {
                    o.push(format!(
                        "max_time_per_restart={}",
                        secs(c.max_time_per_restart)
                    ));
                }
                format!("sys_scp({})", o.join(", "))
            }
        };
        items.push(format!("projections({inner})"));
    }
    let mut options = vec![format!("[{}]", items.join(", "))];
    if config.orders_seed != default.orders_seed {
        options.push(format!(
            "orders=greedy_orders(random_seed={})",
            config.orders_seed
        ));
    }
    if let Some(interval) = config.online_interval {
        if interval != 10_000 {
            options.push(format!("interval={interval}"));
        }
    } else {
        if config.max_orders != default.max_orders {
            options.push(format!("max_orders={}", int(config.max_orders)));
        }
        if config.diversify != default.diversify {
            options.push(format!("diversify={}", config.diversify));
        }
        if config.samples != default.samples {
            options.push(format!("samples={}", config.samples));
        }
    }
    if config.max_time != default.max_time {
        options.push(format!("max_time={}", secs(config.max_time)));
    }
    if config.random_seed != default.random_seed {
        options.push(format!("random_seed={}", config.random_seed));
    }
    write!(f, "{name}({})", options.join(", "))
}

/// `manual_patterns([[0, 1], [2]])`.
fn manual_patterns(t: &Term) -> Result<Vec<Vec<u32>>, ConfigError> {
    let mut args = Args::new(t, &["patterns"])?;
    let list = args
        .take("patterns")?
        .ok_or_else(|| ConfigError::MissingArgument {
            function: "manual_patterns".into(),
            argument: "patterns".into(),
        })?;
    args.finish()?;
    let Value::List(items) = list else {
        return Err(invalid(
            "manual_patterns",
            "expected a list of patterns such as [[0, 1], [2]]",
        ));
    };
    items
        .iter()
        .map(|p| variables("manual_patterns", p))
        .collect()
}

/// The `pattern_max_size` of `systematic(...)` (default 1).
fn systematic_size(t: &Term) -> Result<u64, ConfigError> {
    let mut args = Args::new(t, &["pattern_max_size"])?;
    let size = match args.take("pattern_max_size")? {
        Some(v) => integer("systematic", v, false)?,
        None => 1,
    };
    args.finish()?;
    Ok(size)
}

fn invalid(function: &str, message: &str) -> ConfigError {
    ConfigError::InvalidArgument {
        function: function.into(),
        message: message.into(),
    }
}

/// A bare word: a term without arguments.
fn word(value: &Value) -> Option<&str> {
    match value {
        Value::Term(t) if t.args.is_empty() => Some(&t.name),
        _ => None,
    }
}

/// A non-negative integer with an optional suffix `k`, `m` or `g` (thousands, millions,
/// billions), or `infinity` (`u64::MAX`) where `infinity` is allowed.
fn integer(function: &str, value: &Value, infinity: bool) -> Result<u64, ConfigError> {
    let error = || match word(value) {
        Some(w) => invalid(function, &format!("`{w}` is not a non-negative integer")),
        None => invalid(function, "expected a non-negative integer"),
    };
    let w = word(value).ok_or_else(error)?;
    if infinity && w == "infinity" {
        return Ok(u64::MAX);
    }
    let (digits, factor) = match w.char_indices().last() {
        Some((i, 'k' | 'K')) => (&w[..i], 1_000),
        Some((i, 'm' | 'M')) => (&w[..i], 1_000_000),
        Some((i, 'g' | 'G')) => (&w[..i], 1_000_000_000),
        _ => (w, 1),
    };
    if digits.is_empty() || !digits.bytes().all(|b| b.is_ascii_digit()) {
        return Err(error());
    }
    digits
        .parse::<u64>()
        .ok()
        .and_then(|n| n.checked_mul(factor))
        .ok_or_else(|| {
            invalid(
                function,
                &format!("`{w}` is too large (at most {})", u64::MAX),
            )
        })
}

fn positive(function: &str, param: &str, n: u64) -> Result<u64, ConfigError> {
    if n == 0 {
        return Err(invalid(function, &format!("`{param}` must be positive")));
    }
    Ok(n)
}

/// Seconds (`30`, `1.5`, `1e3`) or `infinity` (`None`). A number of seconds too large
/// for a `Duration` (over about 5.8e11 years) is no limit, as `infinity` is.
fn seconds(function: &str, value: &Value) -> Result<Option<Duration>, ConfigError> {
    let w = word(value).ok_or_else(|| invalid(function, "expected a number of seconds"))?;
    if w == "infinity" {
        return Ok(None);
    }
    w.parse::<f64>()
        .ok()
        .filter(|t| t.is_finite() && *t >= 0.0 && !w.starts_with(['+', '-']))
        .map(|t| Duration::try_from_secs_f64(t).ok())
        .ok_or_else(|| invalid(function, &format!("`{w}` is not a number of seconds")))
}

/// A list of variable indices: `[0, 1]`.
fn variables(function: &str, value: &Value) -> Result<Vec<u32>, ConfigError> {
    let Value::List(items) = value else {
        return Err(invalid(
            function,
            "expected a list of variables such as [0, 1]",
        ));
    };
    items
        .iter()
        .map(|item| {
            let n = integer(function, item, false)?;
            u32::try_from(n).map_err(|_| invalid(function, "a variable index is too large"))
        })
        .collect()
}

/// A term: `name` or `name(args)`.
#[derive(Debug, Clone, PartialEq)]
struct Term {
    name: String,
    args: Vec<Arg>,
}

/// An argument, positional or `key=value`.
#[derive(Debug, Clone, PartialEq)]
struct Arg {
    key: Option<String>,
    value: Value,
}

#[derive(Debug, Clone, PartialEq)]
enum Value {
    /// A term, or a bare word (a number, a name): a term without arguments.
    Term(Term),
    List(Vec<Value>),
}

/// A function's arguments matched to its parameters: positional ones in order, then
/// keywords.
struct Args<'t> {
    function: &'t str,
    params: &'t [&'t str],
    values: Vec<Option<&'t Value>>,
}

impl<'t> Args<'t> {
    fn new(term: &'t Term, params: &'t [&'t str]) -> Result<Args<'t>, ConfigError> {
        let mut values = vec![None; params.len()];
        let unexpected = |argument: String| ConfigError::UnexpectedArgument {
            function: term.name.clone(),
            argument,
        };
        for (i, arg) in term.args.iter().enumerate() {
            let slot = match &arg.key {
                None => i,
                Some(key) => params
                    .iter()
                    .position(|p| p == key)
                    .ok_or_else(|| unexpected(format!("`{key}=`")))?,
            };
            match values.get_mut(slot) {
                Some(v @ None) => *v = Some(&arg.value),
                Some(Some(_)) => {
                    return Err(unexpected(format!("`{}` twice", params[slot])));
                }
                None => return Err(unexpected(format!("number {} (positional)", i + 1))),
            }
        }
        Ok(Args {
            function: &term.name,
            params,
            values,
        })
    }

    fn take(&mut self, param: &str) -> Result<Option<&'t Value>, ConfigError> {
        let i = self
            .params
            .iter()
            .position(|p| *p == param)
            .ok_or_else(|| ConfigError::InvalidArgument {
                function: self.function.to_string(),
                message: format!("internal: no parameter `{param}`"),
            })?;
        Ok(self.values[i].take())
    }

    /// Fails if an argument was given that nothing took.
    fn finish(self) -> Result<(), ConfigError> {
        match self.values.iter().position(Option::is_some) {
            Some(i) => Err(ConfigError::UnexpectedArgument {
                function: self.function.to_string(),
                argument: format!("`{}=`", self.params[i]),
            }),
            None => Ok(()),
        }
    }
}

/// Deepest nesting of terms and lists accepted.
const MAX_DEPTH: usize = 64;

/// A recursive-descent parser for terms.
struct Parser<'s> {
    text: &'s str,
    pos: usize,
}

impl<'s> Parser<'s> {
    fn new(text: &'s str) -> Parser<'s> {
        Parser { text, pos: 0 }
    }

    fn parse(mut self) -> Result<Term, ConfigError> {
        self.skip_space();
        if self.pos == self.text.len() {
            return Err(self.error("the search string is empty"));
        }
        let term = self.term(0)?;
        self.skip_space();
        if self.pos < self.text.len() {
            return Err(self.error("unexpected text after the search engine's closing parenthesis"));
        }
        Ok(term)
    }

    fn error(&self, message: &str) -> ConfigError {
        ConfigError::Syntax {
            position: self.pos,
            message: message.to_string(),
        }
    }

    fn skip_space(&mut self) {
        let rest = &self.text[self.pos..];
        self.pos += rest.len() - rest.trim_start().len();
    }

    fn peek(&self) -> Option<char> {
        self.text[self.pos..].chars().next()
    }

    /// Consumes `c` (after whitespace) if it comes next.
    fn eat(&mut self, c: char) -> bool {
        self.skip_space();
        if self.peek() == Some(c) {
            self.pos += c.len_utf8();
            true
        } else {
            false
        }
    }

    /// A word: letters, digits, `_`, `.`, `-`, `+`.
    fn word(&mut self) -> Result<String, ConfigError> {
        self.skip_space();
        let rest = &self.text[self.pos..];
        let len = rest
            .find(|c: char| !(c.is_ascii_alphanumeric() || matches!(c, '_' | '.' | '-' | '+')))
            .unwrap_or(rest.len());
        if len == 0 {
            return Err(match self.peek() {
                Some(c) => self.error(&format!("expected a name, found `{c}`")),
                None => self.error("expected a name, found the end of the string"),
            });
        }
        self.pos += len;
        Ok(rest[..len].to_string())
    }

    fn term(&mut self, depth: usize) -> Result<Term, ConfigError> {
        if depth > MAX_DEPTH {
            return Err(self.error("nested too deeply"));
        }
        let name = self.word()?;
        let mut args = Vec::new();
        if self.eat('(') && !self.eat(')') {
            loop {
                args.push(self.arg(depth + 1)?);
                if self.eat(')') {
                    break;
                }
                if !self.eat(',') {
                    return Err(self.expected("`,` or `)`"));
                }
            }
        }
        Ok(Term { name, args })
    }

    fn expected(&mut self, what: &str) -> ConfigError {
        self.skip_space();
        match self.peek() {
            Some(c) => self.error(&format!("expected {what}, found `{c}`")),
            None => self.error(&format!("expected {what}, found the end of the string")),
        }
    }

    fn arg(&mut self, depth: usize) -> Result<Arg, ConfigError> {
        self.skip_space();
        if self.peek() == Some('[') {
            return Ok(Arg {
                key: None,
                value: self.value(depth)?,
            });
        }
        let start = self.pos;
        let word = self.word()?;
        if self.eat('=') {
            return Ok(Arg {
                key: Some(word),
                value: self.value(depth)?,
            });
        }
        self.pos = start;
        Ok(Arg {
            key: None,
            value: self.value(depth)?,
        })
    }

    fn value(&mut self, depth: usize) -> Result<Value, ConfigError> {
        if depth > MAX_DEPTH {
            return Err(self.error("nested too deeply"));
        }
        if self.eat('[') {
            let mut items = Vec::new();
            if !self.eat(']') {
                loop {
                    items.push(self.value(depth + 1)?);
                    if self.eat(']') {
                        break;
                    }
                    if !self.eat(',') {
                        return Err(self.expected("`,` or `]`"));
                    }
                }
            }
            return Ok(Value::List(items));
        }
        Ok(Value::Term(self.term(depth)?))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn ok(s: &str) -> SearchConfig {
        parse_search(s).unwrap_or_else(|e| panic!("{s}: {e}"))
    }

    fn err(s: &str) -> String {
        let e = parse_search(s).unwrap_err();
        let text = e.to_string();
        assert!(text.ends_with(&known()), "{text}");
        text.lines().next().unwrap().to_string()
    }

    #[test]
    fn accepts_the_supported_strings() {
        let blind = SearchConfig {
            engine: Engine::AStar,
            heuristic: HeuristicConfig::Blind,
            pruning: PruningConfig::Null,
        };
        let hmax = SearchConfig {
            engine: Engine::AStar,
            heuristic: HeuristicConfig::HMax,
            pruning: PruningConfig::Null,
        };
        assert_eq!(ok("astar(blind())"), blind);
        assert_eq!(ok("  astar ( blind ( ) )  "), blind);
        assert_eq!(ok("astar(\n\tblind()\n)"), blind);
        assert_eq!(ok("astar(blind)"), blind);
        assert_eq!(ok("astar(eval=blind())"), blind);
        assert_eq!(ok("astar(hmax())"), hmax);
        assert_eq!(ok("astar( eval = hmax() )"), hmax);
        assert_eq!(blind.to_string(), "astar(blind())");
        assert_eq!(ok(&hmax.to_string()), hmax);
    }

    #[test]
    fn pattern_database_strings() {
        let pdb = |p: &[u32]| HeuristicConfig::Pdb {
            pattern: p.to_vec(),
        };
        let h = |s: &str| ok(s).heuristic;
        assert_eq!(h("astar(pdb(pattern=[0, 1]))"), pdb(&[0, 1]));
        assert_eq!(h("astar(pdb([2,0]))"), pdb(&[2, 0]));
        assert_eq!(h("astar(pdb(pattern=manual_pattern([0,1])))"), pdb(&[0, 1]));
        assert_eq!(h("astar(pdb(manual_pattern(pattern=[3])))"), pdb(&[3]));
        assert_eq!(h("astar(pdb(pattern=[]))"), pdb(&[]));
        assert_eq!(
            h("astar(ipdb())"),
            HeuristicConfig::Ipdb(IpdbConfig::default())
        );
        assert_eq!(
            h(
                "astar(ipdb(max_time=30, pdb_max_size=2k, collection_max_size=10M, \
               num_samples=50, min_improvement=3, random_seed=7, \
               max_generated_patterns=100, max_time_dominance_pruning=0.5))"
            ),
            HeuristicConfig::Ipdb(IpdbConfig {
                pdb_max_size: 2000,
                collection_max_size: 10_000_000,
                num_samples: 50,
                min_improvement: 3,
                max_time: Some(Duration::from_secs(30)),
                random_seed: 7,
                max_generated_patterns: Some(100),
                max_time_dominance_pruning: Some(Duration::from_millis(500)),
            })
        );
        assert_eq!(
            h(
                "astar(ipdb(random_seed=-1, max_time=infinity, collection_max_size=infinity, \
               max_generated_patterns=infinity))"
            ),
            HeuristicConfig::Ipdb(IpdbConfig {
                collection_max_size: u64::MAX,
                ..IpdbConfig::default()
            })
        );
        let cpdbs = |patterns, pruning| HeuristicConfig::Cpdbs {
            patterns,
            max_time_dominance_pruning: pruning,
        };
        use PatternCollectionConfig::*;
        assert_eq!(h("astar(cpdbs())"), cpdbs(Systematic(1), None));
        assert_eq!(h("astar(cpdbs(systematic(2)))"), cpdbs(Systematic(2), None));
        assert_eq!(
            h("astar(cpdbs(patterns=systematic(pattern_max_size=2), max_time_dominance_pruning=0))"),
            cpdbs(Systematic(2), Some(Duration::ZERO))
        );
        let manual = Manual(vec![vec![0, 1], vec![2]]);
        assert_eq!(h("astar(cpdbs([[0,1],[2]]))"), cpdbs(manual.clone(), None));
        assert_eq!(
            h("astar(cpdbs(patterns=manual_patterns([[0, 1], [2]])))"),
            cpdbs(manual, None)
        );
        let climb = IpdbConfig {
            max_time: Some(Duration::from_secs(5)),
            ..IpdbConfig::default()
        };
        assert_eq!(
            h("astar(cpdbs(hillclimbing(max_time=5)))"),
            cpdbs(HillClimbing(climb), None)
        );
        // Canonical strings, which parse back to the same configuration.
        for (given, canonical) in [
            ("astar(pdb(manual_pattern([2,0])))", "astar(pdb(pattern=[2, 0]))"),
            ("astar(ipdb())", "astar(ipdb())"),
            (
                "astar(ipdb(max_time=1.5,random_seed=3, num_samples=10))",
                "astar(ipdb(num_samples=10, max_time=1.5, random_seed=3))",
            ),
            (
                "astar(ipdb(collection_max_size=infinity, max_time_dominance_pruning=0))",
                "astar(ipdb(collection_max_size=infinity, max_time_dominance_pruning=0))",
            ),
            ("astar(cpdbs())", "astar(cpdbs(patterns=systematic(1)))"),
            (
                "astar(cpdbs([[0,1],[2]], max_time_dominance_pruning=2))",
                "astar(cpdbs(patterns=manual_patterns([[0, 1], [2]]), max_time_dominance_pruning=2))",
            ),
            (
                "astar(cpdbs(hillclimbing(pdb_max_size=1000)))",
                "astar(cpdbs(patterns=hillclimbing(pdb_max_size=1000)))",
            ),
        ] {
            let config = ok(given);
            assert_eq!(config.to_string(), canonical);
            assert_eq!(ok(canonical), config);
        }
    }

    #[test]
    fn pattern_database_errors() {
        assert_eq!(err("astar(pdb())"), "`pdb` needs the argument `pattern`");
        assert_eq!(
            err("astar(pdb(pattern=greedy()))"),
            "`pdb`: the pattern generator `greedy` is not supported; give a list of variables such as [0, 1]"
        );
        assert_eq!(
            err("astar(pdb(pattern=3))"),
            "`pdb`: `pattern` must be a list of variables such as [0, 1]"
        );
        assert_eq!(
            err("astar(pdb(pattern=[a]))"),
            "`pdb`: `a` is not a non-negative integer"
        );
        assert_eq!(
            err("astar(pdb(pattern=[99999999999]))"),
            "`pdb`: a variable index is too large"
        );
        assert_eq!(
            err("astar(ipdb(pdb_max_size=99999999999999999999))"),
            "`ipdb`: `99999999999999999999` is too large (at most 18446744073709551615)"
        );
        assert_eq!(
            err("astar(ipdb(pdb_max_size=20000000000G))"),
            "`ipdb`: `20000000000G` is too large (at most 18446744073709551615)"
        );
        assert_eq!(
            ok("astar(ipdb(max_time=1e300))"),
            ok("astar(ipdb(max_time=infinity))"),
            "beyond a Duration: no limit"
        );
        assert_eq!(
            err("astar(ipdb(max_time=-1))"),
            "`ipdb`: `-1` is not a number of seconds"
        );
        assert_eq!(
            err("astar(ipdb(max_time=[]))"),
            "`ipdb`: expected a number of seconds"
        );
        assert_eq!(
            err("astar(ipdb(num_samples=0))"),
            "`ipdb`: `num_samples` must be positive"
        );
        assert_eq!(
            err("astar(ipdb(pdb_max_size=[1]))"),
            "`ipdb`: expected a non-negative integer"
        );
        assert_eq!(
            err("astar(ipdb(num_samples=infinity))"),
            "`ipdb`: `infinity` is not a non-negative integer"
        );
        assert_eq!(
            err("astar(ipdb(random_seed=-2))"),
            "`ipdb`: `-2` is not a non-negative integer"
        );
        // Fast Downward's seeds are C++ ints.
        assert_eq!(
            err("astar(ipdb(random_seed=2147483648))"),
            "`ipdb`: `random_seed` must be -1 or at most 2147483647"
        );
        assert_eq!(
            err("astar(ipdb(foo=1))"),
            "`ipdb` does not take the argument `foo=`"
        );
        assert_eq!(
            err("astar(cpdbs(systematic(3)))"),
            "`systematic`: `pattern_max_size` must be 1 or 2 (larger sizes are not supported)"
        );
        assert_eq!(
            err("astar(cpdbs(patterns=genetic()))"),
            "`cpdbs`: unknown pattern collection generator `genetic` (known: manual_patterns, systematic, hillclimbing)"
        );
        assert_eq!(
            err("astar(cpdbs(hillclimbing(max_time_dominance_pruning=1)))"),
            "`hillclimbing` does not take the argument `max_time_dominance_pruning=`"
        );
        assert_eq!(
            err("astar(cpdbs(manual_patterns([0])))"),
            "`manual_patterns`: expected a list of variables such as [0, 1]"
        );
    }

    #[test]
    fn error_messages() {
        assert_eq!(err("astar(ff())"), "unknown heuristic `ff`");
        assert_eq!(
            err("lazy_greedy([ff()])"),
            "unknown search engine `lazy_greedy`"
        );
        assert_eq!(err("blind()"), "unknown search engine `blind`");
        assert_eq!(err("astar()"), "`astar` needs the argument `eval`");
        assert_eq!(
            err("astar(blind(), hmax())"),
            "`astar` does not take the argument number 2 (positional)"
        );
        assert_eq!(
            err("astar(blind(), eval=hmax())"),
            "`astar` does not take the argument `eval` twice"
        );
        assert_eq!(
            err("astar(blind(), bound=10)"),
            "`astar` does not take the argument `bound=`"
        );
        assert_eq!(
            err("astar(blind(cache_estimates=false))"),
            "`blind` does not take the argument `cache_estimates=`"
        );
        assert_eq!(
            err("astar(hmax(3))"),
            "`hmax` does not take the argument number 1 (positional)"
        );
        assert_eq!(
            err("astar([blind()])"),
            "`astar`: a list is not a heuristic"
        );
        assert_eq!(
            err("astar(astar(blind()))"),
            "`astar`: `astar` is a search engine, not a heuristic"
        );
        assert_eq!(
            err(""),
            "syntax error at byte 0 of the search string: the search string is empty"
        );
        assert_eq!(
            err("   "),
            "syntax error at byte 3 of the search string: the search string is empty"
        );
        assert_eq!(
            err("astar(blind()"),
            "syntax error at byte 13 of the search string: expected `,` or `)`, found the end of the string"
        );
        assert_eq!(
            err("astar(blind()))"),
            "syntax error at byte 14 of the search string: unexpected text after the search engine's closing parenthesis"
        );
        assert_eq!(
            err("astar(,)"),
            "syntax error at byte 6 of the search string: expected a name, found `,`"
        );
        assert_eq!(
            err("astar(blind() hmax())"),
            "syntax error at byte 14 of the search string: expected `,` or `)`, found `h`"
        );
        assert_eq!(
            err("astar(x=)"),
            "syntax error at byte 8 of the search string: expected a name, found `)`"
        );
        assert_eq!(
            err("(blind())"),
            "syntax error at byte 0 of the search string: expected a name, found `(`"
        );
    }

    #[test]
    fn pruning_strings_with_fast_downwards_names_and_defaults() {
        let pruning = |s: &str| ok(s).pruning;
        let stubborn = |use_sibling_shortcut, atom_selection_strategy| {
            PruningConfig::AtomCentricStubbornSets(StubbornSetsConfig {
                use_sibling_shortcut,
                atom_selection_strategy,
            })
        };
        use AtomSelectionStrategy::*;
        assert_eq!(pruning("astar(blind())"), PruningConfig::Null);
        assert_eq!(
            pruning("astar(blind(), pruning=null())"),
            PruningConfig::Null
        );
        assert_eq!(
            pruning("astar(lmcut(), pruning=atom_centric_stubborn_sets())"),
            stubborn(true, QuickSkip)
        );
        assert_eq!(
            pruning(
                "astar(lmcut(), pruning=atom_centric_stubborn_sets(use_sibling_shortcut=false, \
                 atom_selection_strategy=dynamic_small))"
            ),
            stubborn(false, DynamicSmall)
        );
        for strategy in AtomSelectionStrategy::ALL {
            let s = format!(
                "astar(blind(), pruning=atom_centric_stubborn_sets(atom_selection_strategy={}))",
                strategy.name()
            );
            assert_eq!(pruning(&s), stubborn(true, strategy));
        }
        let limited = pruning(
            "astar(blind(), pruning=limited_pruning(pruning=atom_centric_stubborn_sets(), \
             min_required_pruning_ratio=0.2, expansions_before_checking_pruning_ratio=1000))",
        );
        assert_eq!(
            limited,
            PruningConfig::Limited(LimitedPruningConfig::new(stubborn(true, QuickSkip)))
        );
        assert_eq!(
            pruning(
                "astar(blind(), pruning=limited_pruning(atom_centric_stubborn_sets(), 0.5, 10))"
            ),
            PruningConfig::Limited(LimitedPruningConfig {
                pruning: Box::new(stubborn(true, QuickSkip)),
                min_required_pruning_ratio: Ratio(0.5),
                expansions_before_checking_pruning_ratio: 10,
            })
        );
        // The canonical strings parse back to the same configuration.
        for s in [
            "astar(blind())",
            "astar(lmcut(), pruning=atom_centric_stubborn_sets())",
            "astar(ipdb(max_time=5), pruning=atom_centric_stubborn_sets(use_sibling_shortcut=false, atom_selection_strategy=static_small))",
            "astar(blind(), pruning=limited_pruning(pruning=atom_centric_stubborn_sets()))",
            "astar(blind(), pruning=limited_pruning(pruning=atom_centric_stubborn_sets(), min_required_pruning_ratio=0.5, expansions_before_checking_pruning_ratio=infinity))",
        ] {
            let config = ok(s);
            assert_eq!(config.to_string(), s);
            assert_eq!(ok(&config.to_string()), config);
        }
    }

    #[test]
    fn pruning_errors_name_the_option() {
        assert_eq!(
            err("astar(blind(), pruning=stubborn_sets_simple())"),
            "`astar`: unknown pruning method `stubborn_sets_simple` (known: null, atom_centric_stubborn_sets, limited_pruning)"
        );
        assert_eq!(
            err("astar(blind(), pruning=[1])"),
            "`astar`: `pruning` must be a pruning method, not a list (known: null, atom_centric_stubborn_sets, limited_pruning)"
        );
        assert_eq!(
            err("astar(blind(), pruning=atom_centric_stubborn_sets(atom_selection_strategy=foo))"),
            "`atom_centric_stubborn_sets`: `atom_selection_strategy` must be one of fast_downward, quick_skip, static_small, dynamic_small, not `foo`"
        );
        assert_eq!(
            err("astar(blind(), pruning=atom_centric_stubborn_sets(use_sibling_shortcut=1))"),
            "`atom_centric_stubborn_sets`: `use_sibling_shortcut` must be true or false, not `1`"
        );
        assert_eq!(
            err("astar(blind(), pruning=atom_centric_stubborn_sets(sibling=true))"),
            "`atom_centric_stubborn_sets` does not take the argument `sibling=`"
        );
        assert_eq!(
            err("astar(blind(), pruning=limited_pruning())"),
            "`limited_pruning` needs the argument `pruning`"
        );
        assert_eq!(
            err("astar(blind(), pruning=limited_pruning(pruning=atom_centric_stubborn_sets(), min_required_pruning_ratio=1.5))"),
            "`limited_pruning`: `min_required_pruning_ratio` must be a number from 0 to 1, not `1.5`"
        );
        assert_eq!(
            err("astar(blind(), pruning=limited_pruning(pruning=atom_centric_stubborn_sets(), expansions_before_checking_pruning_ratio=-3))"),
            "`limited_pruning`: `expansions_before_checking_pruning_ratio` must be a non-negative integer or infinity, not `-3`"
        );
        assert_eq!(
            err("astar(blind(), pruning=limited_pruning(pruning=foo()))"),
            "`astar`: unknown pruning method `foo` (known: null, atom_centric_stubborn_sets, limited_pruning)"
        );
        assert_eq!(
            err("astar(blind(), pruning=null(), pruning=null())"),
            "`astar` does not take the argument `pruning` twice"
        );
        assert_eq!(
            err("astar(blind(), atom_centric_stubborn_sets())"),
            "`astar` does not take the argument number 2 (positional)"
        );
    }

    #[test]
    fn saturated_cost_partitioning_strings() {
        let h = |s: &str| match ok(s).heuristic {
            HeuristicConfig::Scp(c) => c,
            other => panic!("{s}: {other:?}"),
        };
        let sys = PatternGenerator::SysScp(SysScpConfig::default());
        assert_eq!(
            h("astar(scp([projections(sys_scp())], orders=greedy_orders()))"),
            ScpConfig {
                abstractions: vec![sys.clone()],
                ..ScpConfig::default()
            }
        );
        let full = h(
            "astar(scp(abstractions=[projections(sys_scp(max_pattern_size=3, \
             max_pdb_size=1k, max_collection_size=10k, max_patterns=20, max_time=5, \
             max_time_per_restart=1)), projections(systematic(3)), \
             projections(hillclimbing(max_time=2)), projections([[0, 1]])], \
             orders=greedy_orders(random_seed=4), max_orders=7, max_time=9, \
             diversify=false, samples=50, random_seed=-1))",
        );
        assert_eq!(
            full,
            ScpConfig {
                abstractions: vec![
                    PatternGenerator::SysScp(SysScpConfig {
                        max_pattern_size: 3,
                        max_pdb_size: 1000,
                        max_collection_size: 10_000,
                        max_patterns: 20,
                        max_time: Some(Duration::from_secs(5)),
                        max_time_per_restart: Some(Duration::from_secs(1)),
                    }),
                    PatternGenerator::Systematic(3),
                    PatternGenerator::HillClimbing(IpdbConfig {
                        max_time: Some(Duration::from_secs(2)),
                        ..IpdbConfig::default()
                    }),
                    PatternGenerator::Manual(vec![vec![0, 1]]),
                ],
                orders_seed: 4,
                max_orders: 7,
                max_time: Some(Duration::from_secs(9)),
                diversify: false,
                samples: 50,
                random_seed: crate::ipdb::DEFAULT_SEED,
                online_interval: None,
            }
        );
        let online = h("astar(scp_online([projections(systematic(2))], interval=10K))");
        assert_eq!(online.online_interval, Some(10_000));
        assert_eq!(
            ok("astar(scp_online([projections(systematic(2))]))")
                .heuristic
                .name(),
            "scp_online"
        );
        // Canonical strings parse back to the same configuration.
        for (given, canonical) in [
            (
                "astar(scp([projections(sys_scp())], orders=greedy_orders()))",
                "astar(scp([projections(sys_scp())]))",
            ),
            (
                "astar(scp([projections(systematic(2)), projections(manual_patterns([[0,1],[2]]))], max_orders=3, diversify=false, samples=9, max_time=infinity, random_seed=5))",
                "astar(scp([projections(systematic(2)), projections(manual_patterns([[0, 1], [2]]))], max_orders=3, diversify=false, samples=9, max_time=infinity, random_seed=5))",
            ),
            (
                "astar(scp_online([projections(hillclimbing(max_time=1)), projections(sys_scp(max_time=3, max_pattern_size=2))], orders=greedy_orders(random_seed=1), interval=100))",
                "astar(scp_online([projections(hillclimbing(max_time=1)), projections(sys_scp(max_pattern_size=2, max_time=3))], orders=greedy_orders(random_seed=1), interval=100))",
            ),
        ] {
            let config = ok(given);
            assert_eq!(config.to_string(), canonical);
            assert_eq!(ok(canonical), config);
        }
    }

    #[test]
    fn saturated_cost_partitioning_errors_name_the_option() {
        for (s, message) in [
            ("astar(scp())", "`scp` needs the argument `abstractions`"),
            (
                "astar(scp(projections(sys_scp())))",
                "`scp`: `abstractions` must be a list such as [projections(sys_scp())]",
            ),
            (
                "astar(scp([cartesian()]))",
                "`scp`: Cartesian abstractions (`cartesian`) are not supported; use projections(...)",
            ),
            (
                "astar(scp([pdbs()]))",
                "`scp`: unknown abstraction generator `pdbs` (known: projections)",
            ),
            (
                "astar(scp([projections(genetic())]))",
                "`projections`: unknown pattern collection generator `genetic` (known: manual_patterns, systematic, hillclimbing, sys_scp)",
            ),
            ("astar(scp([projections()]))", "`projections` needs the argument `patterns`"),
            (
                "astar(scp([projections(sys_scp(max_pdb_size=0))]))",
                "`sys_scp`: `max_pdb_size` must be positive",
            ),
            (
                "astar(scp([projections(sys_scp(max_size=3))]))",
                "`sys_scp` does not take the argument `max_size=`",
            ),
            (
                "astar(scp([projections(systematic(0))]))",
                "`systematic`: `pattern_max_size` must be positive",
            ),
            (
                "astar(scp([projections(sys_scp())], orders=random_orders()))",
                "`scp`: unknown order generator `random_orders` (known: greedy_orders)",
            ),
            (
                "astar(scp([projections(sys_scp())], orders=greedy_orders(dynamic=true)))",
                "`greedy_orders` does not take the argument `dynamic=`",
            ),
            (
                "astar(scp([projections(sys_scp())], diversify=maybe))",
                "`scp`: `diversify` must be true or false, not `maybe`",
            ),
            (
                "astar(scp([projections(sys_scp())], max_orders=0))",
                "`scp`: `max_orders` must be positive",
            ),
            (
                "astar(scp([projections(sys_scp())], max_time=soon))",
                "`scp`: `soon` is not a number of seconds",
            ),
            (
                "astar(scp([projections(sys_scp())], interval=5))",
                "`scp` does not take the argument `interval=`",
            ),
            (
                "astar(scp_online([projections(sys_scp())], max_orders=5))",
                "`scp_online` does not take the argument `max_orders=`",
            ),
            (
                "astar(scp_online([projections(sys_scp())], interval=0))",
                "`scp_online`: `interval` must be positive",
            ),
            (
                "astar(scp([projections(sys_scp())], random_seed=3000000000))",
                "`scp`: `random_seed` must be -1 or at most 2147483647",
            ),
        ] {
            assert_eq!(err(s), message, "{s}");
        }
    }

    #[test]
    fn the_full_message_lists_known_names() {
        let e = parse_search("astar(ff())").unwrap_err();
        assert_eq!(
            e.to_string(),
            "unknown heuristic `ff`\n\
             known search engines: astar\n\
             known heuristics: blind, hmax, lmcut, pdb, ipdb, cpdbs, scp, scp_online"
        );
    }

    #[test]
    fn deep_nesting_is_an_error_not_a_crash() {
        let deep = format!("astar({}{})", "h(".repeat(10_000), ")".repeat(10_000));
        assert!(err(&deep).contains("nested too deeply"));
        let lists = format!("astar({}{})", "[".repeat(10_000), "]".repeat(10_000));
        assert!(err(&lists).contains("nested too deeply"));
    }

    #[test]
    fn generic_terms() {
        let term = Parser::new("f(a, k = [1, 2.5, g(x)], infinity)")
            .parse()
            .unwrap();
        let word = |s: &str| {
            Value::Term(Term {
                name: s.into(),
                args: vec![],
            })
        };
        assert_eq!(
            term,
            Term {
                name: "f".into(),
                args: vec![
                    Arg {
                        key: None,
                        value: word("a")
                    },
                    Arg {
                        key: Some("k".into()),
                        value: Value::List(vec![
                            word("1"),
                            word("2.5"),
                            Value::Term(Term {
                                name: "g".into(),
                                args: vec![Arg {
                                    key: None,
                                    value: word("x")
                                }]
                            }),
                        ]),
                    },
                    Arg {
                        key: None,
                        value: word("infinity")
                    },
                ],
            }
        );
    }

    #[test]
    fn heuristics_build() {
        let task = Task {
            variables: vec![task::Variable::binary("a")],
            mutexes: vec![],
            initial_state: vec![0],
            goal: vec![],
            operators: vec![],
            use_costs: false,
        };
        let configs = [
            "blind()",
            "hmax()",
            "lmcut()",
            "pdb([0])",
            "ipdb()",
            "cpdbs()",
            "cpdbs(systematic(2))",
            "cpdbs([[0], []])",
            "cpdbs(hillclimbing())",
            "scp([projections(sys_scp())])",
            "scp_online([projections(systematic(2)), projections([[0]])], interval=1)",
        ];
        let mut kinds = Vec::new();
        for config in configs {
            let config = ok(&format!("astar({config})")).heuristic;
            assert_eq!(HeuristicName::from_name(config.name()), Some(config.kind()));
            kinds.push(config.kind());
            let mut h = config
                .build_with_limits(&task, &SearchLimits::default())
                .unwrap()
                .into_heuristic()
                .unwrap();
            assert_eq!(h.name(), config.name());
            assert_eq!(h.evaluate(&[0]), Some(0));
            assert_eq!(
                h.pdb_statistics().is_some(),
                matches!(
                    config,
                    HeuristicConfig::Pdb { .. }
                        | HeuristicConfig::Ipdb(_)
                        | HeuristicConfig::Cpdbs { .. }
                )
            );
        }
        // Every heuristic is among them.
        assert!(HeuristicName::ALL.iter().all(|k| kinds.contains(k)));
        let climbs = ok("astar(cpdbs(hillclimbing()))")
            .heuristic
            .build_with_limits(&task, &SearchLimits::default())
            .unwrap()
            .into_heuristic()
            .unwrap();
        assert!(climbs.pdb_statistics().unwrap().hill_climbing.is_some());
        // A pattern that does not fit the task.
        let e = ok("astar(pdb([0, 3]))")
            .heuristic
            .build_with_limits(&task, &SearchLimits::default())
            .err()
            .unwrap();
        assert_eq!(
            e.to_string(),
            "pattern variable 3 does not exist (the task has 1 variables)"
        );
        let e = ok("astar(cpdbs([[0], [1]]))")
            .heuristic
            .build_with_limits(&task, &SearchLimits::default())
            .err()
            .unwrap();
        assert!(matches!(e, SearchError::InvalidPattern(_)));
    }

    /// A task of `n` binary variables, each set by one operator, the goal all set.
    fn binary_task(n: u32) -> Task {
        use task::{Fact, Operator, VarId, Variable};
        Task {
            variables: (0..n).map(|v| Variable::binary(&format!("v{v}"))).collect(),
            mutexes: vec![],
            initial_state: vec![0; n as usize],
            goal: (0..n).map(|v| Fact::new(VarId(v), 1)).collect(),
            operators: (0..n)
                .map(|v| Operator {
                    name: format!("set-v{v}"),
                    preconditions: vec![Fact::new(VarId(v), 0)],
                    effects: vec![Fact::new(VarId(v), 1)],
                    cost: 1,
                })
                .collect(),
            use_costs: false,
        }
    }

    #[test]
    fn fixed_collections_that_do_not_fit_the_memory_limit_are_never_built() {
        let task = binary_task(40);
        let limits = SearchLimits {
            memory_limit_bytes: Some(200 << 20),
            ..SearchLimits::default()
        };
        let pattern: Vec<String> = (0..30).map(|v| v.to_string()).collect();
        let big = pattern.join(", ");
        for s in [
            format!("astar(pdb([{big}]))"),
            format!("astar(cpdbs([[0], [{big}]]))"),
        ] {
            // 2^30 states: 20 GiB by the estimate; allocating them would take seconds.
            let built = ok(&s).heuristic.build_with_limits(&task, &limits).unwrap();
            assert!(
                matches!(built, Built::Stopped(Limit::Memory)),
                "{s}: {built:?}"
            );
            let result = crate::search(&task, &ok(&s), &limits, None).unwrap();
            assert_eq!(result.outcome, crate::Outcome::MemoryLimit, "{s}");
        }
        // What fits is built: 2^10 states.
        let small = ok("astar(pdb([0, 1, 2, 3, 4, 5, 6, 7, 8, 9]))");
        let built = small.heuristic.build_with_limits(&task, &limits).unwrap();
        assert!(matches!(built, Built::Heuristic(_)), "{built:?}");
        // A deadline already past stops a fixed collection before its first database.
        let past = SearchLimits {
            deadline: Some(std::time::Instant::now()),
            ..SearchLimits::default()
        };
        let built = small.heuristic.build_with_limits(&task, &past).unwrap();
        assert!(matches!(built, Built::Stopped(Limit::Time)), "{built:?}");
    }

    #[test]
    fn huge_numbers_of_seconds_are_no_limit_and_never_panic() {
        let task = binary_task(3);
        for s in [
            "astar(ipdb(max_time=1e300))",
            "astar(ipdb(max_time_dominance_pruning=1e19))",
            "astar(cpdbs(systematic(2), max_time_dominance_pruning=1e300))",
            "astar(cpdbs(hillclimbing(max_time=18446744073709551615)))",
        ] {
            let config = ok(s);
            let result = crate::search(&task, &config, &SearchLimits::default(), None).unwrap();
            assert!(matches!(result.outcome, crate::Outcome::Solved(_)), "{s}");
        }
    }
}
