//! Grounding by relaxed reachability.
//!
//! Atoms are discovered in a queue, starting from the initial state. Each atom taken
//! from the queue is matched against every positive precondition of every schema that
//! mentions its predicate, and the other positive preconditions are joined against the
//! atoms taken so far; every complete binding that satisfies the parameter types,
//! (in)equalities and negative static preconditions is a reachable ground action, whose
//! add effects join the queue. A binding is found when the last of its precondition atoms
//! is taken, so the fixpoint instantiates exactly the relaxed-reachable actions, never the
//! cross product of objects. Negative fluent preconditions are ignored in the relaxation.

use rustc_hash::{FxHashMap, FxHashSet};

use crate::model::{Arg, CostTerm, Model, ObjId, Pattern, PredId, Schema};
use crate::watch::Watch;
use crate::TranslateError;

/// Index of a ground atom in [`AtomTable`].
pub(crate) type AtomId = u32;

const UNBOUND: u32 = u32::MAX;

/// Interned ground atoms: `[predicate, args...]` to id.
#[derive(Debug, Default)]
pub(crate) struct AtomTable {
    map: FxHashMap<Box<[u32]>, AtomId>,
    keys: Vec<Box<[u32]>>,
}

impl AtomTable {
    fn key(pred: PredId, args: impl IntoIterator<Item = u32>) -> Box<[u32]> {
        std::iter::once(pred.0).chain(args).collect()
    }

    fn intern(&mut self, key: Box<[u32]>) -> (AtomId, bool) {
        if let Some(&id) = self.map.get(&key) {
            return (id, false);
        }
        let id = self.keys.len() as AtomId;
        self.keys.push(key.clone());
        self.map.insert(key, id);
        (id, true)
    }

    fn get(&self, key: &[u32]) -> Option<AtomId> {
        self.map.get(key).copied()
    }

    pub fn len(&self) -> usize {
        self.keys.len()
    }

    pub fn pred(&self, atom: AtomId) -> PredId {
        PredId(self.keys[atom as usize][0])
    }

    pub fn args(&self, atom: AtomId) -> &[u32] {
        &self.keys[atom as usize][1..]
    }
}

/// A reachable ground action with static conditions compiled away.
#[derive(Debug, Clone)]
pub(crate) struct GroundAction {
    pub schema: u32,
    pub args: Vec<ObjId>,
    /// Positive fluent preconditions, sorted, deduplicated.
    pub pre: Vec<AtomId>,
    /// Negative fluent preconditions on reachable atoms, sorted, deduplicated.
    pub neg: Vec<AtomId>,
    pub add: Vec<AtomId>,
    /// Deletes of reachable atoms that the action does not also add.
    pub del: Vec<AtomId>,
    pub cost: u64,
}

/// The grounded propositional task.
#[derive(Debug)]
pub(crate) struct Grounding {
    pub atoms: AtomTable,
    pub fluent: Vec<bool>,
    pub actions: Vec<GroundAction>,
    /// Fluent atoms true initially, sorted.
    pub init: Vec<AtomId>,
    pub goal_pos: Vec<AtomId>,
    pub goal_neg: Vec<AtomId>,
    /// Set when the goal cannot be reached even in the relaxation.
    pub unsolvable: Option<String>,
}

struct Reach<'m, 'w> {
    model: &'m Model,
    /// The run's limits, ticked once per binding completed and atom taken.
    watch: &'w Watch<'w>,
    atoms: AtomTable,
    by_pred: Vec<Vec<AtomId>>,
    by_arg: FxHashMap<(u32, u32, u32), Vec<AtomId>>,
    /// Per predicate: (schema, positive precondition index) it can trigger.
    triggers: Vec<Vec<(usize, usize)>>,
    /// Join order of the other positive preconditions, per (schema, trigger index).
    orders: FxHashMap<(usize, usize), Vec<usize>>,
    seen: FxHashSet<(u32, Box<[u32]>)>,
    /// Atoms with id <= current have been taken from the queue.
    current: AtomId,
}

fn join_order(s: &Schema, first: usize) -> Vec<usize> {
    let mut bound: FxHashSet<u32> = params_of(&s.positive[first]).collect();
    let mut rest: Vec<usize> = (0..s.positive.len()).filter(|&i| i != first).collect();
    let mut order = Vec::new();
    while !rest.is_empty() {
        // Most bound arguments first: the join stays narrow.
        let (pos, _) = rest
            .iter()
            .enumerate()
            .map(|(pos, &i)| {
                let p = &s.positive[i];
                let unbound = p
                    .args
                    .iter()
                    .filter(|a| matches!(a, Arg::Param(v) if !bound.contains(v)))
                    .count();
                (pos, (unbound, i))
            })
            .min_by_key(|&(_, key)| key)
            .unwrap_or((0, (0, 0)));
        let i = rest.remove(pos);
        bound.extend(params_of(&s.positive[i]));
        order.push(i);
    }
    order
}

