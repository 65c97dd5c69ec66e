//! Saturated cost partitioning over projections (Seipp, Keller and Helmert, JAIR 2020),
//! with Sys-SCP pattern selection (Seipp, IJCAI 2019): `scp(...)` and `scp_online(...)`.
//!
//! *Projections.* A [`Projection`] is a pattern's abstract transition system stored
//! explicitly: every abstract transition `s -o-> t` with `s != t`, grouped by target, so
//! that goal distances can be computed under any cost function (a backward Dijkstra,
//! O(transitions * log states)).
//!
//! *Saturated costs.* Under a cost function `c` with goal distances `h`, the saturated
//! cost of operator `o` is `max(0, max { h(s) - h(t) : s -o-> t, h(s) and h(t) finite })`:
//! the least non-negative cost that keeps every goal distance as it is. This is the
//! *non-negative* variant of the paper (transitions into or out of dead ends impose no
//! constraint, which is the paper's `-infinity` rule; the result is clipped at 0, so
//! that every cost function stays non-negative). Operators without effects on the
//! pattern get 0.
//!
//! *An order.* Saturated cost partitioning in an order `A1, ..., An` gives `A1` the full
//! costs, `A2` what `A1` does not need (the remaining costs `c - saturated(A1)`), and so
//! on; the sum of the abstract goal distances is admissible because the parts sum to at
//! most `c`. Tables that are 0 everywhere are not stored. The heuristic is the maximum
//! over the orders it keeps and over the single projections under the full costs (a
//! lookup each, which the dead-end test makes anyway; so it is never below the best
//! single pattern database); a state is a dead end if any projection says so (dead ends
//! do not depend on costs).
//!
//! *Greedy orders* (`greedy_orders()`, the paper's static `h/stolen` ordering): for a
//! state `s`, projections sorted by `h(s) / max(1, stolen)` in decreasing order, where
//! `h` is the projection's distance under the full costs and `stolen` is
//! `sum_o min(saturated(o), sum of the others' saturated(o))` under the full costs; ties
//! are broken by a seeded random permutation.
//!
//! *Offline diversification* (`scp(..., diversify=true)`): `samples` states are drawn by
//! random walks from the initial state (length binomial around the initial state's
//! estimate divided by the average operator cost); the initial state and then each
//! sample in turn gets a greedy order, which is kept if it raises the estimate of some
//! sample above that of the orders kept so far. Without `diversify` every order is kept.
//! Both stop at `max_orders` kept orders, after the last sample, or at `max_time`
//! (counted from the end of pattern generation, as Scorpion's).
//!
//! *Online* (`scp_online(..., interval=N)`): one order for the initial state at
//! construction, then during the search, every `N`-th evaluated state gets a greedy
//! order, kept if it raises that state's estimate, until `max_time` has passed since
//! the projections were built.
//!
//! *Pattern generators* (`projections(...)`): `systematic(k)` (goal variables grown by
//! causal-graph predecessors, see [`systematic_up_to`]), `hillclimbing(...)` (the iPDB
//! climb) and `sys_scp(...)`: the patterns of `systematic` in order of increasing size,
//! each kept if its projection has a positive finite goal distance under the costs that
//! the patterns kept before it leave (then those costs shrink by its saturated costs);
//! once `max_time_per_restart` has passed (and the restart kept a pattern) the costs are
//! reset and the loop starts over with the patterns not kept yet. It ends when it has
//! been through every size (`max_pattern_size` or until no pattern grows), or at a limit.
//!
//! Everything is deterministic for a fixed seed as long as no time limit is reached.
//! Construction respects the run's limits: every phase stops at the deadline, the
//! cancel flag or the memory limit and keeps what it has (any subset of orders and
//! patterns is admissible); each phase takes at most half the time left before the
//! run's deadline.

use std::cmp::Reverse;
use std::collections::BinaryHeap;
use std::time::{Duration, Instant};

use rustc_hash::FxHashSet;
use task::{OpId, Task, VarId};

use crate::astar::SearchLimits;
use crate::fd_random::FdRandom;
use crate::heuristic::Heuristic;
use crate::ipdb::{hill_climbing, IpdbConfig};
use crate::pdb::{normalize_pattern, pattern_size, PatternError, MAX_PDB_SIZE};
use crate::successor::SuccessorGenerator;

/// "No goal state reachable" in distances under a cost function.
const INF: u64 = u64::MAX;
/// "Dead end" in a stored table.
const DEAD: u32 = u32::MAX;
/// The largest distance stored in a table (larger ones are capped: still admissible).
const CAP: u32 = u32::MAX - 1;
/// The most transitions one projection may have.
pub const MAX_TRANSITIONS: u64 = 1 << 25;

/// A generator of patterns inside `projections(...)`.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum PatternGenerator {
    /// `manual_patterns([[0, 1], [2]])` (or a list).
    Manual(Vec<Vec<u32>>),
    /// `systematic(k)`: see [`systematic_up_to`].
    Systematic(u32),
    /// `hillclimbing(...)`: the iPDB climb's collection.
    HillClimbing(IpdbConfig),
    /// `sys_scp(...)`.
    SysScp(SysScpConfig),
}

/// The options of `sys_scp(...)`, with Scorpion's defaults.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct SysScpConfig {
    /// Largest pattern, in variables (`u64::MAX`: no limit).
    pub max_pattern_size: u64,
    /// Largest projection, in abstract states.
    pub max_pdb_size: u64,
    /// Largest total of the kept projections, in abstract states.
    pub max_collection_size: u64,
    /// Most patterns kept (`u64::MAX`: no limit).
    pub max_patterns: u64,
    /// Time limit of the selection (`None`: none).
    pub max_time: Option<Duration>,
    /// Time after which the costs are reset and the loop starts over.
    pub max_time_per_restart: Option<Duration>,
}

