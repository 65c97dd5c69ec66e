//! iPDB: a pattern collection chosen by hill climbing for the canonical heuristic (Haslum,
//! Botea, Helmert, Bonet and Koenig, AAAI 2007), as Fast Downward documents its `ipdb()`.
//!
//! The climb starts with one pattern per goal variable. Its neighbours are the *candidate*
//! patterns: a pattern `P` of the collection plus one variable `v` *relevant* to a
//! variable `w` of `P`, whose database has at most `pdb_max_size` abstract states. Relevant
//! are `w`'s precondition-to-effect predecessors in the causal graph (an operator has a
//! precondition on `v` and an effect on `w`) and the goal variables among `w`'s successors
//! (an operator has a precondition or an effect on `w` and an effect on the goal variable
//! `v`): the neighbourhood of the paper with its errata, under which adding a goal
//! variable that depends on `P` can raise the estimate. Candidates are generated in the
//! order of `P`'s variables, then of their relevant variables, skipping patterns generated
//! before. Every candidate's database is built once, when the candidate is generated, and
//! kept until it is chosen or rejected. Each iteration:
//!
//! 1. samples `num_samples` states by random walks from the initial state. A walk's
//!    length is binomially distributed with `n = 4 * steps` trials of probability 1/2
//!    (mean twice the estimated number of solution steps, `steps = round(h(initial) /
//!    average operator cost)` under the current collection), `n = 10` when `h(initial)`
//!    is 0. A walk ends early in a state without applicable operators, and restarts at the
//!    initial state when it reaches a dead end of the current collection. Applicable
//!    operators are either tracked incrementally (a count of unsatisfied preconditions
//!    per operator: a step costs the operators whose preconditions mention the changed
//!    values) or listed by the successor generator (a step costs the tree nodes on the
//!    way), whichever a probe walk finds cheaper for the task (see `Walker`);
//! 2. counts, for every candidate, the samples whose canonical value would rise with the
//!    candidate added: a sample `s` improves if the candidate's database calls it a dead
//!    end, or if for some maximal additive subset `C` of the current collection the sum
//!    over the patterns of `C` additive with the candidate, plus the candidate's value,
//!    exceeds the current value of `s` (the counting approximation of the paper); samples
//!    that are dead ends of the collection never improve. Candidates not additive with
//!    the same collection patterns share the work: where they need the collection's part
//!    on few samples, the cliques are scanned per sample by decreasing sum, lazily; where
//!    on most, the part is summed over all samples at once (see `count_improvements`);
//! 3. adds the candidate with the most improved samples (the first of equals) if it
//!    improves at least `min_improvement` of them, and generates the candidates of the new
//!    pattern; otherwise the climb ends.
//!
//! Candidates whose database would take the collection beyond `collection_max_size`
//! abstract states are rejected (when generated, without building their database, or
//! when next evaluated). The climb also ends when the initial
//! state is a dead end, at `max_time`, at the caller's deadline or memory limit, or once
//! `max_generated_patterns` candidates were generated. Under a memory limit a candidate
//! whose database would take memory use beyond it ([`crate::construction_bytes`]) is
//! rejected before its database is allocated, and the climb ends there: the search then
//! runs with the collection found so far, in the memory left. The clique enumeration
//! and the dominance pruning after the climb stop at the caller's deadline.
//!
//! Without `max_time` (unlimited, Fast Downward's default) but with a caller's deadline
//! (`demoplan plan --overall-time-limit`), the climb takes at most half the time left
//! before that deadline, so that the search gets the other half with the collection found
//! so far. Fast Downward's climb would take all of it and leave the search none: where
//! the climb is that slow (large neighbourhoods of patterns over variables with large
//! domains, e.g. pipesworld's batch positions under demoplan's translation), a search
//! with the collection found by then mostly finishes quickly.
//!
//! The default options are Fast Downward's (`pdb_max_size=2000000`,
//! `collection_max_size=20000000`, `num_samples=1000`, `min_improvement=10`, no time
//! limit). The random walks draw Fast Downward's random numbers, draw for draw
//! ([`crate::fd_random`]: its Mersenne Twister, seeded 2011 unless `random_seed` says
//! otherwise), and choose among the applicable operators in the order of Fast Downward's
//! successor generator: operators sorted by their preconditions (as sorted lists of
//! variable-value pairs), then by index. On a task with Fast Downward's variables and
//! operators in its order (`demoplan translate` gives that on all but a few benchmark
//! domains), the climb therefore samples the same states and adds the same patterns as
//! Fast Downward's with the same seed. A run is deterministic.

use std::time::{Duration, Instant};

use rustc_hash::{FxHashMap, FxHashSet};
use task::{OpId, Task, VarId};

use crate::astar::SearchLimits;
use crate::cpdbs::{additive_cliques, Additivity, CanonicalPdbs};
use crate::fd_random::FdRandom;
pub use crate::fd_random::DEFAULT_SEED;
use crate::pdb::{
    construction_bytes, pattern_size, PatternDatabase, PatternError, PdbBuilder, MAX_PDB_SIZE,
};
use crate::successor::SuccessorGenerator;

const DEAD: u32 = u32::MAX;

/// The options of `ipdb(...)`, with Fast Downward's defaults.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct IpdbConfig {
    /// Largest database of a candidate pattern, in abstract states.
    pub pdb_max_size: u64,
    /// Largest total of the collection's databases, in abstract states.
    pub collection_max_size: u64,
    /// States sampled per iteration.
    pub num_samples: u32,
    /// Fewest improved samples for a candidate to be added.
    pub min_improvement: u32,
    /// Time limit of the climb (`None`: unlimited, but at most half the time left before
    /// the caller's deadline if there is one; see the module documentation).
    pub max_time: Option<Duration>,
    /// Seed of the random walks' Mersenne Twister (Fast Downward's `random_seed`; its
    /// `-1` is the default, [`DEFAULT_SEED`]).
    pub random_seed: u32,
    /// The climb ends once this many candidate patterns were generated (`None`: no limit).
    pub max_generated_patterns: Option<u64>,
    /// Time limit of the dominance pruning of cliques after the climb (`None`: unlimited;
    /// zero: no pruning).
    pub max_time_dominance_pruning: Option<Duration>,
}

impl Default for IpdbConfig {
    fn default() -> IpdbConfig {
        IpdbConfig {
            pdb_max_size: 2_000_000,
            collection_max_size: 20_000_000,
            num_samples: 1000,
            min_improvement: 10,
            max_time: None,
            random_seed: DEFAULT_SEED,
            max_generated_patterns: None,
            max_time_dominance_pruning: None,
        }
    }
}

/// Why the hill climbing ended.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum ClimbEnd {
    /// No candidate improved `min_improvement` samples (or none was left).
    #[default]
    Converged,
    /// The initial state is a dead end of the collection.
    InitialDeadEnd,
    /// `max_time` or the caller's deadline passed.
    TimeLimit,
    /// The caller's memory limit was exceeded.
    MemoryLimit,
    /// `max_generated_patterns` candidates were generated.
    GeneratedPatternsLimit,
    /// The caller cancelled the run (`Limits::cancel`); the search then stops at its
    /// first check.
    Cancelled,
}

impl std::fmt::Display for ClimbEnd {
    /// `converged`, `initial state is a dead end`, `time limit`, ...
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(match self {
            ClimbEnd::Converged => "converged",
            ClimbEnd::InitialDeadEnd => "initial state is a dead end",
            ClimbEnd::TimeLimit => "time limit",
            ClimbEnd::MemoryLimit => "memory limit",
            ClimbEnd::GeneratedPatternsLimit => "generated patterns limit",
            ClimbEnd::Cancelled => "cancelled",
        })
    }
}

