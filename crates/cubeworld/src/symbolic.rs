//! The PDDL side: the scene of a problem, ground actions of a domain, and symbolic
//! states (sets of ground atoms), mapped to the grounding's facts.

use std::collections::BTreeSet;

use grounding::{Fact, FactId, FactSpace, Predicate};
use pddl::{Action, Domain, Effect, InitEntry, Problem, Term, Type};
use recording::{Activity, Header};

use crate::world::{Layout, MAX_TOWERS};
use crate::ExecuteError;

/// A ground atom: predicate and object names, lowercase as PDDL has them.
pub type Atom = (String, Vec<String>);

/// The objects of a problem by kind.
#[derive(Debug, Clone, PartialEq)]
pub struct SceneObjects {
    /// Hands.
    pub hands: Vec<String>,
    /// Cubes.
    pub cubes: Vec<String>,
    /// The table.
    pub table: String,
}

fn type_name(ty: &Option<Type>) -> String {
    match ty {
        Some(Type::Named(n)) => n.as_str().to_string(),
        Some(Type::Either(ns)) => ns
            .first()
            .map(|n| n.as_str().to_string())
            .unwrap_or_default(),
        None => "object".into(),
    }
}

/// The hands, cubes and table of a problem (objects typed `hand`, `cube`, `table`).
pub fn scene_objects(problem: &Problem) -> Result<SceneObjects, ExecuteError> {
    let mut hands = Vec::new();
    let mut cubes = Vec::new();
    let mut tables = Vec::new();
    for o in &problem.objects {
        let name = o.name.as_str().to_string();
        if !recording::is_valid_name(&name) {
            return Err(ExecuteError::Scene(format!(
                "object `{name}` cannot be named in a recording"
            )));
        }
        match type_name(&o.ty).as_str() {
            "hand" => hands.push(name),
            "cube" => cubes.push(name),
            "table" => tables.push(name),
            other => {
                return Err(ExecuteError::Scene(format!(
                "object `{name}` is of type `{other}`: the cube world has hands, cubes and a table"
            )))
            }
        }
    }
    if hands.is_empty() || hands.len() > 2 {
        return Err(ExecuteError::Scene(format!(
            "the cube world has one or two hands, the problem has {}",
            hands.len()
        )));
    }
    let [table] = tables.as_slice() else {
        return Err(ExecuteError::Scene(format!(
            "the cube world has one table, the problem has {}",
            tables.len()
        )));
    };
    if cubes.len() > MAX_TOWERS {
        return Err(ExecuteError::Scene(format!(
            "the table has room for {MAX_TOWERS} cubes, the problem has {}",
            cubes.len()
        )));
    }
    Ok(SceneObjects {
        hands,
        cubes,
        table: table.clone(),
    })
}

/// The initial atoms of a problem.
pub fn initial_atoms(problem: &Problem) -> BTreeSet<Atom> {
    problem
        .init
        .iter()
        .filter_map(|e| match e {
            InitEntry::Fact(a) => Some(ground_atom(&a.predicate, &a.args, &[])),
            _ => None,
        })
        .collect()
}

fn ground_atom(predicate: &pddl::Name, args: &[Term], binding: &[(String, String)]) -> Atom {
    let args = args
        .iter()
        .map(|t| match t {
            Term::Object(n) => n.as_str().to_string(),
            Term::Variable(v) => binding
                .iter()
                .find(|(k, _)| k == v.as_str())
                .map(|(_, o)| o.clone())
                .unwrap_or_else(|| v.as_str().to_string()),
        })
        .collect();
    (predicate.as_str().to_string(), args)
}