impl Default for SysScpConfig {
    fn default() -> SysScpConfig {
        SysScpConfig {
            max_pattern_size: u64::MAX,
            max_pdb_size: 2_000_000,
            max_collection_size: 20_000_000,
            max_patterns: u64::MAX,
            max_time: Some(Duration::from_secs(100)),
            max_time_per_restart: Some(Duration::from_secs(10)),
        }
    }
}

/// The options of `scp(...)` and `scp_online(...)`, with Scorpion's defaults.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct ScpConfig {
    /// The pattern generators, one per `projections(...)`.
    pub abstractions: Vec<PatternGenerator>,
    /// Seed of `greedy_orders(random_seed=...)`: the tie-breaking permutation.
    pub orders_seed: u32,
    /// Most orders kept (`u64::MAX`: no limit; offline only).
    pub max_orders: u64,
    /// Time limit of the order generation, from the end of pattern generation.
    pub max_time: Option<Duration>,
    /// Keep an order only if it raises the estimate of a sample (offline only).
    pub diversify: bool,
    /// Samples for diversification (offline only).
    pub samples: u32,
    /// Seed of the random walks.
    pub random_seed: u32,
    /// `scp_online`: compute an order for every `interval`-th evaluated state.
    pub online_interval: Option<u64>,
}

impl Default for ScpConfig {
    fn default() -> ScpConfig {
        ScpConfig {
            abstractions: vec![PatternGenerator::Systematic(2)],
            orders_seed: crate::ipdb::DEFAULT_SEED,
            max_orders: u64::MAX,
            max_time: Some(Duration::from_secs(200)),
            diversify: true,
            samples: 1000,
            random_seed: crate::ipdb::DEFAULT_SEED,
            online_interval: None,
        }
    }
}

/// The interesting patterns of at most `max_size` variables, grown as iPDB's climb
/// grows them: of one variable the goal variables; of `k + 1` every pattern of `k` with
/// one neighbour of one of its variables added: a causal-graph predecessor (a variable
/// with a precondition or an effect in an operator that has an effect on the pattern's
/// variable) or a goal variable among its successors. Each pattern's variables are
/// connected in the causal graph and reach a goal variable. Size by size, each size sorted; for sizes 1 and 2 these are exactly
/// `cpdbs`' `systematic` patterns. Patterns whose projection would exceed
/// `max_pdb_size` are left out (and not grown). Stops early, with what it has, when
/// `stop()` says so (checked per pattern grown).
pub fn systematic_up_to(
    task: &Task,
    max_size: u64,
    max_pdb_size: u64,
    mut stop: impl FnMut() -> bool,
) -> Vec<Vec<u32>> {
    let predecessors = causal_predecessors(task);
    let mut level = goal_patterns(task, max_pdb_size);
    let mut out = Vec::new();
    let mut size = 1;
    while !level.is_empty() {
        out.extend(level.iter().cloned());
        if size >= max_size {
            break;
        }
        let (next, stopped) = grow(task, &predecessors, &level, max_pdb_size, &mut stop);
        if stopped {
            return out;
        }
        level = next;
        size += 1;
    }
    out
}

/// The patterns of one goal variable each, sorted, that fit `max_pdb_size`.
fn goal_patterns(task: &Task, max_pdb_size: u64) -> Vec<Vec<u32>> {
    let mut goals: Vec<u32> = task.goal.iter().map(|f| f.var.0).collect();
    goals.sort_unstable();
    goals.dedup();
    goals
        .into_iter()
        .map(|v| vec![v])
        .filter(|p| fits(task, p, max_pdb_size))
        .collect()
}

/// The next size: each pattern of `level` with one predecessor of one of its variables
/// added, deduplicated and sorted; true if `stop()` said so (then the list is partial).
fn grow(
    task: &Task,
    predecessors: &[Vec<u32>],
    level: &[Vec<u32>],
    max_pdb_size: u64,
    stop: &mut impl FnMut() -> bool,
) -> (Vec<Vec<u32>>, bool) {
    let mut next: FxHashSet<Vec<u32>> = FxHashSet::default();
    let mut stopped = false;
    for p in level {
        if stop() {
            stopped = true;
            break;
        }
        for &v in p {
            for &w in &predecessors[v as usize] {
                if p.binary_search(&w).is_ok() {
                    continue;
                }
                let mut q = p.clone();
                let at = q.partition_point(|&x| x < w);
                q.insert(at, w);
                if fits(task, &q, max_pdb_size) {
                    next.insert(q);
                }
            }
        }
    }
    let mut next: Vec<Vec<u32>> = next.into_iter().collect();
    next.sort_unstable();
    (next, stopped)
}

fn fits(task: &Task, pattern: &[u32], max_pdb_size: u64) -> bool {
    let vars: Vec<VarId> = pattern.iter().map(|&v| VarId(v)).collect();
    pattern_size(task, &vars, max_pdb_size.min(MAX_PDB_SIZE)).is_some()
}

/// For each variable `v`, the variables with a precondition or an effect in an operator
/// that has an effect on `v`, and the goal variables among `v`'s successors (effects of
/// operators with a precondition or an effect on `v`, as iPDB's climb adds them), `v`
/// left out; sorted.
fn causal_predecessors(task: &Task) -> Vec<Vec<u32>> {
    let mut is_goal = vec![false; task.variables.len()];
    for f in &task.goal {
        is_goal[f.var.index()] = true;
    }
    let mut pred: Vec<Vec<u32>> = vec![Vec::new(); task.variables.len()];
    for op in &task.operators {
        for e in &op.effects {
            for f in op.preconditions.iter().chain(&op.effects) {
                if f.var != e.var {
                    pred[e.var.index()].push(f.var.0);
                    if is_goal[e.var.index()] {
                        pred[f.var.index()].push(e.var.0);
                    }
                }
            }
        }
    }
    for p in &mut pred {
        p.sort_unstable();
        p.dedup();
    }
    pred
}

