//! What a domain and problem declare that the validator looks up: the type hierarchy, the
//! objects and their types, the actions by name.

use std::collections::{HashMap, HashSet};

use pddl::{Action, Domain, Problem, Type};

/// The lookup tables of one domain and problem.
#[derive(Debug)]
pub(crate) struct World<'a> {
    /// The declared parents of each type; a type without one is a child of `object`.
    parents: HashMap<&'a str, Vec<&'a str>>,
    /// Each object and constant with its declared types (`object` if untyped).
    objects: HashMap<&'a str, Vec<&'a str>>,
    actions: HashMap<&'a str, &'a Action>,
}

impl<'a> World<'a> {
    pub(crate) fn new(domain: &'a Domain, problem: &'a Problem) -> World<'a> {
        let mut parents: HashMap<&str, Vec<&str>> = HashMap::new();
        for t in &domain.types {
            let entry = parents.entry(t.name.as_str()).or_default();
            entry.extend(t.ty.iter().flat_map(Type::names).map(|n| n.as_str()));
        }
        let mut objects: HashMap<&str, Vec<&str>> = HashMap::new();
        for o in domain.constants.iter().chain(&problem.objects) {
            let types = objects.entry(o.name.as_str()).or_default();
            match &o.ty {
                Some(ty) => types.extend(ty.names().iter().map(|n| n.as_str())),
                None => types.push("object"),
            }
        }
        // The first action of a name wins; the pddl crate's checks refuse duplicates.
        let mut actions = HashMap::new();
        for a in &domain.actions {
            actions.entry(a.name.as_str()).or_insert(a);
        }
        World {
            parents,
            objects,
            actions,
        }
    }

    pub(crate) fn action(&self, name: &str) -> Option<&'a Action> {
        self.actions.get(name).copied()
    }

    /// The declared types of an object, or `None` if it is neither an object of the
    /// problem nor a constant of the domain.
    pub(crate) fn object_types(&self, object: &str) -> Option<&[&'a str]> {
        self.objects.get(object).map(Vec::as_slice)
    }

    /// Whether `object` belongs to `ty`: one of its declared types is `ty` or a
    /// descendant of one of the types `ty` names. No type means `object`, which every
    /// object belongs to.
    pub(crate) fn has_type(&self, object: &str, ty: Option<&Type>) -> bool {
        let Some(ty) = ty else {
            return self.objects.contains_key(object);
        };
        self.object_types(object).is_some_and(|declared| {
            declared
                .iter()
                .any(|d| ty.names().iter().any(|t| self.is_subtype(d, t.as_str())))
        })
    }

    /// Whether `sub` is `sup` or a descendant of it. A breadth-first walk up the
    /// hierarchy that visits each type once, so a cycle cannot make it loop.
    fn is_subtype(&self, sub: &str, sup: &str) -> bool {
        if sup == "object" || sub == sup {
            return true;
        }
        let mut seen: HashSet<&str> = HashSet::from([sub]);
        let mut queue: Vec<&str> = vec![sub];
        while let Some(t) = queue.pop() {
            for &p in self.parents.get(t).into_iter().flatten() {
                if p == sup {
                    return true;
                }
                if seen.insert(p) {
                    queue.push(p);
                }
            }
        }
        false
    }
}
