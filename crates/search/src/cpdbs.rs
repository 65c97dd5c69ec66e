//! The canonical heuristic over a collection of pattern databases (Haslum, Botea,
//! Helmert, Bonet and Koenig, AAAI 2007).
//!
//! Two patterns are *additive* if no operator has effects on variables of both: then
//! every operator's cost is counted by at most one of their projections, and the sum of
//! their values is admissible. The canonical heuristic is the maximum, over the maximal
//! cliques of the compatibility graph (patterns as vertices, edges between additive
//! patterns), of the sum of the clique's values; a dead end in any database makes the
//! state a dead end. Cliques are found once per collection (Bron and Kerbosch with
//! Tomita's pivot, on bit sets), and optionally pruned by dominance (Pommerening, Röger
//! and Helmert, IJCAI 2013): a clique is dropped if every one of its patterns is a subset
//! of a pattern of another clique, and databases left in no clique are dropped.

use std::time::{Duration, Instant};

use task::{Deadline, Task, VarId};

use crate::heuristic::Heuristic;
use crate::pdb::PatternDatabase;

const DEAD: u32 = u32::MAX;

/// Answers "are these two patterns additive?" for one task.
#[derive(Debug, Clone)]
pub(crate) struct Additivity {
    /// For each variable, the variables that some operator has effects on together with
    /// it, itself included if any operator affects it: `together[start[v]..start[v + 1]]`,
    /// sorted.
    start: Vec<u32>,
    together: Vec<u32>,
}

impl Additivity {
    /// O(sum over operators of effects squared).
    pub(crate) fn new(task: &Task) -> Additivity {
        let n = task.variables.len();
        let mut lists: Vec<Vec<u32>> = vec![Vec::new(); n];
        for op in &task.operators {
            for a in &op.effects {
                lists[a.var.index()].extend(op.effects.iter().map(|b| b.var.0));
            }
        }
        let mut start = Vec::with_capacity(n + 1);
        let mut together = Vec::new();
        start.push(0);
        for mut list in lists {
            list.sort_unstable();
            list.dedup();
            together.extend_from_slice(&list);
            start.push(together.len() as u32);
        }
        Additivity { start, together }
    }

    /// True if no operator has effects on a variable of `a` and one of `b` (both sorted).
    /// O(|a| * affected-together list * log |b|).
    pub(crate) fn additive(&self, a: &[VarId], b: &[VarId]) -> bool {
        a.iter().all(|v| {
            let list =
                &self.together[self.start[v.index()] as usize..self.start[v.index() + 1] as usize];
            list.iter().all(|&w| b.binary_search(&VarId(w)).is_err())
        })
    }
}

/// The maximal cliques of the graph on `0..n` whose adjacency rows are the bit sets
/// `adjacent[v]` (`n` bits each, symmetric, no loops), each sorted, in a deterministic
/// order. Bron–Kerbosch with Tomita's pivot: O(3^(n/3)) in the worst case, fast on the
/// sparse or nearly complete graphs pattern collections give. Stops at `deadline`,
/// keeping the cliques found so far (each maximal).
pub(crate) fn maximal_cliques(
    n: usize,
    adjacent: &[Vec<u64>],
    deadline: Deadline,
) -> Vec<Vec<u32>> {
    let words = n.div_ceil(64);
    let mut candidates = vec![0u64; words];
    for v in 0..n {
        candidates[v / 64] |= 1 << (v % 64);
    }
    let mut out = Vec::new();
    let mut clique = Vec::new();
    let mut clock = Clock { deadline, calls: 0 };
    expand(
        adjacent,
        &mut clique,
        candidates,
        vec![0u64; words],
        &mut out,
        &mut clock,
    );
    out
}

/// The deadline (and cancel flag) of a clique enumeration, read every 256 calls (a call
/// is cheap; reading the clock on each would be a large part of it).
struct Clock {
    deadline: Deadline,
    calls: u32,
}

impl Clock {
    fn passed(&mut self) -> bool {
        self.calls = self.calls.wrapping_add(1);
        self.calls.is_multiple_of(256) && self.deadline.passed()
    }
}