/// A projection's abstract transition system, explicit; see the module documentation.
#[derive(Debug, Clone)]
pub struct Projection {
    pattern: Vec<VarId>,
    vars: Vec<u32>,
    multipliers: Vec<u32>,
    size: u32,
    goal_states: Vec<u32>,
    /// Transitions into `t`: `preds[pred_start[t]..pred_start[t + 1]]`, as (source,
    /// operator).
    pred_start: Vec<u32>,
    preds: Vec<(u32, u32)>,
}

impl Projection {
    /// The projection of `task` (valid) onto `pattern` (variable indices); fails if a
    /// variable does not exist or the projection has more than [`MAX_PDB_SIZE`] states.
    /// `Ok(None)` if it has more than [`MAX_TRANSITIONS`] transitions or their memory
    /// would exceed `limits`' memory limit. O(transitions + operators * pattern size).
    pub fn new(
        task: &Task,
        pattern: &[u32],
        limits: &SearchLimits,
    ) -> Result<Option<Projection>, PatternError> {
        let pattern = normalize_pattern(task, pattern)?;
        let Some(size) = pattern_size(task, &pattern, MAX_PDB_SIZE) else {
            return Err(PatternError::TooLarge {
                pattern: pattern.iter().map(|v| v.0).collect(),
                limit: MAX_PDB_SIZE,
            });
        };
        let k = pattern.len();
        let mut position = vec![u32::MAX; task.variables.len()];
        let mut multipliers = Vec::with_capacity(k);
        let mut domains = Vec::with_capacity(k);
        let mut m = 1u32;
        for (i, v) in pattern.iter().enumerate() {
            position[v.index()] = i as u32;
            multipliers.push(m);
            let d = task.variables[v.index()].domain_size();
            domains.push(d);
            m = m.wrapping_mul(d);
        }
        // Per operator with an effect on the pattern: fixed positions (preconditions) and
        // effects, as positions.
        struct AbstractOp {
            op: u32,
            fixed: Vec<(usize, u32)>,
            effects: Vec<(usize, u32)>,
        }
        let mut ops = Vec::new();
        let mut transitions: u64 = 0;
        for (o, op) in task.operators.iter().enumerate() {
            let effects: Vec<(usize, u32)> = op
                .effects
                .iter()
                .filter(|f| position[f.var.index()] != u32::MAX)
                .map(|f| (position[f.var.index()] as usize, f.value))
                .collect();
            if effects.is_empty() {
                continue;
            }
            let fixed: Vec<(usize, u32)> = op
                .preconditions
                .iter()
                .filter(|f| position[f.var.index()] != u32::MAX)
                .map(|f| (position[f.var.index()] as usize, f.value))
                .collect();
            let count = (0..k)
                .filter(|p| fixed.iter().all(|&(q, _)| q != *p))
                .map(|p| u64::from(domains[p]))
                .product::<u64>();
            transitions = transitions.saturating_add(count);
            ops.push(AbstractOp {
                op: o as u32,
                fixed,
                effects,
            });
        }
        let bytes = transitions.saturating_mul(20).saturating_add(size * 8);
        if transitions > MAX_TRANSITIONS || limits.would_exceed(bytes, || 0) {
            return Ok(None);
        }
        let size32 = size as u32;
        // (target, source, operator), then grouped by target.
        let mut list: Vec<(u32, u32, u32)> = Vec::with_capacity(transitions as usize);
        let mut values = vec![0u32; k];
        for a in &ops {
            let free: Vec<usize> = (0..k)
                .filter(|p| a.fixed.iter().all(|&(q, _)| q != *p))
                .collect();
            for &(p, v) in &a.fixed {
                values[p] = v;
            }
            for &p in &free {
                values[p] = 0;
            }
            loop {
                let s: u32 = (0..k).map(|p| values[p] * multipliers[p]).sum();
                let mut t = s;
                for &(p, v) in &a.effects {
                    t = t - values[p] * multipliers[p] + v * multipliers[p];
                }
                if t != s {
                    list.push((t, s, a.op));
                }
                // Next assignment of the free positions.
                let mut i = 0;
                while i < free.len() {
                    let p = free[i];
                    values[p] += 1;
                    if values[p] < domains[p] {
                        break;
                    }
                    values[p] = 0;
                    i += 1;
                }
                if i == free.len() {
                    break;
                }
            }
        }
        let mut pred_start = vec![0u32; size as usize + 1];
        for &(t, _, _) in &list {
            pred_start[t as usize + 1] += 1;
        }
        for i in 0..size as usize {
            pred_start[i + 1] += pred_start[i];
        }
        let mut fill = pred_start.clone();
        let mut preds = vec![(0u32, 0u32); list.len()];
        for &(t, s, o) in &list {
            preds[fill[t as usize] as usize] = (s, o);
            fill[t as usize] += 1;
        }
        drop(list);
        // Goal states: the goal's values on the pattern fixed, the rest free.
        let goal: Vec<(usize, u32)> = task
            .goal
            .iter()
            .filter(|f| position[f.var.index()] != u32::MAX)
            .map(|f| (position[f.var.index()] as usize, f.value))
            .collect();
        let goal_states: Vec<u32> = (0..size32)
            .filter(|&s| {
                goal.iter()
                    .all(|&(p, v)| s / multipliers[p] % domains[p] == v)
            })
            .collect();
        Ok(Some(Projection {
            vars: pattern.iter().map(|v| v.0).collect(),
            pattern,
            multipliers,
            size: size32,
            goal_states,
            pred_start,
            preds,
        }))
    }

