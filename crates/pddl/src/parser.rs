//! From S-expressions to the typed AST: PDDL's grammar, and the line between the
//! supported fragment and the rest of PDDL.

// A reader of untrusted input (issue 23): no arithmetic that can wrap or panic, no
// cast that can truncate; each such operation is checked, saturating or proved in range.
#![deny(clippy::arithmetic_side_effects, clippy::cast_possible_truncation)]

use crate::ast::*;
use crate::lexer::{read_single_list, Comments, SExpr, Token};
use crate::{PddlError, Span};

/// A parsed file: a domain or a problem.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum PddlFile {
    /// `(define (domain ...) ...)`.
    Domain(Domain),
    /// `(define (problem ...) ...)`.
    Problem(Problem),
}

pub(crate) fn parse_file(source: &str) -> Result<(PddlFile, Comments), PddlError> {
    let (top, comments) = read_single_list(source)?;
    let (items, span) = as_list(&top, "`(define ...)`")?;
    let define = items
        .first()
        .ok_or_else(|| PddlError::syntax(span, "empty list where `(define ...)` was expected"))?;
    let define_token = expect_token(define, "`define`")?;
    if define_token.text != "define" {
        return Err(PddlError::syntax(
            define_token.span,
            format!("expected `define`, found `{}`", define_token.text),
        )
        .with_label("a PDDL file starts with `(define`"));
    }
    let header = items.get(1).ok_or_else(|| {
        PddlError::syntax(
            span,
            "`(define` has no `(domain NAME)` or `(problem NAME)` header",
        )
    })?;
    let (header_items, header_span) = as_list(header, "`(domain NAME)` or `(problem NAME)`")?;
    let kind = header_items
        .first()
        .map(|e| expect_token(e, "`domain` or `problem`"))
        .transpose()?
        .ok_or_else(|| {
            PddlError::syntax(header_span, "expected `(domain NAME)` or `(problem NAME)`")
        })?;
    if header_items.len() != 2 {
        return Err(PddlError::syntax(
            header_span,
            format!("expected `({} NAME)` with exactly one name", kind.text),
        ));
    }
    let name = plain_name(expect_token(&header_items[1], "a name")?, "a name")?;
    let sections = &items[2..];
    match kind.text.as_str() {
        "domain" => Ok((PddlFile::Domain(domain(name, sections)?), comments)),
        "problem" => Ok((PddlFile::Problem(problem(name, sections)?), comments)),
        other => Err(PddlError::syntax(
            kind.span,
            format!("expected `domain` or `problem`, found `{other}`"),
        )),
    }
}

fn as_list<'a>(e: &'a SExpr, what: &str) -> Result<(&'a [SExpr], Span), PddlError> {
    match e {
        SExpr::List { items, span } => Ok((items, *span)),
        SExpr::Token(t) => Err(PddlError::syntax(
            t.span,
            format!("expected {what} in parentheses, found `{}`", t.text),
        )
        .with_label("expected `(`")),
    }
}

fn expect_token<'a>(e: &'a SExpr, what: &str) -> Result<&'a Token, PddlError> {
    match e {
        SExpr::Token(t) => Ok(t),
        SExpr::List { span, .. } => Err(PddlError::syntax(
            *span,
            format!("expected {what}, found a parenthesised list"),
        )
        .with_label(format!("expected {what}"))),
    }
}

/// A name of a type, predicate, function, action or object: not a variable, keyword or `-`.
fn plain_name(t: &Token, what: &str) -> Result<Name, PddlError> {
    let bad = if t.text.starts_with('?') {
        Some("a variable")
    } else if t.text.starts_with(':') {
        Some("a keyword")
    } else if t.text == "-" {
        Some("`-`")
    } else {
        None
    };
    match bad {
        Some(found) => Err(PddlError::syntax(
            t.span,
            format!("expected {what}, found {found} `{}`", t.text),
        )
        .with_label(format!("expected {what}"))),
        None => Ok(Name {
            text: t.text.clone(),
            span: t.span,
        }),
    }
}

fn variable(t: &Token) -> Result<Name, PddlError> {
    if t.text.starts_with('?') && t.text.len() > 1 {
        Ok(Name {
            text: t.text.clone(),
            span: t.span,
        })
    } else {
        Err(PddlError::syntax(
            t.span,
            format!("expected a variable `?name`, found `{}`", t.text),
        )
        .with_label("parameters start with `?`"))
    }
}

