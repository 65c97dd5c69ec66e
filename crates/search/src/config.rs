//! Fast Downward-style search strings: `astar(blind())`, `astar(hmax())`.
//!
//! A string is first read as a generic term, `name(arg, key=value, ...)`, where a value is
//! a term, a bare word (a number such as `10`, `1.5`, `2M` or `infinity`, or a name) or a
//! list `[a, b]`; then the term is interpreted. Adding a heuristic is one match arm in
//! [`HeuristicConfig`]'s interpretation.

use std::fmt;

use task::Task;

use crate::astar::SearchError;
use crate::heuristic::{Blind, Heuristic};
use crate::hmax::HMax;
use crate::lmcut::LmCut;

/// The search engines demoplan runs.
pub const SEARCH_ENGINES: &[&str] = &["astar"];

/// The heuristics demoplan computes.
pub const HEURISTICS: &[&str] = &["blind", "hmax", "lmcut"];

/// Heuristics Fast Downward has that demoplan will support, but does not yet.
pub const PLANNED_HEURISTICS: &[&str] = &["ipdb", "cpdbs"];

/// Fast Downward's aliases that demoplan knows: name and search string.
pub const ALIASES: &[(&str, &str)] = &[("seq-opt-lmcut", "astar(lmcut())")];

/// The search string for a Fast Downward alias (`seq-opt-lmcut`), if known.
pub fn alias(name: &str) -> Option<&'static str> {
    ALIASES
        .iter()
        .find(|(alias, _)| *alias == name)
        .map(|&(_, search)| search)
}

/// A parsed search string.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct SearchConfig {
    /// The search engine.
    pub engine: Engine,
    /// The heuristic it is guided by.
    pub heuristic: HeuristicConfig,
}

/// A search engine.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Engine {
    /// Optimal eager A* with reopening ([`crate::astar`]).
    AStar,
}

/// A heuristic, as the search string names it.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum HeuristicConfig {
    /// [`Blind`].
    Blind,
    /// [`HMax`].
    HMax,
    /// [`LmCut`].
    LmCut,
}

impl HeuristicConfig {
    /// Its name in search strings.
    pub fn name(self) -> &'static str {
        match self {
            HeuristicConfig::Blind => "blind",
            HeuristicConfig::HMax => "hmax",
            HeuristicConfig::LmCut => "lmcut",
        }
    }

    /// The heuristic for `task`; fails if the task is invalid.
    pub fn build(self, task: &Task) -> Result<Box<dyn Heuristic>, SearchError> {
        Ok(match self {
            HeuristicConfig::Blind => Box::new(Blind::new(task)),
            HeuristicConfig::HMax => Box::new(HMax::new(task)?),
            HeuristicConfig::LmCut => Box::new(LmCut::new(task)?),
        })
    }
}

impl fmt::Display for SearchConfig {
    /// The canonical search string: `astar(hmax())`.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self.engine {
            Engine::AStar => write!(f, "astar({}())", self.heuristic.name()),
        }
    }
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
    /// A heuristic Fast Downward has and demoplan does not yet.
    #[error("heuristic `{name}` is not yet supported by demoplan\n{}", known())]
    NotYetSupported {
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
        "known search engines: {}\nknown heuristics: {} (planned: {})",
        SEARCH_ENGINES.join(", "),
        HEURISTICS.join(", "),
        PLANNED_HEURISTICS.join(", ")
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
            let mut args = Args::new(term, &["eval"])?;
            let eval = args
                .take("eval")?
                .ok_or_else(|| ConfigError::MissingArgument {
                    function: term.name.clone(),
                    argument: "eval".into(),
                })?;
            args.finish()?;
            let heuristic = interpret_heuristic(eval)?;
            Ok(SearchConfig {
                engine: Engine::AStar,
                heuristic,
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
    let heuristic = match term.name.as_str() {
        "blind" => HeuristicConfig::Blind,
        "hmax" => HeuristicConfig::HMax,
        "lmcut" => HeuristicConfig::LmCut,
        name if PLANNED_HEURISTICS.contains(&name) => {
            return Err(ConfigError::NotYetSupported {
                name: name.to_string(),
            })
        }
        name if SEARCH_ENGINES.contains(&name) => {
            return Err(ConfigError::InvalidArgument {
                function: "astar".into(),
                message: format!("`{name}` is a search engine, not a heuristic"),
            })
        }
        name => {
            return Err(ConfigError::UnknownHeuristic {
                name: name.to_string(),
            })
        }
    };
    Args::new(term, &[])?.finish()?;
    Ok(heuristic)
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
        };
        let hmax = SearchConfig {
            engine: Engine::AStar,
            heuristic: HeuristicConfig::HMax,
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
    fn aliases() {
        assert_eq!(alias("seq-opt-lmcut"), Some("astar(lmcut())"));
        assert_eq!(alias("seq-opt-blind"), None);
        // Every alias parses, or names a heuristic that is planned.
        for (_, search) in ALIASES {
            match parse_search(search) {
                Ok(_) | Err(ConfigError::NotYetSupported { .. }) => {}
                Err(e) => panic!("{search}: {e}"),
            }
        }
    }

    #[test]
    fn planned_heuristics_are_not_yet_supported() {
        assert_eq!(
            err("astar(ipdb(max_time=infinity, pdb_max_size=2000000))"),
            "heuristic `ipdb` is not yet supported by demoplan"
        );
        assert_eq!(
            err("astar(cpdbs(patterns=[[0, 1], [2]]))"),
            "heuristic `cpdbs` is not yet supported by demoplan"
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
    fn the_full_message_lists_known_names() {
        let e = parse_search("astar(ipdb())").unwrap_err();
        assert_eq!(
            e.to_string(),
            "heuristic `ipdb` is not yet supported by demoplan\n\
             known search engines: astar\n\
             known heuristics: blind, hmax, lmcut (planned: ipdb, cpdbs)"
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
        for config in [HeuristicConfig::Blind, HeuristicConfig::HMax] {
            let mut h = config.build(&task).unwrap();
            assert_eq!(h.name(), config.name());
            assert_eq!(h.evaluate(&[0]), Some(0));
        }
    }
}
