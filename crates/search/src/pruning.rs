//! Partial-order reduction: pruning the applicable operators of a state before its
//! successors are generated, as Fast Downward's `pruning=` option of `astar(...)` does.
//!
//! - [`PruningConfig::AtomCentricStubbornSets`]: strong stubborn sets (Wehrle and
//!   Helmert, ICAPS 2014) computed from atoms rather than operators (Röger, Helmert,
//!   Seipp and Sievers, "An Atom-Centric Perspective on Stubborn Sets", SoCS 2020).
//!   Expanding only the applicable operators of a strong stubborn set preserves
//!   completeness and optimality of A* with any admissible heuristic.
//! - [`PruningConfig::Limited`]: another method, switched off for good when, after a
//!   number of expansions, it has pruned less than a required share of the successors.
//!
//! Written from the papers and from how Fast Downward structures its `search/pruning/`
//! (read, not copied): the same queue discipline and atom selection, so that the same
//! states are pruned and the expansions match Fast Downward's on the same translation.

use task::{OpId, Task};

/// A pruning method as the search string names it.
#[derive(Debug, Clone, PartialEq, Eq, Default)]
pub enum PruningConfig {
    /// `null()`: no pruning (the default).
    #[default]
    Null,
    /// `atom_centric_stubborn_sets(use_sibling_shortcut=true, atom_selection_strategy=quick_skip)`.
    AtomCentricStubbornSets(StubbornSetsConfig),
    /// `limited_pruning(pruning=..., min_required_pruning_ratio=0.2,
    /// expansions_before_checking_pruning_ratio=1000)`.
    Limited(LimitedPruningConfig),
}

/// The options of `atom_centric_stubborn_sets(...)`, with Fast Downward's names and
/// defaults.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct StubbornSetsConfig {
    /// `use_sibling_shortcut` (default true): remember per variable which of its values
    /// has not had its producers (consumers) enqueued yet, so that "all other values of
    /// the variable" is enqueued once, not once per value.
    pub use_sibling_shortcut: bool,
    /// `atom_selection_strategy` (default `quick_skip`).
    pub atom_selection_strategy: AtomSelectionStrategy,
}

impl Default for StubbornSetsConfig {
    fn default() -> StubbornSetsConfig {
        StubbornSetsConfig {
            use_sibling_shortcut: true,
            atom_selection_strategy: AtomSelectionStrategy::QuickSkip,
        }
    }
}

/// Which unsatisfied atom of a goal or of an operator's preconditions is a necessary
/// enabling set; ties go to the first atom in variable order in every strategy.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum AtomSelectionStrategy {
    /// `fast_downward`: the first unsatisfied atom in variable order.
    FastDownward,
    /// `quick_skip`: an unsatisfied atom whose producers are enqueued already, if there
    /// is one; else the first.
    QuickSkip,
    /// `static_small`: the atom with the fewest achievers.
    StaticSmall,
    /// `dynamic_small`: the atom with the fewest achievers not yet stubborn.
    DynamicSmall,
}

impl AtomSelectionStrategy {
    /// Every strategy, in the order error messages list them.
    pub const ALL: [AtomSelectionStrategy; 4] = [
        AtomSelectionStrategy::FastDownward,
        AtomSelectionStrategy::QuickSkip,
        AtomSelectionStrategy::StaticSmall,
        AtomSelectionStrategy::DynamicSmall,
    ];

    /// Its name in search strings.
    pub fn name(self) -> &'static str {
        match self {
            AtomSelectionStrategy::FastDownward => "fast_downward",
            AtomSelectionStrategy::QuickSkip => "quick_skip",
            AtomSelectionStrategy::StaticSmall => "static_small",
            AtomSelectionStrategy::DynamicSmall => "dynamic_small",
        }
    }

    /// The strategy of a name, if there is one.
    pub fn from_name(name: &str) -> Option<AtomSelectionStrategy> {
        AtomSelectionStrategy::ALL
            .into_iter()
            .find(|s| s.name() == name)
    }
}

