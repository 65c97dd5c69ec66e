//! The test oracle of LM-cut: slow, obviously correct, and stating the supporter rule
//! whose values depend only on the costs (`SupporterRule::KeepRoundStart`, which exists
//! for this comparison alone).

use task::{Fact, Task};

/// LM-cut, recomputing h^max from scratch each round with plain fixpoint iterations:
/// slow and obviously correct. Facts are numbered as in `LmCut` (variable offsets, then the
/// always-true fact, then the goal fact). Supporters follow the same tie-breaking rules,
/// stated here as plainly as possible:
/// - an operator's preconditions are ordered by `super::tie_breaking_order`;
/// - round 1: the precondition reached last (`first_supporters`);
/// - later rounds: the supporter of the round before while it still has the highest
///   h^max, else the first precondition of highest h^max;
/// - while the goal zone is marked (depth first from the goal fact, achievers in operator
///   order), a zero-cost operator's supporter becomes the first precondition tying with it
///   that has no zero-cost achiever or is already in the zone.
pub(super) fn reference_lmcut(task: &Task, state: &[u32]) -> Option<u64> {
    const INF: u64 = u64::MAX;
    let mut offset = Vec::new();
    let mut n = 0usize;
    for v in &task.variables {
        offset.push(n);
        n += v.domain_size() as usize;
    }
    let (fact_i, fact_g) = (n, n + 1);
    let fact = |f: &Fact| offset[f.var.index()] + f.value as usize;
    let rank = task.atom_order_ranks();
    let mut ops: Vec<(Vec<usize>, Vec<usize>, u64)> = task
        .operators
        .iter()
        .map(|o| {
            let mut pre: Vec<usize> = super::tie_breaking_order(o, &rank).map(fact).collect();
            if pre.is_empty() {
                pre.push(fact_i);
            }
            (pre, o.effects.iter().map(fact).collect(), task.cost(o))
        })
        .collect();
    let mut goal: Vec<usize> = task.goal.iter().map(fact).collect();
    if goal.is_empty() {
        goal.push(fact_i);
    }
    ops.push((goal, vec![fact_g], 0));
    let mut in_state = vec![false; n + 2];
    for (var, &value) in state.iter().enumerate() {
        in_state[offset[var] + value as usize] = true;
    }
    in_state[fact_i] = true;
    let mut supporter = first_supporters(&ops, state, &offset, fact_i);
    let mut h = 0;
    loop {
        let mut hm: Vec<u64> = in_state.iter().map(|&t| if t { 0 } else { INF }).collect();
        loop {
            let mut changed = false;
            for (pre, eff, c) in &ops {
                if pre.iter().all(|&p| hm[p] != INF) {
                    let v = c + pre.iter().map(|&p| hm[p]).max().unwrap();
                    for &e in eff {
                        if v < hm[e] {
                            hm[e] = v;
                            changed = true;
                        }
                    }
                }
            }
            if !changed {
                break;
            }
        }
        if hm[fact_g] == INF {
            return None;
        }
        if hm[fact_g] == 0 {
            return Some(h);
        }
        for (o, (pre, _, _)) in ops.iter().enumerate() {
            if pre.iter().any(|&p| hm[p] == INF) {
                continue;
            }
            let best = pre.iter().map(|&p| hm[p]).max().unwrap();
            let keep = supporter[o].is_some_and(|s| hm[s] == best);
            if !keep {
                supporter[o] = pre.iter().copied().find(|&p| hm[p] == best);
            }
        }
        let mut zone = vec![false; n + 2];
        mark_zone(fact_g, &ops, &hm, &mut supporter, &mut zone);
        let enters_zone = |eff: &Vec<usize>, zone: &[bool]| eff.iter().any(|&e| zone[e]);
        let mut reached = in_state.clone();
        loop {
            let mut changed = false;
            for (o, (_, eff, _)) in ops.iter().enumerate() {
                // An operator entering the goal zone is in the cut; its other effects are
                // beyond the cut and not reached.
                if supporter[o].is_some_and(|s| reached[s]) && !enters_zone(eff, &zone) {
                    for &e in eff {
                        if !reached[e] {
                            reached[e] = true;
                            changed = true;
                        }
                    }
                }
            }
            if !changed {
                break;
            }
        }
        let cut: Vec<usize> = (0..ops.len())
            .filter(|&o| supporter[o].is_some_and(|s| reached[s]) && enters_zone(&ops[o].1, &zone))
            .collect();
        let m = cut.iter().map(|&o| ops[o].2).min().unwrap();
        assert!(m > 0, "a cut of zero cost");
        h += m;
        for &o in &cut {
            ops[o].2 -= m;
        }
    }
}

