//! Eager A* with reopening.

use std::time::{Duration, Instant};

use task::{OpId, Task, TaskError};

use crate::heuristic::Heuristic;
use crate::open_list::OpenList;
use crate::plan::Plan;
use crate::pruning::{Pruning, PruningStatistics};
use crate::segmented::SegmentedVec;
use crate::state::{StateId, StatePacker, StateRegistry};
use crate::successor::SuccessorGenerator;

/// How often the limits are checked: every `interval` open-list pops and heuristic
/// evaluations together, the interval adapting to what they cost. Evaluations count
/// too, and the interval shrinks to 1 when they are slow: on scanalyzer p19 one LM-cut
/// evaluation takes 50 ms (51,030 operators), and a fixed 64 let the time limit slip by
/// 3 s. When they are cheap the interval grows to [`MAX_CHECK_INTERVAL`], so that blind
/// search does not read the clock at every node.
#[derive(Debug)]
struct LimitCheck {
    countdown: u32,
    interval: u32,
    last: Instant,
}

/// The longest interval between limit checks, in pops and evaluations.
const MAX_CHECK_INTERVAL: u32 = 64;
/// Checks further apart than this shrink the interval; closer than a tenth grow it.
const CHECK_EVERY: Duration = Duration::from_millis(2);

impl LimitCheck {
    /// Due at the first call.
    fn new() -> LimitCheck {
        LimitCheck {
            countdown: 1,
            interval: 1,
            last: Instant::now(),
        }
    }

    /// Counts one pop or evaluation; true when the limits are to be checked.
    fn due(&mut self) -> bool {
        self.countdown -= 1;
        if self.countdown > 0 {
            return false;
        }
        let now = Instant::now();
        let spent = now - self.last;
        self.last = now;
        if spent > CHECK_EVERY {
            self.interval = (self.interval / 2).max(1);
        } else if spent < CHECK_EVERY / 10 {
            self.interval = (self.interval * 2).min(MAX_CHECK_INTERVAL);
        }
        self.countdown = self.interval;
        true
    }
}

/// When to give up: the run's limits ([`task::Limits`], shared with translation), under
/// the name the search's API has always used. The default has no limits. Without a
/// `memory_usage` probe the search counts the bytes of its own main structures (states,
/// per-state information, open list), which leaves out the task and the heuristic.
pub type SearchLimits = task::Limits;

/// Counters reported when the search enters a new, higher f-layer.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Progress {
    /// The new f value (g + h of the state about to be expanded).
    pub f: u64,
    /// States expanded before this one.
    pub expanded: u64,
    /// States evaluated by the heuristic so far.
    pub evaluated: u64,
    /// Successors generated so far.
    pub generated: u64,
}

/// What the search counted, in Fast Downward's terms.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct Statistics {
    /// States expanded (taken from the open list and closed; includes the goal state).
    pub expanded: u64,
    /// States evaluated by the heuristic (each registered state once).
    pub evaluated: u64,
    /// Successors generated (one per applicable operator of an expanded state).
    pub generated: u64,
    /// Closed states reopened because a cheaper path to them was found.
    pub reopened: u64,
    /// States the heuristic recognised as dead ends.
    pub dead_ends: u64,
    /// `expanded` when the last f-layer began ("Expanded until last jump").
    pub expanded_until_last_jump: u64,
    /// `evaluated` when the last f-layer began.
    pub evaluated_until_last_jump: u64,
    /// `generated` when the last f-layer began.
    pub generated_until_last_jump: u64,
    /// The heuristic value of the initial state (`None`: a dead end).
    pub initial_h: Option<u64>,
    /// Wall-clock time of the search, including building its structures.
    pub search_time: Duration,
    /// Distinct states registered.
    pub registered_states: u64,
    /// What partial-order reduction did; `None` without pruning (`null()`).
    pub pruning: Option<PruningStatistics>,
}

/// How a search ended.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Outcome {
    /// An optimal plan (given an admissible heuristic).
    Solved(Plan),
    /// The search space was exhausted: no plan exists.
    Unsolvable,
    /// The deadline passed.
    TimeLimit,
    /// The memory limit was exceeded, or the number of states outgrew 32-bit ids.
    MemoryLimit,
    /// The caller cancelled the search (`Limits::cancel`).
    Cancelled,
}