/// What the hill climbing did, in Fast Downward's terms, and where its time went.
#[derive(Debug, Clone, Default, PartialEq, Eq)]
pub struct HillClimbingStatistics {
    /// Iterations begun ("Hill climbing iterations").
    pub iterations: u32,
    /// Candidate patterns generated, each with its database.
    pub generated_patterns: u64,
    /// Patterns not generated because their database would exceed `pdb_max_size`,
    /// counted each time one comes up (Fast Downward's "rejected patterns").
    pub rejected_patterns: u64,
    /// Candidates dropped because the collection had no room left for them.
    pub dropped_patterns: u64,
    /// The largest database generated, in abstract states.
    pub max_pdb_size: u64,
    /// Patterns in the collection at the end of the climb.
    pub patterns: usize,
    /// Abstract states over the collection's databases at the end of the climb.
    pub total_size: u64,
    /// Why it ended.
    pub end: ClimbEnd,
    /// Wall-clock time of the climb.
    pub time: Duration,
    /// Of which building databases (initial patterns and candidates).
    pub pdb_time: Duration,
    /// Of which sampling states by random walks.
    pub sampling_time: Duration,
    /// Of which counting improved samples (and the collection's values on samples).
    pub evaluation_time: Duration,
    /// The number of samples each added pattern improved, in the order added (Fast
    /// Downward's "found a better pattern with improvement N").
    pub improvements: Vec<u64>,
}

/// The `ipdb()` heuristic: the canonical heuristic over the collection the hill climbing
/// finds (see the module documentation), with dominance pruning; its
/// [`statistics`](CanonicalPdbs::statistics) include the climb's. The climb stops early
/// at `limits.deadline` or when memory use exceeds `limits.memory_limit_bytes`.
pub fn ipdb(
    task: &Task,
    config: &IpdbConfig,
    limits: &SearchLimits,
) -> Result<CanonicalPdbs, PatternError> {
    let start = Instant::now();
    task.validate()?;
    let (collection, climb) = hill_climbing(task, config, limits);
    let pruning = match config.max_time_dominance_pruning {
        Some(t) if t.is_zero() => None,
        Some(t) => Some(t),
        None => Some(Duration::MAX),
    };
    let mut heuristic = CanonicalPdbs::within(task, collection, pruning, "ipdb", limits.clock());
    let statistics = heuristic.statistics_mut();
    statistics.hill_climbing = Some(climb);
    statistics.total_time = start.elapsed();
    Ok(heuristic)
}

/// A candidate pattern with its database, and which collection patterns it is additive
/// with (extended as the collection grows).
#[derive(Debug)]
struct Candidate {
    pdb: PatternDatabase,
    additive: Vec<bool>,
}

/// Runs the climb on a valid task; returns the collection and what it did.
pub(crate) fn hill_climbing(
    task: &Task,
    config: &IpdbConfig,
    limits: &SearchLimits,
) -> (Vec<PatternDatabase>, HillClimbingStatistics) {
    let start = Instant::now();
    let deadline = climb_deadline(start, config.max_time, limits.deadline);
    let mut climb = Climb::new(task, config, limits, deadline);
    climb.stats.end = climb.run();
    climb.stats.patterns = climb.collection.len();
    climb.stats.total_size = climb.collection_size;
    climb.stats.time = start.elapsed();
    (climb.collection, climb.stats)
}

/// When a climb begun at `start` must end: `max_time` after `start`, but not after the
/// caller's `deadline`; without `max_time`, half the time left before `deadline` (see the
/// module documentation). `None`: never.
fn climb_deadline(
    start: Instant,
    max_time: Option<Duration>,
    deadline: Option<Instant>,
) -> Option<Instant> {
    let own = match max_time {
        Some(t) => start.checked_add(t),
        // The other half is the search's.
        None => deadline.map(|d| start + d.saturating_duration_since(start) / 2),
    };
    match (own, deadline) {
        (Some(a), Some(b)) => Some(a.min(b)),
        (a, b) => a.or(b),
    }
}

/// Which of the caller's limits has been reached, if any: the cancel flag, `deadline`
/// (the climb's), and the memory limit (the process's use if the caller reads it, else
/// the tables built so far, `table_bytes`).
fn resource_limit(
    limits: &SearchLimits,
    deadline: Option<Instant>,
    table_bytes: u64,
) -> Option<ClimbEnd> {
    if limits.cancelled() {
        return Some(ClimbEnd::Cancelled);
    }
    if deadline.is_some_and(|d| Instant::now() >= d) {
        return Some(ClimbEnd::TimeLimit);
    }
    let limit = limits.memory_limit_bytes?;
    let used = match limits.memory_usage {
        Some(read) => read(),
        None => table_bytes,
    };
    (used > limit).then_some(ClimbEnd::MemoryLimit)
}

/// The state of a climb.
struct Climb<'t> {
    task: &'t Task,
    config: &'t IpdbConfig,
    limits: &'t SearchLimits,
    deadline: Option<Instant>,
    builder: PdbBuilder,
    additivity: Additivity,
    /// The variables that may be added to a pattern containing `v`, sorted: `v`'s
    /// precondition-to-effect predecessors and the goal variables among its successors
    /// (see the module documentation).
    neighbours: Vec<Vec<u32>>,
    collection: Vec<PatternDatabase>,
    collection_size: u64,
    cliques: Vec<Vec<u32>>,
    /// Candidates in order of generation; `None` once chosen or rejected.
    candidates: Vec<Option<Candidate>>,
    generated: FxHashSet<Vec<VarId>>,
    /// Bytes of the collection's and the candidates' tables.
    table_bytes: u64,
    stats: HillClimbingStatistics,
    rng: FdRandom,
    walker: Walker,
    average_cost: f64,
    /// Sampled states, `num_vars` values each.
    samples: Vec<u32>,
    /// Collection values on the samples: `values[p * num_samples + s]` (0 for dead
    /// ends).
    values: Vec<u32>,
    /// The collection's canonical value of each sample (`None`: a dead end).
    sample_h: Vec<Option<u64>>,
}

