//! Pattern databases (Culberson and Schaeffer 1998; Edelkamp 2001 for planning).
//!
//! A *pattern* is a set of variables. Projecting the task onto it keeps, of every state,
//! only the values of those variables, and of every operator only its preconditions and
//! effects on them; the projection is an abstraction, so the cheapest cost to an abstract
//! goal state is an admissible and consistent estimate of the true cost. A
//! [`PatternDatabase`] holds that cost for every abstract state.
//!
//! Construction ([`PdbBuilder`]), in O(abstract operators * depth + abstract states *
//! (tree nodes visited + applicable abstract operators)) time:
//!
//! 1. *Projection and regression.* Operators without effects on the pattern are ignored
//!    (they only loop in the abstraction). Every other operator becomes regression
//!    operators: applicable in an abstract state where its effects and its other
//!    preconditions on the pattern hold, leading to the state with each effect variable
//!    set back to its precondition value. An effect variable without a precondition may
//!    have had any value, so the operator is multiplied out over that variable's values.
//!    A regression operator is a condition list and a *hash delta*: the predecessor's
//!    index is the state's index plus the delta (wrapping arithmetic). Regression
//!    operators that change nothing are dropped; of duplicates (same conditions, same
//!    delta) only the cheapest is kept.
//! 2. *Match tree.* The regression operators go into a decision tree over pattern
//!    positions (like [`crate::SuccessorGenerator`]), so an abstract state's applicable
//!    operators are found without scanning all of them.
//! 3. *Backward search.* Dijkstra from all abstract goal states over the regression
//!    operators: a FIFO queue when every abstract operator has the same positive cost
//!    (breadth-first search), otherwise a radix heap. Distances are `u32`, capped at
//!    `u32::MAX - 1` (a lower value is still admissible), with `u32::MAX` for states from
//!    which no goal state is reachable (dead ends).
//!
//! *Perfect hashing*: the index of an abstract state is `sum(value_i * multiplier_i)`
//! with `multiplier_0 = 1` and `multiplier_{i+1} = multiplier_i * domain_size_i`, over the
//! pattern's variables in increasing order. *Compact tables*: the distances are stored in
//! `u8`, `u16` or `u32` entries, the narrowest that holds the largest finite distance
//! (the widest value of each width means "dead end"). A lookup computes the index from the
//! unpacked state and reads one entry: O(pattern size), no allocation.

use std::convert::Infallible;

use task::{Limit, Limits, Task, TaskError, VarId};

use crate::astar::SearchError;
use crate::radix_heap::RadixHeap;

const NONE: u32 = u32::MAX;
/// "No goal state reachable" in the `u32` distances.
const DEAD: u32 = u32::MAX;
/// The largest finite distance stored; larger ones are capped (still admissible).
const CAP: u32 = u32::MAX - 1;

/// The largest operator cost for which the backward search uses Dial's buckets.
const MAX_BUCKET_COST: u32 = 1 << 12;
/// Steps (operators projected, tree nodes built, abstract states expanded) between two
/// checks of the limits while a database is built: a few microseconds' work at most.
const CHECK_EVERY: u32 = 1 << 12;

/// The most abstract states a pattern database may have (2^31).
pub const MAX_PDB_SIZE: u64 = 1 << 31;

/// A pattern that cannot have a database.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum PatternError {
    /// A pattern names a variable the task does not have.
    #[error("pattern variable {var} does not exist (the task has {num_variables} variables)")]
    VariableOutOfRange {
        /// The variable given.
        var: u32,
        /// The number of variables of the task.
        num_variables: usize,
    },
    /// The abstract state space is too large to store.
    #[error("pattern {pattern:?} has more than {limit} abstract states")]
    TooLarge {
        /// The pattern (variable indices).
        pattern: Vec<u32>,
        /// The limit it exceeds.
        limit: u64,
    },
    /// The task breaks its invariants.
    #[error("invalid task: {0}")]
    InvalidTask(#[from] TaskError),
}

/// The pattern `vars` as a sorted list of distinct variables of `task`; fails if a
/// variable does not exist.
pub fn normalize_pattern(task: &Task, vars: &[u32]) -> Result<Vec<VarId>, PatternError> {
    let mut pattern: Vec<VarId> = Vec::with_capacity(vars.len());
    for &var in vars {
        if var as usize >= task.variables.len() {
            return Err(PatternError::VariableOutOfRange {
                var,
                num_variables: task.variables.len(),
            });
        }
        pattern.push(VarId(var));
    }
    pattern.sort_unstable();
    pattern.dedup();
    Ok(pattern)
}

/// The number of abstract states of `pattern` (the product of its domain sizes), or
/// `None` if it exceeds `limit`. O(pattern size).
pub fn pattern_size(task: &Task, pattern: &[VarId], limit: u64) -> Option<u64> {
    let mut size: u64 = 1;
    for var in pattern {
        let domain = u64::from(task.variables.get(var.index())?.domain_size());
        size = size.checked_mul(domain).filter(|&s| s <= limit)?;
    }
    Some(size)
}

/// Peak bytes that building databases of `sizes` abstract states, one after the other
/// with one builder, and keeping them all takes: an upper estimate, used to stop before
/// allocating what a memory limit does not allow (`--overall-memory-limit`). Each kept
/// table takes at most 4 bytes per state (`u32` entries); the builder's scratch for the
/// largest takes its `u32` distances (4), the queue, which may hold every state and
/// double its capacity once more (8), and the reached-state bits, rounded up to 4 for
/// the radix heap's slack. The regression operators and match tree, proportional to the
/// task's operators rather than to the states, are left out. Saturates instead of
/// overflowing.
pub fn construction_bytes(sizes: impl IntoIterator<Item = u64>) -> u64 {
    let (mut tables, mut largest) = (0u64, 0u64);
    for size in sizes {
        tables = tables.saturating_add(size.saturating_mul(4));
        largest = largest.max(size);
    }
    tables.saturating_add(largest.saturating_mul(16))
}