impl Outcome {
    /// The outcome of a run that reached `limit`.
    pub fn limit(limit: task::Limit) -> Outcome {
        match limit {
            task::Limit::Time => Outcome::TimeLimit,
            task::Limit::Memory => Outcome::MemoryLimit,
            task::Limit::Cancelled => Outcome::Cancelled,
        }
    }
}

/// The outcome of a search and what it counted on the way.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct SearchResult {
    /// How it ended.
    pub outcome: Outcome,
    /// The counters.
    pub statistics: Statistics,
}

/// A search that could not start.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum SearchError {
    /// The task breaks its invariants.
    #[error("invalid task: {0}")]
    InvalidTask(#[from] TaskError),
    /// A pattern of a pattern-database heuristic does not fit the task.
    #[error("{0}")]
    InvalidPattern(crate::pdb::PatternError),
    /// A path cost more than the 32 bits a search node stores for g (Fast Downward
    /// allows less still).
    #[error(
        "a path costs {cost}, more than the {max} the search can store; tasks with costs \
         this large are not supported",
        max = u32::MAX
    )]
    CostTooLarge {
        /// The cost of the path that did not fit.
        cost: u64,
    },
}

/// A node's status; the discriminants are its two bits in [`Node::h_and_status`].
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Status {
    Open = 0,
    Closed = 1,
    DeadEnd = 2,
}

const NO_OP: OpId = OpId(u32::MAX);

/// Per-operator data in the forms the inner loop wants.
struct Operators {
    cost: Vec<u64>,
    /// Effects on packed states: `(word, bits to clear, bits to set)`, one per touched word.
    packed_start: Vec<u32>,
    packed: Vec<(u32, u64, u64)>,
    /// Effects on unpacked states: `(variable, value)`.
    unpacked_start: Vec<u32>,
    unpacked: Vec<(u32, u32)>,
}

impl Operators {
    fn new(task: &Task, packer: &StatePacker) -> Operators {
        let mut ops = Operators {
            cost: Vec::with_capacity(task.operators.len()),
            packed_start: vec![0],
            packed: Vec::new(),
            unpacked_start: vec![0],
            unpacked: Vec::new(),
        };
        let mut writes = Vec::new();
        for op in &task.operators {
            ops.cost.push(task.cost(op));
            writes.clear();
            writes.extend(
                op.effects
                    .iter()
                    .map(|f| packer.write_mask(f.var.index(), f.value)),
            );
            writes.sort_by_key(|w| w.0);
            let begin = ops.packed.len();
            for &(word, clear, set) in &writes {
                match ops.packed[begin..].last_mut() {
                    Some(last) if last.0 == word => {
                        last.1 |= clear;
                        last.2 |= set;
                    }
                    _ => ops.packed.push((word, clear, set)),
                }
            }
            ops.packed_start.push(ops.packed.len() as u32);
            ops.unpacked
                .extend(op.effects.iter().map(|f| (f.var.0, f.value)));
            ops.unpacked_start.push(ops.unpacked.len() as u32);
        }
        ops
    }

    #[inline]
    fn apply_packed(&self, op: usize, packed: &mut [u64]) {
        let range = self.packed_start[op] as usize..self.packed_start[op + 1] as usize;
        for &(word, clear, set) in &self.packed[range] {
            let w = &mut packed[word as usize];
            *w = (*w & !clear) | set;
        }
    }

    #[inline]
    fn apply_unpacked(&self, op: usize, state: &mut [u32]) {
        let range = self.unpacked_start[op] as usize..self.unpacked_start[op + 1] as usize;
        for &(var, value) in &self.unpacked[range] {
            state[var as usize] = value;
        }
    }
}

/// The search node of one state: 16 bytes, as in Fast Downward, since on long searches
/// the nodes are a third of the memory (openstacks p16: 9.2 million states).
///
/// g is stored in 32 bits: a path costing more stops the search with
/// [`SearchError::CostTooLarge`] rather than wrapping. The cached heuristic value and the
/// status share the other word.
#[derive(Debug, Clone, Copy)]
struct Node {
    g: u32,
    /// The status in the top two bits, the cached heuristic value in the rest, saturated
    /// at [`H_MAX`] (a lower value stays admissible).
    h_and_status: u32,
    parent: StateId,
    creating_op: OpId,
}