impl<'t> Climb<'t> {
    fn new(
        task: &'t Task,
        config: &'t IpdbConfig,
        limits: &'t SearchLimits,
        deadline: Option<Instant>,
    ) -> Climb<'t> {
        let n = task.variables.len();
        let mut is_goal = vec![false; n];
        for f in &task.goal {
            is_goal[f.var.index()] = true;
        }
        let mut neighbours: Vec<Vec<u32>> = vec![Vec::new(); n];
        for op in &task.operators {
            for e in &op.effects {
                let v = e.var.index();
                // Precondition-to-effect predecessors of v.
                neighbours[v].extend(op.preconditions.iter().map(|f| f.var.0));
                // Goal variables among v's successors: effects of operators with a
                // precondition or an effect on v.
                for f in op.effects.iter().filter(|f| is_goal[f.var.index()]) {
                    neighbours[v].push(f.var.0);
                }
            }
            for p in &op.preconditions {
                for f in op.effects.iter().filter(|f| is_goal[f.var.index()]) {
                    neighbours[p.var.index()].push(f.var.0);
                }
            }
        }
        for (v, list) in neighbours.iter_mut().enumerate() {
            list.sort_unstable();
            list.dedup();
            list.retain(|&w| w as usize != v);
        }
        let total_cost: f64 = task.operators.iter().map(|op| task.cost(op) as f64).sum();
        let average_cost = if task.operators.is_empty() {
            1.0
        } else {
            total_cost / task.operators.len() as f64
        };
        Climb {
            task,
            config,
            limits,
            deadline,
            builder: PdbBuilder::new(task),
            additivity: Additivity::new(task),
            neighbours,
            collection: Vec::new(),
            collection_size: 0,
            cliques: Vec::new(),
            candidates: Vec::new(),
            generated: FxHashSet::default(),
            table_bytes: 0,
            stats: HillClimbingStatistics::default(),
            rng: FdRandom::new(config.random_seed),
            walker: Walker::new(task),
            average_cost,
            samples: Vec::new(),
            values: Vec::new(),
            sample_h: Vec::new(),
        }
    }

    /// The climb; returns why it ended.
    fn run(&mut self) -> ClimbEnd {
        let mut goal_vars: Vec<VarId> = self.task.goal.iter().map(|f| f.var).collect();
        goal_vars.sort_unstable();
        goal_vars.dedup();
        for var in goal_vars {
            match self.build(&[var]) {
                Ok(pdb) => self.add_to_collection(pdb),
                Err(end) => return end,
            }
        }
        for p in 0..self.collection.len() {
            if let Some(end) = self.generate_candidates(p) {
                return end;
            }
        }
        loop {
            if let Some(end) = self.limit_reached() {
                return end;
            }
            self.stats.iterations += 1;
            let Some(initial_h) = self.canonical(&self.task.initial_state) else {
                return ClimbEnd::InitialDeadEnd;
            };
            let t = Instant::now();
            let sampled = self.sample(initial_h);
            self.stats.sampling_time += t.elapsed();
            if let Some(end) = sampled {
                return end;
            }
            let t = Instant::now();
            let best = self.best_candidate();
            self.stats.evaluation_time += t.elapsed();
            let Some((best, improvement)) = best else {
                return ClimbEnd::Converged;
            };
            if improvement < u64::from(self.config.min_improvement) {
                return ClimbEnd::Converged;
            }
            let Some(chosen) = self.candidates[best].take() else {
                return ClimbEnd::Converged;
            };
            self.stats.improvements.push(improvement);
            self.add_to_collection(chosen.pdb);
            if let Some(end) = self.generate_candidates(self.collection.len() - 1) {
                return end;
            }
        }
    }

    /// The database of `pattern`, or why the climb ends if a limit is reached while it is
    /// built (a large task's database takes long: see `PdbBuilder::build_with`).
    fn build(&mut self, pattern: &[VarId]) -> Result<PatternDatabase, ClimbEnd> {
        let t = Instant::now();
        let (limits, deadline, table_bytes) = (self.limits, self.deadline, self.table_bytes);
        let pdb = self.builder.build_with(pattern, || {
            resource_limit(limits, deadline, table_bytes).map_or(Ok(()), Err)
        });
        self.stats.pdb_time += t.elapsed();
        let pdb = pdb?;
        self.table_bytes += pdb.memory_bytes() as u64;
        Ok(pdb)
    }

    fn add_to_collection(&mut self, pdb: PatternDatabase) {
        self.collection_size += pdb.size() as u64;
        self.collection.push(pdb);
        let patterns: Vec<&[VarId]> = self.collection.iter().map(|p| p.pattern()).collect();
        self.cliques = additive_cliques(
            &self.additivity,
            &patterns,
            task::Deadline {
                at: self.deadline,
                cancel: self.limits.cancel,
            },
        );
    }

    /// The time or memory limit that has been reached, if any.
    fn limit_reached(&self) -> Option<ClimbEnd> {
        if let Some(end) = resource_limit(self.limits, self.deadline, self.table_bytes) {
            return Some(end);
        }
        if self
            .config
            .max_generated_patterns
            .is_some_and(|m| self.stats.generated_patterns >= m)
        {
            return Some(ClimbEnd::GeneratedPatternsLimit);
        }
        None
    }

    /// Generates the candidates of collection pattern `p`, building their databases;
    /// returns the limit that stopped it, if one did.
    fn generate_candidates(&mut self, p: usize) -> Option<ClimbEnd> {
        let pattern = self.collection[p].pattern().to_vec();
        // In order of the pattern's variables, then of their neighbours.
        let extra: Vec<u32> = pattern
            .iter()
            .flat_map(|v| self.neighbours[v.index()].iter().copied())
            .filter(|&w| pattern.binary_search(&VarId(w)).is_err())
            .collect();
        for w in extra {
            let mut candidate = pattern.clone();
            let at = candidate.partition_point(|v| v.0 < w);
            candidate.insert(at, VarId(w));
            let limit = self.config.pdb_max_size.min(MAX_PDB_SIZE);
            let Some(size) = pattern_size(self.task, &candidate, limit) else {
                self.stats.rejected_patterns += 1;
                continue;
            };
            if self.generated.contains(&candidate) {
                continue;
            }
            if let Some(end) = self.limit_reached() {
                return Some(end);
            }
            self.stats.generated_patterns += 1;
            self.stats.max_pdb_size = self.stats.max_pdb_size.max(size);
            let room = self
                .config
                .collection_max_size
                .saturating_sub(self.collection_size);
            if size > room {
                // The room only shrinks: it would be rejected at its first evaluation.
                self.generated.insert(candidate);
                self.stats.dropped_patterns += 1;
                continue;
            }
            if self
                .limits
                .would_exceed(construction_bytes([size]), || self.table_bytes)
            {
                // Its database does not fit the memory limit: rejected unbuilt, and the
                // climb ends, so that the search runs with the collection found so far.
                self.stats.dropped_patterns += 1;
                return Some(ClimbEnd::MemoryLimit);
            }
            let pdb = match self.build(&candidate) {
                Ok(pdb) => pdb,
                Err(end) => {
                    // Cut short by a limit: rejected, and the climb ends.
                    self.stats.dropped_patterns += 1;
                    return Some(end);
                }
            };
            self.generated.insert(candidate);
            self.candidates.push(Some(Candidate {
                pdb,
                additive: Vec::new(),
            }));
        }
        None
    }

    /// The canonical value of `state` for the collection.
    fn canonical(&self, state: &[u32]) -> Option<u64> {
        let mut values = Vec::with_capacity(self.collection.len());
        for pdb in &self.collection {
            match pdb.raw(state) {
                DEAD => return None,
                v => values.push(u64::from(v)),
            }
        }
        self.cliques
            .iter()
            .map(|c| c.iter().map(|&m| values[m as usize]).sum())
            .max()
    }

    /// True if a database of the collection calls `state` a dead end.
    fn is_dead_end(&self, state: &[u32]) -> bool {
        self.collection
            .iter()
            .any(|p| p.has_dead_ends() && p.raw(state) == DEAD)
    }

    /// Samples states by random walks (see the module documentation) into `samples`;
    /// stops early, returning why, if the deadline passes (checked after every sample,
    /// as Fast Downward checks its climb's timer: long walks can take seconds).
    fn sample(&mut self, initial_h: u64) -> Option<ClimbEnd> {
        // The number of coin flips of the binomial distribution: four times the
        // estimated number of steps, or 10 if h is 0 (then the average cost need not
        // be positive); capped far beyond any walk that could finish in reasonable time.
        // Fast Downward truncates the rounded estimate to an int.
        let flips = if initial_h == 0 || self.average_cost <= 0.0 {
            10
        } else {
            let steps = (initial_h as f64 / self.average_cost + 0.5).trunc();
            (4.0 * steps).min(1e9) as u64
        };
        let init = &self.task.initial_state;
        let n = init.len();
        let samples = self.config.num_samples as usize;
        self.samples.clear();
        for _ in 0..samples {
            // One double per flip, as Fast Downward draws them.
            let length = (0..flips).filter(|_| self.rng.unit() < 0.5).count();
            self.walker.set_state(init);
            for _ in 0..length {
                let applicable = self.walker.applicable().len();
                if applicable == 0 {
                    break; // The walk ends where it is stuck.
                }
                // Both counts are at most the number of operators, a u32.
                let k = self.rng.below(applicable as u32);
                let op = self.walker.kth_in_fast_downward_order(k as usize);
                self.walker.apply(op);
                if self.is_dead_end(self.walker.state()) {
                    self.walker.set_state(init);
                }
            }
            self.samples.extend_from_slice(self.walker.state());
            if self.limits.cancelled() {
                return Some(ClimbEnd::Cancelled);
            }
            if self.deadline.is_some_and(|d| Instant::now() >= d) {
                return Some(ClimbEnd::TimeLimit);
            }
        }
        // The collection's values on the samples, pattern by pattern (dead ends as 0:
        // those samples are not compared), and the canonical value of each sample.
        let patterns = self.collection.len();
        self.values.clear();
        self.values.resize(patterns * samples, 0);
        self.sample_h.clear();
        self.sample_h.resize(samples, Some(0));
        for (p, pdb) in self.collection.iter().enumerate() {
            let column = &mut self.values[p * samples..(p + 1) * samples];
            for (s, value) in column.iter_mut().enumerate() {
                let v = pdb.raw(&self.samples[s * n..(s + 1) * n]);
                if v == DEAD {
                    self.sample_h[s] = None;
                } else {
                    *value = v;
                }
            }
        }
        let mut h = vec![0u64; samples];
        let mut sum = vec![0u64; samples];
        for clique in &self.cliques {
            sum.fill(0);
            for &m in clique {
                let column = &self.values[m as usize * samples..(m as usize + 1) * samples];
                for (acc, &v) in sum.iter_mut().zip(column) {
                    *acc += u64::from(v);
                }
            }
            for (best, &acc) in h.iter_mut().zip(&sum) {
                *best = (*best).max(acc);
            }
        }
        for (current, value) in self.sample_h.iter_mut().zip(h) {
            if current.is_some() {
                *current = Some(value);
            }
        }
        None
    }

    /// The first candidate improving the most samples, with that number; rejects the
    /// candidates the collection has no room for.
    fn best_candidate(&mut self) -> Option<(usize, u64)> {
        let room = self
            .config
            .collection_max_size
            .saturating_sub(self.collection_size);
        let patterns = self.collection.len();
        let n = self.task.variables.len();
        let samples = self.config.num_samples as usize;
        // Group the candidates by the collection patterns they are not additive with.
        let mut keys: FxHashMap<Vec<bool>, usize> = FxHashMap::default();
        let mut non_additive: Vec<Vec<u32>> = Vec::new();
        let mut key_of: Vec<usize> = vec![usize::MAX; self.candidates.len()];
        for (c, slot) in self.candidates.iter_mut().enumerate() {
            let Some(candidate) = slot else {
                continue;
            };
            if candidate.pdb.size() as u64 > room {
                self.table_bytes -= candidate.pdb.memory_bytes() as u64;
                *slot = None;
                self.stats.dropped_patterns += 1;
                continue;
            }
            while candidate.additive.len() < patterns {
                let other = self.collection[candidate.additive.len()].pattern();
                let additive = self.additivity.additive(candidate.pdb.pattern(), other);
                candidate.additive.push(additive);
            }
            let next = keys.len();
            key_of[c] = *keys.entry(candidate.additive.clone()).or_insert_with(|| {
                let others = (0..patterns as u32)
                    .filter(|&p| !candidate.additive[p as usize])
                    .collect();
                non_additive.push(others);
                next
            });
        }
        // The candidates' values on the samples.
        let live: Vec<usize> = (0..self.candidates.len())
            .filter(|&c| self.candidates[c].is_some())
            .collect();
        let mut candidate_h = vec![0u32; live.len() * samples];
        for (i, &c) in live.iter().enumerate() {
            let Some(candidate) = &self.candidates[c] else {
                continue;
            };
            let row = &mut candidate_h[i * samples..(i + 1) * samples];
            for (s, h) in row.iter_mut().enumerate() {
                *h = candidate.pdb.raw(&self.samples[s * n..(s + 1) * n]);
            }
        }
        let keys: Vec<usize> = live.iter().map(|&c| key_of[c]).collect();
        let collection = CollectionOnSamples {
            cliques: &self.cliques,
            values: &self.values,
            sample_h: &self.sample_h,
            patterns,
            non_additive: &non_additive,
        };
        let improved = count_improvements(&collection, &keys, &candidate_h);
        let mut best: Option<(usize, u64)> = None;
        for (&c, &improved) in live.iter().zip(&improved) {
            if best.is_none_or(|(_, b)| improved > b) {
                best = Some((c, improved));
            }
        }
        best
    }
}