fn bits(set: &[u64]) -> impl Iterator<Item = usize> + '_ {
    set.iter().enumerate().flat_map(|(w, &word)| {
        let mut rest = word;
        std::iter::from_fn(move || {
            if rest == 0 {
                return None;
            }
            let bit = rest.trailing_zeros() as usize;
            rest &= rest - 1;
            Some(w * 64 + bit)
        })
    })
}

fn count_common(a: &[u64], b: &[u64]) -> u32 {
    a.iter().zip(b).map(|(x, y)| (x & y).count_ones()).sum()
}

/// One level of Bron–Kerbosch: `clique` is R, `candidates` P, `excluded` X. The depth
/// is at most the size of a clique. Returns false once the clock's deadline has passed,
/// so that every level returns at once.
fn expand(
    adjacent: &[Vec<u64>],
    clique: &mut Vec<u32>,
    mut candidates: Vec<u64>,
    mut excluded: Vec<u64>,
    out: &mut Vec<Vec<u32>>,
    clock: &mut Clock,
) -> bool {
    if clock.passed() {
        return false;
    }
    if candidates.iter().all(|&w| w == 0) {
        if excluded.iter().all(|&w| w == 0) {
            let mut c = clique.clone();
            c.sort_unstable();
            out.push(c);
        }
        return true;
    }
    // Pivot: the vertex of P or X with the most neighbours in P.
    let pivot = bits(&candidates)
        .chain(bits(&excluded))
        .max_by_key(|&u| {
            (
                count_common(&adjacent[u], &candidates),
                std::cmp::Reverse(u),
            )
        })
        .unwrap_or(0);
    let branch: Vec<usize> = bits(&candidates)
        .filter(|&v| adjacent[pivot][v / 64] >> (v % 64) & 1 == 0)
        .collect();
    for v in branch {
        let row = &adjacent[v];
        let p: Vec<u64> = candidates.iter().zip(row).map(|(a, b)| a & b).collect();
        let x: Vec<u64> = excluded.iter().zip(row).map(|(a, b)| a & b).collect();
        clique.push(v as u32);
        let go_on = expand(adjacent, clique, p, x, out, clock);
        clique.pop();
        if !go_on {
            return false;
        }
        candidates[v / 64] &= !(1 << (v % 64));
        excluded[v / 64] |= 1 << (v % 64);
    }
    true
}

/// The maximal additive subsets of `patterns`: the maximal cliques of their
/// compatibility graph, as far as they are found by `deadline`.
pub(crate) fn additive_cliques(
    additivity: &Additivity,
    patterns: &[&[VarId]],
    deadline: Deadline,
) -> Vec<Vec<u32>> {
    let n = patterns.len();
    let words = n.div_ceil(64);
    let mut adjacent = vec![vec![0u64; words]; n];
    for a in 0..n {
        for b in a + 1..n {
            if additivity.additive(patterns[a], patterns[b]) {
                adjacent[a][b / 64] |= 1 << (b % 64);
                adjacent[b][a / 64] |= 1 << (a % 64);
            }
        }
    }
    maximal_cliques(n, &adjacent, deadline)
}

/// The *interesting* patterns (Pommerening, Röger and Helmert, IJCAI 2013) of at most
/// `max_size` variables, for `max_size` 1 or 2 (larger sizes are treated as 2), as Fast
/// Downward's `systematic` builds them from a goal variable and its causal-graph
/// predecessors. Of one variable: the goal variables. Of two: a goal variable with a
/// precondition-to-effect predecessor (an operator has a precondition on it and an effect
/// on the goal variable) or an effect-to-effect neighbour (an operator has effects on
/// both). Singletons first, then pairs, each sorted. O(task size + pairs).
pub(crate) fn systematic_patterns(task: &Task, max_size: usize) -> Vec<Vec<u32>> {
    let n = task.variables.len();
    let mut is_goal = vec![false; n];
    for f in &task.goal {
        is_goal[f.var.index()] = true;
    }
    let mut out: Vec<Vec<u32>> = (0..n as u32)
        .filter(|&v| is_goal[v as usize])
        .map(|v| vec![v])
        .collect();
    if max_size < 2 {
        return out;
    }
    let mut pairs: Vec<(u32, u32)> = Vec::new();
    for op in &task.operators {
        for e in &op.effects {
            if !is_goal[e.var.index()] {
                continue;
            }
            // Precondition-to-effect arcs into a goal variable, and effect-to-effect
            // arcs.
            for v in op.preconditions.iter().chain(&op.effects).map(|f| f.var) {
                if v != e.var {
                    pairs.push((v.0.min(e.var.0), v.0.max(e.var.0)));
                }
            }
        }
    }
    pairs.sort_unstable();
    pairs.dedup();
    out.extend(pairs.into_iter().map(|(a, b)| vec![a, b]));
    out
}