/// The highest heuristic value a node keeps; higher values are lowered to it.
const H_MAX: u32 = (1 << 30) - 1;
const STATUS_SHIFT: u32 = 30;
const _: () = assert!(std::mem::size_of::<Node>() == 16);

impl Node {
    /// A node; `h` must be clamped already ([`clamp_h`]).
    fn new(g: u32, h: u32, parent: StateId, creating_op: OpId, status: Status) -> Node {
        debug_assert!(h <= H_MAX);
        Node {
            g,
            h_and_status: (status as u32) << STATUS_SHIFT | h,
            parent,
            creating_op,
        }
    }

    #[inline]
    fn h(&self) -> u64 {
        u64::from(self.h_and_status & H_MAX)
    }

    #[inline]
    fn status(&self) -> Status {
        match self.h_and_status >> STATUS_SHIFT {
            0 => Status::Open,
            1 => Status::Closed,
            _ => Status::DeadEnd,
        }
    }

    #[inline]
    fn set_status(&mut self, status: Status) {
        self.h_and_status = (status as u32) << STATUS_SHIFT | (self.h_and_status & H_MAX);
    }
}

/// A heuristic value as a node keeps it; the open list must use the same value.
#[inline]
fn clamp_h(h: u64) -> u32 {
    h.min(u64::from(H_MAX)) as u32
}

/// `g + cost` if it fits a node's 32-bit g.
#[inline]
fn child_g(g: u32, cost: u64) -> Result<u32, SearchError> {
    let sum = u64::from(g) + cost;
    u32::try_from(sum).map_err(|_| SearchError::CostTooLarge { cost: sum })
}

/// Per-state search information indexed by [`StateId`], in fixed-size segments so that
/// growing never copies and never holds twice the memory in use.
struct StateInfo {
    nodes: SegmentedVec<Node>,
}

impl StateInfo {
    fn push(&mut self, g: u32, h: u32, parent: StateId, creating_op: OpId, status: Status) {
        self.nodes
            .push(Node::new(g, h, parent, creating_op, status));
    }

    #[inline]
    fn node(&self, id: StateId) -> &Node {
        self.nodes.get(id.index())
    }

    #[inline]
    fn node_mut(&mut self, id: StateId) -> &mut Node {
        self.nodes.get_mut(id.index())
    }

    fn memory_bytes(&self) -> usize {
        self.nodes.memory_bytes()
    }

    /// The operators on the path from the initial state to `goal`, in order, following
    /// parent links; O(plan length).
    fn extract_plan(&self, goal: StateId) -> Vec<OpId> {
        let mut ops = Vec::new();
        let mut state = goal;
        // Parent links form a tree rooted at the initial state; the bound only guards
        // against a broken invariant turning into an endless loop.
        for _ in 0..self.nodes.len() {
            let node = self.node(state);
            if node.creating_op == NO_OP {
                break;
            }
            ops.push(node.creating_op);
            state = node.parent;
        }
        ops.reverse();
        ops
    }
}

/// Optimal eager A* search from the initial state of `task` to a goal state.
///
/// States are kept in an open list ordered by f = g + h, ties broken by lower h and then
/// first in, first out. The goal test happens when a state is expanded, so with an
/// *admissible* heuristic the plan returned is optimal; the heuristic need not be
/// *consistent*: a closed state reached again by a cheaper path is reopened. States the
/// heuristic calls dead ends are pruned. Zero-cost operators are fine. Each registered
/// state is evaluated once and its value cached.
///
/// Time: O(expansions * (successor generation + branching * (state words + heuristic)));
/// memory: O(registered states * (8 * state words + 16 bytes + hash table)). The result is deterministic:
/// the same task and heuristic give the same plan and the same counts.
///
/// Limits are checked every few dozen expansions and evaluations; `observer` is called
/// at each new, higher f-layer (including the first).
pub fn astar<H: Heuristic + ?Sized>(
    task: &Task,
    heuristic: &mut H,
    limits: &SearchLimits,
    observer: Option<&mut dyn FnMut(Progress)>,
) -> Result<SearchResult, SearchError> {
    astar_with_pruning(task, heuristic, None, limits, observer)
}