    /// The pattern, sorted.
    pub fn pattern(&self) -> &[VarId] {
        &self.pattern
    }

    /// The number of abstract states.
    pub fn size(&self) -> usize {
        self.size as usize
    }

    /// The number of abstract transitions (self-loops left out).
    pub fn num_transitions(&self) -> usize {
        self.preds.len()
    }

    /// The abstract state of `state` (one value per variable of the task).
    #[inline]
    pub fn index(&self, state: &[u32]) -> usize {
        self.vars
            .iter()
            .zip(&self.multipliers)
            .map(|(&v, &m)| state[v as usize] as usize * m as usize)
            .sum()
    }

    /// The goal distance of every abstract state under `costs` (one per operator of the
    /// task), `u64::MAX` for dead ends. Dijkstra: O(transitions * log states).
    pub fn distances(&self, costs: &[u64]) -> Vec<u64> {
        let mut dist = vec![INF; self.size as usize];
        let mut heap = BinaryHeap::new();
        for &g in &self.goal_states {
            dist[g as usize] = 0;
            heap.push(Reverse((0u64, g)));
        }
        while let Some(Reverse((d, t))) = heap.pop() {
            if d > dist[t as usize] {
                continue;
            }
            let range =
                self.pred_start[t as usize] as usize..self.pred_start[t as usize + 1] as usize;
            for &(s, o) in &self.preds[range] {
                let next = d.saturating_add(costs[o as usize]).min(INF - 1);
                if next < dist[s as usize] {
                    dist[s as usize] = next;
                    heap.push(Reverse((next, s)));
                }
            }
        }
        dist
    }

    /// Adds the saturated cost of each operator for distances `dist` into `out` (by
    /// maximum: `out[o] = max(out[o], saturated(o))`, so pass zeros). O(transitions).
    pub fn saturated_costs(&self, dist: &[u64], out: &mut [u64]) {
        for t in 0..self.size as usize {
            let dt = dist[t];
            if dt == INF {
                continue;
            }
            let range = self.pred_start[t] as usize..self.pred_start[t + 1] as usize;
            for &(s, o) in &self.preds[range] {
                let ds = dist[s as usize];
                if ds != INF && ds > dt {
                    let need = ds - dt;
                    if need > out[o as usize] {
                        out[o as usize] = need;
                    }
                }
            }
        }
    }

    fn bytes(&self) -> u64 {
        (self.preds.len() * 8 + self.pred_start.len() * 4 + self.goal_states.len() * 4) as u64
    }
}

/// The stored tables of one order: (projection, distance per abstract state).
#[derive(Debug, Clone)]
struct Order {
    tables: Vec<(u32, Box<[u32]>)>,
}

impl Order {
    /// The sum of the tables at the abstract states `indices` (one per projection); dead
    /// entries count 0 (the heuristic finds dead ends separately).
    fn value(&self, indices: &[usize]) -> u64 {
        self.tables
            .iter()
            .map(|(p, table)| match table[indices[*p as usize]] {
                DEAD => 0,
                v => u64::from(v),
            })
            .sum()
    }

    fn bytes(&self) -> u64 {
        self.tables.iter().map(|(_, t)| t.len() as u64 * 4).sum()
    }
}

/// What building the heuristic did.
#[derive(Debug, Clone, Default, PartialEq, Eq)]
pub struct ScpStatistics {
    /// Projections (after deduplication).
    pub projections: usize,
    /// Abstract states over all projections.
    pub total_size: u64,
    /// Abstract transitions over all projections.
    pub total_transitions: u64,
    /// Orders computed.
    pub orders_computed: u64,
    /// Orders kept.
    pub orders: usize,
    /// Patterns `sys_scp` kept, over all its generators.
    pub sys_scp_patterns: usize,
    /// Time to generate the patterns and build the projections.
    pub abstraction_time: Duration,
    /// Time to build the whole heuristic.
    pub total_time: Duration,
}

impl std::fmt::Display for ScpStatistics {
    /// Log lines after Scorpion's (`Number of abstractions: 12`, ...), one per line,
    /// without a final newline; the last gives the whole construction time, as
    /// `Canonical PDB heuristic computation time` does for pattern databases.
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        writeln!(f, "Number of abstractions: {}", self.projections)?;
        writeln!(f, "Abstract states: {}", self.total_size)?;
        writeln!(f, "Abstract transitions: {}", self.total_transitions)?;
        writeln!(f, "Sys-SCP patterns: {}", self.sys_scp_patterns)?;
        writeln!(f, "Orders computed: {}", self.orders_computed)?;
        writeln!(f, "Orders stored: {}", self.orders)?;
        writeln!(
            f,
            "Time for building abstractions: {:.6}s",
            self.abstraction_time.as_secs_f64()
        )?;
        write!(
            f,
            "Saturated cost partitioning heuristic computation time: {:.6}s",
            self.total_time.as_secs_f64()
        )
    }
}

/// Saturated cost partitioning over projections, maximised over orders; see the module
/// documentation. Admissible (not always consistent: online orders change estimates).
#[derive(Debug, Clone)]
pub struct Scp {
    name: &'static str,
    costs: Vec<u64>,
    projections: Vec<Projection>,
    /// Per projection: the distances under the full costs, capped into `u32`.
    full: Vec<Box<[u32]>>,
    /// Per projection: its `stolen` costs (see the module documentation).
    stolen: Vec<u64>,
    /// The seeded tie-breaking key of each projection.
    tie: Vec<u32>,
    orders: Vec<Order>,
    indices: Vec<usize>,
    online: Option<Online>,
    statistics: ScpStatistics,
}

#[derive(Debug, Clone)]
struct Online {
    interval: u64,
    until: Option<Instant>,
    evaluations: u64,
}