/// The options of `limited_pruning(...)`, with Fast Downward's names and defaults.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct LimitedPruningConfig {
    /// `pruning`: the method applied while it prunes enough.
    pub pruning: Box<PruningConfig>,
    /// `min_required_pruning_ratio` (default 0.2, in [0, 1]).
    pub min_required_pruning_ratio: Ratio,
    /// `expansions_before_checking_pruning_ratio` (default 1000; `u64::MAX`: never).
    pub expansions_before_checking_pruning_ratio: u64,
}

impl LimitedPruningConfig {
    /// `limited_pruning(pruning=pruning)` with the default options.
    pub fn new(pruning: PruningConfig) -> LimitedPruningConfig {
        LimitedPruningConfig {
            pruning: Box::new(pruning),
            min_required_pruning_ratio: Ratio(0.2),
            expansions_before_checking_pruning_ratio: 1000,
        }
    }
}

/// A share between 0 and 1, compared by its bits (so that configurations are `Eq`).
#[derive(Debug, Clone, Copy)]
pub struct Ratio(pub f64);

impl PartialEq for Ratio {
    fn eq(&self, other: &Ratio) -> bool {
        self.0.to_bits() == other.0.to_bits()
    }
}

impl Eq for Ratio {}

/// What pruning did in a search, for Fast Downward's closing lines ("total successors
/// before pruning", "total successors after pruning", "Pruning ratio") and
/// `--stats-json`.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct PruningStatistics {
    /// Applicable operators of the pruned states, summed.
    pub successors_before: u64,
    /// Operators left by pruning, summed.
    pub successors_after: u64,
    /// The check of `limited_pruning`, where it was made.
    pub check: Option<RatioCheck>,
}

impl PruningStatistics {
    /// The share of successors pruned; 1 when nothing was pruned because nothing was
    /// applicable (as Fast Downward reports it).
    pub fn ratio(&self) -> f64 {
        ratio(self.successors_before, self.successors_after)
    }
}

fn ratio(before: u64, after: u64) -> f64 {
    if before == 0 {
        1.0
    } else {
        1.0 - after as f64 / before as f64
    }
}

/// `limited_pruning`'s one check of the pruning ratio.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct RatioCheck {
    /// The pruning calls before the check (`expansions_before_checking_pruning_ratio`).
    pub calls: u64,
    /// The ratio found then, as a share of `successors_before`.
    pub successors_before: u64,
    /// Successors left by then.
    pub successors_after: u64,
    /// The ratio it had to reach.
    pub min_required: Ratio,
    /// Whether pruning was switched off.
    pub switched_off: bool,
}

impl RatioCheck {
    /// The pruning ratio at the check.
    pub fn ratio(&self) -> f64 {
        ratio(self.successors_before, self.successors_after)
    }

    /// Fast Downward's lines for the check: `Pruning ratio after 1000 calls: 0.000000`
    /// and, when it switched pruning off, `-- pruning ratio is lower than minimum
    /// pruning ratio (0.200000) -> switching off pruning`.
    pub fn log_lines(&self) -> Vec<String> {
        let mut lines = vec![format!(
            "Pruning ratio after {} calls: {:.6}",
            self.calls,
            self.ratio()
        )];
        if self.switched_off {
            lines.push(format!(
                "-- pruning ratio is lower than minimum pruning ratio ({:.6}) -> switching off pruning",
                self.min_required.0
            ));
        }
        lines
    }
}

impl PruningConfig {
    /// The method for `task`, ready to prune; `None` for `null()`.
    pub fn build(&self, task: &Task) -> Option<Pruning> {
        let kind = self.kind(task)?;
        Some(Pruning {
            kind,
            statistics: PruningStatistics::default(),
        })
    }

