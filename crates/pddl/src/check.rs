//! Semantic checks: every name is declared, every atom has the right arity, nothing is
//! declared twice, the type hierarchy has no cycle.

use std::collections::{HashMap, HashSet};

use crate::ast::*;
use crate::PddlError;

/// The names a domain declares, for looking up atoms.
struct Declarations<'a> {
    types: HashSet<&'a str>,
    predicates: HashMap<&'a str, usize>,
    functions: HashMap<&'a str, usize>,
    constants: HashSet<&'a str>,
}

impl<'a> Declarations<'a> {
    fn of(d: &'a Domain) -> Declarations<'a> {
        let mut types: HashSet<&str> = HashSet::from(["object"]);
        for t in &d.types {
            types.insert(&t.name.text);
            // A type named only as a parent is declared by that use, as Fast Downward reads it.
            if let Some(parent) = &t.ty {
                types.extend(parent.names().iter().map(|n| n.as_str()));
            }
        }
        Declarations {
            types,
            predicates: d
                .predicates
                .iter()
                .map(|p| (p.name.as_str(), p.params.len()))
                .collect(),
            functions: d
                .functions
                .iter()
                .map(|f| (f.name.as_str(), f.params.len()))
                .collect(),
            constants: d.constants.iter().map(|c| c.name.as_str()).collect(),
        }
    }

    fn check_type(&self, ty: &Option<Type>) -> Result<(), PddlError> {
        for n in ty.iter().flat_map(Type::names) {
            if !self.types.contains(n.as_str()) {
                return Err(
                    PddlError::semantic(n.span, format!("undefined type `{}`", n.text))
                        .with_label("not declared in `(:types ...)`"),
                );
            }
        }
        Ok(())
    }

    fn check_atom(
        &self,
        atom: &Atom,
        known: &dyn Fn(&Term) -> bool,
        where_: &str,
    ) -> Result<(), PddlError> {
        let expected = if atom.is_equality() {
            2
        } else {
            *self
                .predicates
                .get(atom.predicate.as_str())
                .ok_or_else(|| {
                    PddlError::semantic(
                        atom.predicate.span,
                        format!("undefined predicate `{}`", atom.predicate.text),
                    )
                    .with_label("not declared in `(:predicates ...)`")
                })?
        };
        check_arity(
            "predicate",
            &atom.predicate,
            expected,
            atom.args.len(),
            atom.span,
        )?;
        check_terms(&atom.args, known, where_)
    }

    fn check_function_term(
        &self,
        term: &FunctionTerm,
        known: &dyn Fn(&Term) -> bool,
        where_: &str,
    ) -> Result<(), PddlError> {
        let expected = *self.functions.get(term.function.as_str()).ok_or_else(|| {
            PddlError::semantic(
                term.function.span,
                format!("undefined function `{}`", term.function.text),
            )
            .with_label("not declared in `(:functions ...)`")
        })?;
        check_arity(
            "function",
            &term.function,
            expected,
            term.args.len(),
            term.span,
        )?;
        check_terms(&term.args, known, where_)
    }
}

fn check_arity(
    what: &str,
    name: &Name,
    expected: usize,
    found: usize,
    span: crate::Span,
) -> Result<(), PddlError> {
    if expected == found {
        return Ok(());
    }
    let plural = if expected == 1 { "" } else { "s" };
    Err(PddlError::semantic(
        span,
        format!(
            "{what} `{}` takes {expected} argument{plural}, found {found}",
            name.text
        ),
    )
    .with_label(format!("{found} given")))
}

fn check_terms(
    args: &[Term],
    known: &dyn Fn(&Term) -> bool,
    where_: &str,
) -> Result<(), PddlError> {
    for t in args {
        if !known(t) {
            let n = t.name();
            let message = match t {
                Term::Variable(_) => format!("undefined variable `{}`", n.text),
                Term::Object(_) => format!("unknown object `{}`", n.text),
            };
            return Err(
                PddlError::semantic(n.span, message).with_label(format!("not declared {where_}"))
            );
        }
    }
    Ok(())
}

fn no_duplicates<'a>(
    names: impl IntoIterator<Item = &'a Name>,
    what: &str,
) -> Result<(), PddlError> {
    let mut seen: HashSet<&str> = HashSet::new();
    for n in names {
        if !seen.insert(n.as_str()) {
            return Err(PddlError::semantic(
                n.span,
                format!("{what} `{}` is declared twice", n.text),
            )
            .with_label("second declaration"));
        }
    }
    Ok(())
}