impl Scp {
    /// The heuristic `config` describes, for a valid `task`, built under `limits`.
    pub fn new(
        task: &Task,
        config: &ScpConfig,
        limits: &SearchLimits,
    ) -> Result<Scp, PatternError> {
        let start = Instant::now();
        task.validate()?;
        let costs: Vec<u64> = task.operators.iter().map(|o| task.cost(o)).collect();
        let mut patterns: Vec<Vec<u32>> = Vec::new();
        let mut projections: Vec<Projection> = Vec::new();
        let mut seen: FxHashSet<Vec<VarId>> = FxHashSet::default();
        let mut statistics = ScpStatistics::default();
        let own = |p: &[Projection]| p.iter().map(Projection::bytes).sum::<u64>();
        for generator in &config.abstractions {
            match generator {
                PatternGenerator::Manual(list) => patterns.extend(list.iter().cloned()),
                PatternGenerator::Systematic(k) => {
                    let clock = limits.clock();
                    patterns.extend(systematic_up_to(task, u64::from(*k), MAX_PDB_SIZE, || {
                        clock.passed()
                    }));
                }
                PatternGenerator::HillClimbing(ipdb) => {
                    let (pdbs, _) = hill_climbing(task, ipdb, limits);
                    patterns.extend(
                        pdbs.iter()
                            .map(|p| p.pattern().iter().map(|v| v.0).collect()),
                    );
                }
                PatternGenerator::SysScp(sys) => {
                    let selected = sys_scp(task, sys, &costs, limits, &mut seen)?;
                    statistics.sys_scp_patterns += selected.len();
                    projections.extend(selected);
                    continue;
                }
            }
            for p in patterns.drain(..) {
                if limits.reached(|| own(&projections)).is_some() {
                    break;
                }
                let normalized = normalize_pattern(task, &p)?;
                if !seen.insert(normalized) {
                    continue;
                }
                if let Some(projection) = Projection::new(task, &p, limits)? {
                    projections.push(projection);
                }
            }
        }
        statistics.abstraction_time = start.elapsed();
        let full: Vec<Vec<u64>> = projections.iter().map(|p| p.distances(&costs)).collect();
        let mut total = vec![0u64; costs.len()];
        let mut saturated: Vec<Vec<u64>> = Vec::with_capacity(projections.len());
        for (p, d) in projections.iter().zip(&full) {
            let mut s = vec![0u64; costs.len()];
            p.saturated_costs(d, &mut s);
            for (t, &x) in total.iter_mut().zip(&s) {
                *t = t.saturating_add(x);
            }
            saturated.push(s);
        }
        let stolen = saturated
            .iter()
            .map(|s| {
                s.iter()
                    .zip(&total)
                    .map(|(&mine, &all)| mine.min(all - mine))
                    .fold(0u64, u64::saturating_add)
            })
            .collect();
        drop(saturated);
        let mut rng = FdRandom::new(config.orders_seed);
        let tie = (0..projections.len()).map(|_| rng.next_u32()).collect();
        statistics.projections = projections.len();
        statistics.total_size = projections.iter().map(|p| p.size as u64).sum();
        statistics.total_transitions = projections.iter().map(|p| p.preds.len() as u64).sum();
        let mut scp = Scp {
            name: if config.online_interval.is_some() {
                "scp_online"
            } else {
                "scp"
            },
            costs,
            indices: vec![0; projections.len()],
            full: full.into_iter().map(|d| cap(&d)).collect(),
            projections,
            stolen,
            tie,
            orders: Vec::new(),
            online: None,
            statistics,
        };
        // `max_time` counts from here: the time of the orders, not of the patterns.
        let deadline = phase_deadline(Instant::now(), config.max_time, limits.deadline);
        let limit_reached = |scp: &Scp| {
            limits
                .reached(|| scp.orders.iter().map(Order::bytes).sum())
                .is_some()
        };
        let out_of_time =
            |scp: &Scp| deadline.is_some_and(|d| Instant::now() >= d) || limit_reached(scp);
        // The initial state's order, always (unless the run's limits have passed).
        if !limit_reached(&scp) {
            let order = scp.order_for(&task.initial_state);
            scp.statistics.orders_computed += 1;
            scp.orders.push(order);
        }
        if let Some(interval) = config.online_interval {
            scp.online = Some(Online {
                interval: interval.max(1),
                until: deadline,
                evaluations: 0,
            });
        } else if config.max_orders > 1 && !scp.orders.is_empty() {
            let samples = scp.samples(task, config, &out_of_time);
            let sample_indices: Vec<Vec<usize>> = samples
                .iter()
                .map(|s| scp.projections.iter().map(|p| p.index(s)).collect())
                .collect();
            let mut best: Vec<u64> = sample_indices
                .iter()
                .map(|i| scp.orders[0].value(i))
                .collect();
            for sample in &samples {
                if scp.orders.len() as u64 >= config.max_orders || out_of_time(&scp) {
                    break;
                }
                let order = scp.order_for(sample);
                scp.statistics.orders_computed += 1;
                let mut better = !config.diversify;
                for (b, i) in best.iter_mut().zip(&sample_indices) {
                    let v = order.value(i);
                    if v > *b {
                        *b = v;
                        better = true;
                    }
                }
                if better {
                    scp.orders.push(order);
                }
            }
        }
        scp.statistics.orders = scp.orders.len();
        scp.statistics.total_time = start.elapsed();
        Ok(scp)
    }

    /// What building it did.
    pub fn statistics(&self) -> &ScpStatistics {
        &self.statistics
    }

