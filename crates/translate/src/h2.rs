//! h² mutexes (issue 25 item 2): forward h² reachability over the finite-domain task, as
//! Fast Downward's h² preprocessor runs it after translation (Alcázar and Torralba, "A
//! reminder about the importance of computing and exploiting invariants in planning",
//! ICAPS 2015). Written from the paper's definition, not from any implementation.
//!
//! h² over-approximates the facts and the pairs of facts that some reachable state holds.
//! It starts from the initial state's facts and pairs and applies every operator whose
//! preconditions are reachable and pairwise reachable: each effect becomes reachable, and
//! so does its pair with every other effect and with every fact that can hold together
//! with the whole precondition on a variable the operator does not change (prevail
//! conditions included). Pairs inside one of the task's mutex groups (invariant
//! synthesis's, which hold in every reachable state) are never made reachable. At the
//! fixpoint:
//!
//! - an operator whose preconditions are not all pairwise reachable never applies: it is
//!   removed;
//! - an unreachable fact (value) is removed, its variable's values renumbered; a variable
//!   left with one value is constant and removed, with the conditions on it;
//! - an operator left without effects changes nothing: it is removed;
//! - an unreachable pair of facts on two variables is a mutex: the pairs that no mutex
//!   group of the task already holds are added as groups of two;
//! - a goal with an unreachable fact or pair is unreachable: the task is unsolvable.
//!
//! Every reachable state keeps its facts, every plan its operators, so the optimal cost
//! and solvability stay. Backward h² (regression from the goal) is not done.
//!
//! Pairs are a bit matrix over the facts (`F²/8` bytes, checked against the memory limit
//! before it is allocated). An operator is looked at again only when the rows of its
//! preconditions changed since it was last looked at; one look costs `O(|pre| · F/64)`
//! word operations for the facts compatible with its precondition, plus the pairs it
//! adds. The deadline and the cancel flag are read every 1,024 looks.

use task::{Fact, Limit, Task, VarId};

use crate::watch::Watch;

/// What h² removed and found ([`h2_mutexes`]).
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct H2Stats {
    /// Operators that never apply (or change nothing once constant variables are gone).
    pub operators_removed: usize,
    /// Unreachable facts (values) removed.
    pub facts_removed: usize,
    /// Variables left with a single reachable value, removed.
    pub variables_removed: usize,
    /// Mutex pairs found that no mutex group of the task held, added as groups of two.
    pub mutexes_added: usize,
}

impl H2Stats {
    /// Fast Downward-style log lines, one per category, each without a newline.
    pub fn log_lines(&self) -> [String; 4] {
        [
            format!(
                "h2: removed {} unreachable operator(s)",
                self.operators_removed
            ),
            format!("h2: removed {} unreachable fact(s)", self.facts_removed),
            format!(
                "h2: removed {} variable(s) with one reachable value",
                self.variables_removed
            ),
            format!("h2: added {} mutex pair(s)", self.mutexes_added),
        ]
    }
}

/// How [`h2_mutexes`] ended.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum H2Outcome {
    /// The task was pruned as the module says.
    Pruned(H2Stats),
    /// The goal has an h²-unreachable fact or pair: the task is unsolvable (left as it was).
    Unsolvable(String),
    /// A limit was reached before the fixpoint; the task is left as it was.
    Stopped(Limit),
}

/// Runs forward h² on `task` under `limits` and prunes it as the module says.
pub fn h2_mutexes(task: &mut Task, limits: &task::Limits) -> H2Outcome {
    run(task, &Watch::new(limits))
}

/// [`h2_mutexes`] under a translation's watch.
pub(crate) fn run(task: &mut Task, watch: &Watch<'_>) -> H2Outcome {
    let facts = Facts::new(task);
    let Some(pairs) = Reachability::compute(task, &facts, watch) else {
        return H2Outcome::Stopped(watch.stopped().unwrap_or(Limit::Time));
    };
    let goal: Vec<usize> = task.goal.iter().map(|&f| facts.id(f)).collect();
    for (i, &g) in goal.iter().enumerate() {
        if !pairs.reachable(g) {
            let name = facts.name(task, g);
            return H2Outcome::Unsolvable(format!("the goal fact {name} is h2-unreachable"));
        }
        if let Some(&h) = goal[..i].iter().find(|&&h| !pairs.pair(g, h)) {
            let (a, b) = (facts.name(task, h), facts.name(task, g));
            return H2Outcome::Unsolvable(format!("the goal facts {a} and {b} are h2-mutex"));
        }
    }
    H2Outcome::Pruned(prune(task, &facts, &pairs))
}

