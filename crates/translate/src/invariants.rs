//! Invariant synthesis: lifted mutex groups, proved on the action schemas as Fast
//! Downward's translator proves them.
//!
//! An invariant candidate is a set of *parts*, one per predicate, each naming for every
//! argument position either an invariant parameter or the one *counted* position. It
//! claims: for every binding of the parameters, at most one matching atom is true. This is
//! Helmert's invariant synthesis ("Concise finite-domain representations for PDDL
//! planning tasks", AIJ 2009): a candidate is proved when no action can make two of its
//! atoms true at once (*too heavy*) and every add effect it covers is *balanced*, in every
//! instantiation of the schema, by a delete effect on an atom the precondition requires.
//! An unbalanced add effect refines the candidate: each delete effect of that action on a
//! predicate the candidate lacks suggests a part that would balance it, and the refined
//! candidates join a breadth-first queue.
//!
//! The proof reasons about instantiations with a small constraint system over equalities
//! and inequalities of action parameters, invariant parameters and objects
//! ([`Constraints`]). It ignores static facts, so it proves less than a check on the
//! reachable ground actions would: in pipesworld's net2 instances, for example, it cannot
//! prove "where is batch b". That weakness is Fast Downward's too, and this module keeps
//! it on purpose: the variables of the finite-domain task, and through them LM-cut's tie
//! breaking and iPDB's climbs, are Fast Downward's only if the mutex groups are. For the
//! same reason it follows Fast Downward 26.6 in its details:
//!
//! - a pair of parameters that no reachable ground action instantiates with one object
//!   gets an inequality precondition (here from the ground actions, where Fast Downward
//!   uses its relaxed exploration's parameter tuples, which may hold a few more);
//! - the actions threatening a candidate are checked in the random order Fast Downward's
//!   translator draws, from Python's Mersenne Twister seeded with 314159 ([`PythonRandom`]);
//!   the first failing action decides the refinements, so the order matters;
//! - at most [`MAX_CANDIDATES`] candidates are ever queued;
//! - a proved invariant yields a mutex group for each parameter binding with exactly one
//!   atom true initially (none, or two and more, and the binding yields no group).
//!
//! Complexity: per candidate and threatening action, the constraint systems are solved by
//! enumerating their disjunctions, which stay small (one per precondition atom of the
//! deleted predicate).

use std::collections::VecDeque;

use rand_mt::Mt;
use rustc_hash::{FxHashMap, FxHashSet};

use crate::ground::{AtomId, Grounding};
use crate::model::{Arg, Model, Pattern, PredId};
use crate::watch::Watch;

/// Candidates ever queued, as Fast Downward's `--invariant-generation-max-candidates`.
const MAX_CANDIDATES: usize = 100_000;

/// The seed of Fast Downward's translator for the order of its balance checks.
const FAST_DOWNWARD_INVARIANT_SEED: u32 = 314_159;

/// The counted position of a part.
const COUNTED: i8 = -1;

/// A ground mutex group: atoms of which at most one is true in any reachable state.
pub(crate) type Group = Vec<AtomId>;

/// A term of a constraint: an invariant parameter, an action parameter or an object.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
enum Term {
    Invariant(i8),
    Param(u32),
    Object(u32),
}

fn term(arg: Arg) -> Term {
    match arg {
        Arg::Param(p) => Term::Param(p),
        Arg::Obj(o) => Term::Object(o.0),
    }
}

/// A lifted atom with terms.
#[derive(Debug, Clone, PartialEq, Eq, Hash)]
struct Atom {
    pred: PredId,
    args: Vec<Term>,
}

fn atom(p: &Pattern) -> Atom {
    Atom {
        pred: p.pred,
        args: p.args.iter().map(|&a| term(a)).collect(),
    }
}

/// The pairs of two atoms' arguments position by position.
fn zipped(a: &[Term], b: &[Term]) -> Vec<(Term, Term)> {
    a.iter().copied().zip(b.iter().copied()).collect()
}

/// An action schema as the synthesis sees it: Fast Downward's normalised action.
#[derive(Debug)]
struct LiftedAction {
    params: u32,
    positive: Vec<Atom>,
    negative: Vec<Atom>,
    equal: Vec<(Term, Term)>,
    /// Inequality preconditions, written and inferred from the reachable actions.
    unequal: Vec<(Term, Term)>,
    /// Add and delete effects in the schema's order; a delete of an atom the schema also
    /// adds is dropped (add after delete).
    adds: Vec<Atom>,
    dels: Vec<Atom>,
}