    /// The projections' patterns, in order.
    pub fn patterns(&self) -> impl Iterator<Item = &[VarId]> + '_ {
        self.projections.iter().map(|p| p.pattern())
    }

    /// The greedy order for `state` and its saturated cost partitioning.
    fn order_for(&self, state: &[u32]) -> Order {
        let mut order: Vec<usize> = (0..self.projections.len()).collect();
        let score = |i: usize| {
            let h = match self.full[i][self.projections[i].index(state)] {
                DEAD => f64::INFINITY,
                v => f64::from(v),
            };
            h / self.stolen[i].max(1) as f64
        };
        let scores: Vec<f64> = (0..order.len()).map(score).collect();
        order.sort_by(|&a, &b| {
            scores[b]
                .total_cmp(&scores[a])
                .then(self.tie[a].cmp(&self.tie[b]))
                .then(a.cmp(&b))
        });
        self.partition(&order)
    }

    /// Saturated cost partitioning in `order`.
    fn partition(&self, order: &[usize]) -> Order {
        let mut remaining = self.costs.clone();
        let mut tables = Vec::new();
        let mut saturated = vec![0u64; remaining.len()];
        for (k, &i) in order.iter().enumerate() {
            let p = &self.projections[i];
            let d = p.distances(&remaining);
            if d.iter().any(|&x| x != 0 && x != INF) {
                tables.push((i as u32, cap(&d)));
            }
            if k + 1 < order.len() {
                saturated.iter_mut().for_each(|s| *s = 0);
                p.saturated_costs(&d, &mut saturated);
                for (r, &s) in remaining.iter_mut().zip(&saturated) {
                    *r -= s.min(*r);
                }
            }
        }
        Order { tables }
    }

    /// States for diversification: random walks from the initial state, without dead
    /// ends.
    fn samples(
        &self,
        task: &Task,
        config: &ScpConfig,
        out_of_time: &impl Fn(&Scp) -> bool,
    ) -> Vec<Vec<u32>> {
        let mut generator = SuccessorGenerator::new(task);
        let mut rng = FdRandom::new(config.random_seed);
        let init = &task.initial_state;
        let indices: Vec<usize> = self.projections.iter().map(|p| p.index(init)).collect();
        let h = self.orders[0].value(&indices);
        let ops: Vec<u64> = self.costs.iter().copied().filter(|&c| c > 0).collect();
        let average = if ops.is_empty() {
            1.0
        } else {
            ops.iter().sum::<u64>() as f64 / ops.len() as f64
        };
        let depth = ((h as f64 / average).ceil() as u64).clamp(1, 10_000) as u32;
        let mut applicable: Vec<OpId> = Vec::new();
        let mut out = Vec::with_capacity(config.samples as usize);
        let mut state = init.clone();
        while out.len() < config.samples as usize {
            if out_of_time(self) {
                break;
            }
            state.clone_from(init);
            let length = (0..2 * depth).filter(|_| rng.below(2) == 1).count();
            for _ in 0..length {
                generator.applicable(&state, &mut applicable);
                if applicable.is_empty() {
                    break;
                }
                let op = &task.operators
                    [applicable[rng.below(applicable.len() as u32) as usize].index()];
                let before = state.clone();
                for f in &op.effects {
                    state[f.var.index()] = f.value;
                }
                if self.is_dead_end(&state) {
                    state = before;
                    break;
                }
            }
            out.push(state.clone());
        }
        out
    }

    fn is_dead_end(&self, state: &[u32]) -> bool {
        self.projections
            .iter()
            .zip(&self.full)
            .any(|(p, d)| d[p.index(state)] == DEAD)
    }
}

/// When a phase begun at `start` must end: `max_time` after `start`, and not later than
/// half the time left before the run's `deadline`.
fn phase_deadline(
    start: Instant,
    max_time: Option<Duration>,
    deadline: Option<Instant>,
) -> Option<Instant> {
    let own = max_time.and_then(|t| start.checked_add(t));
    let half = deadline.map(|d| start + d.saturating_duration_since(start) / 2);
    match (own, half) {
        (Some(a), Some(b)) => Some(a.min(b)),
        (a, b) => a.or(b),
    }
}

/// Distances as a stored table: capped, with [`DEAD`] for dead ends.
fn cap(d: &[u64]) -> Box<[u32]> {
    d.iter()
        .map(|&x| {
            if x == INF {
                DEAD
            } else {
                x.min(u64::from(CAP)) as u32
            }
        })
        .collect()
}