/// Facts numbered densely: a variable's values are consecutive.
struct Facts {
    offset: Vec<usize>,
    count: usize,
}

impl Facts {
    fn new(task: &Task) -> Facts {
        let mut offset = Vec::with_capacity(task.variables.len() + 1);
        let mut count = 0;
        for v in &task.variables {
            offset.push(count);
            count += v.value_names.len();
        }
        offset.push(count);
        Facts { offset, count }
    }

    fn id(&self, f: Fact) -> usize {
        self.offset[f.var.index()] + f.value as usize
    }

    fn name(&self, task: &Task, id: usize) -> String {
        let var = self.offset.partition_point(|&o| o <= id) - 1;
        let v = &task.variables[var];
        let value = id - self.offset[var];
        format!("{}={} ({})", v.name, value, v.value_names[value])
    }
}

/// Words of a bit set over `n` bits.
fn words(n: usize) -> usize {
    n.div_ceil(64)
}

fn test(set: &[u64], bit: usize) -> bool {
    set[bit / 64] >> (bit % 64) & 1 == 1
}

fn set(set: &mut [u64], bit: usize) {
    set[bit / 64] |= 1 << (bit % 64);
}

/// Clears bits `from..to`.
fn clear_range(set: &mut [u64], from: usize, to: usize) {
    for bit in from..to {
        set[bit / 64] &= !(1 << (bit % 64));
    }
}

/// The reachable pairs at the fixpoint: row `f` holds the facts reachable together with
/// `f`, and `f` itself when `f` is reachable.
struct Reachability {
    rows: Vec<u64>,
    width: usize,
    applicable: Vec<bool>,
}

impl Reachability {
    fn row(&self, f: usize) -> &[u64] {
        &self.rows[f * self.width..(f + 1) * self.width]
    }

    fn reachable(&self, f: usize) -> bool {
        test(self.row(f), f)
    }

    fn pair(&self, f: usize, g: usize) -> bool {
        test(self.row(f), g)
    }