fn check_type_cycles(d: &Domain) -> Result<(), PddlError> {
    let mut parents: HashMap<&str, Vec<&Name>> = HashMap::new();
    for t in &d.types {
        if let Some(p) = &t.ty {
            parents
                .entry(t.name.as_str())
                .or_default()
                .extend(p.names());
        }
    }
    // Depth-first search from every type; a type met again on the current path closes a cycle.
    for t in &d.types {
        let mut path: Vec<&str> = vec![t.name.as_str()];
        let mut stack: Vec<(usize, &Name)> = parents
            .get(t.name.as_str())
            .into_iter()
            .flatten()
            .map(|n| (1, *n))
            .collect();
        let mut visited: HashSet<&str> = HashSet::new();
        while let Some((depth, n)) = stack.pop() {
            path.truncate(depth);
            if path.contains(&n.as_str()) {
                path.push(n.as_str());
                return Err(PddlError::semantic(
                    n.span,
                    format!("type hierarchy has a cycle: {}", path.join(" - ")),
                )
                .with_label("closes the cycle"));
            }
            if !visited.insert(n.as_str()) {
                continue;
            }
            path.push(n.as_str());
            stack.extend(
                parents
                    .get(n.as_str())
                    .into_iter()
                    .flatten()
                    .map(|p| (depth + 1, *p)),
            );
        }
    }
    Ok(())
}

pub(crate) fn check_domain(d: &Domain) -> Result<(), PddlError> {
    let decl = Declarations::of(d);
    for t in &d.types {
        if t.name.as_str() == "object"
            && t.ty
                .as_ref()
                .is_some_and(|p| p.names().iter().any(|n| n.as_str() != "object"))
        {
            return Err(PddlError::semantic(
                t.name.span,
                "`object` is the root type and has no parent",
            ));
        }
    }
    check_type_cycles(d)?;
    for c in &d.constants {
        decl.check_type(&c.ty)?;
    }
    no_duplicates(d.constants.iter().map(|c| &c.name), "constant")?;
    no_duplicates(d.predicates.iter().map(|p| &p.name), "predicate")?;
    no_duplicates(d.functions.iter().map(|f| &f.name), "function")?;
    no_duplicates(d.actions.iter().map(|a| &a.name), "action")?;
    for p in &d.predicates {
        for param in &p.params {
            decl.check_type(&param.ty)?;
        }
    }
    for f in &d.functions {
        for param in &f.params {
            decl.check_type(&param.ty)?;
        }
        if f.name.as_str() == "total-cost" && !f.params.is_empty() {
            return Err(PddlError::semantic(
                f.name.span,
                "`total-cost` takes no arguments",
            ));
        }
    }
    for a in &d.actions {
        check_action(&decl, a)?;
    }
    Ok(())
}

fn check_action(decl: &Declarations<'_>, a: &Action) -> Result<(), PddlError> {
    no_duplicates(a.params.iter().map(|p| &p.name), "parameter")?;
    for p in &a.params {
        decl.check_type(&p.ty)?;
    }
    let params: HashSet<&str> = a.params.iter().map(|p| p.name.as_str()).collect();
    let known = |t: &Term| match t {
        Term::Variable(n) => params.contains(n.as_str()),
        Term::Object(n) => decl.constants.contains(n.as_str()),
    };
    let where_ = "as a parameter of this action or a constant of the domain";
    for l in &a.precondition {
        decl.check_atom(&l.atom, &known, where_)?;
    }
    for e in &a.effects {
        match e {
            Effect::Add(atom) | Effect::Delete(atom) => {
                if atom.is_equality() {
                    return Err(
                        PddlError::semantic(atom.span, "equality cannot be an effect")
                            .with_label("`=` is fixed by the objects"),
                    );
                }
                decl.check_atom(atom, &known, where_)?;
            }
            Effect::IncreaseCost(CostExpr::Constant(n)) => {
                if n.value < 0 {
                    return Err(PddlError::semantic(
                        n.span,
                        format!("negative action cost {}", n.value),
                    )
                    .with_label("costs must be 0 or more"));
                }
            }
            Effect::IncreaseCost(CostExpr::Function(term)) => {
                if term.function.as_str() == "total-cost" {
                    return Err(PddlError::unsupported(
                        term.span,
                        "costs that depend on `total-cost`",
                    ));
                }
                decl.check_function_term(term, &known, where_)?;
            }
        }
    }
    Ok(())
}

pub(crate) fn check_problem(d: &Domain, p: &Problem) -> Result<(), PddlError> {
    let decl = Declarations::of(d);
    for o in &p.objects {
        decl.check_type(&o.ty)?;
    }
    no_duplicates(p.objects.iter().map(|o| &o.name), "object")?;
    let objects: HashSet<&str> = p.objects.iter().map(|o| o.name.as_str()).collect();
    let known = |t: &Term| match t {
        Term::Variable(_) => false,
        Term::Object(n) => objects.contains(n.as_str()) || decl.constants.contains(n.as_str()),
    };
    let where_ = "in `(:objects ...)` or as a constant of the domain";
    for entry in &p.init {
        match entry {
            InitEntry::Fact(atom) => {
                if atom.is_equality() {
                    return Err(PddlError::semantic(
                        atom.span,
                        "equality cannot be an initial fact",
                    )
                    .with_label("`=` is fixed by the objects"));
                }
                decl.check_atom(atom, &known, where_)?;
            }
            InitEntry::FunctionValue { term, .. } => {
                if term.function.as_str() != "total-cost"
                    || decl.functions.contains_key("total-cost")
                {
                    decl.check_function_term(term, &known, where_)?;
                }
            }
        }
    }
    for l in &p.goal {
        decl.check_atom(&l.atom, &known, where_)?;
    }
    Ok(())
}