/// The databases of `patterns` (variable indices in any order) for `task`, in order,
/// sharing one builder. Fails as [`PatternDatabase::new`] does.
pub(crate) fn build_collection(
    task: &Task,
    patterns: &[Vec<u32>],
) -> Result<Vec<PatternDatabase>, PatternError> {
    let (normalized, _) = normalize_collection(task, patterns)?;
    let mut builder = PdbBuilder::new(task);
    Ok(normalized.iter().map(|p| builder.build(p)).collect())
}

/// Like [`build_collection`], under `limits`: `Ok(Err(Limit::Memory))`, before anything
/// is allocated, when [`construction_bytes`] of the collection would take memory use
/// beyond the limit; `Ok(Err(limit))` when a limit is reached while the databases are
/// built (checked before each and every [`CHECK_EVERY`] steps inside one).
pub(crate) fn build_collection_within(
    task: &Task,
    patterns: &[Vec<u32>],
    limits: &Limits,
) -> Result<Result<Vec<PatternDatabase>, Limit>, PatternError> {
    let (normalized, sizes) = normalize_collection(task, patterns)?;
    if limits.would_exceed(construction_bytes(sizes), || 0) {
        return Ok(Err(Limit::Memory));
    }
    let mut builder = PdbBuilder::new(task);
    let mut pdbs = Vec::with_capacity(normalized.len());
    let check = || limits.reached(|| 0).map_or(Ok(()), Err);
    for pattern in &normalized {
        if let Err(limit) = check() {
            return Ok(Err(limit));
        }
        match builder.build_with(pattern, check) {
            Ok(pdb) => pdbs.push(pdb),
            Err(limit) => return Ok(Err(limit)),
        }
    }
    Ok(Ok(pdbs))
}

/// The patterns, sorted and deduplicated, with their numbers of abstract states, for a
/// valid task; fails on an invalid task, a variable out of range or a pattern over
/// [`MAX_PDB_SIZE`].
fn normalize_collection(
    task: &Task,
    patterns: &[Vec<u32>],
) -> Result<(Vec<Vec<VarId>>, Vec<u64>), PatternError> {
    task.validate()?;
    let mut normalized = Vec::with_capacity(patterns.len());
    let mut sizes = Vec::with_capacity(patterns.len());
    for p in patterns {
        let pattern = normalize_pattern(task, p)?;
        let Some(size) = pattern_size(task, &pattern, MAX_PDB_SIZE) else {
            return Err(PatternError::TooLarge {
                pattern: pattern.iter().map(|v| v.0).collect(),
                limit: MAX_PDB_SIZE,
            });
        };
        normalized.push(pattern);
        sizes.push(size);
    }
    Ok((normalized, sizes))
}

impl From<PatternError> for SearchError {
    fn from(e: PatternError) -> SearchError {
        match e {
            PatternError::InvalidTask(e) => SearchError::InvalidTask(e),
            e => SearchError::InvalidPattern(e),
        }
    }
}

/// Distances in the narrowest entries that hold them; the largest value of each width
/// means "dead end".
#[derive(Debug, Clone)]
enum Distances {
    U8(Box<[u8]>),
    U16(Box<[u16]>),
    U32(Box<[u32]>),
}

/// The cost to the goal of every abstract state of a pattern; see the module
/// documentation. Admissible and consistent.
#[derive(Debug, Clone)]
pub struct PatternDatabase {
    pattern: Vec<VarId>,
    /// Variable index and multiplier of each pattern position.
    vars: Vec<u32>,
    multipliers: Vec<u32>,
    distances: Distances,
    has_dead_ends: bool,
}

impl PatternDatabase {
    /// The database of `pattern` (variable indices in any order, duplicates ignored) for
    /// `task`, with costs as [`Task::cost`] gives them. Fails if the task is invalid, a
    /// variable does not exist, or the pattern has more than [`MAX_PDB_SIZE`] abstract
    /// states. See the module documentation for the algorithm and its cost.
    pub fn new(task: &Task, pattern: &[u32]) -> Result<PatternDatabase, PatternError> {
        let mut pdbs = build_collection(task, &[pattern.to_vec()])?;
        pdbs.pop().ok_or(PatternError::TooLarge {
            pattern: pattern.to_vec(),
            limit: MAX_PDB_SIZE,
        })
    }

    /// The pattern, sorted.
    pub fn pattern(&self) -> &[VarId] {
        &self.pattern
    }

    /// The number of abstract states.
    pub fn size(&self) -> usize {
        match &self.distances {
            Distances::U8(d) => d.len(),
            Distances::U16(d) => d.len(),
            Distances::U32(d) => d.len(),
        }
    }

    /// Bytes of the distance table and the pattern.
    pub fn memory_bytes(&self) -> usize {
        let entry = match &self.distances {
            Distances::U8(_) => 1,
            Distances::U16(_) => 2,
            Distances::U32(_) => 4,
        };
        self.size() * entry + self.pattern.len() * 12
    }

    /// True if some abstract state cannot reach an abstract goal state.
    pub fn has_dead_ends(&self) -> bool {
        self.has_dead_ends
    }

    /// The index of the abstract state of `state` (one value per variable of the task).
    #[inline]
    pub fn index(&self, state: &[u32]) -> usize {
        let mut index = 0usize;
        for (&var, &multiplier) in self.vars.iter().zip(&self.multipliers) {
            index += state[var as usize] as usize * multiplier as usize;
        }
        index
    }