fn params_of(p: &Pattern) -> impl Iterator<Item = u32> + '_ {
    p.args.iter().filter_map(|a| match a {
        Arg::Param(v) => Some(*v),
        Arg::Obj(_) => None,
    })
}

fn value(arg: Arg, binding: &[u32]) -> u32 {
    match arg {
        Arg::Param(v) => binding[v as usize],
        Arg::Obj(o) => o.0,
    }
}

impl<'m, 'w> Reach<'m, 'w> {
    fn new(model: &'m Model, watch: &'w Watch<'w>) -> Reach<'m, 'w> {
        let mut triggers = vec![Vec::new(); model.predicates.len()];
        let mut orders = FxHashMap::default();
        for (si, s) in model.schemas.iter().enumerate() {
            for (i, p) in s.positive.iter().enumerate() {
                triggers[p.pred.0 as usize].push((si, i));
                orders.insert((si, i), join_order(s, i));
            }
        }
        Reach {
            model,
            watch,
            atoms: AtomTable::default(),
            by_pred: vec![Vec::new(); model.predicates.len()],
            by_arg: FxHashMap::default(),
            triggers,
            orders,
            seen: FxHashSet::default(),
            current: 0,
        }
    }

    fn run(&mut self) {
        for (pred, args) in &self.model.init {
            self.atoms
                .intern(AtomTable::key(*pred, args.iter().map(|o| o.0)));
        }
        let mut bindings = Vec::new();
        for (si, s) in self.model.schemas.iter().enumerate() {
            if s.positive.is_empty() {
                let mut binding = vec![UNBOUND; s.domains.len()];
                self.complete(s, 0, &mut binding, &mut bindings);
                self.emit_all(si, &mut bindings);
            }
        }
        let mut atom = 0;
        while (atom as usize) < self.atoms.len() {
            if self.watch.tick() {
                return;
            }
            self.current = atom;
            let pred = self.atoms.pred(atom);
            self.by_pred[pred.0 as usize].push(atom);
            for (pos, &obj) in self.atoms.args(atom).iter().enumerate() {
                self.by_arg
                    .entry((pred.0, pos as u32, obj))
                    .or_default()
                    .push(atom);
            }
            let triggers = std::mem::take(&mut self.triggers[pred.0 as usize]);
            for &(si, i) in &triggers {
                let s = &self.model.schemas[si];
                let mut binding = vec![UNBOUND; s.domains.len()];
                if self.unify(s, &s.positive[i], atom, &mut binding, &mut Vec::new()) {
                    let order = self.orders.get(&(si, i)).cloned().unwrap_or_default();
                    self.join(s, &order, 0, &mut binding, &mut bindings);
                    self.emit_all(si, &mut bindings);
                }
            }
            self.triggers[pred.0 as usize] = triggers;
            atom += 1;
        }
    }

    /// Binds the pattern's parameters to the atom's arguments; records what it bound in
    /// `newly` so the caller can undo it.
    fn unify(
        &self,
        s: &Schema,
        p: &Pattern,
        atom: AtomId,
        binding: &mut [u32],
        newly: &mut Vec<u32>,
    ) -> bool {
        let start = newly.len();
        for (arg, &obj) in p.args.iter().zip(self.atoms.args(atom)) {
            let ok = match *arg {
                Arg::Obj(o) => o.0 == obj,
                Arg::Param(v) => {
                    let b = binding[v as usize];
                    if b == UNBOUND {
                        if s.allowed[v as usize][obj as usize] {
                            binding[v as usize] = obj;
                            newly.push(v);
                            true
                        } else {
                            false
                        }
                    } else {
                        b == obj
                    }
                }
            };
            if !ok {
                for v in newly.drain(start..) {
                    binding[v as usize] = UNBOUND;
                }
                return false;
            }
        }
        true
    }

