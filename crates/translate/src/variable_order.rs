//! The order of the finite-domain variables.
//!
//! The order is not cosmetic: LM-cut breaks ties between preconditions of equal h^max by
//! their position, and those ties decide which landmarks it finds. Fast Downward orders
//! variables in two steps, and demoplan does the same so that both planners break LM-cut's
//! ties alike (`tests/fast_downward_order.rs` checks the order on recorded translations):
//!
//! 1. Variables are numbered by their atoms: each variable's atoms sorted by predicate
//!    name and then argument names, and the variables sorted by those lists.
//! 2. The causal graph (an arc from every precondition variable of an operator to each of
//!    its effect variables, weighted by the number of operators that give it) is broken
//!    into strongly connected components, which are ordered topologically (Tarjan's
//!    algorithm, visiting variables and their successors in the order of step 1). Inside a
//!    component, variables are taken greedily: each time the one with the least weight of
//!    arcs coming in from variables not yet taken, the earliest to reach that weight
//!    first. Goal variables come last in their component (their incoming weight carries
//!    a large constant). This is the pruning of cyclic causal graphs of Helmert's 2006
//!    JAIR paper on Fast Downward, with the weights its translator uses.
//!
//! On satellite p09 the order matters for a factor of 4 in LM-cut's expansions, on
//! freecell for more; see bench/README.md.

use std::cmp::Reverse;
use std::collections::{BTreeMap, BinaryHeap};

use task::{Fact, Operator, Task, VarId, Variable};

/// Added to the weight of arcs into goal variables inside a component, so that goal
/// variables are taken last; it is never subtracted.
const GOAL_WEIGHT: u64 = 100_000;

/// `task` with its variables in the order of step 1 (the module documentation), read
/// from their `Atom ...` value names by [`Task::atom_order_ranks`], the same ranks LM-cut
/// breaks ties by.
pub(crate) fn by_atoms(task: Task) -> Task {
    let rank = task.atom_order_ranks();
    let mut order: Vec<usize> = (0..rank.len()).collect();
    order.sort_by_key(|&v| rank[v]);
    renumber(task, &order)
}

/// `task` with its variables in the order of step 2 (the module documentation); the task
/// must already be numbered as step 1 says.
pub(crate) fn by_causal_graph(task: Task) -> Task {
    let order = causal_graph_order(&task);
    renumber(task, &order)
}

/// `task` with variable `order[i]` as its new variable `i`; `order` is a permutation.
pub(crate) fn renumber(task: Task, order: &[usize]) -> Task {
    let mut new_index = vec![0u32; order.len()];
    for (new, &old) in order.iter().enumerate() {
        new_index[old] = new as u32;
    }
    let map = |facts: &[Fact]| -> Vec<Fact> {
        let mut mapped: Vec<Fact> = facts
            .iter()
            .map(|f| Fact::new(VarId(new_index[f.var.index()]), f.value))
            .collect();
        mapped.sort_unstable();
        mapped
    };
    let variables = order
        .iter()
        .enumerate()
        .map(|(new, &old)| Variable {
            name: format!("var{new}"),
            ..task.variables[old].clone()
        })
        .collect();
    Task {
        variables,
        mutexes: task.mutexes.iter().map(|m| map(m)).collect(),
        initial_state: order.iter().map(|&old| task.initial_state[old]).collect(),
        goal: map(&task.goal),
        operators: task
            .operators
            .into_iter()
            .map(|op| Operator {
                preconditions: map(&op.preconditions),
                effects: map(&op.effects),
                ..op
            })
            .collect(),
        use_costs: task.use_costs,
    }
}