/// [`astar`] with partial-order reduction: `pruning` (built for `task`, see
/// [`crate::PruningConfig::build`]) keeps a subset of the applicable operators of each
/// expanded non-goal state, and only those are generated (and counted as generated, as
/// in Fast Downward). With a strong stubborn set method the search stays optimal. Each
/// pruning call counts towards the limit checks as an evaluation does, so that pruning
/// expensive on a large task cannot let the time limit slip; what pruning did is in
/// [`Statistics::pruning`].
pub fn astar_with_pruning<H: Heuristic + ?Sized>(
    task: &Task,
    heuristic: &mut H,
    mut pruning: Option<&mut Pruning>,
    limits: &SearchLimits,
    mut observer: Option<&mut dyn FnMut(Progress)>,
) -> Result<SearchResult, SearchError> {
    let start = Instant::now();
    task.validate()?;
    let packer = StatePacker::for_task(task);
    let words = packer.words_per_state();
    let mut registry = StateRegistry::new(words);
    let mut generator = SuccessorGenerator::new(task);
    let ops = Operators::new(task, &packer);
    let mut info = StateInfo {
        nodes: SegmentedVec::new(),
    };
    let mut open = OpenList::new();
    let mut stats = Statistics::default();

    let n = task.variables.len();
    let mut state = vec![0u32; n];
    let mut child = vec![0u32; n];
    let mut parent_packed = vec![0u64; words];
    let mut child_packed = vec![0u64; words];
    let mut applicable: Vec<OpId> = Vec::new();

    let finish = |outcome: Outcome,
                  mut stats: Statistics,
                  registry: &StateRegistry,
                  pruning: &Option<&mut Pruning>| {
        stats.search_time = start.elapsed();
        stats.registered_states = registry.len() as u64;
        stats.pruning = pruning.as_ref().map(|p| p.statistics());
        Ok(SearchResult {
            outcome,
            statistics: stats,
        })
    };

    packer.pack(&task.initial_state, &mut child_packed);
    let Some((init, _)) = registry.insert(&child_packed) else {
        return finish(Outcome::MemoryLimit, stats, &registry, &pruning);
    };
    stats.evaluated = 1;
    stats.initial_h = heuristic.evaluate(&task.initial_state);
    match stats.initial_h {
        None => {
            stats.dead_ends = 1;
            info.push(0, 0, init, NO_OP, Status::DeadEnd);
            return finish(Outcome::Unsolvable, stats, &registry, &pruning);
        }
        Some(h) => {
            let h = clamp_h(h);
            info.push(0, h, init, NO_OP, Status::Open);
            open.push(u64::from(h), u64::from(h), init);
        }
    }

    let mut layer: Option<u64> = None;
    let mut limit_check = LimitCheck::new();
    loop {
        if let Some(outcome) = limit_reached(&mut limit_check, limits, &registry, &info, &open) {
            return finish(outcome, stats, &registry, &pruning);
        }
        let Some((f, h, id)) = open.pop() else {
            return finish(Outcome::Unsolvable, stats, &registry, &pruning);
        };
        let node = *info.node(id);
        if node.status() != Status::Open || u64::from(node.g) + h != f {
            continue; // A stale entry: expanded already, or since reached more cheaply.
        }
        if layer.is_none_or(|l| f > l) {
            layer = Some(f);
            stats.expanded_until_last_jump = stats.expanded;
            stats.evaluated_until_last_jump = stats.evaluated;
            stats.generated_until_last_jump = stats.generated;
            if let Some(observe) = observer.as_mut() {
                observe(Progress {
                    f,
                    expanded: stats.expanded,
                    evaluated: stats.evaluated,
                    generated: stats.generated,
                });
            }
        }
        info.node_mut(id).set_status(Status::Closed);
        stats.expanded += 1;
        parent_packed.copy_from_slice(registry.get(id));
        packer.unpack(&parent_packed, &mut state);
        if task.is_goal(&state) {
            let plan = Plan {
                operators: info.extract_plan(id),
                cost: u64::from(node.g),
            };
            return finish(Outcome::Solved(plan), stats, &registry, &pruning);
        }
        let g = node.g;
        generator.applicable(&state, &mut applicable);
        if let Some(p) = pruning.as_mut() {
            p.prune(&state, &mut applicable);
            if let Some(outcome) = limit_reached(&mut limit_check, limits, &registry, &info, &open)
            {
                return finish(outcome, stats, &registry, &pruning);
            }
        }
        for &op in &applicable {
            stats.generated += 1;
            let o = op.index();
            child_packed.copy_from_slice(&parent_packed);
            ops.apply_packed(o, &mut child_packed);
            let child_g = child_g(g, ops.cost[o])?;
            let Some((child_id, is_new)) = registry.insert(&child_packed) else {
                return finish(Outcome::MemoryLimit, stats, &registry, &pruning);
            };
            if is_new {
                if let Some(outcome) =
                    limit_reached(&mut limit_check, limits, &registry, &info, &open)
                {
                    return finish(outcome, stats, &registry, &pruning);
                }
                child.copy_from_slice(&state);
                ops.apply_unpacked(o, &mut child);
                stats.evaluated += 1;
                match heuristic.evaluate(&child) {
                    None => {
                        stats.dead_ends += 1;
                        info.push(child_g, 0, id, op, Status::DeadEnd);
                    }
                    Some(child_h) => {
                        let child_h = clamp_h(child_h);
                        info.push(child_g, child_h, id, op, Status::Open);
                        let child_h = u64::from(child_h);
                        open.push(u64::from(child_g) + child_h, child_h, child_id);
                    }
                }
            } else {
                let node = info.node_mut(child_id);
                let status = node.status();
                if status == Status::DeadEnd || child_g >= node.g {
                    continue;
                }
                if status == Status::Closed {
                    stats.reopened += 1;
                }
                node.g = child_g;
                node.parent = id;
                node.creating_op = op;
                node.set_status(Status::Open);
                let child_h = node.h();
                open.push(u64::from(child_g) + child_h, child_h, child_id);
            }
        }
    }
}