/// What building a pattern-database heuristic did, for logs.
#[derive(Debug, Clone, Default, PartialEq, Eq)]
pub struct PdbStatistics {
    /// Pattern databases of the heuristic (after dominance pruning).
    pub patterns: usize,
    /// Abstract states over all its databases.
    pub total_size: u64,
    /// Bytes of all its distance tables.
    pub memory_bytes: u64,
    /// Maximal additive subsets (cliques) it maximises over (after pruning).
    pub cliques: usize,
    /// Cliques dropped by dominance pruning.
    pub pruned_cliques: usize,
    /// Databases dropped by dominance pruning (in no remaining clique).
    pub pruned_patterns: usize,
    /// Time of the dominance pruning.
    pub dominance_pruning_time: Duration,
    /// Time to build the whole heuristic (pattern generation, databases, cliques).
    pub total_time: Duration,
    /// The hill climbing, for `ipdb()`.
    pub hill_climbing: Option<crate::ipdb::HillClimbingStatistics>,
}

impl std::fmt::Display for PdbStatistics {
    /// Log lines in Fast Downward's words (`found a better pattern with improvement 12`
    /// per pattern the climb added, `Hill climbing iterations: 7`, ...), one per line,
    /// without a final newline; the hill climbing's lines only for `ipdb`.
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        if let Some(c) = &self.hill_climbing {
            for improvement in &c.improvements {
                writeln!(f, "found a better pattern with improvement {improvement}")?;
            }
            writeln!(f, "Hill climbing iterations: {}", c.iterations)?;
            writeln!(
                f,
                "Hill climbing generated patterns: {}",
                c.generated_patterns
            )?;
            writeln!(
                f,
                "Hill climbing rejected patterns: {}",
                c.rejected_patterns
            )?;
            writeln!(
                f,
                "Hill climbing patterns dropped for lack of room: {}",
                c.dropped_patterns
            )?;
            writeln!(f, "Hill climbing maximum PDB size: {}", c.max_pdb_size)?;
            writeln!(f, "Hill climbing ended: {}", c.end)?;
            writeln!(f, "Hill climbing time: {:.6}s", c.time.as_secs_f64())?;
            writeln!(
                f,
                "Hill climbing time in PDBs: {:.6}s, sampling: {:.6}s, evaluating candidates: {:.6}s",
                c.pdb_time.as_secs_f64(),
                c.sampling_time.as_secs_f64(),
                c.evaluation_time.as_secs_f64()
            )?;
            writeln!(f, "Hill climbing number of patterns: {}", c.patterns)?;
            writeln!(f, "Hill climbing total PDB size: {}", c.total_size)?;
        }
        let cliques = self.cliques + self.pruned_cliques;
        let patterns = self.patterns + self.pruned_patterns;
        writeln!(
            f,
            "Pruned {} of {cliques} pattern cliques",
            self.pruned_cliques
        )?;
        writeln!(f, "Pruned {} of {patterns} PDBs", self.pruned_patterns)?;
        writeln!(
            f,
            "Dominance pruning took {:.6}s",
            self.dominance_pruning_time.as_secs_f64()
        )?;
        writeln!(
            f,
            "Canonical PDB heuristic number of patterns: {}",
            self.patterns
        )?;
        writeln!(
            f,
            "Canonical PDB heuristic total PDB size: {}",
            self.total_size
        )?;
        writeln!(
            f,
            "Canonical PDB heuristic memory: {} KB",
            self.memory_bytes.div_ceil(1024)
        )?;
        write!(
            f,
            "Canonical PDB heuristic computation time: {:.6}s",
            self.total_time.as_secs_f64()
        )
    }
}

/// The canonical heuristic over a collection of pattern databases; see the module
/// documentation. Admissible and consistent.
///
/// Each evaluation looks every database up once, then sums per clique: O(sum of pattern
/// sizes + sum of clique sizes), no allocation.
#[derive(Debug, Clone)]
pub struct CanonicalPdbs {
    name: &'static str,
    pdbs: Vec<PatternDatabase>,
    /// Members of clique `c`: `members[clique_start[c]..clique_start[c + 1]]`.
    clique_start: Vec<u32>,
    members: Vec<u32>,
    values: Vec<u32>,
    statistics: PdbStatistics,
}