/// Sys-SCP pattern selection (see the module documentation); `seen` holds the patterns
/// of earlier generators (skipped) and receives the ones kept.
fn sys_scp(
    task: &Task,
    config: &SysScpConfig,
    costs: &[u64],
    limits: &SearchLimits,
    seen: &mut FxHashSet<Vec<VarId>>,
) -> Result<Vec<Projection>, PatternError> {
    let start = Instant::now();
    let deadline = phase_deadline(start, config.max_time, limits.deadline);
    let clock = limits.clock().or_earlier(deadline);
    let max_pdb = config.max_pdb_size.min(MAX_PDB_SIZE);
    let predecessors = causal_predecessors(task);
    // The candidates, size by size, generated when the loop first reaches a size.
    let mut levels: Vec<Vec<Vec<u32>>> = vec![goal_patterns(task, max_pdb)];
    let mut done: Vec<Vec<bool>> = vec![vec![false; levels[0].len()]];
    let mut kept: Vec<Projection> = Vec::new();
    let mut kept_size: u64 = 0;
    let own = |kept: &[Projection]| kept.iter().map(Projection::bytes).sum::<u64>();
    'restarts: loop {
        let restart = Instant::now();
        let restart_deadline = config
            .max_time_per_restart
            .and_then(|t| restart.checked_add(t));
        let mut remaining = costs.to_vec();
        let mut added = false;
        let mut saturated = vec![0u64; costs.len()];
        let mut k = 0;
        loop {
            if k == levels.len() {
                if k as u64 >= config.max_pattern_size || levels[k - 1].is_empty() {
                    break;
                }
                let (next, _) = grow(task, &predecessors, &levels[k - 1], max_pdb, &mut || {
                    clock.passed()
                });
                done.push(vec![false; next.len()]);
                levels.push(next);
            }
            for c in 0..levels[k].len() {
                if done[k][c] {
                    continue;
                }
                if clock.passed() || limits.reached(|| own(&kept)).is_some() {
                    break 'restarts;
                }
                // A restart ends once its time is up, but only after it kept a pattern,
                // so that every restart makes progress.
                if added && restart_deadline.is_some_and(|d| Instant::now() >= d) {
                    continue 'restarts;
                }
                if kept.len() as u64 >= config.max_patterns {
                    break 'restarts;
                }
                let pattern = &levels[k][c];
                let normalized = normalize_pattern(task, pattern)?;
                if seen.contains(&normalized) {
                    done[k][c] = true;
                    continue;
                }
                let size = pattern_size(task, &normalized, MAX_PDB_SIZE).unwrap_or(u64::MAX);
                if kept_size.saturating_add(size) > config.max_collection_size {
                    done[k][c] = true;
                    continue;
                }
                let Some(projection) = Projection::new(task, pattern, limits)? else {
                    done[k][c] = true;
                    continue;
                };
                let d = projection.distances(&remaining);
                if d.iter().any(|&x| x != 0 && x != INF) {
                    saturated.iter_mut().for_each(|s| *s = 0);
                    projection.saturated_costs(&d, &mut saturated);
                    for (r, &s) in remaining.iter_mut().zip(&saturated) {
                        *r -= s.min(*r);
                    }
                    done[k][c] = true;
                    seen.insert(normalized);
                    kept_size += size;
                    kept.push(projection);
                    added = true;
                } else if d == projection.distances(costs) {
                    // Useless under the full costs too: never worth another look.
                    done[k][c] = true;
                }
            }
            k += 1;
        }
        // Every size has been seen: a restart comes only from the restart time.
        break;
    }
    Ok(kept)
}

impl Heuristic for Scp {
    fn name(&self) -> &str {
        self.name
    }

    fn evaluate(&mut self, state: &[u32]) -> Option<u64> {
        let mut single = 0u64;
        for (i, p) in self.projections.iter().enumerate() {
            let index = p.index(state);
            match self.full[i][index] {
                DEAD => return None,
                v => single = single.max(u64::from(v)),
            }
            self.indices[i] = index;
        }
        let mut best = self
            .orders
            .iter()
            .map(|o| o.value(&self.indices))
            .max()
            .unwrap_or(0)
            .max(single);
        if let Some(online) = &mut self.online {
            let due = online.evaluations.is_multiple_of(online.interval);
            online.evaluations += 1;
            if due && online.until.is_none_or(|u| Instant::now() < u) {
                let order = self.order_for(state);
                self.statistics.orders_computed += 1;
                let value = order.value(&self.indices);
                if value > best {
                    best = value;
                    self.orders.push(order);
                    self.statistics.orders = self.orders.len();
                }
            }
        }
        Some(best)
    }

    fn scp_statistics(&self) -> Option<&ScpStatistics> {
        Some(&self.statistics)
    }