#[derive(Clone, Copy, PartialEq, Eq)]
enum ItemKind {
    Variable,
    Name,
}

/// `a b - t1 c - (either t2 t3) d`: items followed by `- type` take that type; items at
/// the end without one have none.
fn typed_list(items: &[SExpr], kind: ItemKind, what: &str) -> Result<Vec<Typed>, PddlError> {
    let mut out: Vec<Typed> = Vec::new();
    let mut untyped_from = 0;
    let mut i = 0usize;
    while i < items.len() {
        let token = expect_token(&items[i], what)?;
        if token.text == "-" {
            if untyped_from == out.len() {
                return Err(
                    PddlError::syntax(token.span, format!("`-` with no {what} before it"))
                        .with_label("a type needs names to apply to"),
                );
            }
            let ty = match items.get(i.saturating_add(1)) {
                Some(e) => parse_type(e)?,
                None => {
                    return Err(PddlError::syntax(token.span, "expected a type after `-`")
                        .with_label("the list ends here"))
                }
            };
            for item in &mut out[untyped_from..] {
                item.ty = Some(ty.clone());
            }
            untyped_from = out.len();
            i = i.saturating_add(2);
        } else {
            let name = match kind {
                ItemKind::Variable => variable(token)?,
                ItemKind::Name => plain_name(token, what)?,
            };
            out.push(Typed { name, ty: None });
            i = i.saturating_add(1);
        }
    }
    Ok(out)
}

fn parse_type(e: &SExpr) -> Result<Type, PddlError> {
    match e {
        SExpr::Token(t) => Ok(Type::Named(plain_name(t, "a type")?)),
        SExpr::List { items, span } => {
            let head = items
                .first()
                .map(|h| expect_token(h, "`either`"))
                .transpose()?;
            match head {
                Some(h) if h.text == "either" && items.len() > 1 => {
                    let names = items[1..]
                        .iter()
                        .map(|e| plain_name(expect_token(e, "a type")?, "a type"))
                        .collect::<Result<Vec<_>, _>>()?;
                    Ok(Type::Either(names))
                }
                _ => Err(PddlError::syntax(
                    *span,
                    "expected a type name or `(either t1 t2 ...)`",
                )),
            }
        }
    }
}

/// The keyword heading a section, e.g. `:predicates`.
fn section_keyword<'a>(
    e: &'a SExpr,
    what: &str,
) -> Result<(&'a Token, &'a [SExpr], Span), PddlError> {
    let (items, span) = as_list(e, what)?;
    let head = items
        .first()
        .ok_or_else(|| PddlError::syntax(span, format!("empty list where {what} was expected")))?;
    let head = expect_token(head, "a section keyword such as `:predicates`")?;
    if !head.text.starts_with(':') {
        return Err(PddlError::syntax(
            head.span,
            format!(
                "expected a section keyword such as `:action`, found `{}`",
                head.text
            ),
        )
        .with_label("sections start with `:`")
        .with_help("check the parentheses: this list may have closed too early or too late"));
    }
    Ok((head, &items[1..], span))
}

fn once(seen: &mut Vec<String>, head: &Token) -> Result<(), PddlError> {
    if seen.contains(&head.text) {
        return Err(
            PddlError::syntax(head.span, format!("section `{}` appears twice", head.text))
                .with_label("second occurrence"),
        );
    }
    seen.push(head.text.clone());
    Ok(())
}