/// For each candidate, the number of samples it improves (see the module
/// documentation). The collection's values on sample `s` are in
/// `values[p * samples + s]`, its canonical value in `sample_h[s]`; candidate `i`'s
/// values in `candidate_h[i * samples + s]`, and the collection patterns it is not
/// additive with in `non_additive[keys[i]]`.
///
/// A sample needs the collection's part, `max_C sum(C \ N)` over its cliques `C`, only
/// if the candidate's value there is positive, finite and at most the canonical value.
/// Candidates with the same `N` form a group. Where a group needs that part on at most
/// half the samples (pegsol: about 10 of 1,000, most values 0) the cliques are scanned
/// per sample in order of their sums and the scan stops early; where it needs it on most
/// (logistics: nearly all, with a thousand cliques) the part is summed for all samples
/// at once, four times faster there. Each way is much faster somewhere (pegsol: per
/// sample 14x; storage p15: all at once 27x), measured in `bench/README.md`.
fn count_improvements(
    collection: &CollectionOnSamples<'_>,
    keys: &[usize],
    candidate_h: &[u32],
) -> Vec<u64> {
    let (sample_h, non_additive) = (collection.sample_h, collection.non_additive);
    let samples = sample_h.len();
    let all: Vec<usize> = (0..keys.len()).collect();
    let mut needed = vec![0usize; non_additive.len()];
    let mut marked = vec![usize::MAX; samples];
    for (k, members) in by_group(keys, &all, non_additive.len()).iter().enumerate() {
        for &i in members {
            for (s, (&h, current)) in candidate_h[i * samples..(i + 1) * samples]
                .iter()
                .zip(sample_h)
                .enumerate()
            {
                let needs = h != DEAD && h != 0 && current.is_some_and(|c| u64::from(h) <= c);
                if needs && marked[s] != k {
                    marked[s] = k;
                    needed[k] += 1;
                }
            }
        }
    }
    let (dense, sparse): (Vec<usize>, Vec<usize>) = all
        .into_iter()
        .partition(|&i| 2 * needed[keys[i]] > samples);
    let mut improved = vec![0u64; keys.len()];
    let counting = |chosen| Counting {
        on: collection,
        keys,
        candidate_h,
        chosen,
    };
    count_by_reduced_cliques(counting(&dense), &mut improved);
    count_by_sorted_cliques(counting(&sparse), &mut improved);
    improved
}

/// The candidates `chosen` grouped by their key: group `k` lists, in order, those with
/// `keys[i] == k`.
fn by_group(keys: &[usize], chosen: &[usize], groups: usize) -> Vec<Vec<usize>> {
    let mut by_group: Vec<Vec<usize>> = vec![Vec::new(); groups];
    for &i in chosen {
        by_group[keys[i]].push(i);
    }
    by_group
}

/// What a way of counting counts: for each candidate `i` in `chosen`, the samples it
/// improves, into `improved[i]` (the other fields as [`count_improvements`] takes them).
#[derive(Debug, Clone, Copy)]
struct Counting<'a> {
    on: &'a CollectionOnSamples<'a>,
    keys: &'a [usize],
    candidate_h: &'a [u32],
    chosen: &'a [usize],
}

/// A way of counting.
#[cfg(test)]
type CountFn = fn(Counting<'_>, &mut [u64]);

/// The collection's side of evaluating candidates: its cliques, its patterns' values on
/// the samples (`values[p * samples + s]`), its canonical value per sample (`None`: a
/// dead end), and the groups of collection patterns candidates are not additive with.
#[derive(Debug, Clone, Copy)]
struct CollectionOnSamples<'a> {
    cliques: &'a [Vec<u32>],
    values: &'a [u32],
    sample_h: &'a [Option<u64>],
    patterns: usize,
    non_additive: &'a [Vec<u32>],
}