    fn construction_log(&self) -> Option<String> {
        Some(self.statistics.to_string())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::pdb::PatternDatabase;
    use crate::successor::tests::{random_task, Rng};

    fn no_limits() -> SearchLimits {
        SearchLimits::default()
    }

    /// Under the full costs a projection's distances equal its pattern database's, and
    /// its saturated costs keep every distance as it is while never exceeding the costs.
    #[test]
    fn distances_match_pattern_databases_and_saturated_costs_keep_them() {
        let mut rng = Rng(7);
        for round in 0..200 {
            let mut t = random_task(&mut rng, 2 + round % 5, 3 + round % 15);
            t.use_costs = round % 3 != 0;
            let pattern: Vec<u32> = (0..t.variables.len() as u32)
                .filter(|_| rng.below(2) == 0)
                .collect();
            let costs: Vec<u64> = t.operators.iter().map(|o| t.cost(o)).collect();
            let p = Projection::new(&t, &pattern, &no_limits())
                .unwrap()
                .unwrap();
            let pdb = PatternDatabase::new(&t, &pattern).unwrap();
            let d = p.distances(&costs);
            for (i, &x) in d.iter().enumerate() {
                assert_eq!(pdb.value_at(i), (x != INF).then_some(x), "round {round}");
            }
            let mut s = vec![0u64; costs.len()];
            p.saturated_costs(&d, &mut s);
            assert!(s.iter().zip(&costs).all(|(a, b)| a <= b), "round {round}");
            assert_eq!(p.distances(&s), d, "round {round}");
        }
    }

    /// Two counters, each stepped by its own operators, and one operator that moves
    /// both: the single projections give 2 each, saturated cost partitioning their sum
    /// (the shared operator's cost is not needed by either projection's distances).
    fn two_counters() -> Task {
        use crate::test_tasks::op;
        use task::{Fact, Variable};
        let var = |name: &str| Variable {
            name: name.into(),
            value_names: (0..3).map(|v| format!("{name}{v}")).collect(),
        };
        Task {
            variables: vec![var("a"), var("b")],
            mutexes: vec![],
            initial_state: vec![0, 0],
            goal: vec![Fact::new(VarId(0), 2), Fact::new(VarId(1), 2)],
            operators: vec![
                op("a01", &[(0, 0)], &[(0, 1)], 1),
                op("a12", &[(0, 1)], &[(0, 2)], 1),
                op("b01", &[(1, 0)], &[(1, 1)], 1),
                op("b12", &[(1, 1)], &[(1, 2)], 1),
                op("both", &[(0, 0), (1, 0)], &[(0, 2), (1, 2)], 5),
            ],
            use_costs: true,
        }
    }

    #[test]
    fn saturated_cost_partitioning_adds_what_the_maximum_cannot() {
        let task = two_counters();
        let config = ScpConfig {
            abstractions: vec![PatternGenerator::Manual(vec![vec![0], vec![1]])],
            ..ScpConfig::default()
        };
        let mut h = Scp::new(&task, &config, &no_limits()).unwrap();
        assert_eq!(h.evaluate(&[0, 0]), Some(4));
        assert_eq!(h.evaluate(&[1, 0]), Some(3));
        assert_eq!(h.evaluate(&[2, 2]), Some(0));
        assert_eq!(h.name(), "scp");
        assert_eq!(h.statistics().projections, 2);
        // The saturated costs of projection [0]: a01 and a12 at 1, `both` at 2 (it
        // skips two steps of cost 1), b01 and b12 at 0.
        let p = Projection::new(&task, &[0], &no_limits()).unwrap().unwrap();
        let costs: Vec<u64> = task.operators.iter().map(|o| o.cost).collect();
        let mut s = vec![0; costs.len()];
        p.saturated_costs(&p.distances(&costs), &mut s);
        assert_eq!(s, [1, 1, 0, 0, 2]);
        // Sys-SCP keeps both goal variables (each useful under what the other leaves)
        // and nothing larger (the pair adds no information once both are in).
        let sys = ScpConfig {
            abstractions: vec![PatternGenerator::SysScp(SysScpConfig::default())],
            ..ScpConfig::default()
        };
        let mut h = Scp::new(&task, &sys, &no_limits()).unwrap();
        let patterns: Vec<Vec<VarId>> = h.patterns().map(<[VarId]>::to_vec).collect();
        assert_eq!(patterns, [vec![VarId(0)], vec![VarId(1)]]);
        assert_eq!(h.evaluate(&[0, 0]), Some(4));
    }

    #[test]
    fn construction_stops_at_the_limits_and_keeps_an_admissible_heuristic() {
        let task = two_counters();
        let config = ScpConfig {
            abstractions: vec![PatternGenerator::SysScp(SysScpConfig::default())],
            ..ScpConfig::default()
        };
        static CANCEL: std::sync::atomic::AtomicBool = std::sync::atomic::AtomicBool::new(true);
        for limits in [
            SearchLimits {
                deadline: Some(Instant::now()),
                ..SearchLimits::default()
            },
            SearchLimits {
                cancel: Some(&CANCEL),
                ..SearchLimits::default()
            },
            SearchLimits {
                memory_limit_bytes: Some(1),
                ..SearchLimits::default()
            },
        ] {
            let mut h = Scp::new(&task, &config, &limits).unwrap();
            assert_eq!(h.statistics().projections, 0, "{limits:?}");
            assert_eq!(h.evaluate(&[0, 0]), Some(0));
        }
    }

    #[test]
    fn online_orders_are_added_at_the_interval_when_they_help() {
        let task = two_counters();
        let config = ScpConfig {
            abstractions: vec![PatternGenerator::Manual(vec![vec![0], vec![1], vec![0, 1]])],
            online_interval: Some(2),
            ..ScpConfig::default()
        };
        let mut h = Scp::new(&task, &config, &no_limits()).unwrap();
        assert_eq!(h.name(), "scp_online");
        let before = h.statistics().orders_computed;
        for state in [[0, 0], [1, 0], [0, 1], [1, 1], [2, 0]] {
            h.evaluate(&state);
        }
        // Evaluations 1, 3 and 5 computed an order.
        assert_eq!(h.statistics().orders_computed, before + 3);
        // The pair alone is exact here: 4 from the start.
        assert_eq!(h.evaluate(&[0, 0]), Some(4));
    }

    #[test]
    fn systematic_up_to_two_is_cpdbs_systematic() {
        let mut rng = Rng(3);
        for round in 0..100 {
            let t = random_task(&mut rng, 2 + round % 6, 3 + round % 12);
            for k in 1..=2 {
                let ours = systematic_up_to(&t, k, MAX_PDB_SIZE, || false);
                let theirs = crate::cpdbs::systematic_patterns(&t, k as usize);
                let mut a = ours.clone();
                let mut b = theirs.clone();
                a.sort();
                b.sort();
                assert_eq!(a, b, "round {round}, k {k}");
            }
            let three = systematic_up_to(&t, 3, MAX_PDB_SIZE, || false);
            assert!(three.windows(2).all(|w| w[0].len() <= w[1].len()));
            assert!(three
                .iter()
                .all(|p| p.len() <= 3 && p.windows(2).all(|w| w[0] < w[1])));
        }
    }

    #[test]
    fn a_stopped_generation_keeps_what_it_has() {
        let mut rng = Rng(5);
        let t = random_task(&mut rng, 6, 20);
        let all = systematic_up_to(&t, 3, MAX_PDB_SIZE, || false);
        let first = systematic_up_to(&t, 3, MAX_PDB_SIZE, || true);
        assert!(first.len() <= all.len());
        assert_eq!(first, all[..first.len()]);
    }

    #[test]
    fn too_many_transitions_or_too_little_memory_give_no_projection() {
        let mut rng = Rng(9);
        let t = random_task(&mut rng, 4, 10);
        let tight = SearchLimits {
            memory_limit_bytes: Some(1),
            ..SearchLimits::default()
        };
        assert!(Projection::new(&t, &[0, 1, 2, 3], &tight)
            .unwrap()
            .is_none());
        assert!(Projection::new(&t, &[0, 1, 2, 3], &no_limits())
            .unwrap()
            .is_some());
        assert!(matches!(
            Projection::new(&t, &[9], &no_limits()),
            Err(PatternError::VariableOutOfRange { var: 9, .. })
        ));
    }
}