    /// The fixpoint, or `None` once a limit is reached.
    fn compute(task: &Task, facts: &Facts, watch: &Watch<'_>) -> Option<Reachability> {
        let n = facts.count;
        let width = words(n);
        let groups = task.mutexes.len();
        let bytes = (n + groups + 2) as u64 * width as u64 * 8 + task.operators.len() as u64 * 9;
        if watch.would_exceed(bytes) {
            return None;
        }
        // Each mutex group of the task as a bit set, and the groups of each fact.
        let mut group_bits = vec![0u64; groups * width];
        let mut groups_of: Vec<Vec<usize>> = vec![Vec::new(); n];
        for (g, group) in task.mutexes.iter().enumerate() {
            for &f in group {
                let id = facts.id(f);
                set(&mut group_bits[g * width..(g + 1) * width], id);
                groups_of[id].push(g);
            }
        }
        let mut h2 = Reachability {
            rows: vec![0u64; n * width],
            width,
            applicable: vec![false; task.operators.len()],
        };
        let mut reach = vec![0u64; width];
        let init: Vec<usize> = (0..task.variables.len())
            .map(|v| facts.id(Fact::new(VarId(v as u32), task.initial_state[v])))
            .collect();
        for &f in &init {
            set(&mut reach, f);
            for &g in &init {
                set(&mut h2.rows[f * width..(f + 1) * width], g);
            }
        }
        // Change tracking: `clock` counts changes; a fact's row, and the reachable set,
        // remember the clock of their last change, an operator the clock it was last
        // looked at with. Its look depends only on its preconditions' rows (on the
        // reachable set without preconditions), so it is looked at again only when one
        // of them changed since.
        let mut clock: u64 = 1;
        let mut row_changed = vec![1u64; n];
        let mut reach_changed = 1u64;
        let mut looked = vec![0u64; task.operators.len()];
        let mut compatible = vec![0u64; width];
        let mut added = vec![0u64; width];
        let mut effects = vec![0u64; width];
        let pre_ids: Vec<Vec<usize>> = task
            .operators
            .iter()
            .map(|o| o.preconditions.iter().map(|&f| facts.id(f)).collect())
            .collect();
        let eff_ids: Vec<Vec<usize>> = task
            .operators
            .iter()
            .map(|o| o.effects.iter().map(|&f| facts.id(f)).collect())
            .collect();
        loop {
            let sweep_start = clock;
            for (o, op) in task.operators.iter().enumerate() {
                if watch.tick() {
                    return None;
                }
                let pre = &pre_ids[o];
                let stale = match pre.iter().map(|&p| row_changed[p]).max() {
                    Some(c) => c > looked[o],
                    None => reach_changed > looked[o],
                };
                if !stale {
                    continue;
                }
                looked[o] = clock;
                let applies = pre
                    .iter()
                    .enumerate()
                    .all(|(i, &p)| pre[..=i].iter().all(|&q| h2.pair(p, q)));
                if !applies {
                    continue;
                }
                h2.applicable[o] = true;
                // The facts that can hold together with the whole precondition, on the
                // variables the operator leaves alone, and the effects themselves.
                match pre.split_first() {
                    Some((&first, rest)) => {
                        compatible.copy_from_slice(h2.row(first));
                        for &p in rest {
                            for (c, r) in compatible.iter_mut().zip(h2.row(p)) {
                                *c &= r;
                            }
                        }
                    }
                    None => compatible.copy_from_slice(&reach),
                }
                effects.iter_mut().for_each(|w| *w = 0);
                for (f, &e) in op.effects.iter().zip(&eff_ids[o]) {
                    let v = f.var.index();
                    clear_range(&mut compatible, facts.offset[v], facts.offset[v + 1]);
                    set(&mut effects, e);
                }
                for (c, e) in compatible.iter_mut().zip(&effects) {
                    *c |= e;
                }
                for &e in &eff_ids[o] {
                    added.copy_from_slice(&compatible);
                    for &g in &groups_of[e] {
                        for (a, m) in added.iter_mut().zip(&group_bits[g * width..]) {
                            *a &= !m;
                        }
                    }
                    set(&mut added, e);
                    let row = &mut h2.rows[e * width..(e + 1) * width];
                    let mut new = false;
                    for (a, r) in added.iter_mut().zip(row.iter_mut()) {
                        *a &= !*r;
                        *r |= *a;
                        new |= *a != 0;
                    }
                    if !new {
                        continue;
                    }
                    clock += 1;
                    row_changed[e] = clock;
                    if !test(&reach, e) {
                        set(&mut reach, e);
                        reach_changed = clock;
                    }
                    for (w, &bits) in added.iter().enumerate() {
                        let mut bits = bits;
                        while bits != 0 {
                            let q = w * 64 + bits.trailing_zeros() as usize;
                            bits &= bits - 1;
                            if q != e {
                                set(&mut h2.rows[q * width..(q + 1) * width], e);
                                row_changed[q] = clock;
                            }
                        }
                    }
                }
            }
            if clock == sweep_start {
                return if watch.check() { None } else { Some(h2) };
            }
        }
    }
}

