//! A planner configuration: how to translate and how to search, the one thing a planning
//! run of demoplan's own planner is given.
//!
//! A [`PlannerConfig`] is a parsed search string ([`search::SearchConfig`]) together with
//! the translator's options ([`translate::TranslateOptions`]). It comes from a search
//! string and the translator options given beside it, or from an [`Alias`] by name
//! (`--alias demoplan-opt`), which fixes both: [`PlannerConfig::resolve`] is the one
//! place where the command line (`plan`, `solve`), the Python package and library users
//! turn "a search or an alias, and translator options" into a configuration.
//!
//! ```
//! let config = slim::PlannerConfig::alias("demoplan-opt").unwrap();
//! assert!(config.translator.h2_mutexes && config.translator.remove_dominated_operators);
//! let plain = slim::PlannerConfig::resolve(Some("astar(lmcut())"), None, Default::default());
//! assert_eq!(plain.unwrap().translator, translate::TranslateOptions::default());
//! ```

use translate::TranslateOptions;

use crate::ExitCode;

/// A named configuration, `--alias NAME`: a search string and translator options. One
/// configuration each, not a portfolio; none looks at the task it is run on.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Alias {
    /// Its name.
    pub name: &'static str,
    /// The search string it runs.
    pub search: &'static str,
    /// The translator options it switches on.
    pub translator: TranslateOptions,
}

/// Both translator options on.
const BOTH: TranslateOptions = TranslateOptions {
    h2_mutexes: true,
    remove_dominated_operators: true,
};

/// The aliases demoplan knows: Fast Downward's `seq-opt-lmcut`, and `demoplan-opt`,
/// demoplan's optimal configuration, chosen by measurement (`bench/choose-alias`; the
/// choice and its numbers are in `bench/README.md`).
pub const ALIASES: &[Alias] = &[
    Alias {
        name: "seq-opt-lmcut",
        search: "astar(lmcut())",
        translator: TranslateOptions {
            h2_mutexes: false,
            remove_dominated_operators: false,
        },
    },
    Alias {
        name: "demoplan-opt",
        search: "astar(ipdb(), pruning=limited_pruning(pruning=atom_centric_stubborn_sets(), \
                 min_required_pruning_ratio=0.2, expansions_before_checking_pruning_ratio=1000))",
        translator: BOTH,
    },
];

/// How to translate and how to search.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct PlannerConfig {
    /// The search.
    pub search: search::SearchConfig,
    /// The translator's options (they act on PDDL; a task given translated is searched
    /// as it is).
    pub translator: TranslateOptions,
}

impl From<search::SearchConfig> for PlannerConfig {
    /// A search on Fast Downward's translation (no translator options).
    fn from(search: search::SearchConfig) -> PlannerConfig {
        PlannerConfig {
            search,
            translator: TranslateOptions::default(),
        }
    }
}

/// Why a configuration could not be made.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum ConfigError {
    /// The search string does not parse.
    #[error("--search: {0}")]
    Search(#[from] search::ConfigError),
    /// An alias's name that is not in [`ALIASES`].
    #[error("unknown alias `{0}`; known aliases: {known}", known = alias_names())]
    UnknownAlias(String),
    /// Neither a search nor an alias.
    #[error("give a search with --search or --alias")]
    Missing,
    /// Both a search and an alias.
    #[error("give --search or --alias, not both")]
    Both,
}

impl ConfigError {
    /// The exit code of a command that stops here: a bad search string is Fast
    /// Downward's search input error (33), the rest are usage errors (36).
    pub fn exit_code(&self) -> ExitCode {
        match self {
            ConfigError::Search(_) => ExitCode::SEARCH_INPUT_ERROR,
            _ => ExitCode::USAGE,
        }
    }
}

/// The names of [`ALIASES`], comma-separated.
pub fn alias_names() -> String {
    ALIASES
        .iter()
        .map(|a| a.name)
        .collect::<Vec<_>>()
        .join(", ")
}

impl PlannerConfig {
    /// A search string with these translator options.
    pub fn new(search: &str, translator: TranslateOptions) -> Result<PlannerConfig, ConfigError> {
        Ok(PlannerConfig {
            search: search::parse_search(search)?,
            translator,
        })
    }

