//! Tasks and an oracle for tests, shared by the test suites of every crate that works
//! on finite-domain tasks (search's heuristics and pruning, translate's h² and
//! dominated operators): random valid tasks for property tests, `op`, an operator
//! written briefly, [`task`], a task written briefly, and [`optimal_cost`], uniform-cost
//! search over the explicit state space, the slow, obviously correct oracle of optimal
//! cost. Behind the `testing` feature, which only dev-dependencies enable: nothing of it
//! is in a binary.

use std::cmp::Reverse;
use std::collections::{BinaryHeap, HashMap};

use crate::{Fact, Operator, Task, VarId, Variable};
use proptest::prelude::*;

/// An operator from `(variable, value)` pairs: its preconditions and its effects.
pub fn op(name: &str, pre: &[(u32, u32)], eff: &[(u32, u32)], cost: u64) -> Operator {
    let facts = |fs: &[(u32, u32)]| fs.iter().map(|&(v, x)| Fact::new(VarId(v), x)).collect();
    Operator {
        name: name.into(),
        preconditions: facts(pre),
        effects: facts(eff),
        cost,
    }
}

/// A task over variables of these domain sizes (variable `i` is named `var{i}`, its
/// values `v{i}-{x}`), from its initial state, its goal as `(variable, value)` pairs and
/// its operators; with action costs. Not validated: tests of invalid input use it too.
pub fn task(sizes: &[u32], init: &[u32], goal: &[(u32, u32)], operators: Vec<Operator>) -> Task {
    Task {
        variables: sizes
            .iter()
            .enumerate()
            .map(|(i, &s)| Variable {
                name: format!("var{i}"),
                value_names: (0..s).map(|x| format!("v{i}-{x}")).collect(),
            })
            .collect(),
        mutexes: vec![],
        initial_state: init.to_vec(),
        goal: goal.iter().map(|&(v, x)| Fact::new(VarId(v), x)).collect(),
        operators,
        use_costs: true,
    }
}

/// A partial assignment over variables of these domain sizes.
fn partial(sizes: &[u32], density: f64) -> impl Strategy<Value = Vec<Fact>> {
    let per_var: Vec<_> = sizes
        .iter()
        .map(|&s| proptest::option::weighted(density, 0..s))
        .collect();
    per_var.prop_map(|values| {
        values
            .into_iter()
            .enumerate()
            .filter_map(|(v, x)| x.map(|x| Fact::new(VarId(v as u32), x)))
            .collect()
    })
}

/// What an operator does with one variable.
#[derive(Debug, Clone)]
enum Role {
    Untouched,
    /// A precondition the operator leaves alone.
    Prevail(u32),
    /// An effect, maybe with a precondition on the old value.
    Change(Option<u32>, u32),
}

/// An operator over variables of these domain sizes, shaped like a transition in a
/// domain transition graph, so that operators chain into longer plans.
fn operator(sizes: &[u32]) -> impl Strategy<Value = (Vec<Fact>, Vec<Fact>)> {
    let roles: Vec<_> = sizes
        .iter()
        .map(|&s| {
            prop_oneof![
                8 => Just(Role::Untouched),
                1 => (0..s).prop_map(Role::Prevail),
                6 => (proptest::option::weighted(0.6, 0..s), 0..s).prop_map(|(p, e)| Role::Change(p, e)),
            ]
        })
        .collect();
    roles.prop_map(|roles| {
        let (mut pre, mut eff) = (Vec::new(), Vec::new());
        for (v, role) in roles.into_iter().enumerate() {
            let var = VarId(v as u32);
            match role {
                Role::Untouched => {}
                Role::Prevail(x) => pre.push(Fact::new(var, x)),
                Role::Change(p, e) => {
                    pre.extend(p.map(|x| Fact::new(var, x)));
                    eff.push(Fact::new(var, e));
                }
            }
        }
        (pre, eff)
    })
}