/// The layout of the initial atoms: towers from `ontop`, held cubes from `inhand`, closed
/// hands from a missing `handopen`.
pub fn layout(objects: &SceneObjects, init: &BTreeSet<Atom>) -> Result<Layout, ExecuteError> {
    let cube_index = |n: &str| objects.cubes.iter().position(|c| c == n);
    let mut below: Vec<Option<Option<usize>>> = vec![None; objects.cubes.len()];
    for (p, args) in init {
        if p == "ontop" && args.len() == 2 {
            let Some(c) = cube_index(&args[0]) else {
                continue;
            };
            let support = if args[1] == objects.table {
                None
            } else if let Some(b) = cube_index(&args[1]) {
                Some(b)
            } else {
                continue;
            };
            if below[c].is_some() {
                return Err(ExecuteError::Scene(format!(
                    "`{}` is on top of two things in the initial state",
                    args[0]
                )));
            }
            below[c] = Some(support);
        }
    }
    let mut held = vec![None; objects.hands.len()];
    let mut closed = vec![false; objects.hands.len()];
    for (h, hand) in objects.hands.iter().enumerate() {
        closed[h] = !init.contains(&("handopen".to_string(), vec![hand.clone()]));
        for (c, cube) in objects.cubes.iter().enumerate() {
            if init.contains(&("inhand".to_string(), vec![hand.clone(), cube.clone()])) {
                if below[c].is_some() {
                    return Err(ExecuteError::Scene(format!(
                        "`{cube}` is both held and on top of something in the initial state"
                    )));
                }
                held[h] = Some(c);
                closed[h] = true;
            }
        }
    }
    let is_held = |c: usize| held.contains(&Some(c));
    // Towers: from each cube on the table (or on nothing, and not held) upwards.
    let mut towers = Vec::new();
    let mut placed = vec![false; objects.cubes.len()];
    for c in 0..objects.cubes.len() {
        if matches!(below[c], Some(None)) || (below[c].is_none() && !is_held(c)) {
            let mut tower = vec![c];
            placed[c] = true;
            let mut top = c;
            while let Some(next) = (0..objects.cubes.len()).find(|&d| below[d] == Some(Some(top))) {
                if placed[next] {
                    break;
                }
                placed[next] = true;
                tower.push(next);
                top = next;
            }
            towers.push(tower);
        }
    }
    if let Some(c) = (0..objects.cubes.len()).find(|&c| !placed[c] && !is_held(c)) {
        return Err(ExecuteError::Scene(format!(
            "`{}` does not stand on the table (its `ontop` facts form a cycle, or two cubes \
             are on one)",
            objects.cubes[c]
        )));
    }
    Ok(Layout {
        towers,
        held,
        closed,
    })
}

/// A ground action: its schema's effects with the arguments put in.
#[derive(Debug, Clone, PartialEq)]
pub struct GroundAction {
    /// The action's name.
    pub name: String,
    /// The arguments.
    pub args: Vec<String>,
    /// Its type.
    pub kind: Activity,
    /// Positive preconditions.
    pub pre_positive: Vec<Atom>,
    /// Negative preconditions (equality left out).
    pub pre_negative: Vec<Atom>,
    /// Added atoms.
    pub add: Vec<Atom>,
    /// Deleted atoms.
    pub delete: Vec<Atom>,
}

/// The ground action `name(args)` of a domain.
pub fn ground_action(
    domain: &Domain,
    name: &str,
    args: &[String],
) -> Result<GroundAction, ExecuteError> {
    let lower = name.to_ascii_lowercase();
    let action: &Action = domain
        .actions
        .iter()
        .find(|a| a.name.as_str() == lower)
        .ok_or_else(|| ExecuteError::Plan(format!("the domain has no action `{lower}`")))?;
    let kind = Activity::of_operator_name(&lower).ok_or_else(|| {
        ExecuteError::Plan(format!(
            "`{lower}` is not a reach, take, put, stack or idle action (its name without \
             trailing digits says its type)"
        ))
    })?;
    if action.params.len() != args.len() {
        return Err(ExecuteError::Plan(format!(
            "`{lower}` takes {} arguments, the plan gives {}",
            action.params.len(),
            args.len()
        )));
    }
    let binding: Vec<(String, String)> = action
        .params
        .iter()
        .zip(args)
        .map(|(p, a)| (p.name.as_str().to_string(), a.to_ascii_lowercase()))
        .collect();
    let mut g = GroundAction {
        name: lower,
        args: binding.iter().map(|(_, a)| a.clone()).collect(),
        kind,
        pre_positive: Vec::new(),
        pre_negative: Vec::new(),
        add: Vec::new(),
        delete: Vec::new(),
    };
    for l in &action.precondition {
        if l.atom.is_equality() {
            continue;
        }
        let a = ground_atom(&l.atom.predicate, &l.atom.args, &binding);
        if l.positive {
            g.pre_positive.push(a);
        } else {
            g.pre_negative.push(a);
        }
    }
    for e in &action.effects {
        match e {
            Effect::Add(a) => g.add.push(ground_atom(&a.predicate, &a.args, &binding)),
            Effect::Delete(a) => g.delete.push(ground_atom(&a.predicate, &a.args, &binding)),
            Effect::IncreaseCost(_) => {}
        }
    }
    // Delete then add: an atom both deleted and added is added.
    let add = g.add.clone();
    g.delete.retain(|a| !add.contains(a));
    Ok(g)
}