fn domain(name: Name, sections: &[SExpr]) -> Result<Domain, PddlError> {
    let mut d = Domain {
        name,
        requirements: Vec::new(),
        types: Vec::new(),
        constants: Vec::new(),
        predicates: Vec::new(),
        functions: Vec::new(),
        actions: Vec::new(),
    };
    let mut seen = Vec::new();
    for section in sections {
        let (head, body, span) = section_keyword(section, "a domain section")?;
        match head.text.as_str() {
            ":requirements" => {
                once(&mut seen, head)?;
                d.requirements = requirements(body)?;
            }
            ":types" => {
                once(&mut seen, head)?;
                d.types = typed_list(body, ItemKind::Name, "type names")?;
            }
            ":constants" => {
                once(&mut seen, head)?;
                d.constants = typed_list(body, ItemKind::Name, "constant names")?;
            }
            ":predicates" => {
                once(&mut seen, head)?;
                for p in body {
                    let (items, span) = as_list(p, "a predicate declaration")?;
                    let (name, params) = skeleton(items, span, "a predicate name")?;
                    d.predicates.push(PredicateDecl { name, params });
                }
            }
            ":functions" => {
                once(&mut seen, head)?;
                d.functions = functions(body)?;
            }
            ":action" => d.actions.push(action(body, span)?),
            ":derived" => {
                return Err(PddlError::unsupported(
                    head.span,
                    "derived predicates (`:derived`)",
                ))
            }
            ":durative-action" => {
                return Err(PddlError::unsupported(
                    head.span,
                    "durative actions (`:durative-action`)",
                ))
            }
            ":constraints" => {
                return Err(PddlError::unsupported(
                    head.span,
                    "constraints (`:constraints`)",
                ))
            }
            ":process" | ":event" => {
                return Err(PddlError::unsupported(
                    head.span,
                    "processes and events (PDDL+)",
                ))
            }
            other => {
                return Err(PddlError::syntax(
                    head.span,
                    format!("unknown domain section `{other}`"),
                )
                .with_label("not a domain section")
                .with_help(
                    "a domain has :requirements, :types, :constants, :predicates, :functions \
                         and :action sections",
                ))
            }
        }
    }
    Ok(d)
}

fn requirements(body: &[SExpr]) -> Result<Vec<Requirement>, PddlError> {
    body.iter()
        .map(|e| {
            let t = expect_token(e, "a requirement such as `:strips`")?;
            if t.text.starts_with(':') && t.text.len() > 1 {
                Ok(Requirement {
                    name: t.text.clone(),
                    span: t.span,
                })
            } else {
                Err(PddlError::syntax(
                    t.span,
                    format!(
                        "expected a requirement such as `:strips`, found `{}`",
                        t.text
                    ),
                )
                .with_label("requirements start with `:`"))
            }
        })
        .collect()
}

/// `(name ?a ?b - t)`: a predicate or function declaration.
fn skeleton(items: &[SExpr], span: Span, what: &str) -> Result<(Name, Vec<Typed>), PddlError> {
    let head = items
        .first()
        .ok_or_else(|| PddlError::syntax(span, format!("empty list where {what} was expected")))?;
    let name = plain_name(expect_token(head, what)?, what)?;
    let params = typed_list(&items[1..], ItemKind::Variable, "parameters")?;
    Ok((name, params))
}

fn functions(body: &[SExpr]) -> Result<Vec<FunctionDecl>, PddlError> {
    let mut out = Vec::new();
    let mut i = 0usize;
    while i < body.len() {
        match &body[i] {
            SExpr::List { items, span } => {
                let (name, params) = skeleton(items, *span, "a function name")?;
                out.push(FunctionDecl { name, params });
                i = i.saturating_add(1);
            }
            SExpr::Token(t) if t.text == "-" => {
                match body.get(i.saturating_add(1)) {
                    Some(SExpr::Token(ty)) if ty.text == "number" => {}
                    Some(other) => {
                        return Err(PddlError::unsupported(
                            other.span(),
                            "functions of a type other than `number` (object fluents)",
                        ))
                    }
                    None => return Err(PddlError::syntax(t.span, "expected `number` after `-`")),
                }
                i = i.saturating_add(2);
            }
            SExpr::Token(t) => {
                return Err(PddlError::syntax(
                    t.span,
                    format!(
                        "expected a function declaration `(name ?params)`, found `{}`",
                        t.text
                    ),
                ))
            }
        }
    }
    Ok(out)
}