/// The variables of `task` in causal-graph order (step 2).
fn causal_graph_order(task: &Task) -> Vec<usize> {
    let n = task.variables.len();
    // weights[source][target]: how many operators give the arc (one per effect).
    let mut weights: Vec<BTreeMap<usize, u64>> = vec![BTreeMap::new(); n];
    for op in &task.operators {
        for e in &op.effects {
            for p in &op.preconditions {
                if p.var != e.var {
                    *weights[p.var.index()].entry(e.var.index()).or_insert(0) += 1;
                }
            }
        }
    }
    let successors: Vec<Vec<usize>> = weights
        .iter()
        .map(|w| w.keys().copied().collect())
        .collect();
    let mut is_goal = vec![false; n];
    for f in &task.goal {
        is_goal[f.var.index()] = true;
    }
    // A vertex's position in its component, for the greedy order's arrays.
    let mut local = vec![usize::MAX; n];
    let mut order = Vec::with_capacity(n);
    for component in strongly_connected_components(&successors) {
        if component.len() == 1 {
            order.push(component[0]);
            continue;
        }
        for (i, &v) in component.iter().enumerate() {
            local[v] = i;
        }
        let in_component = |t: usize| local[t] < component.len() && component[local[t]] == t;
        let arcs: Vec<Vec<(usize, u64, bool)>> = component
            .iter()
            .map(|&v| {
                weights[v]
                    .iter()
                    .filter(|(&t, _)| in_component(t))
                    .map(|(&t, &w)| (local[t], w, is_goal[t]))
                    .collect()
            })
            .collect();
        order.extend(
            greedy_acyclic_order(&arcs)
                .into_iter()
                .map(|i| component[i]),
        );
    }
    order
}

/// Tarjan's algorithm, iterative: the strongly connected components of the graph, in
/// topological order (a component before those it has arcs into), each listing its
/// vertices in the order they were first visited. Vertices are visited in index order,
/// successors in the order given.
fn strongly_connected_components(successors: &[Vec<usize>]) -> Vec<Vec<usize>> {
    let n = successors.len();
    const UNVISITED: usize = usize::MAX;
    let mut index = vec![UNVISITED; n];
    let mut lowlink = vec![0usize; n];
    let mut on_stack = vec![false; n];
    let mut stack: Vec<usize> = Vec::new();
    let mut stack_position = vec![0usize; n];
    let mut components: Vec<Vec<usize>> = Vec::new();
    let mut next_index = 0;
    // (vertex, position of the next successor to look at)
    let mut frames: Vec<(usize, usize)> = Vec::new();
    for root in 0..n {
        if index[root] != UNVISITED {
            continue;
        }
        index[root] = next_index;
        lowlink[root] = next_index;
        next_index += 1;
        stack_position[root] = stack.len();
        stack.push(root);
        on_stack[root] = true;
        frames.push((root, 0));
        while let Some(&mut (v, ref mut next)) = frames.last_mut() {
            if let Some(&w) = successors[v].get(*next) {
                *next += 1;
                if index[w] == UNVISITED {
                    index[w] = next_index;
                    lowlink[w] = next_index;
                    next_index += 1;
                    stack_position[w] = stack.len();
                    stack.push(w);
                    on_stack[w] = true;
                    frames.push((w, 0));
                } else if on_stack[w] {
                    lowlink[v] = lowlink[v].min(index[w]);
                }
                continue;
            }
            frames.pop();
            if let Some(&(parent, _)) = frames.last() {
                lowlink[parent] = lowlink[parent].min(lowlink[v]);
            }
            if lowlink[v] == index[v] {
                let component: Vec<usize> = stack.drain(stack_position[v]..).collect();
                for &x in &component {
                    on_stack[x] = false;
                }
                components.push(component);
            }
        }
    }
    // Tarjan finishes a component after every component it reaches.
    components.reverse();
    components
}