/// Counts one pop or evaluation; when a check is due, the outcome the limits call for,
/// if any, with the search's own memory as the fallback measure.
fn limit_reached(
    check: &mut LimitCheck,
    limits: &SearchLimits,
    registry: &StateRegistry,
    info: &StateInfo,
    open: &OpenList,
) -> Option<Outcome> {
    if !check.due() {
        return None;
    }
    let own_bytes = || registry.memory_bytes() + info.memory_bytes() + open.memory_bytes();
    if let Some(outcome) = check_limits(limits, own_bytes) {
        return Some(outcome);
    }
    // Stop before the state table's next doubling if it would not fit, rather than
    // after it: the limit then holds for the process's peak, not only after the step.
    let growth = registry.imminent_growth_bytes() as u64;
    if growth > 0 && limits.would_exceed(growth, || own_bytes() as u64) {
        return Some(Outcome::MemoryLimit);
    }
    // Likewise in time: the doubling rehashes every state at once, seconds on a large
    // table, and no check runs inside it. Fewer new states than the check interval
    // are left before it, so it may come before the next check.
    let rehash = registry.growth_time_within(MAX_CHECK_INTERVAL as usize + 1)?;
    let deadline = limits.deadline?;
    (Instant::now() + rehash > deadline).then_some(Outcome::TimeLimit)
}

/// The outcome the limits call for, if any.
fn check_limits(limits: &SearchLimits, own_bytes: impl FnOnce() -> usize) -> Option<Outcome> {
    limits.reached(|| own_bytes() as u64).map(Outcome::limit)
}

#[cfg(test)]
pub(crate) mod tests {
    use super::*;
    use crate::heuristic::Blind;
    use crate::hmax::HMax;
    use task::{Fact, Operator, VarId, Variable};

    /// A task over one variable `name` of `values` values (`{prefix}0`, `{prefix}1`,
    /// ...), starting at the first, with the goal at the last.
    fn one_variable(name: &str, prefix: &str, values: u32, operators: Vec<Operator>) -> Task {
        Task {
            variables: vec![Variable {
                name: name.into(),
                value_names: (0..values).map(|i| format!("{prefix}{i}")).collect(),
            }],
            mutexes: vec![],
            initial_state: vec![0],
            goal: vec![Fact::new(VarId(0), values - 1)],
            operators,
            use_costs: false,
        }
    }