    /// The distance stored for abstract state `index`, with `u32::MAX` for a dead end.
    #[inline]
    pub(crate) fn raw_at(&self, index: usize) -> u32 {
        match &self.distances {
            Distances::U8(d) => match d[index] {
                u8::MAX => DEAD,
                v => u32::from(v),
            },
            Distances::U16(d) => match d[index] {
                u16::MAX => DEAD,
                v => u32::from(v),
            },
            Distances::U32(d) => d[index],
        }
    }

    /// The distance of `state` with `u32::MAX` for a dead end.
    #[inline]
    pub(crate) fn raw(&self, state: &[u32]) -> u32 {
        self.raw_at(self.index(state))
    }

    /// The cost from abstract state `index` to the goal; `None` for a dead end.
    #[inline]
    pub fn value_at(&self, index: usize) -> Option<u64> {
        match self.raw_at(index) {
            DEAD => None,
            v => Some(u64::from(v)),
        }
    }

    /// The abstract cost from `state` (one value per variable of the task) to the goal;
    /// `None` if the abstract state cannot reach the goal (then neither can `state`).
    #[inline]
    pub fn value(&self, state: &[u32]) -> Option<u64> {
        self.value_at(self.index(state))
    }
}

/// A node of the match tree over regression operators.
#[derive(Debug, Clone, Copy)]
struct Node {
    /// `ceil(2^64 / (multiplier * domain))` of the position switched on, so that its
    /// value in state `s`, `s / multiplier % domain`, is
    /// `((magic * s mod 2^64) * domain) >> 64` (Lemire, Kaser and Kurz 2019: exact for
    /// 32-bit `s` and `multiplier * domain`); 0 if `multiplier * domain` is 1.
    magic: u64,
    /// The domain size of the position switched on; 0 for a leaf.
    domain: u32,
    /// One child per value in `children[children_start..children_start + domain]`.
    children_start: u32,
    /// The child for operators without a condition on `pos`, or `NONE`.
    dont_care: u32,
    /// The operators whose conditions all hold once this node is reached:
    /// `leaf_ops[ops_start..ops_end]`.
    ops_start: u32,
    ops_end: u32,
}

/// A regression operator during construction: conditions in `conditions[start..end]`.
#[derive(Debug, Clone, Copy)]
struct AbstractOp {
    start: u32,
    end: u32,
    delta: u32,
    cost: u32,
}

/// Builds pattern databases for one task, reusing its buffers across patterns (the
/// hill climbing builds hundreds).
#[derive(Debug, Clone)]
pub(crate) struct PdbBuilder {
    domain: Vec<u32>,
    op_cost: Vec<u32>,
    /// Preconditions and effects of each operator, as `(variable, value)`:
    /// `pre[pre_start[o]..pre_start[o + 1]]`, likewise `eff`.
    pre_start: Vec<u32>,
    pre: Vec<(u32, u32)>,
    eff_start: Vec<u32>,
    eff: Vec<(u32, u32)>,
    goal: Vec<(u32, u32)>,
    /// Operators with an effect on variable `v`: `affecting[affecting_start[v]..]`.
    affecting_start: Vec<u32>,
    affecting: Vec<u32>,
    // Scratch.
    op_mark: Vec<u32>,
    stamp: u32,
    position: Vec<u32>,
    conditions: Vec<(u32, u32)>,
    ops: Vec<AbstractOp>,
    order: Vec<u32>,
    /// Effect variables without a precondition: position, effect value, current value.
    free: Vec<(u32, u32, u32)>,
    /// Domain size of each pattern position.
    pos_domain: Vec<u32>,
    nodes: Vec<Node>,
    children: Vec<u32>,
    leaf_ops: Vec<(u32, u32)>,
    items: Vec<(u32, u32)>,
    sorted: Vec<(u32, u32)>,
    counts: Vec<u32>,
    work: Vec<(u32, u32, u32)>,
    stack: Vec<u32>,
    distances: Vec<u32>,
    seen: Vec<u64>,
    fifo: Vec<u32>,
    buckets: Vec<Vec<u32>>,
    heap: RadixHeap,
}

impl PdbBuilder {
    /// A builder for `task`, which must be valid. O(size of the task).
    pub(crate) fn new(task: &Task) -> PdbBuilder {
        let num_vars = task.variables.len();
        let mut b = PdbBuilder {
            domain: task.variables.iter().map(|v| v.domain_size()).collect(),
            op_cost: Vec::with_capacity(task.operators.len()),
            pre_start: vec![0],
            pre: Vec::new(),
            eff_start: vec![0],
            eff: Vec::new(),
            goal: task.goal.iter().map(|f| (f.var.0, f.value)).collect(),
            affecting_start: vec![0; num_vars + 1],
            affecting: Vec::new(),
            op_mark: vec![0; task.operators.len()],
            stamp: 0,
            position: vec![NONE; num_vars],
            conditions: Vec::new(),
            ops: Vec::new(),
            order: Vec::new(),
            free: Vec::new(),
            pos_domain: Vec::new(),
            nodes: Vec::new(),
            children: Vec::new(),
            leaf_ops: Vec::new(),
            items: Vec::new(),
            sorted: Vec::new(),
            counts: Vec::new(),
            work: Vec::new(),
            stack: Vec::new(),
            distances: Vec::new(),
            seen: Vec::new(),
            fifo: Vec::new(),
            buckets: Vec::new(),
            heap: RadixHeap::new(),
        };
        for op in &task.operators {
            b.op_cost.push(task.cost(op).min(u64::from(CAP)) as u32);
            b.pre
                .extend(op.preconditions.iter().map(|f| (f.var.0, f.value)));
            b.pre_start.push(b.pre.len() as u32);
            b.eff.extend(op.effects.iter().map(|f| (f.var.0, f.value)));
            b.eff_start.push(b.eff.len() as u32);
            for f in &op.effects {
                b.affecting_start[f.var.index() + 1] += 1;
            }
        }
        for v in 0..num_vars {
            b.affecting_start[v + 1] += b.affecting_start[v];
        }
        let mut next = b.affecting_start.clone();
        b.affecting = vec![0; b.eff.len()];
        for (o, op) in task.operators.iter().enumerate() {
            for f in &op.effects {
                let slot = &mut next[f.var.index()];
                b.affecting[*slot as usize] = o as u32;
                *slot += 1;
            }
        }
        b
    }