impl GroundAction {
    /// Applies the action to a symbolic state (delete, then add).
    pub fn apply(&self, state: &mut BTreeSet<Atom>) {
        for a in &self.delete {
            state.remove(a);
        }
        for a in &self.add {
            state.insert(a.clone());
        }
    }

    /// Preconditions the state does not satisfy.
    pub fn unmet(&self, state: &BTreeSet<Atom>) -> Vec<String> {
        let mut out = Vec::new();
        for a in &self.pre_positive {
            if !state.contains(a) {
                out.push(atom_text(a));
            }
        }
        for a in &self.pre_negative {
            if state.contains(a) {
                out.push(format!("(not {})", atom_text(a)));
            }
        }
        out
    }
}

/// `(inhand left_hand cube_2)`.
pub fn atom_text(a: &Atom) -> String {
    let mut s = format!("({}", a.0);
    for x in &a.1 {
        s.push(' ');
        s.push_str(x);
    }
    s.push(')');
    s
}

/// The predicate of a PDDL predicate name.
pub fn predicate(name: &str) -> Option<Predicate> {
    Predicate::ALL
        .into_iter()
        .find(|p| p.name().eq_ignore_ascii_case(name))
}

/// The grounding's fact for an atom: `Err` when the predicate is not one of Table 2 or an
/// argument is not in the scene; `Ok(None)` when the scene can never have it (e.g.
/// `actedon` of the table).
pub fn fact_of(
    header: &Header,
    space: &FactSpace,
    atom: &Atom,
) -> Result<Option<FactId>, ExecuteError> {
    let p = predicate(&atom.0).ok_or_else(|| {
        ExecuteError::Plan(format!(
            "`{}` is not a predicate of the cube world (handmove, handopen, actedon, graspable, \
             inhand, intouch, ontop)",
            atom.0
        ))
    })?;
    let ids = atom
        .1
        .iter()
        .map(|n| {
            header
                .find(n)
                .ok_or_else(|| ExecuteError::Plan(format!("`{n}` is not an object of the problem")))
        })
        .collect::<Result<Vec<_>, _>>()?;
    let fact = match (p.arity(), ids.as_slice()) {
        (1, [a]) => Fact::unary(p, *a),
        (2, [a, b]) => Fact::binary(p, *a, *b),
        _ => {
            return Err(ExecuteError::Plan(format!(
                "`{}` takes {} arguments",
                atom.0,
                p.arity()
            )))
        }
    };
    Ok(space.id(&fact))
}

/// A grounding fact in PDDL's words: `(ontop cube_2 cube_1)`.
pub fn fact_text(header: &Header, fact: &Fact) -> String {
    let mut s = format!("({}", fact.predicate.name().to_ascii_lowercase());
    for a in fact.args() {
        s.push(' ');
        s.push_str(
            header
                .entities
                .get(a.index())
                .map_or("?", |e| e.name.as_str()),
        );
    }
    s.push(')');
    s
}