    /// The configuration an alias names.
    pub fn alias(name: &str) -> Result<PlannerConfig, ConfigError> {
        let alias = ALIASES
            .iter()
            .find(|a| a.name == name)
            .ok_or_else(|| ConfigError::UnknownAlias(name.to_string()))?;
        PlannerConfig::new(alias.search, alias.translator)
    }

    /// The configuration of a search string or an alias (exactly one of them), and the
    /// translator options given besides. With an alias, an option given besides is
    /// switched on in addition to the alias's own: the options only switch on, so
    /// `--alias demoplan-opt --h2-mutexes` is `--alias demoplan-opt`, and `--alias
    /// seq-opt-lmcut --h2-mutexes` is LM-cut on the h² translation.
    pub fn resolve(
        search: Option<&str>,
        alias: Option<&str>,
        translator: TranslateOptions,
    ) -> Result<PlannerConfig, ConfigError> {
        match (search, alias) {
            (Some(search), None) => PlannerConfig::new(search, translator),
            (None, Some(name)) => {
                let mut config = PlannerConfig::alias(name)?;
                config.translator.h2_mutexes |= translator.h2_mutexes;
                config.translator.remove_dominated_operators |=
                    translator.remove_dominated_operators;
                Ok(config)
            }
            (None, None) => Err(ConfigError::Missing),
            (Some(_), Some(_)) => Err(ConfigError::Both),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::{ConfigError, PlannerConfig, ALIASES};
    use crate::ExitCode;
    use translate::TranslateOptions;

    #[test]
    fn every_alias_parses_and_demoplan_opt_switches_both_translator_options_on() {
        for alias in ALIASES {
            let config = PlannerConfig::alias(alias.name).unwrap();
            assert_eq!(config.translator, alias.translator, "{}", alias.name);
        }
        let opt = PlannerConfig::alias("demoplan-opt").unwrap();
        assert!(opt.translator.h2_mutexes && opt.translator.remove_dominated_operators);
        let lmcut = PlannerConfig::alias("seq-opt-lmcut").unwrap();
        assert_eq!(
            lmcut,
            PlannerConfig::new("astar(lmcut())", TranslateOptions::default()).unwrap()
        );
    }

    #[test]
    fn translator_options_beside_an_alias_only_switch_on() {
        let h2 = TranslateOptions {
            h2_mutexes: true,
            ..Default::default()
        };
        let opt = PlannerConfig::alias("demoplan-opt").unwrap();
        assert_eq!(
            PlannerConfig::resolve(None, Some("demoplan-opt"), h2).unwrap(),
            opt
        );
        let lmcut_h2 = PlannerConfig::resolve(None, Some("seq-opt-lmcut"), h2).unwrap();
        assert_eq!(lmcut_h2, PlannerConfig::new("astar(lmcut())", h2).unwrap());
        let search = PlannerConfig::resolve(Some("astar(blind())"), None, h2).unwrap();
        assert_eq!(search.translator, h2);
    }

    #[test]
    fn a_bad_alias_or_search_is_an_error_with_its_exit_code() {
        let unknown = PlannerConfig::alias("seq-opt-hmax").unwrap_err();
        assert_eq!(
            unknown.to_string(),
            "unknown alias `seq-opt-hmax`; known aliases: seq-opt-lmcut, demoplan-opt"
        );
        assert_eq!(unknown.exit_code(), ExitCode::USAGE);
        let bad = PlannerConfig::resolve(Some("astar(nope())"), None, Default::default());
        assert!(matches!(bad, Err(ConfigError::Search(_))), "{bad:?}");
        assert_eq!(bad.unwrap_err().exit_code(), ExitCode::SEARCH_INPUT_ERROR);
        let none = PlannerConfig::resolve(None, None, Default::default()).unwrap_err();
        assert_eq!(
            (none.clone(), none.exit_code()),
            (ConfigError::Missing, ExitCode::USAGE)
        );
        let both = PlannerConfig::resolve(
            Some("astar(blind())"),
            Some("demoplan-opt"),
            Default::default(),
        );
        assert_eq!(both.unwrap_err(), ConfigError::Both);
    }
}