    fn kind(&self, task: &Task) -> Option<Kind> {
        match self {
            PruningConfig::Null => None,
            PruningConfig::AtomCentricStubbornSets(config) => {
                Some(Kind::Stubborn(Box::new(StubbornSets::new(task, *config))))
            }
            PruningConfig::Limited(config) => Some(Kind::Limited(Box::new(Limited {
                inner: config.pruning.kind(task),
                min_required: config.min_required_pruning_ratio,
                check_after: config.expansions_before_checking_pruning_ratio,
                calls: 0,
                disabled: false,
            }))),
        }
    }

    /// Fast Downward's lines when the search sets the method up: `pruning method:
    /// atom-centric stubborn sets`, then `pruning method: limited` around it.
    pub fn setup_lines(&self) -> Vec<&'static str> {
        match self {
            PruningConfig::Null => vec!["pruning method: none"],
            PruningConfig::AtomCentricStubbornSets(_) => {
                vec!["pruning method: atom-centric stubborn sets"]
            }
            PruningConfig::Limited(config) => {
                let mut lines = config.pruning.setup_lines();
                lines.push("pruning method: limited");
                lines
            }
        }
    }
}

/// A pruning method built for a task ([`PruningConfig::build`]), with its counters.
#[derive(Debug)]
pub struct Pruning {
    kind: Kind,
    statistics: PruningStatistics,
}

#[derive(Debug)]
enum Kind {
    Stubborn(Box<StubbornSets>),
    Limited(Box<Limited>),
}

#[derive(Debug)]
struct Limited {
    inner: Option<Kind>,
    min_required: Ratio,
    check_after: u64,
    calls: u64,
    disabled: bool,
}

impl Pruning {
    /// Keeps, of `applicable` (the operators applicable in `state`, a non-goal state),
    /// those the method does not prune, in their order. O(size of the task) at worst
    /// per call; the stubborn-set computation touches only the atoms and operators it
    /// reaches, and clears only those afterwards.
    pub fn prune(&mut self, state: &[u32], applicable: &mut Vec<OpId>) {
        let before = applicable.len() as u64;
        prune_with(&mut self.kind, &mut self.statistics, state, applicable);
        self.statistics.successors_before += before;
        self.statistics.successors_after += applicable.len() as u64;
    }

    /// What it did so far.
    pub fn statistics(&self) -> PruningStatistics {
        self.statistics
    }
}

/// Prunes with `kind`; `statistics` are those of the outermost method (what a limited
/// method checks its ratio on, as Fast Downward does).
fn prune_with(
    kind: &mut Kind,
    statistics: &mut PruningStatistics,
    state: &[u32],
    applicable: &mut Vec<OpId>,
) {
    match kind {
        Kind::Stubborn(s) => s.prune(state, applicable),
        Kind::Limited(limited) => {
            if limited.disabled {
                return;
            }
            if limited.calls == limited.check_after && limited.min_required.0 > 0.0 {
                let check = RatioCheck {
                    calls: limited.calls,
                    successors_before: statistics.successors_before,
                    successors_after: statistics.successors_after,
                    min_required: limited.min_required,
                    switched_off: false,
                };
                let switched_off = check.ratio() < limited.min_required.0;
                statistics.check = Some(RatioCheck {
                    switched_off,
                    ..check
                });
                if switched_off {
                    limited.disabled = true;
                    return;
                }
            }
            limited.calls += 1;
            if let Some(inner) = &mut limited.inner {
                prune_with(inner, statistics, state, applicable);
            }
        }
    }
}

/// No value of a variable marked yet (sibling shortcut).
const MARKED_NONE: u32 = u32::MAX;
/// Every value of a variable marked (sibling shortcut).
const MARKED_ALL: u32 = u32::MAX - 1;

/// Atom-centric strong stubborn sets for one task: the static tables and the per-call
/// marks, cleared after each call by what was touched.
#[derive(Debug)]
struct StubbornSets {
    tables: Tables,
    marks: Marks,
    config: StubbornSetsConfig,
}