fn lifted_actions(model: &Model, g: &Grounding) -> Vec<LiftedAction> {
    // Per schema, the parameter pairs some reachable ground action binds to one object.
    let mut may_coincide: Vec<FxHashSet<(u32, u32)>> =
        vec![FxHashSet::default(); model.schemas.len()];
    for action in &g.actions {
        let pairs = &mut may_coincide[action.schema as usize];
        for (i, a) in action.args.iter().enumerate() {
            for (j, b) in action.args.iter().enumerate().skip(i + 1) {
                if a == b {
                    pairs.insert((i as u32, j as u32));
                }
            }
        }
    }
    model
        .schemas
        .iter()
        .zip(&may_coincide)
        .map(|(s, coincide)| {
            let params = s.domains.len() as u32;
            let mut equal = Vec::new();
            let mut unequal = Vec::new();
            for &(x, y, positive) in &s.equalities {
                if positive {
                    equal.push((term(x), term(y)));
                } else {
                    unequal.push((term(x), term(y)));
                }
            }
            if params >= 2 {
                for i in 0..params {
                    for j in i + 1..params {
                        if !coincide.contains(&(i, j)) {
                            unequal.push((Term::Param(i), Term::Param(j)));
                        }
                    }
                }
            }
            let adds: Vec<Atom> = s.add.iter().map(atom).collect();
            let dels = s
                .delete
                .iter()
                .map(atom)
                .filter(|d| !adds.contains(d))
                .collect();
            LiftedAction {
                params,
                positive: s.positive.iter().map(atom).collect(),
                negative: s.negative.iter().map(atom).collect(),
                equal,
                unequal,
                adds,
                dels,
            }
        })
        .collect()
}

/// A conjunction over equalities and inequalities of terms (Fast Downward's
/// `ConstraintSystem`). It is solvable if one conjunction can be picked from every
/// choice such that, in the finest equivalence relation their equalities induce, no
/// class holds two objects, no term of `not_objects` is in a class with an object, and
/// every inequality clause has a pair in different classes.
#[derive(Debug, Clone, Default)]
struct Constraints {
    /// Each entry: one of these conjunctions of equalities holds.
    equality_choices: Vec<Vec<Vec<(Term, Term)>>>,
    /// Each entry: at least one of these pairs differs.
    inequality_clauses: Vec<Vec<(Term, Term)>>,
    /// Terms that stand for no particular object.
    not_objects: Vec<Term>,
}

impl Constraints {
    fn require_equal(&mut self, equalities: Vec<(Term, Term)>) {
        self.equality_choices.push(vec![equalities]);
    }

    /// Some pair differs; an empty clause (two 0-ary atoms) is left out, as Fast Downward
    /// leaves it out.
    fn require_some_differ(&mut self, pairs: Vec<(Term, Term)>) {
        if !pairs.is_empty() {
            self.inequality_clauses.push(pairs);
        }
    }

    fn extend(&mut self, other: &Constraints) {
        self.equality_choices
            .extend(other.equality_choices.iter().cloned());
        self.inequality_clauses
            .extend(other.inequality_clauses.iter().cloned());
        self.not_objects.extend(other.not_objects.iter().copied());
    }

    fn solvable(&self) -> bool {
        if self.equality_choices.iter().any(Vec::is_empty) {
            return false;
        }
        let mut picked = vec![0usize; self.equality_choices.len()];
        loop {
            let mut classes = Partition::default();
            for (choice, &k) in self.equality_choices.iter().zip(&picked) {
                for &(a, b) in &choice[k] {
                    classes.union(a, b);
                }
            }
            if classes.consistent()
                && !self.not_objects.iter().any(|&t| classes.has_object(t))
                && self
                    .inequality_clauses
                    .iter()
                    .all(|clause| clause.iter().any(|&(a, b)| !classes.same(a, b)))
            {
                return true;
            }
            // The next combination, the last choice fastest.
            let mut i = picked.len();
            loop {
                if i == 0 {
                    return false;
                }
                i -= 1;
                picked[i] += 1;
                if picked[i] < self.equality_choices[i].len() {
                    break;
                }
                picked[i] = 0;
            }
        }
    }
}

/// Equivalence classes of the few terms of one constraint system (union-find on a list).
#[derive(Debug, Default)]
struct Partition {
    terms: Vec<Term>,
    parent: Vec<usize>,
}

impl Partition {
    fn index(&mut self, t: Term) -> usize {
        match self.terms.iter().position(|&x| x == t) {
            Some(i) => i,
            None => {
                self.terms.push(t);
                self.parent.push(self.parent.len());
                self.terms.len() - 1
            }
        }
    }

    fn root(&self, mut i: usize) -> usize {
        while self.parent[i] != i {
            i = self.parent[i];
        }
        i
    }

    fn union(&mut self, a: Term, b: Term) {
        let (ia, ib) = (self.index(a), self.index(b));
        let (ra, rb) = (self.root(ia), self.root(ib));
        if ra != rb {
            self.parent[ra] = rb;
        }
    }

