//! The lifted task with names resolved to indices: objects, predicates split into static
//! and fluent, action schemas as patterns over parameters, and the ground init and goal.

use rustc_hash::{FxHashMap, FxHashSet};

use crate::TranslateError;

/// Index of an object (domain constant or problem object).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub(crate) struct ObjId(pub u32);

/// Index of a predicate.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub(crate) struct PredId(pub u32);

/// An argument of a pattern: a schema parameter or an object.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub(crate) enum Arg {
    Param(u32),
    Obj(ObjId),
}

/// A lifted atom.
#[derive(Debug, Clone, PartialEq, Eq)]
pub(crate) struct Pattern {
    pub pred: PredId,
    pub args: Vec<Arg>,
}

/// A summand of an action's cost.
#[derive(Debug, Clone, PartialEq, Eq)]
pub(crate) enum CostTerm {
    Constant(u64),
    Function { name: String, args: Vec<Arg> },
}

/// An action schema compiled to patterns.
#[derive(Debug, Clone)]
pub(crate) struct Schema {
    pub name: String,
    /// Per parameter, the objects of its type, and a membership table by object index.
    pub domains: Vec<Vec<ObjId>>,
    pub allowed: Vec<Vec<bool>>,
    pub positive: Vec<Pattern>,
    pub negative: Vec<Pattern>,
    /// `(= a b)` (true) and `(not (= a b))` (false).
    pub equalities: Vec<(Arg, Arg, bool)>,
    pub add: Vec<Pattern>,
    pub delete: Vec<Pattern>,
    pub cost: Vec<CostTerm>,
}

/// A predicate.
#[derive(Debug, Clone)]
pub(crate) struct Predicate {
    pub name: String,
    /// True if some action changes it; static predicates are compiled away.
    pub fluent: bool,
}

/// The whole task with indices.
#[derive(Debug, Clone)]
pub(crate) struct Model {
    pub objects: Vec<String>,
    pub predicates: Vec<Predicate>,
    pub schemas: Vec<Schema>,
    pub init: Vec<(PredId, Vec<ObjId>)>,
    /// Ground goal literals; equality is already evaluated.
    pub goal: Vec<(bool, PredId, Vec<ObjId>)>,
    /// False if a goal literal over equality is false.
    pub goal_equalities_hold: bool,
    pub function_values: FxHashMap<(String, Vec<ObjId>), i64>,
    pub use_costs: bool,
}