/// The task as the computation reads it; atoms are numbered `offset[var] + value`.
#[derive(Debug)]
struct Tables {
    offset: Vec<u32>,
    /// The variable of each atom.
    atom_var: Vec<u32>,
    /// Goal atoms, sorted by variable.
    goal: Vec<(u32, u32)>,
    /// Preconditions and effects of each operator as `(var, value)`, sorted by variable.
    pre_start: Vec<u32>,
    pre: Vec<(u32, u32)>,
    eff_start: Vec<u32>,
    eff: Vec<(u32, u32)>,
    /// Operators with an effect on each atom, in operator order.
    achievers_start: Vec<u32>,
    achievers: Vec<u32>,
    /// Operators with a precondition on each atom, in operator order.
    consumers_start: Vec<u32>,
    consumers: Vec<u32>,
}

#[derive(Debug, Default)]
struct Marks {
    stubborn: Vec<bool>,
    stubborn_ops: Vec<u32>,
    producers: Vec<bool>,
    consumers: Vec<bool>,
    /// Atoms marked in `producers` or `consumers`, to clear them.
    touched_atoms: Vec<u32>,
    producer_var: Vec<u32>,
    consumer_var: Vec<u32>,
    touched_vars: Vec<u32>,
    producer_queue: Vec<u32>,
    consumer_queue: Vec<u32>,
}

/// Flattens per-item lists into `(start, items)`.
fn flatten<T: Copy>(lists: &[Vec<T>]) -> (Vec<u32>, Vec<T>) {
    let mut start = Vec::with_capacity(lists.len() + 1);
    let mut items = Vec::new();
    start.push(0);
    for list in lists {
        items.extend_from_slice(list);
        start.push(items.len() as u32);
    }
    (start, items)
}

impl Tables {
    fn new(task: &Task) -> Tables {
        let mut offset = Vec::with_capacity(task.variables.len() + 1);
        let mut atom_var = Vec::new();
        offset.push(0);
        for (v, var) in task.variables.iter().enumerate() {
            atom_var.extend(std::iter::repeat_n(v as u32, var.domain_size() as usize));
            offset.push(atom_var.len() as u32);
        }
        let atoms = atom_var.len();
        let pair = |f: &task::Fact| (f.var.0, f.value);
        let sorted = |facts: &[task::Fact]| {
            let mut v: Vec<(u32, u32)> = facts.iter().map(pair).collect();
            v.sort_unstable();
            v
        };
        let pres: Vec<Vec<(u32, u32)>> = task
            .operators
            .iter()
            .map(|op| sorted(&op.preconditions))
            .collect();
        let effs: Vec<Vec<(u32, u32)>> = task
            .operators
            .iter()
            .map(|op| sorted(&op.effects))
            .collect();
        let mut achievers = vec![Vec::new(); atoms];
        let mut consumers = vec![Vec::new(); atoms];
        for (o, (pre, eff)) in pres.iter().zip(&effs).enumerate() {
            for &(v, x) in eff {
                achievers[(offset[v as usize] + x) as usize].push(o as u32);
            }
            for &(v, x) in pre {
                consumers[(offset[v as usize] + x) as usize].push(o as u32);
            }
        }
        let (pre_start, pre) = flatten(&pres);
        let (eff_start, eff) = flatten(&effs);
        let (achievers_start, achievers) = flatten(&achievers);
        let (consumers_start, consumers) = flatten(&consumers);
        Tables {
            offset,
            atom_var,
            goal: sorted(&task.goal),
            pre_start,
            pre,
            eff_start,
            eff,
            achievers_start,
            achievers,
            consumers_start,
            consumers,
        }
    }

    fn atom(&self, (var, value): (u32, u32)) -> u32 {
        self.offset[var as usize] + value
    }

    fn achievers(&self, atom: u32) -> &[u32] {
        let a = atom as usize;
        &self.achievers[self.achievers_start[a] as usize..self.achievers_start[a + 1] as usize]
    }
}