    fn class_of(&self, t: Term) -> Option<usize> {
        self.terms
            .iter()
            .position(|&x| x == t)
            .map(|i| self.root(i))
    }

    fn same(&self, a: Term, b: Term) -> bool {
        a == b || matches!((self.class_of(a), self.class_of(b)), (Some(x), Some(y)) if x == y)
    }

    /// The object of each class, if any; `None` if a class holds two objects.
    fn objects(&self) -> Option<Vec<Option<u32>>> {
        let mut object = vec![None; self.terms.len()];
        for (i, &t) in self.terms.iter().enumerate() {
            if let Term::Object(o) = t {
                let r = self.root(i);
                match object[r] {
                    Some(other) if other != o => return None,
                    _ => object[r] = Some(o),
                }
            }
        }
        Some(object)
    }

    fn consistent(&self) -> bool {
        self.objects().is_some()
    }

    fn has_object(&self, t: Term) -> bool {
        if matches!(t, Term::Object(_)) {
            return true;
        }
        let Some(class) = self.class_of(t) else {
            return false;
        };
        self.terms
            .iter()
            .enumerate()
            .any(|(i, x)| matches!(x, Term::Object(_)) && self.root(i) == class)
    }
}

/// A predicate in a candidate: `args[pos]` is the invariant parameter at `pos`, or
/// [`COUNTED`]. Parts order as Fast Downward sorts them, by predicate name, then
/// arguments (`rank` is the name's rank).
#[derive(Debug, Clone, PartialEq, Eq, Hash, PartialOrd, Ord)]
struct Part {
    rank: u32,
    pred: PredId,
    args: Vec<i8>,
}

impl Part {
    fn arity(&self) -> usize {
        self.args.iter().filter(|&&a| a != COUNTED).count()
    }

    /// The equalities making the invariant parameters the atom's arguments.
    fn cover(&self, args: &[Term]) -> Vec<(Term, Term)> {
        self.args
            .iter()
            .zip(args)
            .filter(|(&a, _)| a != COUNTED)
            .map(|(&a, &t)| (Term::Invariant(a), t))
            .collect()
    }

    /// The parts for `other` (a deleted atom of a predicate the candidate lacks) whose
    /// invariant parameters take the values they take in `own` (this part's added atom):
    /// every position of `other` gets the parameter whose value it holds, one position may
    /// stay counted. Several positions with one value give one part per permutation, in
    /// Fast Downward's order. Each part goes to `take`, until it returns false (there
    /// can be factorially many).
    fn balancing_parts(
        &self,
        own: &[Term],
        other: &Atom,
        rank: u32,
        take: &mut dyn FnMut(Part) -> bool,
    ) {
        let mut omissions_left = match other.args.len().checked_sub(self.arity()) {
            Some(n @ (0 | 1)) => n,
            _ => return,
        };
        // The invariant parameters by value, in the order of their positions in `own`.
        let mut params_of: Vec<(Term, Vec<i8>)> = Vec::new();
        for (&a, &t) in self.args.iter().zip(own) {
            if a == COUNTED {
                continue;
            }
            match params_of.iter_mut().find(|(x, _)| *x == t) {
                Some((_, params)) => params.push(a),
                None => params_of.push((t, vec![a])),
            }
        }
        // Per value of `other`, in order of first occurrence: its positions and the
        // parameters (or the counted position) they may take.
        let mut factors: Vec<(Vec<usize>, Vec<i8>)> = Vec::new();
        for (pos, &t) in other.args.iter().enumerate() {
            match factors
                .iter_mut()
                .find(|(positions, _)| other.args[positions[0]] == t)
            {
                Some((positions, _)) => positions.push(pos),
                None => factors.push((vec![pos], Vec::new())),
            }
        }
        for (positions, params) in &mut factors {
            let t = other.args[positions[0]];
            *params = params_of
                .iter()
                .find(|(x, _)| *x == t)
                .map(|(_, p)| p.clone())
                .unwrap_or_default();
            match params.len() as isize - positions.len() as isize {
                0 => {}
                -1 if omissions_left == 1 => {
                    params.push(COUNTED);
                    omissions_left = 0;
                }
                _ => return,
            }
        }
        let mut args = vec![COUNTED; other.args.len()];
        assign_factors(&factors, 0, &mut args, &mut |args| {
            take(Part {
                rank,
                pred: other.pred,
                args: args.to_vec(),
            })
        });
    }
}