    /// The database of `pattern`, which must be sorted, free of duplicates, and of at
    /// most [`MAX_PDB_SIZE`] abstract states.
    pub(crate) fn build(&mut self, pattern: &[VarId]) -> PatternDatabase {
        match self.build_with(pattern, || Ok::<(), Infallible>(())) {
            Ok(pdb) => pdb,
            Err(never) => match never {},
        }
    }

    /// Like [`PdbBuilder::build`], calling `stop` every [`CHECK_EVERY`] steps of the
    /// projection, the match tree and the abstract search, and giving up with its error.
    /// A database is not linear in its states: each state's step visits its applicable
    /// abstract operators, of which a large task has many (scanalyzer's p19, 49,572
    /// operators, needs minutes for six variables of ten values each), so the limits are
    /// checked inside it as well as between databases.
    pub(crate) fn build_with<E>(
        &mut self,
        pattern: &[VarId],
        mut stop: impl FnMut() -> Result<(), E>,
    ) -> Result<PatternDatabase, E> {
        let result = self.build_checked(pattern, &mut stop);
        for &var in pattern {
            self.position[var.index()] = NONE;
        }
        result
    }

    fn build_checked<E>(
        &mut self,
        pattern: &[VarId],
        stop: &mut impl FnMut() -> Result<(), E>,
    ) -> Result<PatternDatabase, E> {
        let vars: Vec<u32> = pattern.iter().map(|v| v.0).collect();
        let mut multipliers = Vec::with_capacity(vars.len());
        let mut size: u32 = 1;
        for (pos, &var) in vars.iter().enumerate() {
            multipliers.push(size);
            size = size.wrapping_mul(self.domain[var as usize]);
            self.position[var as usize] = pos as u32;
        }
        self.pos_domain.clear();
        self.pos_domain
            .extend(vars.iter().map(|&v| self.domain[v as usize]));
        self.project(&vars, &multipliers, stop)?;
        self.build_tree(&multipliers, stop)?;
        self.search(&multipliers, size as usize, stop)?;
        let distances = &self.distances[..size as usize];
        let has_dead_ends = distances.contains(&DEAD);
        let max = distances.iter().filter(|&&d| d != DEAD).max().copied();
        let table = match max {
            Some(m) if m >= u32::from(u16::MAX) => Distances::U32(distances.into()),
            Some(m) if m >= u32::from(u8::MAX) => Distances::U16(
                distances
                    .iter()
                    .map(|&d| if d == DEAD { u16::MAX } else { d as u16 })
                    .collect(),
            ),
            _ => Distances::U8(
                distances
                    .iter()
                    .map(|&d| if d == DEAD { u8::MAX } else { d as u8 })
                    .collect(),
            ),
        };
        Ok(PatternDatabase {
            pattern: pattern.to_vec(),
            vars,
            multipliers,
            distances: table,
            has_dead_ends,
        })
    }

    /// Fills `ops` and `conditions` with the deduplicated regression operators of the
    /// projection onto `vars` (positions are set in `position`).
    fn project<E>(
        &mut self,
        vars: &[u32],
        multipliers: &[u32],
        stop: &mut impl FnMut() -> Result<(), E>,
    ) -> Result<(), E> {
        let mut steps: u32 = 0;
        self.conditions.clear();
        self.ops.clear();
        self.stamp = self.stamp.wrapping_add(1);
        if self.stamp == 0 {
            self.op_mark.fill(0);
            self.stamp = 1;
        }
        for &var in vars {
            let range = self.affecting_start[var as usize] as usize
                ..self.affecting_start[var as usize + 1] as usize;
            for i in range {
                let o = self.affecting[i] as usize;
                if self.op_mark[o] == self.stamp {
                    continue;
                }
                self.op_mark[o] = self.stamp;
                self.project_operator(o, multipliers);
                steps = steps.wrapping_add(1);
                if steps.is_multiple_of(CHECK_EVERY) {
                    stop()?;
                }
            }
        }
        // Keep the cheapest of each (conditions, delta).
        let (conditions, ops) = (&self.conditions, &self.ops);
        let key = |op: &AbstractOp| (&conditions[op.start as usize..op.end as usize], op.delta);
        self.order.clear();
        self.order.extend(0..ops.len() as u32);
        self.order.sort_unstable_by(|&a, &b| {
            let (a, b) = (&ops[a as usize], &ops[b as usize]);
            key(a).cmp(&key(b)).then(a.cost.cmp(&b.cost))
        });
        let mut kept: Vec<AbstractOp> = Vec::with_capacity(ops.len());
        for &i in &self.order {
            let op = ops[i as usize];
            if kept.last().is_some_and(|last| key(last) == key(&op)) {
                continue;
            }
            kept.push(op);
        }
        // Drop dominated operators: of two with the same delta, one whose conditions
        // include the other's and that costs no less adds no transition. Within each
        // delta, fewer conditions first; groups beyond 256 are left alone (quadratic).
        kept.sort_unstable_by(|a, b| {
            (a.delta, a.end - a.start, key(a).0, a.cost).cmp(&(
                b.delta,
                b.end - b.start,
                key(b).0,
                b.cost,
            ))
        });
        let mut undominated: Vec<AbstractOp> = Vec::with_capacity(kept.len());
        let mut group_start = 0;
        for op in kept {
            if undominated
                .get(group_start)
                .is_none_or(|first| first.delta != op.delta)
            {
                group_start = undominated.len();
            }
            let group = &undominated[group_start..];
            let conditions = key(&op).0;
            let dominated = group.len() <= 256
                && group
                    .iter()
                    .any(|other| other.cost <= op.cost && is_subset(key(other).0, conditions));
            if !dominated {
                undominated.push(op);
            }
        }
        self.ops = undominated;
        Ok(())
    }