impl Model {
    pub fn build(domain: &pddl::Domain, problem: &pddl::Problem) -> Result<Model, TranslateError> {
        // Objects: constants, then problem objects, each with its declared type.
        let mut objects: Vec<String> = Vec::new();
        let mut object_index: FxHashMap<&str, ObjId> = FxHashMap::default();
        let mut object_types: Vec<Vec<&str>> = Vec::new();
        for t in domain.constants.iter().chain(&problem.objects) {
            let id = *object_index.entry(t.name.as_str()).or_insert_with(|| {
                objects.push(t.name.text.clone());
                object_types.push(Vec::new());
                ObjId(objects.len() as u32 - 1)
            });
            match &t.ty {
                Some(ty) => {
                    object_types[id.0 as usize].extend(ty.names().iter().map(|n| n.as_str()))
                }
                None => object_types[id.0 as usize].push("object"),
            }
        }
        // Type hierarchy: every ancestor of every declared type (a type may have several
        // parents when it is declared more than once).
        let mut parents: FxHashMap<&str, Vec<&str>> = FxHashMap::default();
        for t in &domain.types {
            if let Some(p) = &t.ty {
                parents
                    .entry(t.name.as_str())
                    .or_default()
                    .extend(p.names().iter().map(|n| n.as_str()));
            }
        }
        let mut members: FxHashMap<&str, Vec<ObjId>> = FxHashMap::default();
        for (i, declared) in object_types.iter().enumerate() {
            let mut seen: FxHashSet<&str> = FxHashSet::default();
            let mut stack: Vec<&str> = declared.clone();
            stack.push("object");
            while let Some(t) = stack.pop() {
                if seen.insert(t) {
                    members.entry(t).or_default().push(ObjId(i as u32));
                    stack.extend(parents.get(t).into_iter().flatten());
                }
            }
        }
        let all_objects: Vec<ObjId> = (0..objects.len() as u32).map(ObjId).collect();
        let objects_of = |ty: &Option<pddl::Type>| -> Vec<ObjId> {
            match ty {
                None => all_objects.clone(),
                Some(ty) => {
                    let mut out: Vec<ObjId> = ty
                        .names()
                        .iter()
                        .flat_map(|n| members.get(n.as_str()).into_iter().flatten().copied())
                        .collect();
                    out.sort_unstable();
                    out.dedup();
                    out
                }
            }
        };

        let mut fluent: FxHashSet<&str> = FxHashSet::default();
        for a in &domain.actions {
            for e in &a.effects {
                if let pddl::Effect::Add(atom) | pddl::Effect::Delete(atom) = e {
                    fluent.insert(atom.predicate.as_str());
                }
            }
        }
        let predicates: Vec<Predicate> = domain
            .predicates
            .iter()
            .map(|p| Predicate {
                name: p.name.text.clone(),
                fluent: fluent.contains(p.name.as_str()),
            })
            .collect();
        let pred_index: FxHashMap<&str, PredId> = domain
            .predicates
            .iter()
            .enumerate()
            .map(|(i, p)| (p.name.as_str(), PredId(i as u32)))
            .collect();
        let pred_of = |name: &pddl::Name| {
            pred_index.get(name.as_str()).copied().ok_or_else(|| {
                TranslateError::Internal(format!("undeclared predicate `{}`", name.text))
            })
        };
        let obj_of = |name: &pddl::Name| {
            object_index.get(name.as_str()).copied().ok_or_else(|| {
                TranslateError::Internal(format!("undeclared object `{}`", name.text))
            })
        };

        let mut schemas = Vec::new();
        for a in &domain.actions {
            let params: FxHashMap<&str, u32> = a
                .params
                .iter()
                .enumerate()
                .map(|(i, p)| (p.name.as_str(), i as u32))
                .collect();
            let arg_of = |t: &pddl::Term| -> Result<Arg, TranslateError> {
                match t {
                    pddl::Term::Variable(n) => params
                        .get(n.as_str())
                        .map(|&i| Arg::Param(i))
                        .ok_or_else(|| {
                            TranslateError::Internal(format!("undeclared variable `{}`", n.text))
                        }),
                    pddl::Term::Object(n) => obj_of(n).map(Arg::Obj),
                }
            };
            let pattern_of = |atom: &pddl::Atom| -> Result<Pattern, TranslateError> {
                Ok(Pattern {
                    pred: pred_of(&atom.predicate)?,
                    args: atom.args.iter().map(arg_of).collect::<Result<_, _>>()?,
                })
            };
            let domains: Vec<Vec<ObjId>> = a.params.iter().map(|p| objects_of(&p.ty)).collect();
            let allowed = domains
                .iter()
                .map(|d| {
                    let mut v = vec![false; objects.len()];
                    for o in d {
                        v[o.0 as usize] = true;
                    }
                    v
                })
                .collect();
            let mut s = Schema {
                name: a.name.text.clone(),
                domains,
                allowed,
                positive: Vec::new(),
                negative: Vec::new(),
                equalities: Vec::new(),
                add: Vec::new(),
                delete: Vec::new(),
                cost: Vec::new(),
            };
            for l in &a.precondition {
                if l.atom.is_equality() {
                    let (x, y) = match l.atom.args.as_slice() {
                        [x, y] => (arg_of(x)?, arg_of(y)?),
                        _ => {
                            return Err(TranslateError::Internal(
                                "equality with other than 2 arguments".into(),
                            ))
                        }
                    };
                    s.equalities.push((x, y, l.positive));
                } else if l.positive {
                    s.positive.push(pattern_of(&l.atom)?);
                } else {
                    s.negative.push(pattern_of(&l.atom)?);
                }
            }
            for e in &a.effects {
                match e {
                    pddl::Effect::Add(atom) => s.add.push(pattern_of(atom)?),
                    pddl::Effect::Delete(atom) => s.delete.push(pattern_of(atom)?),
                    pddl::Effect::IncreaseCost(pddl::CostExpr::Constant(n)) => {
                        let value = u64::try_from(n.value).map_err(|_| {
                            TranslateError::Internal(format!("negative cost {}", n.value))
                        })?;
                        s.cost.push(CostTerm::Constant(value));
                    }
                    pddl::Effect::IncreaseCost(pddl::CostExpr::Function(f)) => {
                        s.cost.push(CostTerm::Function {
                            name: f.function.text.clone(),
                            args: f.args.iter().map(arg_of).collect::<Result<_, _>>()?,
                        })
                    }
                }
            }
            schemas.push(s);
        }

        let mut init = Vec::new();
        let mut function_values = FxHashMap::default();
        for entry in &problem.init {
            match entry {
                pddl::InitEntry::Fact(atom) => {
                    let args = atom
                        .args
                        .iter()
                        .map(|t| obj_of(t.name()))
                        .collect::<Result<Vec<_>, _>>()?;
                    init.push((pred_of(&atom.predicate)?, args));
                }
                pddl::InitEntry::FunctionValue { term, value } => {
                    let args = term
                        .args
                        .iter()
                        .map(|t| obj_of(t.name()))
                        .collect::<Result<Vec<_>, _>>()?;
                    function_values.insert((term.function.text.clone(), args), value.value);
                }
            }
        }
        let mut goal = Vec::new();
        let mut goal_equalities_hold = true;
        for l in &problem.goal {
            let args = l
                .atom
                .args
                .iter()
                .map(|t| obj_of(t.name()))
                .collect::<Result<Vec<_>, _>>()?;
            if l.atom.is_equality() {
                let equal = args.first() == args.get(1);
                goal_equalities_hold &= equal == l.positive;
            } else {
                goal.push((l.positive, pred_of(&l.atom.predicate)?, args));
            }
        }
        Ok(Model {
            objects,
            predicates,
            schemas,
            init,
            goal,
            goal_equalities_hold,
            function_values,
            use_costs: problem.metric.is_some(),
        })
    }
}