/// Every way to give each factor's positions a permutation of its parameters: factors
/// in order, the first varying slowest, permutations in lexicographic order of indices
/// (Python's `itertools.product` over `itertools.permutations`). Stops, returning false,
/// when `emit` returns false.
fn assign_factors(
    factors: &[(Vec<usize>, Vec<i8>)],
    k: usize,
    args: &mut [i8],
    emit: &mut dyn FnMut(&[i8]) -> bool,
) -> bool {
    let Some((positions, params)) = factors.get(k) else {
        return emit(args);
    };
    fn permute(
        positions: &[usize],
        remaining: &mut Vec<i8>,
        depth: usize,
        args: &mut [i8],
        then: &mut dyn FnMut(&mut [i8]) -> bool,
    ) -> bool {
        if depth == positions.len() {
            return then(args);
        }
        for i in 0..remaining.len() {
            let p = remaining.remove(i);
            args[positions[depth]] = p;
            let go_on = permute(positions, remaining, depth + 1, args, then);
            remaining.insert(i, p);
            if !go_on {
                return false;
            }
        }
        true
    }
    let mut remaining = params.clone();
    permute(positions, &mut remaining, 0, args, &mut |args| {
        assign_factors(factors, k + 1, args, emit)
    })
}

/// An invariant candidate: its parts in Fast Downward's sorted order.
#[derive(Debug, Clone, PartialEq, Eq, Hash)]
struct Candidate {
    parts: Vec<Part>,
}

impl Candidate {
    fn part(&self, pred: PredId) -> Option<&Part> {
        self.parts.iter().find(|p| p.pred == pred)
    }

    fn with(&self, part: Part) -> Candidate {
        let mut parts = self.parts.clone();
        parts.push(part);
        parts.sort_unstable();
        Candidate { parts }
    }
}

/// Python's `random.Random`: `randrange(n)` as CPython's `_randbelow_with_getrandbits`.
struct PythonRandom(Mt);

impl PythonRandom {
    /// `random.Random(seed)` for a seed below 2^32.
    fn new(seed: u32) -> PythonRandom {
        // CPython seeds an integer below 2^32 with init_by_array([seed]).
        PythonRandom(Mt::new_with_key([seed]))
    }

    /// An integer in `[0, n)`, `0 < n < 2^32`: `k`-bit draws (the top bits of one
    /// output) until one is below `n`, `k` the bit length of `n`.
    fn randrange(&mut self, n: usize) -> usize {
        debug_assert!(n > 0 && n <= u32::MAX as usize);
        let bits = usize::BITS - n.leading_zeros();
        loop {
            let r = (self.0.next_u32() >> (32 - bits)) as usize;
            if r < n {
                return r;
            }
        }
    }
}

struct Synthesis {
    actions: Vec<LiftedAction>,
    /// Per predicate, the actions that add it, in schema order.
    threats: Vec<Vec<usize>>,
    rank: Vec<u32>,
    random: PythonRandom,
    queue: VecDeque<Candidate>,
    seen: FxHashSet<Candidate>,
}

impl Synthesis {
    /// Whether `c` is an invariant; if not, its refinements are queued.
    fn check(&mut self, c: &Candidate) -> bool {
        let mut actions: Vec<usize> = Vec::new();
        for part in &c.parts {
            for &a in &self.threats[part.pred.0 as usize] {
                if !actions.contains(&a) {
                    actions.push(a);
                }
            }
        }
        while !actions.is_empty() {
            let pos = self.random.randrange(actions.len());
            let last = actions.len() - 1;
            actions.swap(pos, last);
            let Some(a) = actions.pop() else { break };
            let action = &self.actions[a];
            if too_heavy(c, action) {
                return false;
            }
            if let Some(add) = unbalanced_add(c, action) {
                refine(c, action, add, &self.rank, &mut self.queue, &mut self.seen);
                return false;
            }
        }
        true
    }
}

/// Constraints that the action's precondition and the given negated atoms can hold at
/// once: its (in)equalities, and each positive atom differing from each negative one of
/// its predicate.
fn precondition_satisfiable(system: &mut Constraints, action: &LiftedAction, negated: &[&Atom]) {
    for &(a, b) in &action.equal {
        system.require_equal(vec![(a, b)]);
    }
    for &(a, b) in &action.unequal {
        system.require_some_differ(vec![(a, b)]);
    }
    let mut positive: Vec<&Atom> = Vec::new();
    for p in &action.positive {
        if !positive.contains(&p) {
            positive.push(p);
        }
    }
    let mut negative: Vec<&Atom> = Vec::new();
    for n in action.negative.iter().chain(negated.iter().copied()) {
        if !negative.contains(&n) {
            negative.push(n);
        }
    }
    for p in &positive {
        for n in negative.iter().filter(|n| n.pred == p.pred) {
            system.require_some_differ(zipped(&n.args, &p.args));
        }
    }
}