fn action(body: &[SExpr], span: Span) -> Result<Action, PddlError> {
    let name_expr = body
        .first()
        .ok_or_else(|| PddlError::syntax(span, "`:action` without a name"))?;
    let name = plain_name(expect_token(name_expr, "an action name")?, "an action name")?;
    let mut a = Action {
        name,
        params: Vec::new(),
        precondition: Vec::new(),
        effects: Vec::new(),
    };
    let mut seen = Vec::new();
    let mut i = 1;
    while i < body.len() {
        let key = expect_token(&body[i], "`:parameters`, `:precondition` or `:effect`")?;
        let value = body.get(i.saturating_add(1)).ok_or_else(|| {
            PddlError::syntax(key.span, format!("`{}` has no value", key.text))
                .with_label("expected a list after this")
        })?;
        match key.text.as_str() {
            ":parameters" => {
                once(&mut seen, key)?;
                let (items, _) = as_list(value, "a parameter list")?;
                a.params = typed_list(items, ItemKind::Variable, "parameters")?;
            }
            ":precondition" => {
                once(&mut seen, key)?;
                condition(value, &mut a.precondition, Scope::Schema)?;
            }
            ":effect" => {
                once(&mut seen, key)?;
                effect(value, &mut a.effects)?;
            }
            ":vars" | ":duration" | ":condition" => {
                return Err(PddlError::unsupported(
                    key.span,
                    &format!("action keywords like `{}`", key.text),
                ))
            }
            other => {
                return Err(PddlError::syntax(
                    key.span,
                    format!(
                        "expected `:parameters`, `:precondition` or `:effect`, found `{other}`"
                    ),
                )
                .with_label("not an action keyword"))
            }
        }
        i = i.saturating_add(2);
    }
    Ok(a)
}

/// Where a condition stands: an action schema may use variables, a goal may not.
#[derive(Clone, Copy, PartialEq, Eq)]
enum Scope {
    Schema,
    Goal,
}

/// Adds the literals of a condition to `out`, flattening `and`.
fn condition(e: &SExpr, out: &mut Vec<Literal>, scope: Scope) -> Result<(), PddlError> {
    let (items, span) = as_list(e, "a condition")?;
    let Some(head) = items.first() else {
        return Ok(());
    };
    let head = expect_token(head, "a predicate name or `and`/`not`")?;
    match head.text.as_str() {
        "and" => {
            for c in &items[1..] {
                condition(c, out, scope)?;
            }
            Ok(())
        }
        "not" => {
            let [inner] = &items[1..] else {
                return Err(PddlError::syntax(span, "`not` takes exactly one condition"));
            };
            let (inner_items, inner_span) = as_list(inner, "an atom")?;
            if let Some(SExpr::Token(h)) = inner_items.first() {
                if let Some(feature) = compound_condition(&h.text) {
                    return Err(PddlError::unsupported(
                        h.span,
                        &format!("negated {feature}"),
                    ));
                }
            }
            out.push(Literal {
                positive: false,
                atom: atom(inner_items, inner_span, scope)?,
            });
            Ok(())
        }
        text => {
            if let Some(feature) = compound_condition(text) {
                return Err(PddlError::unsupported(head.span, feature));
            }
            out.push(Literal {
                positive: true,
                atom: atom(items, span, scope)?,
            });
            Ok(())
        }
    }
}

/// The feature name of a condition head outside the fragment, if it is one.
fn compound_condition(head: &str) -> Option<&'static str> {
    Some(match head {
        "and" | "not" => "compound conditions (`and`/`not` inside `not`)",
        "or" => "disjunctive conditions (`or`)",
        "imply" => "implications (`imply`)",
        "exists" => "existential quantifiers (`exists`)",
        "forall" => "universal quantifiers (`forall`)",
        "<" | "<=" | ">" | ">=" => "numeric conditions",
        "preference" => "preferences",
        "when" => "conditional effects (`when`)",
        _ => return None,
    })
}

fn atom(items: &[SExpr], span: Span, scope: Scope) -> Result<Atom, PddlError> {
    let head = items
        .first()
        .ok_or_else(|| PddlError::syntax(span, "empty list where an atom was expected"))?;
    let head = expect_token(head, "a predicate name")?;
    let predicate = if head.text == "=" {
        Name {
            text: head.text.clone(),
            span: head.span,
        }
    } else {
        plain_name(head, "a predicate name")?
    };
    let args = items[1..]
        .iter()
        .map(|e| term(e, scope, predicate.text == "="))
        .collect::<Result<_, _>>()?;
    Ok(Atom {
        predicate,
        args,
        span,
    })
}

fn term(e: &SExpr, scope: Scope, in_equality: bool) -> Result<Term, PddlError> {
    match e {
        SExpr::Token(t) if t.text.starts_with('?') => {
            if scope == Scope::Goal {
                return Err(PddlError::syntax(
                    t.span,
                    format!("variable `{}` outside an action", t.text),
                )
                .with_label("goals and initial states name objects, not variables"));
            }
            Ok(Term::Variable(variable(t)?))
        }
        SExpr::Token(t) => Ok(Term::Object(plain_name(t, "an object or variable")?)),
        SExpr::List { span, .. } => Err(PddlError::unsupported(
            *span,
            if in_equality {
                "numeric conditions"
            } else {
                "function terms as arguments (object fluents)"
            },
        )),
    }
}