    fn join(
        &self,
        s: &Schema,
        order: &[usize],
        k: usize,
        binding: &mut Vec<u32>,
        out: &mut Vec<Box<[u32]>>,
    ) {
        let Some(&next) = order.get(k) else {
            self.complete(s, 0, binding, out);
            return;
        };
        let p = &s.positive[next];
        let mut all_bound = true;
        let mut narrowest: Option<&Vec<AtomId>> = None;
        for (pos, arg) in p.args.iter().enumerate() {
            let v = value(*arg, binding);
            if v == UNBOUND {
                all_bound = false;
                continue;
            }
            match self.by_arg.get(&(p.pred.0, pos as u32, v)) {
                None => return,
                Some(list) => {
                    if narrowest.is_none_or(|n| list.len() < n.len()) {
                        narrowest = Some(list);
                    }
                }
            }
        }
        if all_bound {
            let key = AtomTable::key(p.pred, p.args.iter().map(|a| value(*a, binding)));
            if self.atoms.get(&key).is_some_and(|id| id <= self.current) {
                self.join(s, order, k + 1, binding, out);
            }
            return;
        }
        let candidates = narrowest.unwrap_or(&self.by_pred[p.pred.0 as usize]);
        let mut newly = Vec::new();
        for &atom in candidates {
            if self.watch.stopped().is_some() {
                return;
            }
            if self.unify(s, p, atom, binding, &mut newly) {
                self.join(s, order, k + 1, binding, out);
                for v in newly.drain(..) {
                    binding[v as usize] = UNBOUND;
                }
            }
        }
    }

    /// Binds the parameters no positive precondition mentions, then checks the rest.
    fn complete(&self, s: &Schema, v: usize, binding: &mut Vec<u32>, out: &mut Vec<Box<[u32]>>) {
        if v == binding.len() {
            // A schema with many parameters over many objects can have more bindings
            // than memory holds: the limits are checked per binding.
            if !self.watch.tick() && self.satisfies_static_conditions(s, binding) {
                out.push(binding.clone().into_boxed_slice());
            }
            return;
        }
        if binding[v] != UNBOUND {
            self.complete(s, v + 1, binding, out);
            return;
        }
        for o in &s.domains[v] {
            if self.watch.stopped().is_some() {
                break;
            }
            binding[v] = o.0;
            self.complete(s, v + 1, binding, out);
        }
        binding[v] = UNBOUND;
    }

    fn satisfies_static_conditions(&self, s: &Schema, binding: &[u32]) -> bool {
        let equalities_hold = s
            .equalities
            .iter()
            .all(|&(x, y, positive)| (value(x, binding) == value(y, binding)) == positive);
        equalities_hold
            && s.negative.iter().all(|p| {
                // A static atom is reachable only if it is initially true.
                self.model.predicates[p.pred.0 as usize].fluent || {
                    let key = AtomTable::key(p.pred, p.args.iter().map(|a| value(*a, binding)));
                    self.atoms.get(&key).is_none()
                }
            })
    }

    /// Records the bindings found for `schema`, unless a limit stopped the grounding:
    /// then what is left is thrown away at once (recording it could take as long again).
    fn emit_all(&mut self, schema: usize, bindings: &mut Vec<Box<[u32]>>) {
        if self.watch.stopped().is_some() {
            *bindings = Vec::new();
            return;
        }
        for b in bindings.drain(..) {
            self.emit(schema, b);
        }
    }

    /// Records a reachable binding once. The set of bindings is the only copy (one
    /// allocation per ground action: a blow-up stopped at a limit frees them quickly).
    fn emit(&mut self, schema: usize, binding: Box<[u32]>) {
        let found = (schema as u32, binding);
        if self.seen.contains(&found) {
            return;
        }
        let s = &self.model.schemas[schema];
        for p in &s.add {
            let key = AtomTable::key(p.pred, p.args.iter().map(|a| value(*a, &found.1)));
            self.atoms.intern(key);
        }
        self.seen.insert(found);
    }
}