/// Whether one application of `action` can add two atoms of one group of `c`.
fn too_heavy(c: &Candidate, action: &LiftedAction) -> bool {
    let adds: Vec<(&Atom, &Part)> = action
        .adds
        .iter()
        .filter_map(|a| c.part(a.pred).map(|p| (a, p)))
        .collect();
    for (i, &(e1, p1)) in adds.iter().enumerate() {
        for &(e2, p2) in &adds[i + 1..] {
            let mut system = Constraints::default();
            if e1.pred == e2.pred {
                system.require_some_differ(zipped(&e1.args, &e2.args));
            }
            system.require_equal(p1.cover(&e1.args));
            system.require_equal(p2.cover(&e2.args));
            precondition_satisfiable(&mut system, action, &[e1, e2]);
            if system.solvable() {
                return true;
            }
        }
    }
    false
}

/// The first add effect of `action` that no delete effect balances in every
/// instantiation, if any.
fn unbalanced_add<'a>(c: &Candidate, action: &'a LiftedAction) -> Option<&'a Atom> {
    let dels: Vec<(&Atom, &Part)> = action
        .dels
        .iter()
        .filter_map(|d| c.part(d.pred).map(|p| (d, p)))
        .collect();
    action
        .adds
        .iter()
        .filter_map(|a| c.part(a.pred).map(|p| (a, p)))
        .find(|&(add, part)| {
            let add_cover = part.cover(&add.args);
            // The add threatens the group whatever the action's parameters are, except
            // as far as covering it forces them: a balance may not assume parameters
            // equal, or bound to an object, unless the cover makes them so.
            let mut classes = Partition::default();
            for &(a, b) in &add_cover {
                classes.union(a, b);
            }
            let mut params_free = Constraints::default();
            for p in 0..action.params {
                if !classes.has_object(Term::Param(p)) {
                    params_free.not_objects.push(Term::Param(p));
                }
                for q in p + 1..action.params {
                    if !classes.same(Term::Param(p), Term::Param(q)) {
                        params_free.require_some_differ(vec![(Term::Param(p), Term::Param(q))]);
                    }
                }
            }
            !dels.iter().any(|&(del, del_part)| {
                balances(action, add, &add_cover, del, del_part, &params_free)
            })
        })
        .map(|(add, _)| add)
}

/// Whether deleting `del` balances adding `add` in every instantiation that threatens
/// the group: the precondition requires the deleted atom, it is another atom than the
/// added one, and both are in the same group.
fn balances(
    action: &LiftedAction,
    add: &Atom,
    add_cover: &[(Term, Term)],
    del: &Atom,
    del_part: &Part,
    params_free: &Constraints,
) -> bool {
    let required: Vec<Vec<(Term, Term)>> = action
        .positive
        .iter()
        .filter(|p| p.pred == del.pred)
        .map(|p| zipped(&del.args, &p.args))
        .collect();
    if required.is_empty() {
        return false;
    }
    let mut system = Constraints::default();
    system.require_equal(add_cover.to_vec());
    system.require_equal(del_part.cover(&del.args));
    system.equality_choices.push(required);
    if add.pred == del.pred {
        system.require_some_differ(zipped(&add.args, &del.args));
    }
    system.extend(params_free);
    system.solvable()
}

/// Queues the candidates refining `c` for an unbalanced `add` of `action`: one more
/// part, for a predicate `action` deletes and `c` lacks, in Fast Downward's order, until
/// [`MAX_CANDIDATES`] candidates have been queued in all.
fn refine(
    c: &Candidate,
    action: &LiftedAction,
    add: &Atom,
    rank: &[u32],
    queue: &mut VecDeque<Candidate>,
    seen: &mut FxHashSet<Candidate>,
) {
    let Some(part) = c.part(add.pred) else {
        return;
    };
    for del in &action.dels {
        if seen.len() >= MAX_CANDIDATES {
            return;
        }
        if c.part(del.pred).is_none() {
            part.balancing_parts(&add.args, del, rank[del.pred.0 as usize], &mut |new_part| {
                let refined = c.with(new_part);
                if !seen.contains(&refined) {
                    seen.insert(refined.clone());
                    queue.push_back(refined);
                }
                seen.len() < MAX_CANDIDATES
            });
        }
    }
}

/// The initial candidates: per fluent predicate in declaration order, no position
/// counted, then each position counted in turn.
fn initial_candidates(model: &Model, rank: &[u32], arity: &[Option<usize>]) -> Vec<Candidate> {
    let mut out = Vec::new();
    for (i, p) in model.predicates.iter().enumerate() {
        let Some(n) = arity[i].filter(|_| p.fluent) else {
            continue;
        };
        let pred = PredId(i as u32);
        let all: Vec<i8> = (0..n as i8).collect();
        out.push(Candidate {
            parts: vec![Part {
                rank: rank[i],
                pred,
                args: all.clone(),
            }],
        });
        for counted in 0..n {
            let mut args: Vec<i8> = all[..n - 1].to_vec();
            args.insert(counted, COUNTED);
            out.push(Candidate {
                parts: vec![Part {
                    rank: rank[i],
                    pred,
                    args,
                }],
            });
        }
    }
    out
}