    /// A robot on a line of `n` positions, starting at 0, with the goal at `n - 1`.
    pub(crate) fn line(n: u32) -> Task {
        let step = |from: u32, to: u32| Operator {
            name: format!("move p{from} p{to}"),
            preconditions: vec![Fact::new(VarId(0), from)],
            effects: vec![Fact::new(VarId(0), to)],
            cost: 1,
        };
        let moves = (1..n).flat_map(|i| [step(i - 1, i), step(i, i - 1)]);
        one_variable("at", "p", n, moves.collect())
    }

    #[test]
    fn statistics_and_layers_in_fast_downwards_terms() {
        let task = line(4);
        let mut layers = Vec::new();
        let result = astar(
            &task,
            &mut Blind::new(&task),
            &SearchLimits::default(),
            Some(&mut |p| layers.push(p)),
        )
        .unwrap();
        let Outcome::Solved(plan) = result.outcome else {
            panic!("solvable")
        };
        assert_eq!(plan.operators, vec![OpId(0), OpId(2), OpId(4)]);
        assert_eq!(plan.cost, 3);
        let progress = |f, expanded, evaluated, generated| Progress {
            f,
            expanded,
            evaluated,
            generated,
        };
        assert_eq!(
            layers,
            vec![
                progress(1, 0, 1, 0),
                progress(2, 1, 2, 1),
                progress(3, 2, 3, 3)
            ]
        );
        let s = result.statistics;
        assert_eq!(
            (
                s.expanded,
                s.evaluated,
                s.generated,
                s.reopened,
                s.dead_ends
            ),
            (4, 4, 5, 0, 0)
        );
        assert_eq!(
            (
                s.expanded_until_last_jump,
                s.evaluated_until_last_jump,
                s.generated_until_last_jump
            ),
            (2, 3, 3)
        );
        assert_eq!(s.initial_h, Some(1));
        assert_eq!(s.registered_states, 4);
    }

    #[test]
    fn goal_in_the_initial_state() {
        let mut task = line(3);
        task.initial_state = vec![2];
        let result = blind_search(&task).unwrap();
        assert_eq!(
            result.outcome,
            Outcome::Solved(Plan {
                operators: vec![],
                cost: 0
            })
        );
        assert_eq!(result.statistics.expanded, 1);
        assert_eq!(result.statistics.initial_h, Some(0));
    }

    #[test]
    fn unsolvable_and_dead_ends() {
        // Only forward moves up to position 2, goal 3: the space is exhausted.
        let mut task = line(4);
        task.operators.retain(|op| op.name != "move p2 p3");
        let result = blind_search(&task).unwrap();
        assert_eq!(result.outcome, Outcome::Unsolvable);
        assert_eq!(result.statistics.expanded, 3);
        // h^max sees it at once: the initial state is a dead end.
        let result = hmax_search(&task).unwrap();
        assert_eq!(result.outcome, Outcome::Unsolvable);
        assert_eq!(result.statistics.initial_h, None);
        assert_eq!(
            (result.statistics.expanded, result.statistics.dead_ends),
            (0, 1)
        );
        // Dead ends among successors are pruned: a trap position with no way out.
        let mut task = line(3);
        task.variables[0].value_names.push("trap".into());
        task.operators.push(Operator {
            name: "fall".into(),
            preconditions: vec![Fact::new(VarId(0), 0)],
            effects: vec![Fact::new(VarId(0), 3)],
            cost: 0,
        });
        let result = hmax_search(&task).unwrap();
        assert!(matches!(result.outcome, Outcome::Solved(ref p) if p.cost == 2));
        assert_eq!(result.statistics.dead_ends, 1);
    }