impl CanonicalPdbs {
    /// The canonical heuristic over `pdbs` (databases of one task; duplicate patterns
    /// are dropped), named `name` in logs, with dominance pruning if
    /// `dominance_pruning` is given (its time limit; the pruning stops when it passes).
    pub fn new(
        task: &Task,
        pdbs: Vec<PatternDatabase>,
        dominance_pruning: Option<Duration>,
        name: &'static str,
    ) -> CanonicalPdbs {
        CanonicalPdbs::within(task, pdbs, dominance_pruning, name, Deadline::default())
    }

    /// Like [`new`](Self::new), but the clique enumeration and the pruning stop at
    /// `deadline` (the run's, `--overall-time-limit`), keeping the cliques found so far:
    /// any set of additive cliques gives an admissible heuristic, only a weaker one, and
    /// a run whose deadline passed stops at the search's first check anyway.
    pub fn within(
        task: &Task,
        mut pdbs: Vec<PatternDatabase>,
        dominance_pruning: Option<Duration>,
        name: &'static str,
        deadline: Deadline,
    ) -> CanonicalPdbs {
        let start = Instant::now();
        let mut seen = rustc_hash::FxHashSet::default();
        pdbs.retain(|p| seen.insert(p.pattern().to_vec()));
        let additivity = Additivity::new(task);
        let patterns: Vec<&[VarId]> = pdbs.iter().map(|p| p.pattern()).collect();
        let mut cliques = additive_cliques(&additivity, &patterns, deadline);
        let mut statistics = PdbStatistics::default();
        if let Some(limit) = dominance_pruning {
            let before = cliques.len();
            let until = deadline.or_earlier(start.checked_add(limit));
            cliques = prune_dominated(&patterns, cliques, until);
            statistics.pruned_cliques = before - cliques.len();
            statistics.dominance_pruning_time = start.elapsed();
            // Drop the databases no clique uses, renumbering the cliques' members.
            let mut used = vec![false; pdbs.len()];
            for c in &cliques {
                for &m in c {
                    used[m as usize] = true;
                }
            }
            let mut new_index = vec![u32::MAX; pdbs.len()];
            let mut next = 0;
            for (i, &u) in used.iter().enumerate() {
                if u {
                    new_index[i] = next;
                    next += 1;
                }
            }
            let mut i = 0;
            pdbs.retain(|_| {
                i += 1;
                used[i - 1]
            });
            for c in &mut cliques {
                for m in c.iter_mut() {
                    *m = new_index[*m as usize];
                }
            }
            statistics.pruned_patterns = used.len() - pdbs.len();
        }
        let mut clique_start = vec![0u32];
        let mut members = Vec::new();
        for c in &cliques {
            members.extend_from_slice(c);
            clique_start.push(members.len() as u32);
        }
        statistics.patterns = pdbs.len();
        statistics.total_size = pdbs.iter().map(|p| p.size() as u64).sum();
        statistics.memory_bytes = pdbs.iter().map(|p| p.memory_bytes() as u64).sum();
        statistics.cliques = cliques.len();
        statistics.total_time = start.elapsed();
        CanonicalPdbs {
            name,
            values: vec![0; pdbs.len()],
            pdbs,
            clique_start,
            members,
            statistics,
        }
    }

    /// The pattern databases.
    pub fn pdbs(&self) -> &[PatternDatabase] {
        &self.pdbs
    }

    /// The cliques (maximal additive subsets), as indices into [`pdbs`](Self::pdbs).
    pub fn cliques(&self) -> impl Iterator<Item = &[u32]> + '_ {
        self.clique_start
            .windows(2)
            .map(|w| &self.members[w[0] as usize..w[1] as usize])
    }

    /// What building it did.
    pub fn statistics(&self) -> &PdbStatistics {
        &self.statistics
    }

    pub(crate) fn statistics_mut(&mut self) -> &mut PdbStatistics {
        &mut self.statistics
    }
}

impl Heuristic for CanonicalPdbs {
    fn name(&self) -> &str {
        self.name
    }