/// Orders the vertices `0..arcs.len()` of one component: repeatedly the vertex with the
/// least weight of arcs from vertices not yet taken, ties to the one that reached that
/// weight first (at the start, the lower index). `arcs[v]` lists `v`'s arcs inside the
/// component as (target, weight, target is a goal variable).
fn greedy_acyclic_order(arcs: &[Vec<(usize, u64, bool)>]) -> Vec<usize> {
    let k = arcs.len();
    let mut incoming = vec![0u64; k];
    for out in arcs {
        for &(t, w, goal) in out {
            incoming[t] += w + if goal { GOAL_WEIGHT + w } else { 0 };
        }
    }
    // Min-heap of (weight, when the vertex reached it, vertex); entries whose weight is no
    // longer the vertex's are stale and skipped.
    let mut heap: BinaryHeap<Reverse<(u64, usize, usize)>> =
        (0..k).map(|v| Reverse((incoming[v], v, v))).collect();
    let mut clock = k;
    let mut taken = vec![false; k];
    let mut order = Vec::with_capacity(k);
    while let Some(Reverse((weight, _, v))) = heap.pop() {
        if taken[v] || incoming[v] != weight {
            continue;
        }
        taken[v] = true;
        order.push(v);
        for &(t, w, goal) in &arcs[v] {
            if taken[t] {
                continue;
            }
            // A goal target carries its arc twice (the second time with GOAL_WEIGHT); both
            // are removed without the constant, one after the other.
            for _ in 0..if goal { 2 } else { 1 } {
                incoming[t] -= w;
                heap.push(Reverse((incoming[t], clock, t)));
                clock += 1;
            }
        }
    }
    order
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn components_come_in_topological_order_with_vertices_in_visit_order() {
        // 0 -> 1 <-> 2 -> 3, and 4 alone.
        let successors = vec![vec![1], vec![2], vec![1, 3], vec![], vec![]];
        assert_eq!(
            strongly_connected_components(&successors),
            vec![vec![4], vec![0], vec![1, 2], vec![3]]
        );
    }

    #[test]
    fn the_greedy_order_takes_the_least_constrained_vertex_first() {
        // A cycle 0 -> 1 -> 2 -> 0 with weights 5, 1, 3: vertex 2 has the least incoming
        // weight (1), then 0 (its arc from 2 is gone), then 1.
        let arcs = vec![
            vec![(1, 5, false)],
            vec![(2, 1, false)],
            vec![(0, 3, false)],
        ];
        assert_eq!(greedy_acyclic_order(&arcs), vec![2, 0, 1]);
    }

    #[test]
    fn goal_variables_come_last_in_their_component() {
        // The same cycle, but 2 is a goal variable: it goes last despite its light arc.
        let arcs = vec![vec![(1, 5, false)], vec![(2, 1, true)], vec![(0, 3, false)]];
        assert_eq!(greedy_acyclic_order(&arcs), vec![0, 1, 2]);
    }

    #[test]
    fn ties_go_to_the_vertex_that_reached_the_weight_first() {
        // 0 -> 1 (2), 0 -> 2 (2), 1 -> 0 (1), 2 -> 0 (1): 0 goes first (weight 2, ahead
        // of 1 and 2 by index), then 1 and 2 both drop to 0; 1 dropped first.
        let arcs = vec![
            vec![(1, 2, false), (2, 2, false)],
            vec![(0, 1, false)],
            vec![(0, 1, false)],
        ];
        assert_eq!(greedy_acyclic_order(&arcs), vec![0, 1, 2]);
    }

    #[test]
    fn renumbering_moves_every_part_of_the_task() {
        let f = |v: u32, x: u32| Fact::new(VarId(v), x);
        let var = |name: &str| Variable {
            name: name.into(),
            value_names: vec!["a".into(), "b".into()],
        };
        let task = Task {
            variables: vec![var("x"), var("y")],
            mutexes: vec![vec![f(0, 0), f(1, 1)]],
            initial_state: vec![0, 1],
            goal: vec![f(0, 1)],
            operators: vec![Operator {
                name: "o".into(),
                preconditions: vec![f(0, 0), f(1, 1)],
                effects: vec![f(0, 1)],
                cost: 1,
            }],
            use_costs: false,
        };
        let swapped = renumber(task, &[1, 0]);
        assert_eq!(swapped.initial_state, vec![1, 0]);
        assert_eq!(swapped.goal, vec![f(1, 1)]);
        assert_eq!(swapped.operators[0].preconditions, vec![f(0, 1), f(1, 0)]);
        assert_eq!(swapped.operators[0].effects, vec![f(1, 1)]);
        assert_eq!(swapped.mutexes, vec![vec![f(0, 1), f(1, 0)]]);
        assert_eq!(swapped.variables[0].name, "var0");
        assert_eq!(swapped.variables[1].value_names, vec!["a", "b"]);
    }
}