/// The invariant parameters' values for an atom of a part.
fn key_of(part: &Part, args: &[u32]) -> Vec<u32> {
    let mut key = vec![0; part.arity()];
    for (&a, &o) in part.args.iter().zip(args) {
        if a != COUNTED {
            key[a as usize] = o;
        }
    }
    key
}

/// Synthesises invariants and returns their ground mutex groups (each sorted, size >= 2,
/// deduplicated, in a deterministic order); `None` if `watch` stopped it at a limit.
pub(crate) fn mutex_groups(model: &Model, g: &Grounding, watch: &Watch) -> Option<Vec<Group>> {
    let mut names: Vec<(&str, usize)> = model
        .predicates
        .iter()
        .enumerate()
        .map(|(i, p)| (p.name.as_str(), i))
        .collect();
    names.sort_unstable();
    let mut rank = vec![0u32; model.predicates.len()];
    for (r, &(_, i)) in names.iter().enumerate() {
        rank[i] = r as u32;
    }
    let mut arity: Vec<Option<usize>> = vec![None; model.predicates.len()];
    for s in &model.schemas {
        for p in s
            .positive
            .iter()
            .chain(&s.negative)
            .chain(&s.add)
            .chain(&s.delete)
        {
            arity[p.pred.0 as usize] = Some(p.args.len());
        }
    }
    for (pred, args) in &model.init {
        arity[pred.0 as usize] = Some(args.len());
    }

    let actions = lifted_actions(model, g);
    let mut threats: Vec<Vec<usize>> = vec![Vec::new(); model.predicates.len()];
    for (i, a) in actions.iter().enumerate() {
        for add in &a.adds {
            let list = &mut threats[add.pred.0 as usize];
            if list.last() != Some(&i) {
                list.push(i);
            }
        }
    }
    let mut synthesis = Synthesis {
        actions,
        threats,
        rank: rank.clone(),
        random: PythonRandom::new(FAST_DOWNWARD_INVARIANT_SEED),
        queue: VecDeque::new(),
        seen: FxHashSet::default(),
    };
    for c in initial_candidates(model, &rank, &arity)
        .into_iter()
        .take(MAX_CANDIDATES)
    {
        if synthesis.seen.insert(c.clone()) {
            synthesis.queue.push_back(c);
        }
    }
    let mut invariants: Vec<Candidate> = Vec::new();
    while let Some(c) = synthesis.queue.pop_front() {
        if watch.tick() {
            return None;
        }
        if synthesis.check(&c) {
            invariants.push(c);
        }
    }
    let groups = ground_groups(model, g, &invariants, watch);
    (!watch.check()).then_some(groups)
}

/// The groups of the invariants: per invariant and parameter binding with exactly one
/// atom true initially, the reachable fluent atoms of that binding.
fn ground_groups(
    model: &Model,
    g: &Grounding,
    invariants: &[Candidate],
    watch: &Watch,
) -> Vec<Group> {
    // Initial atoms in the problem's order, each once.
    let mut init: Vec<(PredId, Vec<u32>)> = Vec::new();
    let mut init_seen: FxHashSet<(PredId, Vec<u32>)> = FxHashSet::default();
    for (pred, args) in &model.init {
        let args: Vec<u32> = args.iter().map(|o| o.0).collect();
        if init_seen.insert((*pred, args.clone())) {
            init.push((*pred, args));
        }
    }
    let mut groups: Vec<Group> = Vec::new();
    let mut group_set: FxHashSet<Group> = FxHashSet::default();
    for inv in invariants {
        let mut initially: FxHashMap<Vec<u32>, usize> = FxHashMap::default();
        let mut keys_in_order: Vec<Vec<u32>> = Vec::new();
        for (pred, args) in &init {
            if let Some(part) = inv.part(*pred) {
                let key = key_of(part, args);
                let count = initially.entry(key.clone()).or_insert(0);
                if *count == 0 {
                    keys_in_order.push(key);
                }
                *count += 1;
            }
        }
        keys_in_order.retain(|k| initially[k] == 1);
        if keys_in_order.is_empty() {
            continue;
        }
        let mut by_key: FxHashMap<Vec<u32>, Vec<AtomId>> = FxHashMap::default();
        for a in 0..g.atoms.len() as AtomId {
            if watch.tick() {
                return groups;
            }
            if !g.fluent[a as usize] {
                continue;
            }
            if let Some(part) = inv.part(g.atoms.pred(a)) {
                by_key
                    .entry(key_of(part, g.atoms.args(a)))
                    .or_default()
                    .push(a);
            }
        }
        for key in keys_in_order {
            let Some(mut atoms) = by_key.remove(&key) else {
                continue;
            };
            atoms.sort_unstable();
            atoms.dedup();
            if atoms.len() >= 2 && group_set.insert(atoms.clone()) {
                groups.push(atoms);
            }
        }
    }
    groups
}