impl StubbornSets {
    fn new(task: &Task, config: StubbornSetsConfig) -> StubbornSets {
        let tables = Tables::new(task);
        let atoms = tables.atom_var.len();
        let vars = task.variables.len();
        let marks = Marks {
            stubborn: vec![false; task.operators.len()],
            producers: vec![false; atoms],
            consumers: vec![false; atoms],
            producer_var: vec![MARKED_NONE; vars],
            consumer_var: vec![MARKED_NONE; vars],
            ..Marks::default()
        };
        StubbornSets {
            tables,
            marks,
            config,
        }
    }

    /// The operators of a strong stubborn set for `state` that are in `applicable`.
    fn prune(&mut self, state: &[u32], applicable: &mut Vec<OpId>) {
        self.compute(state);
        let stubborn = &self.marks.stubborn;
        applicable.retain(|op| stubborn[op.index()]);
        self.clear();
    }

    /// Marks a strong stubborn set for `state` in `marks.stubborn`. Starts from the
    /// producers of an unsatisfied goal atom; an applicable stubborn operator adds the
    /// producers of the other values of the variables it reads or writes and the
    /// consumers of the other values of those it writes (whatever can disable it, or
    /// conflict with it, or be disabled by it); an inapplicable one adds the producers of
    /// one of its unsatisfied preconditions (a necessary enabling set). Producers are
    /// handled before consumers, each queue last-in first-out.
    fn compute(&mut self, state: &[u32]) {
        let Some(goal) = self.select(&self.tables.goal, state) else {
            return; // A goal state: nothing to expand.
        };
        self.enqueue_producers(goal);
        loop {
            if let Some(atom) = self.marks.producer_queue.pop() {
                for i in self.tables.achievers_start[atom as usize]
                    ..self.tables.achievers_start[atom as usize + 1]
                {
                    let op = self.tables.achievers[i as usize];
                    self.handle(state, op);
                }
            } else if let Some(atom) = self.marks.consumer_queue.pop() {
                for i in self.tables.consumers_start[atom as usize]
                    ..self.tables.consumers_start[atom as usize + 1]
                {
                    let op = self.tables.consumers[i as usize];
                    self.handle(state, op);
                }
            } else {
                break;
            }
        }
    }

    fn handle(&mut self, state: &[u32], op: u32) {
        if self.marks.stubborn[op as usize] {
            return;
        }
        self.marks.stubborn[op as usize] = true;
        self.marks.stubborn_ops.push(op);
        let (start, end) = (
            self.tables.pre_start[op as usize] as usize,
            self.tables.pre_start[op as usize + 1] as usize,
        );
        match self.select(&self.tables.pre[start..end], state) {
            // Inapplicable: a necessary enabling set.
            Some(atom) => self.enqueue_producers(atom),
            None => {
                for i in start..end {
                    let fact = self.tables.pre[i];
                    self.enqueue_siblings(fact, Side::Producers);
                }
                let (start, end) = (
                    self.tables.eff_start[op as usize] as usize,
                    self.tables.eff_start[op as usize + 1] as usize,
                );
                for i in start..end {
                    let fact = self.tables.eff[i];
                    self.enqueue_siblings(fact, Side::Producers);
                    self.enqueue_siblings(fact, Side::Consumers);
                }
            }
        }
    }

    /// The unsatisfied atom of `facts` the strategy picks, `None` if all hold.
    fn select(&self, facts: &[(u32, u32)], state: &[u32]) -> Option<u32> {
        let unsatisfied = facts
            .iter()
            .filter(|&&(v, x)| state[v as usize] != x)
            .map(|&f| self.tables.atom(f));
        match self.config.atom_selection_strategy {
            AtomSelectionStrategy::FastDownward => unsatisfied.into_iter().next(),
            AtomSelectionStrategy::QuickSkip => {
                let mut first = None;
                for atom in unsatisfied {
                    if self.marks.producers[atom as usize] {
                        return Some(atom);
                    }
                    first = first.or(Some(atom));
                }
                first
            }
            AtomSelectionStrategy::StaticSmall => {
                min_by_count(unsatisfied, |atom| self.tables.achievers(atom).len())
            }
            AtomSelectionStrategy::DynamicSmall => min_by_count(unsatisfied, |atom| {
                self.tables
                    .achievers(atom)
                    .iter()
                    .filter(|&&op| !self.marks.stubborn[op as usize])
                    .count()
            }),
        }
    }