/// [`count_improvements`] for groups whose candidates need the collection's part on
/// many samples.
///
/// A candidate with value `h` improves `s` if `h` is a dead end, or if
/// `h + max_C sum(C \ N) > h(s)` over the cliques `C` of the collection, `N` the patterns
/// it is not additive with. The maximum depends on `N` only, so it is computed once per
/// group of candidates with the same `N`, for all samples at once: each distinct reduced
/// clique `C \ N` adds its patterns' value columns (contiguous, so the loop runs over
/// samples in vector registers) and the group keeps the largest sum per sample. Fast
/// Downward instead sums each clique per candidate and sample.
fn count_by_reduced_cliques(c: Counting<'_>, improved: &mut [u64]) {
    let (on, samples) = (c.on, c.on.sample_h.len());
    let by_group = by_group(c.keys, c.chosen, on.non_additive.len());
    let mut excluded = vec![false; on.patterns];
    let mut reduced_seen: FxHashSet<Vec<u32>> = FxHashSet::default();
    let mut best = vec![0u64; samples];
    let mut sum = vec![0u64; samples];
    for (group, members) in on.non_additive.iter().zip(&by_group) {
        if members.is_empty() {
            continue;
        }
        excluded.fill(false);
        for &p in group {
            excluded[p as usize] = true;
        }
        reduced_seen.clear();
        best.fill(0);
        for clique in on.cliques {
            let reduced: Vec<u32> = clique
                .iter()
                .copied()
                .filter(|&m| !excluded[m as usize])
                .collect();
            if reduced.is_empty() || reduced_seen.contains(&reduced) {
                continue;
            }
            sum.fill(0);
            for &m in &reduced {
                let column = &on.values[m as usize * samples..(m as usize + 1) * samples];
                for (acc, &v) in sum.iter_mut().zip(column) {
                    *acc += u64::from(v);
                }
            }
            for (b, &acc) in best.iter_mut().zip(&sum) {
                *b = (*b).max(acc);
            }
            reduced_seen.insert(reduced);
        }
        for &i in members {
            let row = &c.candidate_h[i * samples..(i + 1) * samples];
            improved[i] = row
                .iter()
                .zip(on.sample_h)
                .zip(&best)
                .filter(|((&h, current), &best)| {
                    h == DEAD || current.is_some_and(|current| u64::from(h) + best > current)
                })
                .count() as u64;
        }
    }
}

/// [`count_improvements`] for groups whose candidates need the collection's part on few
/// samples, with its arguments laid out as there.
///
/// A candidate with value `h` improves `s` if `h` is a dead end, or if some clique `C`
/// has `sum(C) - sum(C ∩ N) > h(s) - h`. Per sample the cliques are ordered by
/// decreasing sum lazily (a binary heap, popped only as far as some query needs), and
/// each group of candidates with the same `N` keeps how far it has scanned that order
/// and the best difference found: a query answers from that state or scans on, stopping
/// at a clique whose sum is no larger than the threshold or than the best found. Most
/// queries look at a few cliques. A candidate with value 0 never improves a sample
/// (the difference is at most `h(s)`).
fn count_by_sorted_cliques(of: Counting<'_>, improved: &mut [u64]) {
    let (on, samples) = (of.on, of.on.sample_h.len());
    let words = on.patterns.div_ceil(64).max(1);
    let mut members = vec![0u64; on.cliques.len() * words];
    for (c, clique) in on.cliques.iter().enumerate() {
        for &m in clique {
            members[c * words + m as usize / 64] |= 1 << (m % 64);
        }
    }
    let mut excluded_sets = vec![0u64; on.non_additive.len() * words];
    for (k, others) in on.non_additive.iter().enumerate() {
        for &p in others {
            excluded_sets[k * words + p as usize / 64] |= 1 << (p % 64);
        }
    }
    let mut column = vec![0u64; on.patterns];
    let mut heap_storage: Vec<(u64, std::cmp::Reverse<u32>)> = Vec::with_capacity(on.cliques.len());
    let mut prefix: Vec<(u64, u32)> = Vec::with_capacity(on.cliques.len());
    // Per group: cliques of the prefix scanned, best difference found.
    let mut scan: Vec<(u32, u64)> = vec![(0, 0); on.non_additive.len()];
    for (s, current) in on.sample_h.iter().enumerate() {
        let current = *current;
        for (p, value) in column.iter_mut().enumerate() {
            *value = u64::from(on.values[p * samples + s]);
        }
        heap_storage.clear();
        heap_storage.extend(on.cliques.iter().enumerate().map(|(c, clique)| {
            let sum: u64 = clique.iter().map(|&m| column[m as usize]).sum();
            (sum, std::cmp::Reverse(c as u32))
        }));
        let mut heap = std::collections::BinaryHeap::from(std::mem::take(&mut heap_storage));
        prefix.clear();
        scan.fill((0, 0));
        for &i in of.chosen {
            let (k, h) = (of.keys[i], of.candidate_h[i * samples + s]);
            let better = match current {
                _ if h == DEAD => true,
                None => false,
                Some(_) if h == 0 => false,
                Some(current) if u64::from(h) > current => true,
                Some(current) => {
                    let threshold = current - u64::from(h);
                    let others = &excluded_sets[k * words..(k + 1) * words];
                    let (pos, best) = &mut scan[k];
                    loop {
                        if *best > threshold {
                            break true;
                        }
                        if *pos as usize == prefix.len() {
                            match heap.pop() {
                                Some((sum, std::cmp::Reverse(c))) => prefix.push((sum, c)),
                                None => break false,
                            }
                        }
                        let (sum, c) = prefix[*pos as usize];
                        if sum <= threshold || sum <= *best {
                            break false; // No later clique has a larger sum.
                        }
                        *pos += 1;
                        let row = &members[c as usize * words..(c as usize + 1) * words];
                        let mut excluded = 0u64;
                        for (w, (&a, &b)) in row.iter().zip(others).enumerate() {
                            let mut common = a & b;
                            while common != 0 {
                                excluded += column[w * 64 + common.trailing_zeros() as usize];
                                common &= common - 1;
                            }
                        }
                        *best = (*best).max(sum - excluded);
                    }
                }
            };
            improved[i] += u64::from(better);
        }
        heap_storage = heap.into_vec();
    }
}

/// A state under a random walk and its applicable operators in Fast Downward's order,
/// kept one of two ways, whichever the task makes cheaper; both take the same walks.
/// An [`IncrementalWalker`] pays, per move, for the operators with a precondition on a
/// changed value (thousands per fact in big scanalyzer tasks, where it spent 3.2 s of a
/// 3.7 s climb against 0.07 s for the other); a [`GeneratedWalker`] pays for the
/// successor generator's nodes on the way to them (many with many binary variables, as
/// in sokoban, where it is 8 times slower). The choice compares the two costs along a
/// short probe walk from the initial state. Each walker is much faster somewhere (airport:
/// incremental 7x; scanalyzer p27: generated 13x), measured in `bench/README.md`.
#[derive(Debug)]
enum Walker {
    Incremental(IncrementalWalker),
    Generated(GeneratedWalker),
}

impl Walker {
    fn new(task: &Task) -> Walker {
        // A probe walk of fixed pseudo-random moves (not drawn from the climb's generator,
        // whose draws must stay Fast Downward's) measures both costs on the states a walk
        // meets; the initial state alone can mislead (parcprinter).
        const PROBE_MOVES: usize = 256;
        let mut incremental = IncrementalWalker::new(task);
        let generated = GeneratedWalker::new(task);
        let (mut visited, mut touched) = (0u64, 0u64);
        let mut pick = 0x2545_f491u32;
        for _ in 0..PROBE_MOVES {
            visited += generated.generator.visited_nodes(incremental.state()) as u64;
            let applicable = incremental.applicable();
            if applicable.is_empty() {
                break;
            }
            pick = pick.wrapping_mul(1_664_525).wrapping_add(1_013_904_223);
            let op = applicable[(pick >> 8) as usize % applicable.len()];
            touched += incremental.touched_by(op);
            incremental.apply(op);
        }
        if visited < touched {
            Walker::Generated(generated)
        } else {
            incremental.set_state(&task.initial_state);
            Walker::Incremental(incremental)
        }
    }