fn effect(e: &SExpr, out: &mut Vec<Effect>) -> Result<(), PddlError> {
    let (items, span) = as_list(e, "an effect")?;
    let Some(head) = items.first() else {
        return Ok(());
    };
    let head = expect_token(head, "a predicate name or `and`/`not`/`increase`")?;
    match head.text.as_str() {
        "and" => {
            for c in &items[1..] {
                effect(c, out)?;
            }
            Ok(())
        }
        "not" => {
            let [inner] = &items[1..] else {
                return Err(PddlError::syntax(span, "`not` takes exactly one atom"));
            };
            let (inner_items, inner_span) = as_list(inner, "an atom")?;
            if let Some(SExpr::Token(h)) = inner_items.first() {
                if matches!(h.text.as_str(), "and" | "not" | "when" | "forall") {
                    return Err(
                        PddlError::syntax(h.span, "`not` in an effect takes an atom")
                            .with_label("expected a predicate name"),
                    );
                }
            }
            out.push(Effect::Delete(atom(
                inner_items,
                inner_span,
                Scope::Schema,
            )?));
            Ok(())
        }
        "increase" => {
            out.push(Effect::IncreaseCost(increase(&items[1..], span)?));
            Ok(())
        }
        "when" => Err(PddlError::unsupported(
            head.span,
            "conditional effects (`when`)",
        )),
        "forall" => Err(PddlError::unsupported(
            head.span,
            "universal effects (`forall`)",
        )),
        "decrease" | "assign" | "scale-up" | "scale-down" => Err(PddlError::unsupported(
            head.span,
            &format!("numeric effects (`{}`)", head.text),
        )),
        "oneof" | "probabilistic" => Err(PddlError::unsupported(
            head.span,
            "non-deterministic effects",
        )),
        "or" | "exists" | "imply" => Err(PddlError::syntax(
            head.span,
            format!("`{}` cannot be an effect", head.text),
        )),
        _ => {
            let a = atom(items, span, Scope::Schema)?;
            out.push(Effect::Add(a));
            Ok(())
        }
    }
}

fn increase(args: &[SExpr], span: Span) -> Result<CostExpr, PddlError> {
    let [target, amount] = args else {
        return Err(PddlError::syntax(
            span,
            "`increase` takes a function and an amount",
        ));
    };
    let (t_items, t_span) = as_list(target, "`(total-cost)`")?;
    let is_total_cost = matches!(t_items, [SExpr::Token(t)] if t.text == "total-cost");
    if !is_total_cost {
        return Err(PddlError::unsupported(
            t_span,
            "numeric fluents other than `total-cost`",
        ));
    }
    match amount {
        SExpr::Token(t) => Ok(CostExpr::Constant(number(t)?)),
        SExpr::List { items, span } => {
            if let Some(SExpr::Token(h)) = items.first() {
                if matches!(h.text.as_str(), "+" | "-" | "*" | "/") {
                    return Err(PddlError::unsupported(
                        h.span,
                        "arithmetic in cost expressions",
                    ));
                }
            }
            Ok(CostExpr::Function(function_term(
                items,
                *span,
                Scope::Schema,
            )?))
        }
    }
}

fn function_term(items: &[SExpr], span: Span, scope: Scope) -> Result<FunctionTerm, PddlError> {
    let head = items
        .first()
        .ok_or_else(|| PddlError::syntax(span, "empty list where a function term was expected"))?;
    let function = plain_name(expect_token(head, "a function name")?, "a function name")?;
    let args = items[1..]
        .iter()
        .map(|e| term(e, scope, false))
        .collect::<Result<_, _>>()?;
    Ok(FunctionTerm {
        function,
        args,
        span,
    })
}

fn number(t: &Token) -> Result<Number, PddlError> {
    if let Ok(value) = t.text.parse::<i64>() {
        return Ok(Number {
            value,
            span: t.span,
        });
    }
    if t.text.parse::<f64>().is_ok() {
        return Err(PddlError::unsupported(t.span, "non-integer numbers")
            .with_help("action costs and function values must be integers"));
    }
    Err(PddlError::syntax(
        t.span,
        format!("expected an integer, found `{}`", t.text),
    ))
}