    /// Adds the regression operators of task operator `o` to `ops`.
    fn project_operator(&mut self, o: usize, multipliers: &[u32]) {
        let pre = &self.pre[self.pre_start[o] as usize..self.pre_start[o + 1] as usize];
        let eff = &self.eff[self.eff_start[o] as usize..self.eff_start[o + 1] as usize];
        let start = self.conditions.len() as u32;
        let mut delta: u32 = 0;
        self.free.clear();
        // Merge preconditions and effects, both sorted by variable.
        let (mut i, mut j) = (0, 0);
        while i < pre.len() || j < eff.len() {
            let pv = pre.get(i).map_or(u32::MAX, |f| f.0);
            let ev = eff.get(j).map_or(u32::MAX, |f| f.0);
            let var = pv.min(ev);
            let p = (pv == var).then(|| pre[i].1);
            let e = (ev == var).then(|| eff[j].1);
            i += usize::from(pv == var);
            j += usize::from(ev == var);
            let pos = self.position[var as usize];
            if pos == NONE {
                continue;
            }
            let m = multipliers[pos as usize];
            match (p, e) {
                (Some(p), Some(e)) => {
                    self.conditions.push((pos, e));
                    delta = delta.wrapping_add(p.wrapping_sub(e).wrapping_mul(m));
                }
                (None, Some(e)) => {
                    self.conditions.push((pos, e));
                    self.free.push((pos, e, e));
                }
                (Some(p), None) => self.conditions.push((pos, p)),
                (None, None) => {}
            }
        }
        let end = self.conditions.len() as u32;
        let cost = self.op_cost[o];
        // Multiply out the effect variables without a precondition: an odometer over
        // their previous values, starting with each equal to its effect value.
        loop {
            if delta != 0 {
                self.ops.push(AbstractOp {
                    start,
                    end,
                    delta,
                    cost,
                });
            }
            let mut k = 0;
            loop {
                let Some(free) = self.free.get_mut(k) else {
                    return;
                };
                let (pos, effect, old) = *free;
                let new = if old + 1 == self.pos_domain[pos as usize] {
                    0
                } else {
                    old + 1
                };
                free.2 = new;
                let m = multipliers[pos as usize];
                delta = delta.wrapping_add(new.wrapping_sub(old).wrapping_mul(m));
                if new != effect {
                    break; // A combination not seen yet.
                }
                k += 1; // Wrapped around: carry to the next variable.
            }
        }
    }

    /// Builds the match tree over `ops` into `nodes`, `children` and `leaf_ops`, without
    /// allocating per node: a work stack of ranges of `items` (operator, next condition),
    /// each split by a counting sort on the value of the position switched on.
    fn build_tree<E>(
        &mut self,
        multipliers: &[u32],
        stop: &mut impl FnMut() -> Result<(), E>,
    ) -> Result<(), E> {
        let mut steps: u32 = 0;
        self.nodes.clear();
        self.children.clear();
        self.leaf_ops.clear();
        self.items.clear();
        self.items.extend(
            self.ops
                .iter()
                .enumerate()
                .map(|(i, op)| (i as u32, op.start)),
        );
        self.nodes.push(empty_node());
        self.work.clear();
        self.work.push((0, 0, self.items.len() as u32));
        while let Some((node, start, end)) = self.work.pop() {
            steps = steps.wrapping_add(1);
            if steps.is_multiple_of(CHECK_EVERY) {
                stop()?;
            }
            let (start, end) = (start as usize, end as usize);
            // Operators with every condition tested go first and stay at this node.
            let mut done = start;
            for i in start..end {
                let (op, cursor) = self.items[i];
                if cursor == self.ops[op as usize].end {
                    self.items.swap(i, done);
                    done += 1;
                }
            }
            let ops_start = self.leaf_ops.len() as u32;
            for &(op, _) in &self.items[start..done] {
                let op = self.ops[op as usize];
                self.leaf_ops.push((op.delta, op.cost));
            }
            let mut this = Node {
                ops_start,
                ops_end: self.leaf_ops.len() as u32,
                ..empty_node()
            };
            if done < end {
                let conditions = &self.conditions;
                let pos = self.items[done..end]
                    .iter()
                    .map(|&(_, cursor)| conditions[cursor as usize].0)
                    .min()
                    .unwrap_or(0);
                let domain = self.pos_domain[pos as usize];
                // Key: the value required at `pos`, or `domain` for "don't care".
                let key = |cursor: u32| {
                    let (p, value) = conditions[cursor as usize];
                    if p == pos {
                        value
                    } else {
                        domain
                    }
                };
                self.counts.clear();
                self.counts.resize(domain as usize + 2, 0);
                for &(_, cursor) in &self.items[done..end] {
                    self.counts[key(cursor) as usize + 1] += 1;
                }
                for k in 0..=domain as usize {
                    self.counts[k + 1] += self.counts[k];
                }
                self.sorted.clear();
                self.sorted.resize(end - done, (0, 0));
                for &(op, cursor) in &self.items[done..end] {
                    let k = key(cursor);
                    let slot = &mut self.counts[k as usize];
                    let next = if k < domain { cursor + 1 } else { cursor };
                    self.sorted[*slot as usize] = (op, next);
                    *slot += 1;
                }
                self.items[done..end].copy_from_slice(&self.sorted);
                // Now group k is `sorted[counts[k - 1]..counts[k]]`.
                this.domain = domain;
                let period = u64::from(multipliers[pos as usize]) * u64::from(domain);
                this.magic = if period > 1 { u64::MAX / period + 1 } else { 0 };
                this.children_start = self.children.len() as u32;
                self.children
                    .resize(self.children.len() + domain as usize, NONE);
                let mut low = 0;
                for k in 0..=domain {
                    let high = self.counts[k as usize];
                    if high > low {
                        let child = self.nodes.len() as u32;
                        self.nodes.push(empty_node());
                        if k < domain {
                            self.children[(this.children_start + k) as usize] = child;
                        } else {
                            this.dont_care = child;
                        }
                        let base = done as u32;
                        self.work.push((child, base + low, base + high));
                    }
                    low = high;
                }
            }
            self.nodes[node as usize] = this;
        }
        Ok(())
    }