    fn set_state(&mut self, state: &[u32]) {
        match self {
            Walker::Incremental(w) => w.set_state(state),
            Walker::Generated(w) => w.set_state(state),
        }
    }

    fn apply(&mut self, op: OpId) {
        match self {
            Walker::Incremental(w) => w.apply(op),
            Walker::Generated(w) => w.apply(op),
        }
    }

    fn applicable(&self) -> &[OpId] {
        match self {
            Walker::Incremental(w) => w.applicable(),
            Walker::Generated(w) => w.applicable(),
        }
    }

    fn kth_in_fast_downward_order(&mut self, k: usize) -> OpId {
        match self {
            Walker::Incremental(w) => w.kth_in_fast_downward_order(k),
            Walker::Generated(w) => w.kth_in_fast_downward_order(k),
        }
    }

    fn state(&self) -> &[u32] {
        match self {
            Walker::Incremental(w) => w.state(),
            Walker::Generated(w) => w.state(),
        }
    }
}

/// A state under a random walk, with its applicable operators kept up to date: each
/// operator's count of unsatisfied preconditions, and the set of operators with none.
/// Changing a variable costs O(operators with a precondition on its old or new value),
/// instead of a successor-generator traversal per step.
#[derive(Debug)]
struct IncrementalWalker {
    fact_offset: Vec<u32>,
    /// Operators with fact `f` as a precondition: `pre_of[pre_of_start[f]..pre_of_start[f + 1]]`.
    pre_of_start: Vec<u32>,
    pre_of: Vec<u32>,
    /// Effects of operator `o`: `effects[effect_start[o]..effect_start[o + 1]]`.
    effect_start: Vec<u32>,
    effects: Vec<(u32, u32)>,
    unsatisfied: Vec<u32>,
    /// The applicable operators, and each operator's place among them (`u32::MAX`: none).
    applicable: Vec<OpId>,
    place: Vec<u32>,
    state: Vec<u32>,
    /// Each operator's place in the order of Fast Downward's successor generator.
    fd_rank: Vec<u32>,
    /// Scratch space for choosing among the applicable operators.
    chooser: Vec<OpId>,
}

impl IncrementalWalker {
    /// A walker standing in the initial state of `task` (valid).
    fn new(task: &Task) -> IncrementalWalker {
        let (fact_offset, facts) = crate::heuristic::fact_offsets(task);
        let mut pairs: Vec<(u32, u32)> = Vec::new();
        let mut effect_start = vec![0u32];
        let mut effects = Vec::new();
        for (o, op) in task.operators.iter().enumerate() {
            for f in &op.preconditions {
                pairs.push((fact_offset[f.var.index()] + f.value, o as u32));
            }
            effects.extend(op.effects.iter().map(|f| (f.var.0, f.value)));
            effect_start.push(effects.len() as u32);
        }
        pairs.sort_unstable();
        let mut pre_of_start = vec![0u32; facts as usize + 1];
        for &(f, _) in &pairs {
            pre_of_start[f as usize + 1] += 1;
        }
        for f in 0..facts as usize {
            pre_of_start[f + 1] += pre_of_start[f];
        }
        let unsatisfied: Vec<u32> = task
            .operators
            .iter()
            .map(|op| op.preconditions.len() as u32)
            .collect();
        // Fast Downward's successor generator yields the applicable operators in the
        // order of their sorted preconditions (lexicographically), ties by index.
        let mut by_preconditions: Vec<(Vec<(u32, u32)>, u32)> = task
            .operators
            .iter()
            .enumerate()
            .map(|(o, op)| {
                let mut pre: Vec<(u32, u32)> = op
                    .preconditions
                    .iter()
                    .map(|f| (f.var.0, f.value))
                    .collect();
                pre.sort_unstable();
                (pre, o as u32)
            })
            .collect();
        by_preconditions.sort_unstable();
        let mut fd_rank = vec![0u32; task.operators.len()];
        for (rank, (_, o)) in by_preconditions.iter().enumerate() {
            fd_rank[*o as usize] = rank as u32;
        }
        let mut walker = IncrementalWalker {
            fd_rank,
            chooser: Vec::new(),
            fact_offset,
            pre_of_start,
            pre_of: pairs.into_iter().map(|(_, o)| o).collect(),
            effect_start,
            effects,
            place: vec![u32::MAX; unsatisfied.len()],
            unsatisfied,
            applicable: Vec::new(),
            state: vec![0; task.variables.len()],
        };
        for o in 0..walker.unsatisfied.len() {
            if walker.unsatisfied[o] == 0 {
                walker.add(o as u32);
            }
        }
        // Every variable starts at value 0; the counts then follow set_state.
        for (var, _) in task.variables.iter().enumerate() {
            let fact = walker.fact_offset[var] as usize;
            for i in walker.pre_of_start[fact]..walker.pre_of_start[fact + 1] {
                let o = walker.pre_of[i as usize];
                walker.unsatisfied[o as usize] -= 1;
                if walker.unsatisfied[o as usize] == 0 {
                    walker.add(o);
                }
            }
        }
        walker.set_state(&task.initial_state);
        walker
    }

    fn add(&mut self, o: u32) {
        self.place[o as usize] = self.applicable.len() as u32;
        self.applicable.push(OpId(o));
    }

    fn remove(&mut self, o: u32) {
        let at = self.place[o as usize] as usize;
        self.applicable.swap_remove(at);
        if let Some(moved) = self.applicable.get(at) {
            self.place[moved.index()] = at as u32;
        }
        self.place[o as usize] = u32::MAX;
    }

    fn set(&mut self, var: usize, value: u32) {
        let old = self.state[var];
        if old == value {
            return;
        }
        let fact = (self.fact_offset[var] + old) as usize;
        for i in self.pre_of_start[fact]..self.pre_of_start[fact + 1] {
            let o = self.pre_of[i as usize];
            if self.unsatisfied[o as usize] == 0 {
                self.remove(o);
            }
            self.unsatisfied[o as usize] += 1;
        }
        let fact = (self.fact_offset[var] + value) as usize;
        for i in self.pre_of_start[fact]..self.pre_of_start[fact + 1] {
            let o = self.pre_of[i as usize];
            self.unsatisfied[o as usize] -= 1;
            if self.unsatisfied[o as usize] == 0 {
                self.add(o);
            }
        }
        self.state[var] = value;
    }

    /// Moves to `state`, changing only the variables that differ.
    fn set_state(&mut self, state: &[u32]) {
        for (var, &value) in state.iter().enumerate() {
            self.set(var, value);
        }
    }

    /// Applies operator `op`, which must be applicable.
    fn apply(&mut self, op: OpId) {
        let range =
            self.effect_start[op.index()] as usize..self.effect_start[op.index() + 1] as usize;
        for i in range {
            let (var, value) = self.effects[i];
            self.set(var as usize, value);
        }
    }

    /// The applicable operators, in an order fixed by the walk so far.
    fn applicable(&self) -> &[OpId] {
        &self.applicable
    }

    /// The operators applying `op` touches: those with a precondition on a value it
    /// changes, old or new.
    fn touched_by(&self, op: OpId) -> u64 {
        let uses = |var: u32, value: u32| {
            let fact = (self.fact_offset[var as usize] + value) as usize;
            u64::from(self.pre_of_start[fact + 1] - self.pre_of_start[fact])
        };
        let range =
            self.effect_start[op.index()] as usize..self.effect_start[op.index() + 1] as usize;
        self.effects[range]
            .iter()
            .filter(|&&(var, value)| self.state[var as usize] != value)
            .map(|&(var, value)| uses(var, self.state[var as usize]) + uses(var, value))
            .sum()
    }

    /// The `k`-th applicable operator (from 0) in the order of Fast Downward's successor
    /// generator; O(applicable operators).
    fn kth_in_fast_downward_order(&mut self, k: usize) -> OpId {
        self.chooser.clear();
        self.chooser.extend_from_slice(&self.applicable);
        let rank = &self.fd_rank;
        *self
            .chooser
            .select_nth_unstable_by_key(k, |o| rank[o.index()])
            .1
    }