/// Removes what h² proved unreachable and adds its new mutexes; see the module.
fn prune(task: &mut Task, facts: &Facts, h2: &Reachability) -> H2Stats {
    let mut stats = H2Stats::default();
    // The new index of each variable and value (`None`: removed).
    let mut new_var: Vec<Option<u32>> = Vec::with_capacity(task.variables.len());
    let mut new_value: Vec<Vec<Option<u32>>> = Vec::with_capacity(task.variables.len());
    let mut kept_vars = 0u32;
    for (v, var) in task.variables.iter().enumerate() {
        let mut next = 0u32;
        let values: Vec<Option<u32>> = (0..var.value_names.len())
            .map(|x| {
                h2.reachable(facts.offset[v] + x).then(|| {
                    next += 1;
                    next - 1
                })
            })
            .collect();
        stats.facts_removed += values.iter().filter(|x| x.is_none()).count();
        // A variable with one value is constant; one stays if all are, so that the task
        // keeps a variable.
        let last_chance = v + 1 == task.variables.len() && kept_vars == 0;
        if next > 1 || last_chance {
            new_var.push(Some(kept_vars));
            kept_vars += 1;
        } else {
            new_var.push(None);
            stats.variables_removed += 1;
        }
        new_value.push(values);
    }
    let map = |f: Fact| -> Option<Fact> {
        let var = new_var[f.var.index()]?;
        Some(Fact::new(
            VarId(var),
            new_value[f.var.index()][f.value as usize]?,
        ))
    };
    let map_all = |fs: &[Fact]| -> Vec<Fact> { fs.iter().filter_map(|&f| map(f)).collect() };
    // Mutex pairs no group of the task holds, on kept variables, before renumbering.
    let mut in_group = vec![0u64; h2.width];
    let mut new_pairs: Vec<Vec<Fact>> = Vec::new();
    let fact_of = |id: usize| {
        let var = facts.offset.partition_point(|&o| o <= id) - 1;
        Fact::new(VarId(var as u32), (id - facts.offset[var]) as u32)
    };
    let groups_of = {
        let mut g: Vec<Vec<usize>> = vec![Vec::new(); facts.count];
        for (i, group) in task.mutexes.iter().enumerate() {
            for &f in group {
                g[facts.id(f)].push(i);
            }
        }
        g
    };
    for (p, groups) in groups_of.iter().enumerate() {
        let fp = fact_of(p);
        if !h2.reachable(p) || new_var[fp.var.index()].is_none() {
            continue;
        }
        in_group.iter_mut().for_each(|w| *w = 0);
        for &g in groups {
            for &f in &task.mutexes[g] {
                set(&mut in_group, facts.id(f));
            }
        }
        for q in facts.offset[fp.var.index() + 1]..facts.count {
            let fq = fact_of(q);
            if h2.reachable(q)
                && new_var[fq.var.index()].is_some()
                && !h2.pair(p, q)
                && !test(&in_group, q)
            {
                new_pairs.push(vec![fp, fq]);
            }
        }
    }
    stats.mutexes_added = new_pairs.len();
    let before = task.operators.len();
    let mut index = 0;
    task.operators.retain_mut(|op| {
        let keep = h2.applicable[index];
        index += 1;
        if keep {
            op.preconditions = map_all(&op.preconditions);
            op.effects = map_all(&op.effects);
        }
        keep && !op.effects.is_empty()
    });
    stats.operators_removed = before - task.operators.len();
    task.goal = map_all(&task.goal);
    let old_mutexes = std::mem::take(&mut task.mutexes);
    task.mutexes = old_mutexes
        .iter()
        .chain(&new_pairs)
        .map(|group| map_all(group))
        .filter(|group| group.len() >= 2)
        .collect();
    let old_vars = std::mem::take(&mut task.variables);
    let old_init = std::mem::take(&mut task.initial_state);
    for (v, mut var) in old_vars.into_iter().enumerate() {
        let Some(new) = new_var[v] else { continue };
        let mut x = 0;
        var.value_names.retain(|_| {
            x += 1;
            new_value[v][x - 1].is_some()
        });
        if var.name == format!("var{v}") {
            var.name = format!("var{new}");
        }
        task.variables.push(var);
        task.initial_state
            .push(new_value[v][old_init[v] as usize].unwrap_or(0));
    }
    stats
}

#[cfg(test)]
mod tests {
    use super::*;
    use task::testing::{op, task};

    fn pruned(t: &mut Task) -> H2Stats {
        match h2_mutexes(t, &task::Limits::default()) {
            H2Outcome::Pruned(stats) => stats,
            other => panic!("not pruned: {other:?}"),
        }
    }

    /// Two binary variables, a token moved between them: `a` and `b` are never both
    /// true (h² finds the mutex a relaxation misses), so `both`, which needs them
    /// together, never applies.
    fn token() -> Task {
        task(
            &[2, 2, 2],
            &[1, 0, 0],
            &[(2, 1)],
            vec![
                op("a-to-b", &[(0, 1), (1, 0)], &[(0, 0), (1, 1)], 1),
                op("b-to-a", &[(0, 0), (1, 1)], &[(0, 1), (1, 0)], 1),
                op("both", &[(0, 1), (1, 1)], &[(2, 1)], 1),
                op("one", &[(1, 1)], &[(2, 1)], 5),
            ],
        )
    }

    #[test]
    fn a_pair_no_state_holds_is_a_mutex_and_the_operator_needing_it_goes() {
        let mut t = token();
        let stats = pruned(&mut t);
        let names: Vec<&str> = t.operators.iter().map(|o| o.name.as_str()).collect();
        assert_eq!(names, ["a-to-b", "b-to-a", "one"]);
        assert_eq!(stats.operators_removed, 1);
        assert_eq!((stats.facts_removed, stats.variables_removed), (0, 0));
        // var0=1 with var1=1, and var0=0 with var1=0: the two pairs no state holds.
        let pair = |a: (u32, u32), b: (u32, u32)| {
            vec![Fact::new(VarId(a.0), a.1), Fact::new(VarId(b.0), b.1)]
        };
        assert_eq!(t.mutexes, vec![pair((0, 0), (1, 0)), pair((0, 1), (1, 1))]);
        assert_eq!(stats.mutexes_added, 2);
        assert_eq!(task::testing::optimal_cost(&t), Some(6));
        assert!(t.validate().is_ok());
    }