    /// Backward search from the abstract goal states: fills `distances[..size]`.
    fn search<E>(
        &mut self,
        multipliers: &[u32],
        size: usize,
        stop: &mut impl FnMut() -> Result<(), E>,
    ) -> Result<(), E> {
        let mut steps: u32 = 0;
        let mut step = || {
            steps = steps.wrapping_add(1);
            if steps.is_multiple_of(CHECK_EVERY) {
                stop()
            } else {
                Ok(())
            }
        };
        self.distances.clear();
        self.distances.resize(size, DEAD);
        // The goal states: goal values fixed, every other position free.
        let mut base: u32 = 0;
        let mut fixed = vec![false; multipliers.len()];
        for &(var, value) in &self.goal {
            let pos = self.position[var as usize];
            if pos != NONE {
                fixed[pos as usize] = true;
                base += value * multipliers[pos as usize];
            }
        }
        let free: Vec<(u32, u32)> = (0..multipliers.len())
            .filter(|&p| !fixed[p])
            .map(|p| (multipliers[p], self.pos_domain[p]))
            .collect();
        let mut values = vec![0u32; free.len()];
        self.fifo.clear();
        let mut index = base;
        'goals: loop {
            self.distances[index as usize] = 0;
            self.fifo.push(index);
            let mut k = 0;
            loop {
                let Some(&(m, d)) = free.get(k) else {
                    break 'goals;
                };
                values[k] += 1;
                index += m;
                if values[k] < d {
                    break;
                }
                index -= d * m;
                values[k] = 0;
                k += 1;
            }
        }

        let tree = Tree {
            nodes: &self.nodes,
            children: &self.children,
            leaf_ops: &self.leaf_ops,
        };
        let dist = &mut self.distances;
        let first_cost = self.leaf_ops.first().map_or(0, |&(_, c)| c);
        let uniform = first_cost > 0 && self.leaf_ops.iter().all(|&(_, c)| c == first_cost);
        let max_cost = self.leaf_ops.iter().map(|&(_, c)| c).max().unwrap_or(0);
        // Dial's buckets when costs are small and no distance can reach the cap.
        let buckets = max_cost <= MAX_BUCKET_COST
            && (size as u64).saturating_mul(u64::from(max_cost)) < u64::from(CAP);
        if uniform {
            // Breadth-first: the first time a state is reached is the cheapest. The queue
            // holds the layers one after the other. Reached states are marked in a bit
            // set, which the test that rejects most arcs reads instead of the distances
            // (32 times larger, so mostly out of cache).
            let seen = &mut self.seen;
            seen.clear();
            seen.resize(size.div_ceil(64), 0);
            let is_set = |seen: &[u64], t: usize| seen[t / 64] >> (t % 64) & 1 == 1;
            let fifo = &mut self.fifo;
            for &g in fifo.iter() {
                seen[g as usize / 64] |= 1 << (g % 64);
            }
            let (mut head, mut layer_end, mut next) = (0, fifo.len(), first_cost.min(CAP));
            while let Some(&s) = fifo.get(head) {
                if head == layer_end {
                    layer_end = fifo.len();
                    next = next.saturating_add(first_cost).min(CAP);
                }
                head += 1;
                step()?;
                tree.for_each_applicable(s, &mut self.stack, |delta, _| {
                    let t = s.wrapping_add(delta) as usize;
                    if !is_set(seen, t) {
                        seen[t / 64] |= 1 << (t % 64);
                        dist[t] = next;
                        fifo.push(t as u32);
                    }
                });
            }
        } else if buckets {
            // A circular array of max_cost + 1 buckets: distances in the queue lie in
            // [current, current + max_cost]. Zero-cost arcs push into the bucket being
            // emptied, which is fine: it is emptied until it stays empty.
            let k = max_cost as usize + 1;
            let queue = &mut self.buckets;
            if queue.len() < k {
                queue.resize_with(k, Vec::new);
            }
            for b in queue.iter_mut() {
                b.clear();
            }
            queue[0].extend_from_slice(&self.fifo);
            let mut pending = self.fifo.len();
            let mut current: u32 = 0;
            while pending > 0 {
                let b = current as usize % k;
                while let Some(s) = queue[b].pop() {
                    pending -= 1;
                    if dist[s as usize] != current {
                        continue; // A stale entry: reached more cheaply since.
                    }
                    step()?;
                    tree.for_each_applicable(s, &mut self.stack, |delta, cost| {
                        let t = s.wrapping_add(delta) as usize;
                        let next = current + cost;
                        if next < dist[t] {
                            dist[t] = next;
                            queue[next as usize % k].push(t as u32);
                            pending += 1;
                        }
                    });
                }
                current += 1;
            }
        } else {
            let heap = &mut self.heap;
            heap.clear();
            for &s in &self.fifo {
                heap.push(0, s);
            }
            while let Some((d, s)) = heap.pop() {
                if d > u64::from(dist[s as usize]) {
                    continue; // A stale entry.
                }
                step()?;
                tree.for_each_applicable(s, &mut self.stack, |delta, cost| {
                    let t = s.wrapping_add(delta) as usize;
                    let next = (d + u64::from(cost)).min(u64::from(CAP)) as u32;
                    if next < dist[t] {
                        dist[t] = next;
                        heap.push(u64::from(next), t as u32);
                    }
                });
            }
        }
        Ok(())
    }
}