/// Round 1's supporters: for each operator, the precondition reached last by a Dijkstra
/// exploration whose queue keeps a stack per cost (of the facts queued at one cost, the
/// last queued comes out first). It starts with the state's facts in variable order, then
/// the always-true fact; a fact coming out triggers the operators it is a precondition of
/// in index order, and an operator whose preconditions are all reached queues its effects
/// in its order where they get cheaper. This is how both LmCut and Fast Downward explore.
fn first_supporters(
    ops: &[(Vec<usize>, Vec<usize>, u64)],
    state: &[u32],
    offset: &[usize],
    fact_i: usize,
) -> Vec<Option<usize>> {
    use std::collections::BTreeMap;
    let facts = fact_i + 2;
    let mut cost = vec![u64::MAX; facts];
    let mut unsatisfied: Vec<usize> = ops.iter().map(|(pre, _, _)| pre.len()).collect();
    let mut precondition_of: Vec<Vec<usize>> = vec![Vec::new(); facts];
    for (o, (pre, _, _)) in ops.iter().enumerate() {
        for &p in pre {
            precondition_of[p].push(o);
        }
    }
    let mut queue: BTreeMap<u64, Vec<usize>> = BTreeMap::new();
    let push = |queue: &mut BTreeMap<u64, Vec<usize>>, cost: &mut [u64], f: usize, c: u64| {
        if c < cost[f] {
            cost[f] = c;
            queue.entry(c).or_default().push(f);
        }
    };
    for (var, &value) in state.iter().enumerate() {
        push(&mut queue, &mut cost, offset[var] + value as usize, 0);
    }
    push(&mut queue, &mut cost, fact_i, 0);
    let mut supporter = vec![None; ops.len()];
    while let Some(mut entry) = queue.first_entry() {
        let c = *entry.key();
        let f = entry.get_mut().pop().unwrap();
        if entry.get().is_empty() {
            entry.remove();
        }
        if c > cost[f] {
            continue;
        }
        for &o in &precondition_of[f] {
            unsatisfied[o] -= 1;
            if unsatisfied[o] == 0 {
                supporter[o] = Some(f);
                for &e in &ops[o].1 {
                    push(&mut queue, &mut cost, e, c + ops[o].2);
                }
            }
        }
    }
    supporter
}

/// Marks the goal zone depth first from `fact`, breaking supporter ties of zero-cost
/// achievers on the way.
fn mark_zone(
    fact: usize,
    ops: &[(Vec<usize>, Vec<usize>, u64)],
    hm: &[u64],
    supporter: &mut [Option<usize>],
    zone: &mut [bool],
) {
    if zone[fact] {
        return;
    }
    zone[fact] = true;
    for o in 0..ops.len() {
        let (pre, eff, cost) = &ops[o];
        if *cost != 0 || !eff.contains(&fact) {
            continue;
        }
        let Some(current) = supporter[o] else {
            continue;
        };
        let target = hm[current];
        let no_zero_cost_achiever =
            |p: usize| !ops.iter().any(|(_, e, c)| *c == 0 && e.contains(&p));
        if let Some(p) = pre
            .iter()
            .copied()
            .find(|&p| hm[p] == target && (no_zero_cost_achiever(p) || zone[p]))
        {
            supporter[o] = Some(p);
        }
        let s = supporter[o].unwrap_or(current);
        mark_zone(s, ops, hm, supporter, zone);
    }
}