#[cfg(test)]
mod tests {
    use super::*;

    /// CPython 3.11's `random.Random(314159)`: `[r.randrange(n) for n in [1, 2, 3, 5, 7,
    /// 100, 1000, 1, 1, 2, 9]]` is `[0, 1, 1, 0, 0, 73, 313, 0, 0, 0, 0]`.
    #[test]
    fn draws_are_pythons() {
        let mut r = PythonRandom::new(314_159);
        let draws: Vec<usize> = [1, 2, 3, 5, 7, 100, 1000, 1, 1, 2, 9]
            .iter()
            .map(|&n| r.randrange(n))
            .collect();
        assert_eq!(draws, [0, 1, 1, 0, 0, 73, 313, 0, 0, 0, 0]);
    }

    /// The reference implementation's `mt19937ar.out`: the first outputs after
    /// `init_by_array({0x123, 0x234, 0x345, 0x456})`, the seeding Python's uses.
    #[test]
    fn seeding_by_key_is_the_reference_implementations() {
        let mut rng = Mt::new_with_key([0x123, 0x234, 0x345, 0x456]);
        let first: Vec<u32> = (0..5).map(|_| rng.next_u32()).collect();
        assert_eq!(
            first,
            [
                1_067_595_299,
                955_945_823,
                477_289_528,
                4_107_218_783,
                4_228_976_476
            ]
        );
    }

    fn balancing(p: &Part, own: &[Term], other: &Atom) -> Vec<Part> {
        let mut out = Vec::new();
        p.balancing_parts(own, other, 1, &mut |part| {
            out.push(part);
            true
        });
        out
    }

    fn part(pred: u32, args: &[i8]) -> Part {
        Part {
            rank: pred,
            pred: PredId(pred),
            args: args.to_vec(),
        }
    }

    /// Fast Downward's own example: part `P(v0, v1, v2)`, add `P(a, b, c)`, delete
    /// `Q(b, c, d, a)`: the one balancing part is `Q(v1, v2, counted, v0)`.
    #[test]
    fn balancing_parts_map_values_to_parameters() {
        let (a, b, c, d) = (
            Term::Param(0),
            Term::Param(1),
            Term::Param(2),
            Term::Param(3),
        );
        let p = part(0, &[0, 1, 2]);
        let q = Atom {
            pred: PredId(1),
            args: vec![b, c, d, a],
        };
        assert_eq!(
            balancing(&p, &[a, b, c], &q),
            vec![part(1, &[1, 2, COUNTED, 0])]
        );
        // A value twice in the deleted atom and once in the added one: one position is
        // counted, the other takes the parameter, both ways round.
        let q = Atom {
            pred: PredId(1),
            args: vec![a, a],
        };
        let p = part(0, &[0, COUNTED]);
        assert_eq!(
            balancing(&p, &[a, b], &q),
            vec![part(1, &[0, COUNTED]), part(1, &[COUNTED, 0])]
        );
        // Too many arguments left over: no part.
        let q = Atom {
            pred: PredId(1),
            args: vec![c, d, a],
        };
        assert!(balancing(&p, &[a, b], &q).is_empty());
    }

    /// The groups of a small task, as atom texts, each group sorted.
    fn groups_of(domain: &str, problem: &str) -> Vec<Vec<String>> {
        let domain = pddl::parse_domain(domain).expect("domain");
        let problem = pddl::parse_problem(problem).expect("problem");
        let model = Model::build(&domain, &problem).expect("model");
        let limits = task::Limits::default();
        let watch = Watch::new(&limits);
        let g = crate::ground::ground(&model, &watch)
            .expect("grounding")
            .expect("no limits");
        let mut groups: Vec<Vec<String>> = mutex_groups(&model, &g, &watch)
            .expect("no limits")
            .iter()
            .map(|group| {
                let mut atoms: Vec<String> = group
                    .iter()
                    .map(|&a| {
                        let args = g.atoms.args(a).iter().copied();
                        crate::ground::atom_text(&model, g.atoms.pred(a), args)
                    })
                    .collect();
                atoms.sort();
                atoms
            })
            .collect();
        groups.sort();
        groups
    }