/// True if every element of `a` is in `b` (both sorted).
fn is_subset(a: &[(u32, u32)], b: &[(u32, u32)]) -> bool {
    let mut rest = b;
    a.iter().all(|x| match rest.iter().position(|y| y >= x) {
        Some(i) if rest[i] == *x => {
            rest = &rest[i + 1..];
            true
        }
        _ => false,
    })
}

/// The match tree, borrowed for a search.
struct Tree<'a> {
    nodes: &'a [Node],
    children: &'a [u32],
    leaf_ops: &'a [(u32, u32)],
}

impl Tree<'_> {
    /// Calls `f(delta, cost)` for every regression operator applicable in abstract state
    /// `s`, using `stack` for the branches not taken yet.
    #[inline]
    fn for_each_applicable(&self, s: u32, stack: &mut Vec<u32>, mut f: impl FnMut(u32, u32)) {
        stack.clear();
        let mut n = 0;
        loop {
            let node = self.nodes[n as usize];
            for &(delta, cost) in &self.leaf_ops[node.ops_start as usize..node.ops_end as usize] {
                f(delta, cost);
            }
            if node.domain != 0 {
                let low = node.magic.wrapping_mul(u64::from(s));
                let value = ((u128::from(low) * u128::from(node.domain)) >> 64) as u32;
                let child = self.children[(node.children_start + value) as usize];
                if node.dont_care != NONE {
                    if child != NONE {
                        stack.push(child);
                    }
                    n = node.dont_care;
                    continue;
                }
                if child != NONE {
                    n = child;
                    continue;
                }
            }
            match stack.pop() {
                Some(next) => n = next,
                None => return,
            }
        }
    }
}