    fn enqueue_producers(&mut self, atom: u32) {
        self.enqueue(atom, Side::Producers);
    }

    fn enqueue(&mut self, atom: u32, side: Side) {
        let m = &mut self.marks;
        let (marked, other, queue) = match side {
            Side::Producers => (&mut m.producers, &m.consumers, &mut m.producer_queue),
            Side::Consumers => (&mut m.consumers, &m.producers, &mut m.consumer_queue),
        };
        let a = atom as usize;
        if !marked[a] {
            if !other[a] {
                m.touched_atoms.push(atom);
            }
            marked[a] = true;
            queue.push(atom);
        }
    }

    /// Enqueues the producers (consumers) of every other value of `fact`'s variable;
    /// with the sibling shortcut, only of those not enqueued before.
    fn enqueue_siblings(&mut self, (var, value): (u32, u32), side: Side) {
        let begin = self.tables.offset[var as usize];
        let end = self.tables.offset[var as usize + 1];
        let mark = if self.config.use_sibling_shortcut {
            let marks = match side {
                Side::Producers => &self.marks.producer_var,
                Side::Consumers => &self.marks.consumer_var,
            };
            marks[var as usize]
        } else {
            MARKED_NONE
        };
        let new_mark = if mark == MARKED_NONE {
            for atom in begin..end {
                if atom - begin != value {
                    self.enqueue(atom, side);
                }
            }
            value
        } else if mark != MARKED_ALL && mark != value {
            // Every value but `mark` is enqueued already: only it is left.
            self.enqueue(begin + mark, side);
            MARKED_ALL
        } else {
            return;
        };
        if self.config.use_sibling_shortcut {
            let m = &mut self.marks;
            if m.producer_var[var as usize] == MARKED_NONE
                && m.consumer_var[var as usize] == MARKED_NONE
            {
                m.touched_vars.push(var);
            }
            match side {
                Side::Producers => m.producer_var[var as usize] = new_mark,
                Side::Consumers => m.consumer_var[var as usize] = new_mark,
            }
        }
    }

    /// Resets the marks of the last computation, touching only what it marked.
    fn clear(&mut self) {
        let m = &mut self.marks;
        for op in m.stubborn_ops.drain(..) {
            m.stubborn[op as usize] = false;
        }
        for atom in m.touched_atoms.drain(..) {
            m.producers[atom as usize] = false;
            m.consumers[atom as usize] = false;
        }
        for var in m.touched_vars.drain(..) {
            m.producer_var[var as usize] = MARKED_NONE;
            m.consumer_var[var as usize] = MARKED_NONE;
        }
        debug_assert!(m.producer_queue.is_empty() && m.consumer_queue.is_empty());
    }
}

#[derive(Debug, Clone, Copy)]
enum Side {
    Producers,
    Consumers,
}