    fn state(&self) -> &[u32] {
        &self.state
    }
}

/// A state under a random walk and its applicable operators, listed by the successor
/// generator after every move. The generator lists them in Fast Downward's order (its
/// successor generator's: operators sorted by their sorted preconditions, then index),
/// which the walk's draws index into.
#[derive(Debug)]
struct GeneratedWalker {
    generator: SuccessorGenerator,
    /// Effects of operator `o`: `effects[effect_start[o]..effect_start[o + 1]]`.
    effect_start: Vec<u32>,
    effects: Vec<(u32, u32)>,
    state: Vec<u32>,
    /// The operators applicable in `state`, in Fast Downward's order.
    applicable: Vec<OpId>,
}

impl GeneratedWalker {
    /// A walker standing in the initial state of `task` (valid).
    fn new(task: &Task) -> GeneratedWalker {
        let mut effect_start = vec![0u32];
        let mut effects = Vec::new();
        for op in &task.operators {
            effects.extend(op.effects.iter().map(|f| (f.var.0, f.value)));
            effect_start.push(effects.len() as u32);
        }
        let mut walker = GeneratedWalker {
            generator: SuccessorGenerator::new(task),
            effect_start,
            effects,
            state: task.initial_state.clone(),
            applicable: Vec::new(),
        };
        walker.refresh();
        walker
    }

    fn refresh(&mut self) {
        self.generator.applicable(&self.state, &mut self.applicable);
    }

    /// Moves to `state`.
    fn set_state(&mut self, state: &[u32]) {
        self.state.copy_from_slice(state);
        self.refresh();
    }

    /// Applies operator `op`, which must be applicable.
    fn apply(&mut self, op: OpId) {
        let range =
            self.effect_start[op.index()] as usize..self.effect_start[op.index() + 1] as usize;
        for &(var, value) in &self.effects[range] {
            self.state[var as usize] = value;
        }
        self.refresh();
    }

    /// The applicable operators, in Fast Downward's order.
    fn applicable(&self) -> &[OpId] {
        &self.applicable
    }

    /// The `k`-th applicable operator (from 0) in the order of Fast Downward's successor
    /// generator.
    fn kth_in_fast_downward_order(&self, k: usize) -> OpId {
        self.applicable[k]
    }