    #[test]
    fn a_search_stops_before_a_rehash_that_would_end_past_its_deadline() {
        let mut registry = StateRegistry::new(1);
        let mut i = 0u64;
        while registry.len() < 1000 || registry.insertions_before_growth() > 10 {
            registry.insert(&[i]);
            i += 1;
        }
        let info = StateInfo {
            nodes: SegmentedVec::new(),
        };
        let open = OpenList::new();
        let within = |seconds| SearchLimits {
            deadline: Some(Instant::now() + Duration::from_secs(seconds)),
            ..SearchLimits::default()
        };
        // The last growth moved half the states in 4 s: the next will take about 8 s.
        registry.pretend_last_growth(Duration::from_secs(4), registry.len() / 2);
        let stop = |limits: &SearchLimits| {
            limit_reached(&mut LimitCheck::new(), limits, &registry, &info, &open)
        };
        assert_eq!(stop(&within(5)), Some(Outcome::TimeLimit));
        assert_eq!(stop(&within(60)), None);
        // Far from a growth, the same deadline lets the search go on.
        registry.insert(&[i]);
        let mut far = registry.clone();
        while far.insertions_before_growth() <= 65 {
            i += 1;
            far.insert(&[i]);
        }
        far.pretend_last_growth(Duration::from_secs(4), far.len() / 2);
        let go_on = limit_reached(&mut LimitCheck::new(), &within(5), &far, &info, &open);
        assert_eq!(go_on, None);
    }

    #[test]
    fn limits_end_the_search_with_statistics() {
        let task = line(500);
        let past = SearchLimits {
            deadline: Some(Instant::now()),
            ..SearchLimits::default()
        };
        let result = astar(&task, &mut Blind::new(&task), &past, None).unwrap();
        assert_eq!(result.outcome, Outcome::TimeLimit);
        assert_eq!(result.statistics.evaluated, 1);

        let tiny = SearchLimits {
            memory_limit_bytes: Some(0),
            ..SearchLimits::default()
        };
        let result = astar(&task, &mut Blind::new(&task), &tiny, None).unwrap();
        assert_eq!(result.outcome, Outcome::MemoryLimit);

        fn small() -> u64 {
            1000
        }
        fn large() -> u64 {
            1 << 40
        }
        let fits = SearchLimits {
            memory_limit_bytes: Some(1 << 30),
            memory_usage: Some(small),
            ..SearchLimits::default()
        };
        let result = astar(&task, &mut Blind::new(&task), &fits, None).unwrap();
        assert!(matches!(result.outcome, Outcome::Solved(ref p) if p.cost == 499));
        let over = SearchLimits {
            memory_usage: Some(large),
            ..fits
        };
        assert_eq!(
            astar(&task, &mut Blind::new(&task), &over, None)
                .unwrap()
                .outcome,
            Outcome::MemoryLimit
        );
    }

    #[test]
    fn pruning_is_counted_and_stopped_by_the_limits() {
        use crate::pruning::{PruningConfig, StubbornSetsConfig};
        let task = line(500);
        let config = PruningConfig::AtomCentricStubbornSets(StubbornSetsConfig::default());
        let mut pruning = config.build(&task).unwrap();
        let result = astar_with_pruning(
            &task,
            &mut Blind::new(&task),
            Some(&mut pruning),
            &SearchLimits::default(),
            None,
        )
        .unwrap();
        assert!(matches!(result.outcome, Outcome::Solved(ref p) if p.cost == 499));
        // A line is one variable: every applicable move interferes with the others, so
        // nothing is pruned, and every successor counted is generated.
        let p = result.statistics.pruning.unwrap();
        assert_eq!(p.successors_after, result.statistics.generated);
        assert_eq!(p.successors_after, p.successors_before);

        let past = SearchLimits {
            deadline: Some(Instant::now()),
            ..SearchLimits::default()
        };
        let mut pruning = config.build(&task).unwrap();
        let result = astar_with_pruning(
            &task,
            &mut Blind::new(&task),
            Some(&mut pruning),
            &past,
            None,
        )
        .unwrap();
        assert_eq!(result.outcome, Outcome::TimeLimit);
        assert_eq!(result.statistics.pruning.unwrap().successors_before, 0);
    }

    /// A heuristic that takes 10 ms per state, as LM-cut does on the largest tasks.
    struct Slow;

    impl Heuristic for Slow {
        fn name(&self) -> &str {
            "slow"
        }

        fn evaluate(&mut self, _state: &[u32]) -> Option<u64> {
            std::thread::sleep(Duration::from_millis(10));
            Some(0)
        }
    }