/// Grounds the model; `Ok(None)` if `watch` stopped it at a limit.
pub(crate) fn ground(model: &Model, watch: &Watch) -> Result<Option<Grounding>, TranslateError> {
    let mut reach = Reach::new(model, watch);
    reach.run();
    if watch.check() {
        return Ok(None);
    }
    let Reach { atoms, seen, .. } = reach;
    // Deterministic order: by schema, then by arguments.
    let mut found: Vec<(u32, Box<[u32]>)> = seen.into_iter().collect();
    found.sort_unstable();
    let fluent: Vec<bool> = (0..atoms.len() as AtomId)
        .map(|a| model.predicates[atoms.pred(a).0 as usize].fluent)
        .collect();
    let lookup = |p: &Pattern, binding: &[u32]| {
        atoms.get(&AtomTable::key(
            p.pred,
            p.args.iter().map(|a| value(*a, binding)),
        ))
    };
    let mut actions = Vec::with_capacity(found.len());
    'actions: for (schema, binding) in found {
        if watch.tick() {
            return Ok(None);
        }
        let s = &model.schemas[schema as usize];
        let mut pre = Vec::new();
        for p in s
            .positive
            .iter()
            .filter(|p| model.predicates[p.pred.0 as usize].fluent)
        {
            match lookup(p, &binding) {
                Some(a) => pre.push(a),
                None => continue 'actions,
            }
        }
        let mut neg: Vec<AtomId> = s
            .negative
            .iter()
            .filter(|p| model.predicates[p.pred.0 as usize].fluent)
            .filter_map(|p| lookup(p, &binding))
            .collect();
        let mut add: Vec<AtomId> = s.add.iter().filter_map(|p| lookup(p, &binding)).collect();
        let mut del: Vec<AtomId> = s
            .delete
            .iter()
            .filter_map(|p| lookup(p, &binding))
            .collect();
        for v in [&mut pre, &mut neg, &mut add, &mut del] {
            v.sort_unstable();
            v.dedup();
        }
        if neg.iter().any(|a| pre.binary_search(a).is_ok()) {
            continue; // never applicable
        }
        // PDDL applies deletes before adds: an atom both deleted and added ends true.
        del.retain(|a| add.binary_search(a).is_err());
        let cost = action_cost(model, s, &binding)?;
        actions.push(GroundAction {
            schema,
            args: binding.iter().map(|&o| ObjId(o)).collect(),
            pre,
            neg,
            add,
            del,
            cost,
        });
    }

    let init_set: FxHashSet<AtomId> = model
        .init
        .iter()
        .filter_map(|(pred, args)| atoms.get(&AtomTable::key(*pred, args.iter().map(|o| o.0))))
        .collect();
    let mut init: Vec<AtomId> = init_set
        .iter()
        .copied()
        .filter(|&a| fluent[a as usize])
        .collect();
    init.sort_unstable();
    let mut goal_pos = Vec::new();
    let mut goal_neg = Vec::new();
    let mut unsolvable = None;
    if !model.goal_equalities_hold {
        unsolvable = Some("an equality in the goal is false".to_string());
    }
    for (positive, pred, args) in &model.goal {
        let id = atoms.get(&AtomTable::key(*pred, args.iter().map(|o| o.0)));
        let is_fluent = model.predicates[pred.0 as usize].fluent;
        let text = || atom_text(model, *pred, args.iter().map(|o| o.0));
        match (positive, id) {
            (true, None) => {
                unsolvable.get_or_insert_with(|| {
                    format!("goal {} is not reachable even in the relaxation", text())
                });
            }
            (true, Some(a)) if is_fluent => goal_pos.push(a),
            (true, Some(_)) => {}
            (false, Some(a)) if is_fluent => goal_neg.push(a),
            (false, Some(_)) => {
                unsolvable.get_or_insert_with(|| {
                    format!("goal (not {}) is false in every state", text())
                });
            }
            (false, None) => {}
        }
    }
    for v in [&mut goal_pos, &mut goal_neg] {
        v.sort_unstable();
        v.dedup();
    }
    if goal_pos.iter().any(|a| goal_neg.binary_search(a).is_ok()) {
        unsolvable.get_or_insert_with(|| "the goal requires an atom and its negation".to_string());
    }
    Ok(Some(Grounding {
        atoms,
        fluent,
        actions,
        init,
        goal_pos,
        goal_neg,
        unsolvable,
    }))
}

fn action_cost(model: &Model, s: &Schema, binding: &[u32]) -> Result<u64, TranslateError> {
    let mut total: u64 = 0;
    for term in &s.cost {
        let c = match term {
            CostTerm::Constant(c) => *c,
            CostTerm::Function { name, args } => {
                let objs: Vec<ObjId> = args.iter().map(|a| ObjId(value(*a, binding))).collect();
                let key = (name.clone(), objs);
                let text = || {
                    let names: Vec<&str> = key
                        .1
                        .iter()
                        .map(|o| model.objects[o.0 as usize].as_str())
                        .collect();
                    format!("({} {})", name, names.join(" "))
                };
                match model.function_values.get(&key) {
                    Some(&v) => u64::try_from(v).map_err(|_| TranslateError::NegativeCost {
                        term: text(),
                        value: v,
                    })?,
                    None => {
                        return Err(TranslateError::MissingFunctionValue {
                            term: text(),
                            action: s.name.clone(),
                        })
                    }
                }
            }
        };
        total = total.checked_add(c).ok_or(TranslateError::CostOverflow)?;
    }
    Ok(total)
}