    const GRIPPER: &str = "(define (domain gripper)
        (:predicates (room ?r) (ball ?b) (gripper ?g) (at-robby ?r) (at ?b ?r)
                     (free ?g) (carry ?b ?g))
        (:action move :parameters (?from ?to)
          :precondition (and (room ?from) (room ?to) (at-robby ?from))
          :effect (and (at-robby ?to) (not (at-robby ?from))))
        (:action pick :parameters (?b ?r ?g)
          :precondition (and (ball ?b) (room ?r) (gripper ?g) (at ?b ?r) (at-robby ?r) (free ?g))
          :effect (and (carry ?b ?g) (not (at ?b ?r)) (not (free ?g))))
        (:action drop :parameters (?b ?r ?g)
          :precondition (and (ball ?b) (room ?r) (gripper ?g) (carry ?b ?g) (at-robby ?r))
          :effect (and (at ?b ?r) (free ?g) (not (carry ?b ?g)))))";

    /// Refinement finds the groups that need two predicates: where a ball is (in a room
    /// or in a gripper) and what a gripper holds (nothing or a ball).
    #[test]
    fn refinement_finds_groups_over_two_predicates() {
        let groups = groups_of(
            GRIPPER,
            "(define (problem p) (:domain gripper) (:objects a b l r1 r2)
               (:init (room r1) (room r2) (ball a) (ball b) (gripper l) (at-robby r1)
                      (at a r1) (at b r2) (free l))
               (:goal (and (at a r2) (at b r1))))",
        );
        let text = |g: &[&str]| g.iter().map(|s| s.to_string()).collect::<Vec<_>>();
        assert_eq!(
            groups,
            vec![
                text(&["at(a, r1)", "at(a, r2)", "carry(a, l)"]),
                text(&["at(b, r1)", "at(b, r2)", "carry(b, l)"]),
                text(&["at-robby(r1)", "at-robby(r2)"]),
                text(&["carry(a, l)", "carry(b, l)", "free(l)"]),
            ]
        );
    }

    /// A binding with two atoms true initially yields no group (nor does one with none,
    /// Fast Downward's rule): two robots, so "where is the robot" is no mutex group, while
    /// the balls' groups stay.
    #[test]
    fn bindings_with_two_initial_atoms_give_no_group() {
        let groups = groups_of(
            GRIPPER,
            "(define (problem p) (:domain gripper) (:objects a l r1 r2)
               (:init (room r1) (room r2) (ball a) (gripper l) (at-robby r1) (at-robby r2)
                      (at a r1) (free l))
               (:goal (at a r2)))",
        );
        assert!(
            groups.iter().all(|g| !g[0].starts_with("at-robby")),
            "{groups:?}"
        );
        assert!(groups.contains(&vec![
            "at(a, r1)".to_string(),
            "at(a, r2)".to_string(),
            "carry(a, l)".to_string()
        ]));
    }

    /// An added atom with one variable in all 12 positions, balanced only by a deleted
    /// atom alike, has 12! balancing parts; refinement stops at [`MAX_CANDIDATES`] queued
    /// candidates instead of enumerating 479 million.
    #[test]
    fn refinement_stops_at_the_candidate_limit() {
        let xs = ["?x"; 12].join(" ");
        let params: Vec<String> = (0..12).map(|i| format!("?a{i}")).collect();
        let params = params.join(" ");
        let domain = format!(
            "(define (domain d) (:predicates (p {params}) (q {params}))
               (:action flip :parameters (?x) :precondition (q {xs})
                 :effect (and (p {xs}) (not (q {xs}))))
               (:action flop :parameters (?x) :precondition (p {xs})
                 :effect (and (q {xs}) (not (p {xs})))))"
        );
        let os = ["o"; 12].join(" ");
        let problem = format!(
            "(define (problem p) (:domain d) (:objects o) (:init (q {os})) (:goal (p {os})))"
        );
        let groups = groups_of(&domain, &problem);
        // The two atoms are one group (found among the refinements).
        assert_eq!(groups.len(), 1, "{groups:?}");
    }

    #[test]
    fn constraints_respect_objects_and_inequalities() {
        let (x, y) = (Term::Param(0), Term::Param(1));
        let (o1, o2) = (Term::Object(1), Term::Object(2));
        let mut s = Constraints::default();
        s.require_equal(vec![(x, o1), (y, o2)]);
        assert!(s.solvable());
        s.require_equal(vec![(x, y)]);
        assert!(!s.solvable(), "two objects in one class");
        let mut s = Constraints::default();
        s.equality_choices.push(vec![vec![(x, y)], vec![(x, o1)]]);
        s.require_some_differ(vec![(x, y)]);
        assert!(s.solvable(), "the second choice works");
        s.not_objects.push(x);
        assert!(!s.solvable(), "neither works");
    }
}