    #[inline]
    fn evaluate(&mut self, state: &[u32]) -> Option<u64> {
        for (value, pdb) in self.values.iter_mut().zip(&self.pdbs) {
            *value = pdb.raw(state);
            if *value == DEAD {
                return None;
            }
        }
        let mut best = 0u64;
        for w in self.clique_start.windows(2) {
            let sum: u64 = self.members[w[0] as usize..w[1] as usize]
                .iter()
                .map(|&m| u64::from(self.values[m as usize]))
                .sum();
            best = best.max(sum);
        }
        Some(best)
    }

    fn pdb_statistics(&self) -> Option<&PdbStatistics> {
        Some(&self.statistics)
    }
}

/// The cliques not dominated by another: clique `a` is dominated by `b` if every pattern
/// of `a` is a subset of some pattern of `b` (then `b`'s sum is at least `a`'s, since
/// additive patterns inside one superpattern sum to at most its value). Cliques are taken
/// in order; each one not pruned yet prunes the later and earlier ones it dominates, so
/// of two equivalent cliques the first survives. Stops pruning at `deadline`.
///
/// To avoid comparing all pairs, every clique is filed under one *key* pattern: its
/// member in the fewest cliques among those without a strict superset in the collection
/// (or among all its members if it has none). A clique `b` can only dominate `a` if `b`'s
/// downward closure (the patterns that are subsets of one of `b`'s) holds `a`'s key, and
/// a key without a strict superset is in that closure only if it is in `b` itself; so
/// `b` looks only at the cliques filed under the patterns of its closure. The patterns
/// are distinct. Time O(patterns^2 * pattern size + cliques * clique size) plus the
/// comparisons, each O(clique size) with an early exit.
fn prune_dominated(
    patterns: &[&[VarId]],
    cliques: Vec<Vec<u32>>,
    deadline: Deadline,
) -> Vec<Vec<u32>> {
    let n = patterns.len();
    let words = n.div_ceil(64).max(1);
    let subset = |a: &[VarId], b: &[VarId]| a.iter().all(|v| b.binary_search(v).is_ok());
    // subsets[q]: the patterns contained in pattern q (q included).
    let mut subsets = vec![0u64; n * words];
    let mut maximal = vec![true; n];
    for q in 0..n {
        for p in 0..n {
            if subset(patterns[p], patterns[q]) {
                subsets[q * words + p / 64] |= 1 << (p % 64);
                if p != q {
                    maximal[p] = false;
                }
            }
        }
    }
    let mut count = vec![0u32; n];
    for c in &cliques {
        for &m in c {
            count[m as usize] += 1;
        }
    }
    let key = |c: &[u32]| {
        let rarest = |maximal_only: bool| {
            c.iter()
                .copied()
                .filter(|&m| !maximal_only || maximal[m as usize])
                .min_by_key(|&m| (count[m as usize], m))
        };
        rarest(true).or_else(|| rarest(false))
    };
    // Cliques filed by key: bucket[start[p]..start[p + 1]].
    let mut start = vec![0u32; n + 1];
    let keys: Vec<Option<u32>> = cliques.iter().map(|c| key(c)).collect();
    for k in keys.iter().flatten() {
        start[*k as usize + 1] += 1;
    }
    for p in 0..n {
        start[p + 1] += start[p];
    }
    let mut next = start.clone();
    let mut bucket = vec![0u32; start[n] as usize];
    for (c, k) in keys.iter().enumerate() {
        if let Some(k) = k {
            bucket[next[*k as usize] as usize] = c as u32;
            next[*k as usize] += 1;
        }
    }
    let mut len: Vec<u32> = start.windows(2).map(|w| w[1] - w[0]).collect();
    let mut pruned = vec![false; cliques.len()];
    let mut closure = vec![0u64; words];
    for b in 0..cliques.len() {
        if pruned[b] {
            continue;
        }
        if b % 256 == 0 && deadline.passed() {
            break;
        }
        closure.fill(0);
        for &q in &cliques[b] {
            for (w, &bits) in closure.iter_mut().zip(&subsets[q as usize * words..]) {
                *w |= bits;
            }
        }
        let in_closure = |p: u32| closure[p as usize / 64] >> (p % 64) & 1 == 1;
        for p in (0..n).filter(|&p| in_closure(p as u32)) {
            // Scan the bucket, dropping the cliques pruned by now from it for good.
            let low = start[p] as usize;
            let mut kept = low;
            for i in low..low + len[p] as usize {
                let a = bucket[i] as usize;
                if pruned[a] {
                    continue;
                }
                if a != b && cliques[a].iter().all(|&m| in_closure(m)) {
                    pruned[a] = true;
                    continue;
                }
                bucket[kept] = a as u32;
                kept += 1;
            }
            len[p] = (kept - low) as u32;
        }
    }
    cliques
        .into_iter()
        .zip(pruned)
        .filter(|(_, p)| !p)
        .map(|(c, _)| c)
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn graph(n: usize, edges: &[(usize, usize)]) -> Vec<Vec<u64>> {
        let mut adjacent = vec![vec![0u64; n.div_ceil(64)]; n];
        for &(a, b) in edges {
            adjacent[a][b / 64] |= 1 << (b % 64);
            adjacent[b][a / 64] |= 1 << (a % 64);
        }
        adjacent
    }

    /// Maximal cliques by brute force over all subsets.
    fn brute_force(n: usize, adjacent: &[Vec<u64>]) -> Vec<Vec<u32>> {
        let edge = |a: usize, b: usize| adjacent[a][b / 64] >> (b % 64) & 1 == 1;
        let is_clique = |s: u32| {
            (0..n)
                .all(|a| (0..n).all(|b| a == b || s >> a & 1 == 0 || s >> b & 1 == 0 || edge(a, b)))
        };
        let mut out: Vec<Vec<u32>> = (0..1u32 << n)
            .filter(|&s| is_clique(s) && (0..n).all(|v| s >> v & 1 == 1 || !is_clique(s | 1 << v)))
            .map(|s| (0..n as u32).filter(|&v| s >> v & 1 == 1).collect())
            .collect();
        out.sort();
        out
    }

    #[test]
    fn cliques_match_brute_force() {
        let mut seed = 5u64;
        for round in 0..300 {
            let n = round % 11;
            let mut edges = Vec::new();
            for a in 0..n {
                for b in a + 1..n {
                    seed = seed
                        .wrapping_mul(6364136223846793005)
                        .wrapping_add(1442695040888963407);
                    if (seed >> 33) % 100 < (round as u64 * 7) % 100 {
                        edges.push((a, b));
                    }
                }
            }
            let adjacent = graph(n, &edges);
            let mut got = maximal_cliques(n, &adjacent, Deadline::default());
            got.sort();
            assert_eq!(got, brute_force(n, &adjacent), "{n} {edges:?}");
        }
        // No vertices: one empty clique (the heuristic is then 0).
        assert_eq!(
            maximal_cliques(0, &[], Deadline::default()),
            vec![Vec::<u32>::new()]
        );
        // A 70-vertex complete graph crosses a word boundary.
        let edges: Vec<_> = (0..70)
            .flat_map(|a| (a + 1..70).map(move |b| (a, b)))
            .collect();
        assert_eq!(
            maximal_cliques(70, &graph(70, &edges), Deadline::default()),
            vec![(0..70).collect::<Vec<u32>>()]
        );
    }

    #[test]
    fn clique_enumeration_stops_at_the_deadline_with_maximal_cliques() {
        // Every pair but (2k, 2k + 1) is an edge: 2^12 maximal cliques (one of each pair).
        let n = 24;
        let edges: Vec<_> = (0..n)
            .flat_map(|a| (a + 1..n).map(move |b| (a, b)))
            .filter(|&(a, b)| !(a % 2 == 0 && b == a + 1))
            .collect();
        let adjacent = graph(n, &edges);
        let all = maximal_cliques(n, &adjacent, Deadline::default());
        assert_eq!(all.len(), 1 << 12);
        let cut = maximal_cliques(n, &adjacent, Deadline::at(Some(Instant::now())));
        assert!(cut.len() < all.len(), "stopped early: {}", cut.len());
        assert!(cut.iter().all(|c| all.contains(c)), "only maximal cliques");
    }

    /// Variables a, b, c, d, e; goal a, b, c. `ab` changes a and b, `c-from-d` changes c
    /// given d, `e` changes e.
    fn task() -> Task {
        use task::{Fact, Operator, Variable};
        let fact = |v: u32| Fact::new(VarId(v), 0);
        let op = |name: &str, pre: Vec<Fact>, eff: Vec<Fact>| Operator {
            name: name.into(),
            preconditions: pre,
            effects: eff,
            cost: 1,
        };
        Task {
            variables: ["a", "b", "c", "d", "e"]
                .iter()
                .map(|n| Variable::binary(n))
                .collect(),
            mutexes: vec![],
            initial_state: vec![1; 5],
            goal: vec![fact(0), fact(1), fact(2)],
            operators: vec![
                op("ab", vec![], vec![fact(0), fact(1)]),
                op("c-from-d", vec![fact(3)], vec![fact(2)]),
                op("e", vec![fact(2)], vec![fact(4)]),
            ],
            use_costs: false,
        }
    }

    #[test]
    fn additivity_and_systematic_patterns() {
        let t = task();
        let additivity = Additivity::new(&t);
        let p = |vars: &[u32]| vars.iter().map(|&v| VarId(v)).collect::<Vec<_>>();
        assert!(!additivity.additive(&p(&[0]), &p(&[1])));
        assert!(additivity.additive(&p(&[0]), &p(&[2, 3])));
        // A variable no operator changes is additive with itself.
        assert!(additivity.additive(&p(&[3]), &p(&[3])));
        assert!(!additivity.additive(&p(&[2]), &p(&[2, 4])));
        assert_eq!(systematic_patterns(&t, 1), [vec![0], vec![1], vec![2]]);
        // Pairs: a and b (changed together), c and its precondition d; not c and e (e is
        // no goal, and no predecessor of c).
        assert_eq!(
            systematic_patterns(&t, 2),
            [vec![0], vec![1], vec![2], vec![0, 1], vec![2, 3]]
        );
        let pdbs = crate::pdb::build_collection(&t, &systematic_patterns(&t, 2)).unwrap();
        let mut h = CanonicalPdbs::new(&t, pdbs, None, "cpdbs");
        // Cliques: {a, c}, {a, cd}, {b, c}, {b, cd}, {ab, c}, {ab, cd}.
        assert_eq!(h.cliques().count(), 6);
        // d never changes: without it c is out of reach.
        assert_eq!(h.evaluate(&[1, 1, 1, 1, 1]), None);
        assert_eq!(h.evaluate(&[1, 1, 1, 0, 1]), Some(2));
        assert_eq!(h.evaluate(&[0, 0, 1, 0, 1]), Some(1));
        let mut pruned =
            CanonicalPdbs::new(&t, h.pdbs().to_vec(), Some(Duration::from_secs(9)), "cpdbs");
        // Only {ab, cd} is left, renumbered.
        assert_eq!(pruned.cliques().collect::<Vec<_>>(), [&[0u32, 1][..]]);
        let left: Vec<&[VarId]> = pruned.pdbs().iter().map(|p| p.pattern()).collect();
        assert_eq!(left, [&p(&[0, 1])[..], &p(&[2, 3])[..]]);
        let s = pruned.statistics();
        assert_eq!(
            (s.patterns, s.cliques, s.pruned_cliques, s.pruned_patterns),
            (2, 1, 5, 3)
        );
        assert_eq!(s.total_size, 8);
        assert_eq!(pruned.evaluate(&[1, 1, 1, 0, 1]), Some(2));
        assert_eq!(pruned.name(), "cpdbs");
    }

    #[test]
    fn dominated_cliques_are_pruned() {
        let p = |vars: &[u32]| vars.iter().map(|&v| VarId(v)).collect::<Vec<_>>();
        let patterns = [p(&[0]), p(&[1]), p(&[0, 1]), p(&[2])];
        let refs: Vec<&[VarId]> = patterns.iter().map(|p| p.as_slice()).collect();
        // {0}, {1} additive with each other and {2}; {0, 1} additive with {2}.
        let cliques = vec![vec![0, 1, 3], vec![2, 3]];
        let far = Deadline::at(Some(Instant::now() + Duration::from_secs(60)));
        assert_eq!(
            prune_dominated(&refs, cliques.clone(), far),
            vec![vec![2, 3]]
        );
        let cliques = vec![vec![0, 3], vec![1]];
        assert_eq!(prune_dominated(&refs, cliques.clone(), far), cliques);
    }
}