/// Random valid tasks: 2-6 variables of domain sizes 2-4, 1-12 operators with costs
/// 0-3 (zero costs included), with or without action costs. Most goals are drawn from
/// the end of a random walk from the initial state, so that most tasks are solvable and
/// need several steps; the others are random partial assignments.
pub fn tasks() -> impl Strategy<Value = Task> {
    proptest::collection::vec(2u32..=4, 2..=6).prop_flat_map(|sizes| {
        let op = (operator(&sizes), 0u64..=3).prop_map(|((pre, eff), cost)| (pre, eff, cost));
        let init: Vec<_> = sizes.iter().map(|&s| 0..s).collect();
        (
            Just(sizes.clone()),
            proptest::collection::vec(op, 1..=12),
            init,
            partial(&sizes, 0.4),
            proptest::bool::weighted(0.7),
            (proptest::bool::weighted(0.8), any::<u64>(), 1usize..=10),
        )
            .prop_map(
                |(sizes, ops, initial_state, goal, use_costs, (walk, seed, steps))| {
                    let operators = ops
                        .into_iter()
                        .enumerate()
                        .map(|(i, (preconditions, effects, cost))| Operator {
                            name: format!("op{i}"),
                            preconditions,
                            effects,
                            cost,
                        })
                        .collect();
                    let mut task = task(&sizes, &initial_state, &[], operators);
                    task.goal = goal;
                    task.use_costs = use_costs;
                    if walk {
                        if let Some(goal) = random_walk_goal(&task, seed, steps) {
                            task.goal = goal;
                        }
                    }
                    assert_eq!(
                        task.validate(),
                        Ok(()),
                        "the generator made an invalid task"
                    );
                    task
                },
            )
    })
}

/// A goal drawn from the state a random walk of up to `steps` state-changing steps ends
/// in: the facts the walk changed and some others; `None` if the walk changed nothing.
fn random_walk_goal(task: &Task, mut seed: u64, steps: usize) -> Option<Vec<Fact>> {
    let mut next = |n: usize| {
        seed = seed
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        (seed >> 33) as usize % n.max(1)
    };
    let mut state = task.initial_state.clone();
    for _ in 0..steps {
        let applicable: Vec<&Operator> = task
            .operators
            .iter()
            .filter(|op| {
                task.is_applicable(op, &state)
                    && op.effects.iter().any(|f| state[f.var.index()] != f.value)
            })
            .collect();
        if applicable.is_empty() {
            break;
        }
        for f in &applicable[next(applicable.len())].effects {
            state[f.var.index()] = f.value;
        }
    }
    if state == task.initial_state {
        return None;
    }
    let goal = state
        .iter()
        .enumerate()
        .filter(|&(v, &x)| x != task.initial_state[v] || next(3) == 0)
        .map(|(v, &x)| Fact::new(VarId(v as u32), x))
        .collect();
    Some(goal)
}

/// The optimal cost of `task` (`None`: unsolvable) by uniform-cost search over its
/// explicit state space, with [`Task::cost`]. Exponential in the number of variables:
/// for small tasks only.
pub fn optimal_cost(task: &Task) -> Option<u64> {
    let mut best: HashMap<Vec<u32>, u64> = HashMap::new();
    let mut queue = BinaryHeap::new();
    best.insert(task.initial_state.clone(), 0);
    queue.push(Reverse((0u64, task.initial_state.clone())));
    while let Some(Reverse((g, s))) = queue.pop() {
        if best.get(&s).is_some_and(|&b| b < g) {
            continue;
        }
        if task.is_goal(&s) {
            return Some(g);
        }
        for op in &task.operators {
            if task.is_applicable(op, &s) {
                let mut t = s.clone();
                for e in &op.effects {
                    t[e.var.index()] = e.value;
                }
                let ng = g + task.cost(op);
                if best.get(&t).is_none_or(|&b| ng < b) {
                    best.insert(t.clone(), ng);
                    queue.push(Reverse((ng, t)));
                }
            }
        }
    }
    None
}
