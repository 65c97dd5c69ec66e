//! Test support shared by the integration tests: slow, obviously correct references.

use task::{Fact, Task};

/// LM-cut as the paper defines it, recomputing everything from scratch each round with
/// plain fixpoint iterations: slow and obviously correct. Facts are numbered as in
/// `LmCut` (variable offsets, then the always-true fact, then the goal fact); supporters
/// are the precondition of highest h^max, lowest index on ties.
pub fn reference_lmcut(task: &Task, state: &[u32]) -> Option<u64> {
    const INF: u64 = u64::MAX;
    let mut offset = Vec::new();
    let mut n = 0usize;
    for v in &task.variables {
        offset.push(n);
        n += v.domain_size() as usize;
    }
    let (fact_i, fact_g) = (n, n + 1);
    let fact = |f: &Fact| offset[f.var.index()] + f.value as usize;
    let mut ops: Vec<(Vec<usize>, Vec<usize>, u64)> = task
        .operators
        .iter()
        .map(|o| {
            let mut pre: Vec<usize> = o.preconditions.iter().map(fact).collect();
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
        let applicable = |pre: &Vec<usize>| pre.iter().all(|&p| hm[p] != INF);
        let supporter = |pre: &Vec<usize>| {
            let best = pre.iter().map(|&p| hm[p]).max().unwrap();
            *pre.iter().filter(|&&p| hm[p] == best).min().unwrap()
        };
        let mut zone = vec![false; n + 2];
        zone[fact_g] = true;
        loop {
            let mut changed = false;
            for (pre, eff, c) in &ops {
                if *c == 0 && applicable(pre) && eff.iter().any(|&e| zone[e]) {
                    let s = supporter(pre);
                    if !zone[s] {
                        zone[s] = true;
                        changed = true;
                    }
                }
            }
            if !changed {
                break;
            }
        }
        let mut reached = in_state.clone();
        loop {
            let mut changed = false;
            for (pre, eff, _) in &ops {
                if applicable(pre) && reached[supporter(pre)] {
                    for &e in eff {
                        if !zone[e] && !reached[e] {
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
            .filter(|&o| {
                let (pre, eff, _) = &ops[o];
                applicable(pre) && reached[supporter(pre)] && eff.iter().any(|&e| zone[e])
            })
            .collect();
        let m = cut.iter().map(|&o| ops[o].2).min().unwrap();
        assert!(m > 0, "a cut of zero cost");
        h += m;
        for &o in &cut {
            ops[o].2 -= m;
        }
    }
}