    #[test]
    fn slow_evaluations_do_not_let_the_time_limit_slip() {
        // One variable, 300 values, an operator from 0 to each: the first expansion
        // evaluates 299 children, three seconds of evaluation. The search must stop a
        // few evaluations after the deadline, not at the next expansion.
        let values = 300;
        let go = |to: u32| Operator {
            name: format!("go {to}"),
            preconditions: vec![Fact::new(VarId(0), 0)],
            effects: vec![Fact::new(VarId(0), to)],
            cost: 1,
        };
        let task = one_variable("v", "v", values, (1..values).map(go).collect());
        let start = Instant::now();
        let limits = SearchLimits {
            deadline: Some(start + Duration::from_millis(100)),
            ..SearchLimits::default()
        };
        let result = astar(&task, &mut Slow, &limits, None).unwrap();
        assert_eq!(result.outcome, Outcome::TimeLimit);
        // Generous for a loaded machine; checking per expansion took 3 s here.
        let evaluated = result.statistics.evaluated;
        assert!(evaluated < 60, "{evaluated} evaluations before stopping");
        assert!(
            start.elapsed() < Duration::from_secs(1),
            "{:?}",
            start.elapsed()
        );
    }

    #[test]
    fn invalid_task_is_an_error() {
        let mut task = line(3);
        task.initial_state = vec![7];
        assert!(matches!(
            astar(
                &task,
                &mut Blind::new(&task),
                &SearchLimits::default(),
                None
            ),
            Err(SearchError::InvalidTask(_))
        ));
    }

    #[test]
    fn packed_effects_merge_per_word() {
        // Five binary variables share one word; an operator setting all of them must
        // produce one packed write.
        let mut task = line(2);
        for i in 0..4 {
            task.variables.push(Variable::binary(&format!("b{i}")));
            task.initial_state.push(1);
        }
        task.operators[0].effects = (0..5)
            .map(|v| Fact::new(VarId(v), if v == 0 { 1 } else { 0 }))
            .collect();
        let packer = StatePacker::for_task(&task);
        let ops = Operators::new(&task, &packer);
        assert_eq!(ops.packed_start[1], 1);
        let mut packed = vec![0; packer.words_per_state()];
        packer.pack(&task.initial_state, &mut packed);
        ops.apply_packed(0, &mut packed);
        let mut state = vec![0; 5];
        packer.unpack(&packed, &mut state);
        assert_eq!(state, vec![1, 0, 0, 0, 0]);
    }

    /// A* with the blind heuristic and no limits.
    fn blind_search(task: &Task) -> Result<SearchResult, SearchError> {
        astar(task, &mut Blind::new(task), &SearchLimits::default(), None)
    }

    fn hmax_search(task: &Task) -> Result<SearchResult, SearchError> {
        astar(task, &mut HMax::new(task)?, &SearchLimits::default(), None)
    }

    /// `line(n)` with every move costing `cost`.
    fn costly_line(n: u32, cost: u64) -> Task {
        let mut task = line(n);
        task.use_costs = true;
        for op in &mut task.operators {
            op.cost = cost;
        }
        task
    }

    #[test]
    fn path_costs_up_to_32_bits_are_exact() {
        let task = costly_line(3, u64::from(u32::MAX / 2));
        let result = blind_search(&task).unwrap();
        let Outcome::Solved(plan) = result.outcome else {
            panic!("solvable")
        };
        assert_eq!(plan.cost, u64::from(u32::MAX / 2) * 2);
    }

    #[test]
    fn a_path_costing_more_than_32_bits_is_an_error_not_a_wrap() {
        let task = costly_line(3, 3_000_000_000);
        let err = blind_search(&task).unwrap_err();
        assert_eq!(
            err,
            SearchError::CostTooLarge {
                cost: 6_000_000_000
            }
        );
        assert!(err.to_string().contains("6000000000"), "{err}");
    }

    #[test]
    fn node_keeps_status_and_saturated_h_apart() {
        let mut node = Node::new(7, clamp_h(u64::MAX), StateId(3), OpId(4), Status::Closed);
        assert_eq!(
            (node.g, node.h(), node.status()),
            (7, u64::from(H_MAX), Status::Closed)
        );
        node.set_status(Status::Open);
        assert_eq!((node.h(), node.status()), (u64::from(H_MAX), Status::Open));
        let dead = Node::new(0, 5, StateId(0), NO_OP, Status::DeadEnd);
        assert_eq!((dead.h(), dead.status()), (5, Status::DeadEnd));
    }
}