fn empty_node() -> Node {
    Node {
        magic: 0,
        domain: 0,
        children_start: 0,
        dont_care: NONE,
        ops_start: 0,
        ops_end: 0,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::test_tasks::op;
    use task::{Fact, Variable};

    fn var(name: &str, size: u32) -> Variable {
        Variable {
            name: name.into(),
            value_names: (0..size).map(|v| format!("{name}{v}")).collect(),
        }
    }

    /// A robot on positions 0..4 of a line (steps of cost `step`, position 3 a trap
    /// without exits), a key it can drop anywhere (an effect without precondition);
    /// goal: at 2 with the key dropped.
    fn task(step: u64) -> Task {
        Task {
            variables: vec![var("at", 4), var("key", 2)],
            mutexes: vec![],
            initial_state: vec![0, 0],
            goal: vec![Fact::new(VarId(0), 2), Fact::new(VarId(1), 1)],
            operators: vec![
                op("right-0", &[(0, 0)], &[(0, 1)], step),
                op("right-1", &[(0, 1)], &[(0, 2)], step),
                op("left-1", &[(0, 1)], &[(0, 0)], step),
                op("left-2", &[(0, 2)], &[(0, 1)], step),
                op("fall", &[(0, 2)], &[(0, 3)], 1),
                op("drop", &[], &[(1, 1)], 7),
                op("drop-cheaply-at-1", &[(0, 1)], &[(1, 1)], 2),
            ],
            use_costs: true,
        }
    }

    #[test]
    fn distances_of_a_hand_made_task() {
        let t = task(1);
        let pdb = PatternDatabase::new(&t, &[0, 1]).unwrap();
        assert_eq!(pdb.pattern(), [VarId(0), VarId(1)]);
        assert_eq!(pdb.size(), 8);
        assert!(pdb.has_dead_ends());
        // (at, key): the index is at + 4 * key.
        assert_eq!(pdb.index(&[3, 1]), 7);
        let h = |at, key| pdb.value(&[at, key]);
        assert_eq!(h(0, 0), Some(4)); // right, drop cheaply, right
        assert_eq!(h(1, 0), Some(3));
        assert_eq!(h(2, 0), Some(4)); // left, drop cheaply, right
        assert_eq!(h(2, 1), Some(0));
        assert_eq!(h(0, 1), Some(2));
        assert_eq!(h(3, 0), None);
        assert_eq!(h(3, 1), None);
        // Projected on the key alone: the cheapest drop, wherever the robot is.
        let key = PatternDatabase::new(&t, &[1]).unwrap();
        assert_eq!(key.value(&[3, 0]), Some(2));
        assert_eq!(key.value(&[3, 1]), Some(0));
        assert!(!key.has_dead_ends());
        // The empty pattern: 0 everywhere.
        let empty = PatternDatabase::new(&t, &[]).unwrap();
        assert_eq!((empty.size(), empty.value(&[3, 0])), (1, Some(0)));
        // Unit costs.
        let mut unit = t.clone();
        unit.use_costs = false;
        let pdb = PatternDatabase::new(&unit, &[1, 0]).unwrap();
        assert_eq!(pdb.value(&[0, 0]), Some(3));
        assert_eq!(pdb.value(&[2, 0]), Some(1)); // drop where it stands
    }

    #[test]
    fn tables_are_as_narrow_as_the_distances_allow() {
        for (step, bytes, h) in [
            (1, 1, 4),
            (200, 2, 402),
            (40_000, 4, 80_002),
            (u64::MAX, 4, u64::from(CAP)),
        ] {
            let pdb = PatternDatabase::new(&task(step), &[0, 1]).unwrap();
            assert_eq!(pdb.memory_bytes(), 8 * bytes + 24, "step {step}");
            assert_eq!(pdb.value(&[0, 0]), Some(h), "step {step}");
            assert_eq!(pdb.value(&[3, 0]), None);
            assert_eq!(pdb.value(&[2, 1]), Some(0));
        }
    }

    #[test]
    fn bad_patterns_are_errors() {
        let t = task(1);
        assert_eq!(
            PatternDatabase::new(&t, &[0, 2]).unwrap_err(),
            PatternError::VariableOutOfRange {
                var: 2,
                num_variables: 2
            }
        );
        let mut big = t.clone();
        big.variables = (0..4).map(|i| var(&format!("v{i}"), 1000)).collect();
        big.initial_state = vec![0; 4];
        big.operators.clear();
        big.goal.clear();
        let e = PatternDatabase::new(&big, &[0, 1, 2, 3]).unwrap_err();
        assert_eq!(
            e.to_string(),
            "pattern [0, 1, 2, 3] has more than 2147483648 abstract states"
        );
        assert_eq!(
            pattern_size(&big, &[VarId(0), VarId(1)], 10_000_000),
            Some(1_000_000)
        );
        assert_eq!(
            pattern_size(&big, &[VarId(0), VarId(1), VarId(2)], 10_000_000),
            None
        );
        let mut invalid = t;
        invalid.goal.push(Fact::new(VarId(5), 0));
        assert!(matches!(
            PatternDatabase::new(&invalid, &[0]),
            Err(PatternError::InvalidTask(_))
        ));
    }

    /// Every queue (breadth-first, buckets, radix heap) gives the same distances as the
    /// others on random tasks: costs scaled so that each is chosen.
    #[test]
    fn the_three_queues_agree() {
        use crate::successor::tests::{random_task, Rng};
        let mut rng = Rng(21);
        for round in 0..150 {
            let mut t = random_task(&mut rng, 2 + round % 5, 4 + round % 20);
            t.use_costs = true;
            let pattern: Vec<u32> = (0..t.variables.len() as u32)
                .filter(|_| rng.below(2) == 0)
                .collect();
            let base: Vec<u64> = t.operators.iter().map(|o| o.cost).collect();
            let mut tables = Vec::new();
            // Costs 0..=3: buckets; times 2000 or 2^20: the radix heap.
            for scale in [1u64, 2000, 1 << 20] {
                for (o, &c) in t.operators.iter_mut().zip(&base) {
                    o.cost = c * scale;
                }
                let pdb = PatternDatabase::new(&t, &pattern).unwrap();
                let table: Vec<Option<u64>> = (0..pdb.size())
                    .map(|i| pdb.value_at(i).map(|d| d / scale))
                    .collect();
                tables.push(table);
            }
            // Unit costs: breadth-first search.
            t.use_costs = false;
            let unit = PatternDatabase::new(&t, &pattern).unwrap();
            assert!((0..unit.size()).all(|i| unit.value_at(i).is_none() == tables[0][i].is_none()));
            assert_eq!(tables[0], tables[1], "round {round}");
            assert_eq!(tables[0], tables[2], "round {round}");
        }
    }

    /// Four counters of 0..16 (65,536 abstract states), each stepped up by one operator
    /// per value, at `cost` (or `cost + 1` on odd values, so that costs differ).
    fn counters(cost: u64, varied: bool) -> Task {
        let mut operators = Vec::new();
        for v in 0..4u32 {
            for value in 0..15u32 {
                let c = if varied && value % 2 == 1 {
                    cost + 1
                } else {
                    cost
                };
                operators.push(op(
                    &format!("up{v}-{value}"),
                    &[(v, value)],
                    &[(v, value + 1)],
                    c,
                ));
            }
        }
        Task {
            variables: (0..4).map(|v| var(&format!("c{v}"), 16)).collect(),
            mutexes: vec![],
            initial_state: vec![0; 4],
            goal: (0..4).map(|v| Fact::new(VarId(v), 15)).collect(),
            operators,
            use_costs: true,
        }
    }

    /// A database given up at a limit (the abstract search of every queue is checked, not
    /// only the start of a database) leaves the builder as it was: the next database it
    /// builds equals a fresh builder's.
    #[test]
    fn a_database_stops_where_its_limit_says_and_the_builder_goes_on() {
        let pattern: Vec<VarId> = (0..4).map(VarId).collect();
        // Unit costs (breadth-first), costs 1 and 2 (buckets), large costs (radix heap).
        for task in [
            counters(1, false),
            counters(1, true),
            counters(1 << 20, true),
        ] {
            let mut builder = PdbBuilder::new(&task);
            let mut calls = 0;
            let stopped = builder.build_with(&pattern, || {
                calls += 1;
                if calls < 3 {
                    Ok(())
                } else {
                    Err("limit")
                }
            });
            assert_eq!(stopped.err(), Some("limit"));
            // 65,536 states and 60 operators: the third check is inside the search.
            assert_eq!(calls, 3);
            let after = builder.build(&pattern);
            let fresh = PdbBuilder::new(&task).build(&pattern);
            assert_eq!(after.size(), 1 << 16);
            assert!((0..after.size()).all(|i| after.value_at(i) == fresh.value_at(i)));
            assert_eq!(
                fresh.value_at(0),
                Some(task.operators.iter().map(|o| o.cost).sum())
            );
        }
    }
}