    #[test]
    fn unreachable_values_go_and_variables_left_constant_go_with_them() {
        let mut t = task(
            &[3, 2, 2],
            &[0, 0, 0],
            &[(2, 1)],
            vec![
                op("to1", &[(0, 0)], &[(0, 1)], 1),
                // Needs var1=1, which nothing reaches: never applies, so var0=2 is
                // unreachable, and var1 is constant.
                op("to2", &[(0, 1), (1, 1)], &[(0, 2)], 1),
                op("done", &[(0, 1), (1, 0)], &[(2, 1)], 1),
            ],
        );
        let stats = pruned(&mut t);
        assert_eq!(
            stats,
            H2Stats {
                operators_removed: 1,
                facts_removed: 2,
                variables_removed: 1,
                // var0=0 never holds with var2=1: nothing leads back to var0=0.
                mutexes_added: 1,
            }
        );
        assert_eq!(t.variables.len(), 2);
        assert_eq!(t.variables[0].value_names, ["v0-0", "v0-1"]);
        assert_eq!(
            (
                t.variables[1].name.as_str(),
                t.variables[1].value_names[1].as_str()
            ),
            ("var1", "v2-1")
        );
        assert_eq!(t.initial_state, [0, 0]);
        assert_eq!(t.goal, [Fact::new(VarId(1), 1)]);
        assert_eq!(t.operators[1].preconditions, [Fact::new(VarId(0), 1)]);
        assert_eq!(task::testing::optimal_cost(&t), Some(2));
        assert!(t.validate().is_ok());
    }

    #[test]
    fn a_goal_pair_h2_proves_mutex_is_unsolvable_and_the_task_stays() {
        let mut t = token();
        t.goal = vec![Fact::new(VarId(0), 1), Fact::new(VarId(1), 1)];
        let before = t.clone();
        let outcome = h2_mutexes(&mut t, &task::Limits::default());
        assert_eq!(
            outcome,
            H2Outcome::Unsolvable(
                "the goal facts var0=1 (v0-1) and var1=1 (v1-1) are h2-mutex".into()
            )
        );
        assert_eq!(t, before);
    }

    #[test]
    fn the_task_s_mutex_groups_prune_too_and_stay() {
        // Without the group, `both` applies in the relaxation of pairs only if var0=1 and
        // var1=1 are reachable together; the group says they never are.
        let mut t = task(
            &[2, 2, 2],
            &[0, 0, 0],
            &[(0, 1)],
            vec![
                op("a", &[], &[(0, 1)], 1),
                op("b", &[], &[(1, 1)], 1),
                op("both", &[(0, 1), (1, 1)], &[(2, 1)], 1),
            ],
        );
        let free = pruned(&mut t.clone());
        assert_eq!(free.operators_removed, 0);
        t.mutexes = vec![vec![Fact::new(VarId(0), 1), Fact::new(VarId(1), 1)]];
        let stats = pruned(&mut t);
        assert_eq!(stats.operators_removed, 1);
        // var2=1 went with `both`, and var2 with it.
        assert_eq!((stats.facts_removed, stats.variables_removed), (1, 1));
        assert_eq!(
            t.mutexes.len(),
            1,
            "the group stays, and is not added again"
        );
    }

    #[test]
    fn a_deadline_already_passed_stops_it_and_leaves_the_task() {
        let mut t = token();
        let before = t.clone();
        let limits = task::Limits {
            deadline: Some(std::time::Instant::now()),
            ..task::Limits::default()
        };
        assert_eq!(h2_mutexes(&mut t, &limits), H2Outcome::Stopped(Limit::Time));
        assert_eq!(t, before);
        let tiny = task::Limits {
            memory_limit_bytes: Some(8),
            ..task::Limits::default()
        };
        assert_eq!(h2_mutexes(&mut t, &tiny), H2Outcome::Stopped(Limit::Memory));
        assert_eq!(t, before);
    }
}