/// `pred(a, b)`, as Fast Downward names atoms.
pub(crate) fn atom_text(model: &Model, pred: PredId, args: impl Iterator<Item = u32>) -> String {
    let names: Vec<&str> = args.map(|o| model.objects[o as usize].as_str()).collect();
    format!(
        "{}({})",
        model.predicates[pred.0 as usize].name,
        names.join(", ")
    )
}

impl Grounding {
    /// Removes the actions whose preconditions require two atoms of one mutex group
    /// (they are never applicable), then recomputes relaxed reachability on what is left:
    /// atoms only those actions added become unreachable and are no longer fluent atoms
    /// of the task; atoms true initially and never deleted become constants. Returns
    /// false if the goal became unreachable (or requires a constant to be false).
    pub(crate) fn prune_with_mutexes(&mut self, groups: &[Vec<AtomId>]) -> bool {
        let n = self.atoms.len();
        let mut groups_of: Vec<Vec<u32>> = vec![Vec::new(); n];
        for (i, group) in groups.iter().enumerate() {
            for &a in group {
                groups_of[a as usize].push(i as u32);
            }
        }
        let mut seen_group = vec![u32::MAX; groups.len()];
        let mut keep = vec![true; self.actions.len()];
        for (i, action) in self.actions.iter().enumerate() {
            'pre: for &a in &action.pre {
                for &grp in &groups_of[a as usize] {
                    if seen_group[grp as usize] == i as u32 {
                        keep[i] = false;
                        break 'pre;
                    }
                    seen_group[grp as usize] = i as u32;
                }
            }
        }
        // Relaxed reachability over the remaining actions, by precondition counters.
        let mut reached = vec![false; n];
        let mut missing: Vec<usize> = self.actions.iter().map(|a| a.pre.len()).collect();
        let mut waiting: Vec<Vec<u32>> = vec![Vec::new(); n];
        for (i, action) in self.actions.iter().enumerate() {
            for &a in &action.pre {
                waiting[a as usize].push(i as u32);
            }
        }
        let mut queue: Vec<AtomId> = Vec::new();
        let mut applicable: Vec<bool> = vec![false; self.actions.len()];
        let mut ready: Vec<u32> = Vec::new();
        for &a in &self.init {
            if !reached[a as usize] {
                reached[a as usize] = true;
                queue.push(a);
            }
        }
        for (i, m) in missing.iter().enumerate() {
            if *m == 0 && keep[i] {
                ready.push(i as u32);
            }
        }
        loop {
            while let Some(i) = ready.pop() {
                if applicable[i as usize] {
                    continue;
                }
                applicable[i as usize] = true;
                for &a in &self.actions[i as usize].add {
                    if !reached[a as usize] {
                        reached[a as usize] = true;
                        queue.push(a);
                    }
                }
            }
            let Some(a) = queue.pop() else { break };
            for &i in &waiting[a as usize] {
                missing[i as usize] -= 1;
                if missing[i as usize] == 0 && keep[i as usize] {
                    ready.push(i);
                }
            }
        }
        let mut index = 0;
        self.actions.retain(|_| {
            index += 1;
            applicable[index - 1]
        });
        for (fluent, reached) in self.fluent.iter_mut().zip(&reached) {
            *fluent &= *reached;
        }
        // Atoms true initially that no action deletes are true in every reachable state:
        // constants, compiled away like static facts.
        let mut deleted = vec![false; n];
        for action in &self.actions {
            for &d in &action.del {
                deleted[d as usize] = true;
            }
        }
        let mut constant = vec![false; n];
        for &a in &self.init {
            if self.fluent[a as usize] && !deleted[a as usize] {
                constant[a as usize] = true;
                self.fluent[a as usize] = false;
            }
        }
        if self.goal_neg.iter().any(|&a| constant[a as usize]) {
            return false;
        }
        self.actions
            .retain(|a| !a.neg.iter().any(|&x| constant[x as usize]));
        self.init.retain(|&a| !constant[a as usize]);
        self.goal_pos.retain(|&a| !constant[a as usize]);
        let fluent = &self.fluent;
        for action in &mut self.actions {
            action.pre.retain(|&d| fluent[d as usize]);
            action.add.retain(|&d| fluent[d as usize]);
            action.del.retain(|&d| fluent[d as usize]);
            action.neg.retain(|&d| fluent[d as usize]);
        }
        self.goal_neg.retain(|&d| fluent[d as usize]);
        self.goal_pos.iter().all(|&g| fluent[g as usize])
    }
}