    fn state(&self) -> &[u32] {
        &self.state
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::successor::tests::{random_task, Rng as TestRng};
    use crate::test_tasks::op;
    use task::{Fact, Variable};

    /// Goal a = 1, reached by `set-a`, which needs b = 1, which costs 5 to set: the goal
    /// pattern alone sees 1, with b added 6.
    #[test]
    fn the_climb_adds_a_precondition_variable() {
        let task = Task {
            variables: vec![
                Variable::binary("a"),
                Variable::binary("b"),
                Variable::binary("c"),
            ],
            mutexes: vec![],
            initial_state: vec![0, 0, 0],
            goal: vec![Fact::new(VarId(0), 1)],
            operators: vec![
                op("set-b", &[(1, 0)], &[(1, 1)], 5),
                op("set-a", &[(0, 0), (1, 1)], &[(0, 1)], 1),
                op("set-c", &[], &[(2, 1)], 1),
            ],
            use_costs: true,
        };
        let config = IpdbConfig {
            min_improvement: 1,
            ..IpdbConfig::default()
        };
        let mut h = ipdb(&task, &config, &SearchLimits::default()).unwrap();
        use crate::heuristic::Heuristic;
        assert_eq!(h.name(), "ipdb");
        assert_eq!(h.evaluate(&[0, 0, 0]), Some(6));
        assert_eq!(h.evaluate(&[0, 1, 0]), Some(1));
        assert_eq!(h.evaluate(&[1, 0, 1]), Some(0));
        let s = h.statistics();
        let climb = s.hill_climbing.clone().unwrap();
        // {a} and its one candidate {a, b}, which improves every sample and is added;
        // then there are no candidates left. c is no neighbour of a.
        assert_eq!(climb.generated_patterns, 1);
        assert_eq!(climb.iterations, 2);
        assert_eq!(climb.end, ClimbEnd::Converged);
        assert_eq!(climb.patterns, 2);
        assert_eq!(climb.total_size, 6);
        assert_eq!(climb.max_pdb_size, 4);
        // Dominance pruning keeps only {a, b}.
        let patterns: Vec<&[VarId]> = h.pdbs().iter().map(|p| p.pattern()).collect();
        assert_eq!(patterns, [&[VarId(0), VarId(1)][..]]);
        assert_eq!((s.patterns, s.pruned_patterns, s.pruned_cliques), (1, 1, 1));

        // Under a memory limit that {a}'s table (14 bytes) fits but building {a, b}
        // (4 states: 80 bytes by `construction_bytes`) does not, the candidate is
        // rejected unbuilt, the climb ends, and the heuristic is {a}'s.
        assert_eq!(construction_bytes([4]), 80);
        let fitting = SearchLimits {
            memory_limit_bytes: Some(50),
            ..SearchLimits::default()
        };
        let mut h = ipdb(&task, &config, &fitting).unwrap();
        assert_eq!(h.evaluate(&[0, 0, 0]), Some(1));
        let climb = h.statistics().hill_climbing.clone().unwrap();
        assert_eq!(
            (climb.end, climb.patterns, climb.dropped_patterns),
            (ClimbEnd::MemoryLimit, 1, 1)
        );
        assert_eq!(climb.total_size, 2, "no candidate was built");

        // Without room for {a, b}, the candidate is rejected.
        let config = IpdbConfig {
            min_improvement: 1,
            collection_max_size: 5,
            ..IpdbConfig::default()
        };
        let mut h = ipdb(&task, &config, &SearchLimits::default()).unwrap();
        assert_eq!(h.evaluate(&[0, 0, 0]), Some(1));
        let climb = h.statistics().hill_climbing.clone().unwrap();
        assert_eq!((climb.dropped_patterns, climb.patterns), (1, 1));
        // Nor is it generated when too large (then it counts as rejected, as in Fast
        // Downward), and a zero time limit stops at once.
        for (config, rejected) in [
            (
                IpdbConfig {
                    pdb_max_size: 3,
                    ..IpdbConfig::default()
                },
                1,
            ),
            (
                IpdbConfig {
                    max_time: Some(Duration::ZERO),
                    ..IpdbConfig::default()
                },
                0,
            ),
            (
                IpdbConfig {
                    max_generated_patterns: Some(0),
                    ..IpdbConfig::default()
                },
                0,
            ),
        ] {
            let h = ipdb(&task, &config, &SearchLimits::default()).unwrap();
            let climb = h.statistics().hill_climbing.clone().unwrap();
            assert_eq!(
                (
                    climb.generated_patterns,
                    climb.rejected_patterns,
                    climb.patterns
                ),
                (0, rejected, 1)
            );
        }
        // The caller's limits stop it too.
        let past = SearchLimits {
            deadline: Some(Instant::now()),
            ..SearchLimits::default()
        };
        let tight = SearchLimits {
            memory_limit_bytes: Some(1),
            ..SearchLimits::default()
        };
        for (limits, end) in [(past, ClimbEnd::TimeLimit), (tight, ClimbEnd::MemoryLimit)] {
            let h = ipdb(&task, &IpdbConfig::default(), &limits).unwrap();
            let climb = h.statistics().hill_climbing.clone().unwrap();
            assert_eq!(
                (climb.end, climb.generated_patterns, climb.patterns),
                (end, 0, 1)
            );
        }
        // What the CLI prints.
        let config = IpdbConfig {
            min_improvement: 1,
            ..IpdbConfig::default()
        };
        let shown = ipdb(&task, &config, &SearchLimits::default()).unwrap();
        let text = shown.statistics().to_string();
        assert!(
            text.starts_with(
                "found a better pattern with improvement 1000\n\
                 Hill climbing iterations: 2\nHill climbing generated patterns: 1\n"
            ),
            "{text}"
        );
        assert!(
            text.contains("\nHill climbing ended: converged\n"),
            "{text}"
        );
        assert!(
            text.contains("\nPruned 1 of 2 pattern cliques\nPruned 1 of 2 PDBs\n"),
            "{text}"
        );
        assert!(
            text.contains("\nCanonical PDB heuristic number of patterns: 1\n"),
            "{text}"
        );
        assert!(!text.ends_with('\n'));
        // A dead initial state ends the climb.
        let mut dead = task.clone();
        dead.operators.remove(0);
        let h = ipdb(&dead, &IpdbConfig::default(), &SearchLimits::default()).unwrap();
        let climb = h.statistics().hill_climbing.clone().unwrap();
        assert_eq!(climb.end, ClimbEnd::InitialDeadEnd);
    }

    #[test]
    fn the_climb_leaves_half_the_time_to_the_search_unless_told_otherwise() {
        let start = Instant::now();
        let s = |secs| Duration::from_secs(secs);
        let at = |secs| Some(start + s(secs));
        assert_eq!(climb_deadline(start, None, None), None);
        assert_eq!(climb_deadline(start, None, at(10)), at(5));
        assert_eq!(climb_deadline(start, Some(s(3)), None), at(3));
        assert_eq!(climb_deadline(start, Some(s(3)), at(10)), at(3));
        assert_eq!(climb_deadline(start, Some(s(20)), at(10)), at(10));
        // A deadline already past stays the deadline: the climb stops at once.
        let past = start.checked_sub(s(1));
        if past.is_some() {
            assert_eq!(climb_deadline(start, None, past), past);
        }
    }

    /// On a long line the walks are long (the binomial has 4 * 199,999 trials), so one
    /// iteration's 1,000 samples take many seconds; the climb must still stop at
    /// `max_time`, checked after every sample. (The initial databases take about half a
    /// second alone; 3 s leaves room for them on a loaded machine, where 1 s did not.)
    #[test]
    fn sampling_stops_at_the_deadline() {
        let task = crate::astar::tests::line(200_000);
        let config = IpdbConfig {
            max_time: Some(Duration::from_secs(3)),
            ..IpdbConfig::default()
        };
        let start = Instant::now();
        let h = ipdb(&task, &config, &SearchLimits::default()).unwrap();
        let climb = h.statistics().hill_climbing.clone().unwrap();
        // The deadline passed while sampling, not before.
        assert_eq!((climb.end, climb.iterations), (ClimbEnd::TimeLimit, 1));
        assert!(
            start.elapsed() < Duration::from_secs(7),
            "{:?}",
            start.elapsed()
        );
    }

    /// `count_improvements` against its definition, on random cliques and values.
    #[test]
    fn improvement_counts_match_their_definition() {
        let mut rng = TestRng(3);
        for round in 0..400 {
            let patterns = 1 + rng.below(70) as usize;
            let samples = 1 + rng.below(20) as usize;
            let cliques: Vec<Vec<u32>> = (0..1 + rng.below(12))
                .map(|_| (0..patterns as u32).filter(|_| rng.below(3) == 0).collect())
                .collect();
            let small = round % 3 == 0;
            let value = |rng: &mut TestRng| if small { rng.below(4) } else { rng.below(1000) };
            let values: Vec<u32> = (0..patterns * samples).map(|_| value(&mut rng)).collect();
            let sample_h: Vec<Option<u64>> = (0..samples)
                .map(|s| {
                    let h = cliques
                        .iter()
                        .map(|c| {
                            c.iter()
                                .map(|&m| u64::from(values[m as usize * samples + s]))
                                .sum()
                        })
                        .max()
                        .unwrap_or(0);
                    (rng.below(10) > 0).then_some(h)
                })
                .collect();
            let groups: Vec<Vec<u32>> = (0..1 + rng.below(4))
                .map(|_| (0..patterns as u32).filter(|_| rng.below(4) == 0).collect())
                .collect();
            let candidates = 1 + rng.below(10) as usize;
            let keys: Vec<usize> = (0..candidates)
                .map(|_| rng.below(groups.len() as u32) as usize)
                .collect();
            let candidate_h: Vec<u32> = (0..candidates * samples)
                .map(|_| {
                    if rng.below(20) == 0 {
                        DEAD
                    } else {
                        value(&mut rng) * 2
                    }
                })
                .collect();
            // The dispatcher and both ways of counting, each on every candidate.
            let collection = CollectionOnSamples {
                cliques: &cliques,
                values: &values,
                sample_h: &sample_h,
                patterns,
                non_additive: &groups,
            };
            let all: Vec<usize> = (0..candidates).collect();
            let mut counts = vec![count_improvements(&collection, &keys, &candidate_h)];
            for count in [count_by_reduced_cliques as CountFn, count_by_sorted_cliques] {
                let mut improved = vec![0u64; candidates];
                let counting = Counting {
                    on: &collection,
                    keys: &keys,
                    candidate_h: &candidate_h,
                    chosen: &all,
                };
                count(counting, &mut improved);
                counts.push(improved);
            }
            for (i, &k) in keys.iter().enumerate() {
                let expected: u64 = (0..samples)
                    .filter(|&s| {
                        let h = candidate_h[i * samples + s];
                        let best = cliques
                            .iter()
                            .map(|c| {
                                c.iter()
                                    .filter(|m| !groups[k].contains(m))
                                    .map(|&m| u64::from(values[m as usize * samples + s]))
                                    .sum::<u64>()
                            })
                            .max()
                            .unwrap_or(0);
                        h == DEAD
                            || sample_h[s].is_some_and(|current| u64::from(h) + best > current)
                    })
                    .count() as u64;
                for (way, got) in counts.iter().enumerate() {
                    assert_eq!(got[i], expected, "round {round} candidate {i} way {way}");
                }
            }
        }
    }

    #[test]
    fn the_walker_tracks_applicable_operators() {
        let mut rng = TestRng(11);
        for round in 0..100 {
            let task = random_task(&mut rng, 1 + round % 9, 3 + round * 2 % 40);
            // Both kinds, whichever the probe would choose.
            for mut walker in [
                Walker::Incremental(IncrementalWalker::new(&task)),
                Walker::Generated(GeneratedWalker::new(&task)),
            ] {
                for step in 0..60 {
                    let state = walker.state().to_vec();
                    let mut got: Vec<OpId> = walker.applicable().to_vec();
                    got.sort();
                    let expected: Vec<OpId> = (0..task.operators.len())
                        .filter(|&o| task.is_applicable(&task.operators[o], &state))
                        .map(|o| OpId(o as u32))
                        .collect();
                    assert_eq!(got, expected, "round {round} step {step}");
                    // Fast Downward's successor generator order: sorted preconditions, then
                    // index.
                    let key = |o: &OpId| {
                        let mut pre: Vec<(u32, u32)> = task.operators[o.index()]
                            .preconditions
                            .iter()
                            .map(|f| (f.var.0, f.value))
                            .collect();
                        pre.sort_unstable();
                        (pre, o.0)
                    };
                    let mut in_fd_order = expected.clone();
                    in_fd_order.sort_by_key(key);
                    for (k, &op) in in_fd_order.iter().enumerate() {
                        assert_eq!(walker.kth_in_fast_downward_order(k), op, "round {round}");
                    }
                    if step % 13 == 12 || got.is_empty() {
                        let target: Vec<u32> = task
                            .variables
                            .iter()
                            .map(|v| rng.below(v.domain_size()))
                            .collect();
                        walker.set_state(&target);
                        assert_eq!(walker.state(), target.as_slice());
                    } else {
                        let op = got[rng.below(got.len() as u32) as usize];
                        walker.apply(op);
                        let mut next = state.clone();
                        for f in &task.operators[op.index()].effects {
                            next[f.var.index()] = f.value;
                        }
                        assert_eq!(walker.state(), next.as_slice());
                    }
                }
            }
        }
    }
}