/// The first item with the smallest count.
fn min_by_count(items: impl Iterator<Item = u32>, count: impl Fn(u32) -> usize) -> Option<u32> {
    let mut best: Option<(usize, u32)> = None;
    for item in items {
        let c = count(item);
        if best.is_none_or(|(b, _)| c < b) {
            best = Some((c, item));
        }
    }
    best.map(|(_, item)| item)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::test_tasks::{op, task};

    /// The stubborn operators of `state` among all applicable ones, by name.
    fn kept(task: &Task, config: StubbornSetsConfig, state: &[u32]) -> Vec<String> {
        let mut pruning = PruningConfig::AtomCentricStubbornSets(config)
            .build(task)
            .unwrap();
        let mut applicable: Vec<OpId> = (0..task.operators.len() as u32)
            .map(OpId)
            .filter(|op| task.is_applicable(&task.operators[op.index()], state))
            .collect();
        pruning.prune(state, &mut applicable);
        applicable
            .iter()
            .map(|op| task.operators[op.index()].name.clone())
            .collect()
    }

    /// Two independent switches, goal both on: only the operators of the first goal's
    /// variable are stubborn; the other switch waits (the classic interleaving).
    fn two_switches() -> Task {
        task(
            &[2, 2],
            &[0, 0],
            &[(0, 1), (1, 1)],
            vec![
                op("a-on", &[(0, 0)], &[(0, 1)], 1),
                op("b-on", &[(1, 0)], &[(1, 1)], 1),
                op("a-off", &[(0, 1)], &[(0, 0)], 1),
            ],
        )
    }

    #[test]
    fn independent_operators_are_pruned() {
        let t = two_switches();
        let config = StubbornSetsConfig::default();
        assert_eq!(kept(&t, config, &[0, 0]), ["a-on"]);
        // Once a is on, the unsatisfied goal is b's: only b-on, not a-off.
        assert_eq!(kept(&t, config, &[1, 0]), ["b-on"]);
        // b on, a off: a-on.
        assert_eq!(kept(&t, config, &[0, 1]), ["a-on"]);
    }

    #[test]
    fn interfering_operators_stay() {
        // a-on also switches b off: it conflicts with b-on, so once a-on is stubborn the
        // producers of b's other value (b-off-by-a) and consumers of b's other values
        // come in, and with them b-on.
        let t = task(
            &[2, 2],
            &[0, 0],
            &[(0, 1), (1, 1)],
            vec![
                op("a-on", &[(0, 0)], &[(0, 1), (1, 0)], 1),
                op("b-on", &[(1, 0)], &[(1, 1)], 1),
            ],
        );
        assert_eq!(
            kept(&t, StubbornSetsConfig::default(), &[0, 0]),
            ["a-on", "b-on"]
        );
    }

    #[test]
    fn necessary_enabling_sets_follow_unsatisfied_preconditions() {
        // Goal v0 = 1 needs `finish`, which needs v1 = 1; `prepare` sets it; `other`
        // touches only v2 and is pruned.
        let t = task(
            &[2, 2, 2],
            &[0, 0, 0],
            &[(0, 1)],
            vec![
                op("finish", &[(1, 1)], &[(0, 1)], 1),
                op("prepare", &[(1, 0)], &[(1, 1)], 1),
                op("other", &[(2, 0)], &[(2, 1)], 1),
            ],
        );
        for strategy in AtomSelectionStrategy::ALL {
            for use_sibling_shortcut in [true, false] {
                let config = StubbornSetsConfig {
                    use_sibling_shortcut,
                    atom_selection_strategy: strategy,
                };
                assert_eq!(kept(&t, config, &[0, 0, 0]), ["prepare"], "{config:?}");
            }
        }
    }

    #[test]
    fn quick_skip_prefers_atoms_whose_producers_are_marked() {
        // Goal v0 = 1, reached by `alt` (needs v2 = 1 and v3 = 1) and by `main` (needs
        // v1 = 1 and v2 = 1), handled in that order. `alt` picks v2 = 1 under both
        // strategies and enqueues its producers. For `main`, fast_downward picks the
        // first unsatisfied atom, v1 = 1 (so p1 is stubborn too); quick_skip picks v2 = 1,
        // whose producers are marked already, and p1 is pruned.
        let t = task(
            &[2, 2, 2, 2],
            &[0, 0, 0, 0],
            &[(0, 1)],
            vec![
                op("alt", &[(2, 1), (3, 1)], &[(0, 1)], 1),
                op("main", &[(1, 1), (2, 1)], &[(0, 1)], 1),
                op("p1", &[], &[(1, 1)], 1),
                op("p2", &[], &[(2, 1)], 1),
                op("p3", &[], &[(3, 1)], 1),
            ],
        );
        let fd = StubbornSetsConfig {
            atom_selection_strategy: AtomSelectionStrategy::FastDownward,
            ..StubbornSetsConfig::default()
        };
        assert_eq!(kept(&t, fd, &[0, 0, 0, 0]), ["p1", "p2"]);
        assert_eq!(
            kept(&t, StubbornSetsConfig::default(), &[0, 0, 0, 0]),
            ["p2"]
        );
    }

    #[test]
    fn limited_pruning_switches_off_below_the_ratio_and_counts_as_fast_downward() {
        // One switch: nothing is ever pruned, so the check after 3 calls switches off.
        let t = task(
            &[2],
            &[0],
            &[(0, 1)],
            vec![op("on", &[(0, 0)], &[(0, 1)], 1)],
        );
        let config = PruningConfig::Limited(LimitedPruningConfig {
            expansions_before_checking_pruning_ratio: 3,
            ..LimitedPruningConfig::new(PruningConfig::AtomCentricStubbornSets(
                StubbornSetsConfig::default(),
            ))
        });
        let mut pruning = config.build(&t).unwrap();
        for _ in 0..5 {
            let mut ops = vec![OpId(0)];
            pruning.prune(&[0], &mut ops);
            assert_eq!(ops, [OpId(0)]);
        }
        let s = pruning.statistics();
        assert_eq!((s.successors_before, s.successors_after), (5, 5));
        assert_eq!(s.ratio(), 0.0);
        let check = s.check.unwrap();
        assert_eq!((check.calls, check.switched_off), (3, true));
        assert_eq!(
            check.log_lines(),
            [
                "Pruning ratio after 3 calls: 0.000000",
                "-- pruning ratio is lower than minimum pruning ratio (0.200000) -> switching off pruning"
            ]
        );
        assert_eq!(
            config.setup_lines(),
            [
                "pruning method: atom-centric stubborn sets",
                "pruning method: limited"
            ]
        );

        // Pruning that prunes enough stays on: two_switches at [0, 0] halves.
        let t = two_switches();
        let config = PruningConfig::Limited(LimitedPruningConfig {
            expansions_before_checking_pruning_ratio: 2,
            ..LimitedPruningConfig::new(PruningConfig::AtomCentricStubbornSets(
                StubbornSetsConfig::default(),
            ))
        });
        let mut pruning = config.build(&t).unwrap();
        for _ in 0..4 {
            let mut ops = vec![OpId(0), OpId(1)];
            pruning.prune(&[0, 0], &mut ops);
            assert_eq!(ops, [OpId(0)]);
        }
        let check = pruning.statistics().check.unwrap();
        assert!(!check.switched_off);
        assert_eq!(check.ratio(), 0.5);
        assert_eq!(pruning.statistics().successors_after, 4);
    }

    #[test]
    fn marks_are_cleared_between_calls() {
        // The same state twice gives the same set; a different state after it is not
        // affected by marks of the first.
        let t = two_switches();
        let config = PruningConfig::AtomCentricStubbornSets(StubbornSetsConfig::default());
        let mut pruning = config.build(&t).unwrap();
        let all = || vec![OpId(0), OpId(1), OpId(2)];
        for (state, expected) in [
            (vec![0, 0], vec![OpId(0)]),
            (vec![0, 0], vec![OpId(0)]),
            (vec![1, 0], vec![OpId(1)]),
            (vec![0, 1], vec![OpId(0)]),
        ] {
            let mut ops: Vec<OpId> = all()
                .into_iter()
                .filter(|op| t.is_applicable(&t.operators[op.index()], &state))
                .collect();
            pruning.prune(&state, &mut ops);
            assert_eq!(ops, expected, "{state:?}");
        }
    }
}