fn problem(name: Name, sections: &[SExpr]) -> Result<Problem, PddlError> {
    let whole = name.span;
    let mut domain = None;
    let mut p = Problem {
        name,
        domain: Name::new(""),
        requirements: Vec::new(),
        objects: Vec::new(),
        init: Vec::new(),
        goal: Vec::new(),
        metric: None,
    };
    let mut has_goal = false;
    let mut seen = Vec::new();
    for section in sections {
        let (head, body, span) = section_keyword(section, "a problem section")?;
        once(&mut seen, head)?;
        match head.text.as_str() {
            ":domain" => {
                let [n] = body else {
                    return Err(PddlError::syntax(span, "expected `(:domain NAME)`"));
                };
                domain = Some(plain_name(
                    expect_token(n, "a domain name")?,
                    "a domain name",
                )?);
            }
            ":requirements" => p.requirements = requirements(body)?,
            ":objects" => p.objects = typed_list(body, ItemKind::Name, "object names")?,
            ":init" => {
                for e in body {
                    p.init.push(init_entry(e)?);
                }
            }
            ":goal" => {
                let [g] = body else {
                    return Err(
                        PddlError::syntax(span, "`:goal` takes exactly one condition")
                            .with_help("join several goals with `(and ...)`"),
                    );
                };
                condition(g, &mut p.goal, Scope::Goal)?;
                has_goal = true;
            }
            ":metric" => p.metric = Some(metric(body, span)?),
            ":constraints" => {
                return Err(PddlError::unsupported(
                    head.span,
                    "constraints (`:constraints`)",
                ))
            }
            other => {
                return Err(PddlError::syntax(
                    head.span,
                    format!("unknown problem section `{other}`"),
                )
                .with_label("not a problem section")
                .with_help(
                    "a problem has :domain, :requirements, :objects, :init, :goal and :metric \
                         sections",
                ))
            }
        }
    }
    p.domain = domain.ok_or_else(|| {
        PddlError::syntax(
            whole,
            format!("problem `{}` does not name its domain", p.name.text),
        )
        .with_label("no `(:domain NAME)` in this problem")
        .with_help("add `(:domain NAME)`")
    })?;
    if !has_goal {
        return Err(
            PddlError::syntax(whole, format!("problem `{}` has no `:goal`", p.name.text))
                .with_label("no `(:goal ...)` in this problem"),
        );
    }
    Ok(p)
}

fn init_entry(e: &SExpr) -> Result<InitEntry, PddlError> {
    let (items, span) = as_list(e, "an initial fact")?;
    match items.first() {
        Some(SExpr::Token(h)) if h.text == "=" => {
            let [term_expr, value] = &items[1..] else {
                return Err(PddlError::syntax(
                    span,
                    "expected `(= (function args) value)`",
                ));
            };
            let (t_items, t_span) = as_list(term_expr, "a function term")?;
            let term = function_term(t_items, t_span, Scope::Goal)?;
            let value = number(expect_token(value, "a number")?)?;
            Ok(InitEntry::FunctionValue { term, value })
        }
        Some(SExpr::Token(h)) if h.text == "not" => {
            Err(PddlError::semantic(span, "negative facts in `:init`")
                .with_label("facts not listed are false")
                .with_help("the initial state is closed-world: remove this entry"))
        }
        _ => Ok(InitEntry::Fact(atom(items, span, Scope::Goal)?)),
    }
}

fn metric(body: &[SExpr], span: Span) -> Result<Metric, PddlError> {
    let [direction, expr] = body else {
        return Err(PddlError::syntax(
            span,
            "expected `(:metric minimize (total-cost))`",
        ));
    };
    let direction = expect_token(direction, "`minimize`")?;
    if direction.text != "minimize" {
        return Err(PddlError::unsupported(
            direction.span,
            &format!("`{}` metrics", direction.text),
        )
        .with_help("only `(:metric minimize (total-cost))` is supported"));
    }
    match expr {
        SExpr::List { items, .. } if matches!(items.as_slice(), [SExpr::Token(t)] if t.text == "total-cost") => {
            Ok(Metric { span })
        }
        other => Err(PddlError::unsupported(
            other.span(),
            "metrics other than `(total-cost)`",
        )),
    }
}
