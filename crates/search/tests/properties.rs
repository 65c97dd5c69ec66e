//! Property tests on small random tasks against an explicit-state oracle: uniform-cost
//! search over every state for the optimal cost, and backward Dijkstra for h*.

#![allow(clippy::unwrap_used, clippy::expect_used)] // tests fail loudly by design

use std::collections::{BinaryHeap, HashMap};

use proptest::prelude::*;

mod common;
use common::tasks;
use search::{
    astar, astar_with_pruning, ipdb, parse_search, replay, AtomSelectionStrategy, Blind,
    CanonicalPdbs, HMax, Heuristic, IpdbConfig, LimitedPruningConfig, LmCut, Outcome,
    PatternDatabase, PruningConfig, Ratio, SearchLimits, SearchResult, StubbornSetsConfig,
};
use task::{Fact, OpId, Operator, Task, VarId, Variable};

/// The explicit state space: states numbered in mixed radix, edges with costs.
struct Space {
    states: Vec<Vec<u32>>,
    index: HashMap<Vec<u32>, usize>,
    edges: Vec<Vec<(usize, u64)>>,
}

impl Space {
    fn new(task: &Task) -> Space {
        let mut states = vec![vec![]];
        for v in &task.variables {
            states = states
                .into_iter()
                .flat_map(|s: Vec<u32>| {
                    (0..v.domain_size()).map(move |x| {
                        let mut t = s.clone();
                        t.push(x);
                        t
                    })
                })
                .collect();
        }
        let index: HashMap<Vec<u32>, usize> = states
            .iter()
            .cloned()
            .enumerate()
            .map(|(i, s)| (s, i))
            .collect();
        let edges = states
            .iter()
            .map(|s| {
                task.operators
                    .iter()
                    .filter(|op| task.is_applicable(op, s))
                    .map(|op| {
                        let mut t = s.clone();
                        for f in &op.effects {
                            t[f.var.index()] = f.value;
                        }
                        (index[&t], task.cost(op))
                    })
                    .collect()
            })
            .collect();
        Space {
            states,
            index,
            edges,
        }
    }

    /// Dijkstra from `sources` over `edges`.
    fn dijkstra(edges: &[Vec<(usize, u64)>], sources: &[usize]) -> Vec<Option<u64>> {
        let mut dist = vec![None; edges.len()];
        let mut queue = BinaryHeap::new();
        for &s in sources {
            dist[s] = Some(0);
            queue.push(std::cmp::Reverse((0, s)));
        }
        while let Some(std::cmp::Reverse((d, s))) = queue.pop() {
            if dist[s].is_some_and(|best| d > best) {
                continue;
            }
            for &(t, c) in &edges[s] {
                if dist[t].is_none_or(|best| d + c < best) {
                    dist[t] = Some(d + c);
                    queue.push(std::cmp::Reverse((d + c, t)));
                }
            }
        }
        dist
    }

    /// Distances from the initial state.
    fn forward(&self, task: &Task) -> Vec<Option<u64>> {
        Space::dijkstra(&self.edges, &[self.index[&task.initial_state]])
    }

    /// The oracle's optimal cost: the cheapest distance to a goal state (`None`: no plan).
    fn optimal_cost(&self, task: &Task) -> Option<u64> {
        let forward = self.forward(task);
        (0..self.states.len())
            .filter(|&s| task.is_goal(&self.states[s]))
            .filter_map(|s| forward[s])
            .min()
    }

    /// h*: the cheapest cost from each state to a goal state.
    fn h_star(&self, task: &Task) -> Vec<Option<u64>> {
        let mut reverse = vec![Vec::new(); self.edges.len()];
        for (s, out) in self.edges.iter().enumerate() {
            for &(t, c) in out {
                reverse[t].push((s, c));
            }
        }
        let goals: Vec<usize> = (0..self.states.len())
            .filter(|&s| task.is_goal(&self.states[s]))
            .collect();
        Space::dijkstra(&reverse, &goals)
    }
}

/// A pattern database built the obvious way: every abstract state (values of the pattern's
/// variables, numbered in mixed radix with the first variable least significant), every
/// abstract transition (each operator applicable on the pattern's variables), and
/// Dijkstra backwards from the abstract goal states.
fn reference_pdb(task: &Task, pattern: &[usize]) -> Vec<Option<u64>> {
    let sizes: Vec<usize> = pattern
        .iter()
        .map(|&v| task.variables[v].domain_size() as usize)
        .collect();
    let n: usize = sizes.iter().product();
    let decode = |mut i: usize| -> Vec<u32> {
        sizes
            .iter()
            .map(|&d| {
                let value = (i % d) as u32;
                i /= d;
                value
            })
            .collect()
    };
    let encode = |values: &[u32]| -> usize {
        values
            .iter()
            .zip(&sizes)
            .rev()
            .fold(0, |acc, (&v, &d)| acc * d + v as usize)
    };
    let holds = |facts: &[Fact], values: &[u32]| {
        facts.iter().all(|f| {
            pattern
                .iter()
                .position(|&v| v == f.var.index())
                .is_none_or(|p| values[p] == f.value)
        })
    };
    let mut reverse = vec![Vec::new(); n];
    for (s, edges) in (0..n).map(|s| (s, decode(s))).map(|(s, values)| {
        let edges: Vec<(usize, u64)> = task
            .operators
            .iter()
            .filter(|op| holds(&op.preconditions, &values))
            .map(|op| {
                let mut t = values.clone();
                for f in &op.effects {
                    if let Some(p) = pattern.iter().position(|&v| v == f.var.index()) {
                        t[p] = f.value;
                    }
                }
                (encode(&t), task.cost(op))
            })
            .collect();
        (s, edges)
    }) {
        for (t, c) in edges {
            reverse[t].push((s, c));
        }
    }
    let goals: Vec<usize> = (0..n).filter(|&s| holds(&task.goal, &decode(s))).collect();
    Space::dijkstra(&reverse, &goals)
}

/// The index of `state` in [`reference_pdb`]'s numbering.
fn abstract_index(task: &Task, pattern: &[usize], state: &[u32]) -> usize {
    pattern.iter().rev().fold(0, |acc, &v| {
        acc * task.variables[v].domain_size() as usize + state[v] as usize
    })
}

/// The canonical heuristic the obvious way: the largest sum of the patterns' values
/// ([`reference_pdb`]) over any set of pairwise additive patterns (no operator has
/// effects on variables of both); `None` if a pattern calls the state a dead end.
fn reference_canonical(task: &Task, patterns: &[Vec<usize>], state: &[u32]) -> Option<u64> {
    let values: Vec<u64> = patterns
        .iter()
        .map(|p| reference_pdb(task, p)[abstract_index(task, p, state)])
        .collect::<Option<_>>()?;
    let additive = |a: &[usize], b: &[usize]| {
        !task.operators.iter().any(|op| {
            op.effects.iter().any(|f| a.contains(&f.var.index()))
                && op.effects.iter().any(|f| b.contains(&f.var.index()))
        })
    };
    let n = patterns.len();
    (0u32..1 << n)
        .filter(|set| {
            (0..n).all(|i| {
                (0..n).all(|j| {
                    i == j
                        || set >> i & 1 == 0
                        || set >> j & 1 == 0
                        || additive(&patterns[i], &patterns[j])
                })
            })
        })
        .map(|set| {
            (0..n)
                .filter(|&i| set >> i & 1 == 1)
                .map(|i| values[i])
                .sum()
        })
        .max()
}

/// The patterns of a pattern-database heuristic, as variable indices.
fn patterns_of(h: &CanonicalPdbs) -> Vec<Vec<usize>> {
    h.pdbs()
        .iter()
        .map(|p| p.pattern().iter().map(|v| v.index()).collect())
        .collect()
}

/// h <= h* on every state, and dead ends only where the goal is unreachable.
fn check_admissible<H: Heuristic + ?Sized>(
    task: &Task,
    space: &Space,
    h_star: &[Option<u64>],
    h: &mut H,
) -> Result<(), TestCaseError> {
    for (s, state) in space.states.iter().enumerate() {
        match (h.evaluate(state), h_star[s]) {
            (Some(h), Some(exact)) => {
                prop_assert!(h <= exact, "h = {} > h* = {} in {:?}", h, exact, state)
            }
            (None, Some(exact)) => {
                prop_assert!(false, "dead end claimed in {:?} with h* = {}", state, exact)
            }
            (_, None) => {}
        }
    }
    for state in space.states.iter().filter(|s| task.is_goal(s)) {
        prop_assert_eq!(h.evaluate(state), Some(0));
    }
    Ok(())
}

/// Small hill-climbing options for tiny tasks.
fn small_ipdb(seed: u32) -> IpdbConfig {
    IpdbConfig {
        pdb_max_size: 48,
        collection_max_size: 200,
        num_samples: 30,
        min_improvement: 1,
        random_seed: seed,
        ..IpdbConfig::default()
    }
}

fn run<H: Heuristic + ?Sized>(task: &Task, h: &mut H) -> SearchResult {
    astar(task, h, &SearchLimits::default(), None).unwrap()
}

fn cost(result: &SearchResult) -> Option<u64> {
    match &result.outcome {
        Outcome::Solved(plan) => Some(plan.cost),
        Outcome::Unsolvable => None,
        other => panic!("unexpected outcome {other:?}"),
    }
}

/// The plan is valid, reaches the goal, and costs what it says.
fn check_plan(task: &Task, result: &SearchResult) {
    if let Outcome::Solved(plan) = &result.outcome {
        let end = replay(task, &plan.operators).unwrap();
        assert!(task.is_goal(&end));
        let sum: u64 = plan
            .operators
            .iter()
            .map(|op| task.cost(&task.operators[op.index()]))
            .sum();
        assert_eq!(plan.cost, sum);
    }
}

/// An admissible, inconsistent heuristic: h* on some states, 0 on others (as `seed`
/// picks them), None exactly on dead ends.
struct Erratic {
    h_star: HashMap<Vec<u32>, Option<u64>>,
    seed: u64,
}

impl Erratic {
    fn new(space: &Space, task: &Task, seed: u64) -> Erratic {
        let h_star = space.h_star(task);
        Erratic {
            h_star: space.states.iter().cloned().zip(h_star).collect(),
            seed,
        }
    }
}

impl Heuristic for Erratic {
    fn name(&self) -> &str {
        "erratic"
    }

    fn evaluate(&mut self, state: &[u32]) -> Option<u64> {
        let h = self.h_star[state]?;
        let mix = state.iter().fold(self.seed, |a, &v| {
            (a ^ u64::from(v)).wrapping_mul(0x9e37_79b9_7f4a_7c15)
        });
        Some(if mix >> 63 == 1 { h } else { 0 })
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 512, ..ProptestConfig::default() })]

    #[test]
    fn astar_is_optimal(task in tasks()) {
        let space = Space::new(&task);
        let optimal = space.optimal_cost(&task);

        let hmax = run(&task, &mut HMax::new(&task).unwrap());
        let blind = run(&task, &mut Blind::new(&task));
        let lmcut = run(&task, &mut LmCut::new(&task).unwrap());
        prop_assert_eq!(cost(&lmcut), optimal);
        check_plan(&task, &lmcut);
        prop_assert_eq!(cost(&hmax), optimal);
        prop_assert_eq!(cost(&blind), optimal);
        check_plan(&task, &hmax);
        check_plan(&task, &blind);

        // Every registered state was evaluated exactly once; every dead end is one.
        for result in [&hmax, &blind] {
            let s = &result.statistics;
            prop_assert_eq!(s.registered_states, s.evaluated);
            prop_assert!(s.expanded <= s.evaluated);
            prop_assert!(s.expanded_until_last_jump <= s.expanded);
            prop_assert!(s.evaluated_until_last_jump <= s.evaluated);
            prop_assert!(s.generated_until_last_jump <= s.generated);
        }
        prop_assert_eq!(blind.statistics.dead_ends, 0);

        // An inconsistent heuristic makes the search reopen states, and it stays optimal.
        let result = run(&task, &mut Erratic::new(&space, &task, 1));
        prop_assert_eq!(cost(&result), optimal);
        check_plan(&task, &result);
    }

    #[test]
    fn stubborn_sets_preserve_the_optimal_cost_with_any_heuristic(
        task in tasks(),
        strategy in 0usize..4,
        use_sibling_shortcut in any::<bool>(),
        check_after in 0u64..4,
    ) {
        let space = Space::new(&task);
        let optimal = space.optimal_cost(&task);
        let stubborn = PruningConfig::AtomCentricStubbornSets(StubbornSetsConfig {
            use_sibling_shortcut,
            atom_selection_strategy: AtomSelectionStrategy::ALL[strategy],
        });
        let limited = PruningConfig::Limited(LimitedPruningConfig {
            pruning: Box::new(stubborn.clone()),
            min_required_pruning_ratio: Ratio(0.5),
            expansions_before_checking_pruning_ratio: check_after,
        });
        for config in [stubborn, limited] {
            let heuristics: Vec<Box<dyn Heuristic>> = vec![
                Box::new(Blind::new(&task)),
                Box::new(HMax::new(&task).unwrap()),
                Box::new(LmCut::new(&task).unwrap()),
                Box::new(Erratic::new(&space, &task, 3)),
            ];
            for mut h in heuristics {
                let mut pruning = config.build(&task).unwrap();
                let result = astar_with_pruning(
                    &task, &mut h, Some(&mut pruning), &SearchLimits::default(), None,
                ).unwrap();
                prop_assert_eq!(cost(&result), optimal, "{} with {:?}", h.name(), config);
                check_plan(&task, &result);
                let p = result.statistics.pruning.unwrap();
                prop_assert!(p.successors_after <= p.successors_before);
                prop_assert_eq!(p.successors_after, result.statistics.generated);
            }
        }
    }

    #[test]
    fn hmax_is_admissible(task in tasks()) {
        let space = Space::new(&task);
        let h_star = space.h_star(&task);
        let mut hmax = HMax::new(&task).unwrap();
        for (s, state) in space.states.iter().enumerate() {
            match (hmax.evaluate(state), h_star[s]) {
                (Some(h), Some(exact)) => prop_assert!(h <= exact, "h = {} > h* = {} in {:?}", h, exact, state),
                (None, Some(exact)) => prop_assert!(false, "dead end claimed in {:?} with h* = {}", state, exact),
                (_, None) => {}
            }
        }
        // The goal is free wherever it holds.
        for state in space.states.iter().filter(|s| task.is_goal(s)) {
            prop_assert_eq!(hmax.evaluate(state), Some(0));
        }
    }

    #[test]
    fn lmcut_is_admissible_and_dominates_hmax(task in tasks()) {
        // Its equality with the from-scratch oracle is a unit test of `lmcut` (the
        // oracle's supporter rule is private to the crate).
        let space = Space::new(&task);
        let h_star = space.h_star(&task);
        let mut lmcut = LmCut::new(&task).unwrap();
        let mut hmax = HMax::new(&task).unwrap();
        for (s, state) in space.states.iter().enumerate() {
            let h = lmcut.evaluate(state);
            prop_assert_eq!(h.is_none(), hmax.evaluate(state).is_none());
            if let (Some(h), Some(m)) = (h, hmax.evaluate(state)) {
                prop_assert!(h >= m, "lmcut {} < hmax {} in {:?}", h, m, state);
            }
            match (h, h_star[s]) {
                (Some(h), Some(exact)) => prop_assert!(h <= exact, "h = {} > h* = {} in {:?}", h, exact, state),
                (None, Some(exact)) => prop_assert!(false, "dead end claimed in {:?} with h* = {}", state, exact),
                (_, None) => {}
            }
            if task.is_goal(state) {
                prop_assert_eq!(h, Some(0));
            }
        }
    }

    #[test]
    fn pdb_equals_the_explicit_abstract_graph(task in tasks(), mask in any::<u8>()) {
        let pattern: Vec<usize> = (0..task.variables.len()).filter(|&v| mask >> v & 1 == 1).collect();
        let reference = reference_pdb(&task, &pattern);
        // Any order and duplicates give the same database.
        let mut given: Vec<u32> = pattern.iter().rev().map(|&v| v as u32).collect();
        given.extend(given.clone());
        let pdb = PatternDatabase::new(&task, &given).unwrap();
        prop_assert_eq!(pdb.size(), reference.len());
        let space = Space::new(&task);
        let h_star = space.h_star(&task);
        for (s, state) in space.states.iter().enumerate() {
            let abstract_state: usize = pattern.iter().rev().fold(0, |acc, &v| {
                acc * task.variables[v].domain_size() as usize + state[v] as usize
            });
            prop_assert_eq!(pdb.index(state), abstract_state);
            let h = pdb.value(state);
            prop_assert_eq!(h, reference[abstract_state], "in {:?}", state);
            match (h, h_star[s]) {
                (Some(h), Some(exact)) => prop_assert!(h <= exact),
                (None, Some(exact)) => prop_assert!(false, "dead end claimed in {:?} with h* = {}", state, exact),
                (_, None) => {}
            }
        }
        prop_assert_eq!(pdb.has_dead_ends(), reference.contains(&None));
    }

    #[test]
    fn canonical_pdbs_are_admissible_and_equal_the_reference(
        task in tasks(),
        masks in proptest::collection::vec(any::<u8>(), 1..=4),
    ) {
        let n = task.variables.len();
        let patterns: Vec<Vec<u32>> = masks
            .iter()
            .map(|m| (0..n as u32).filter(|&v| m >> v & 1 == 1).collect())
            .collect();
        let pdbs: Vec<PatternDatabase> = patterns
            .iter()
            .map(|p| PatternDatabase::new(&task, p).unwrap())
            .collect();
        let mut plain = CanonicalPdbs::new(&task, pdbs.clone(), None, "cpdbs");
        let mut pruned = CanonicalPdbs::new(&task, pdbs, Some(std::time::Duration::from_secs(60)), "cpdbs");
        let mut distinct: Vec<Vec<usize>> = Vec::new();
        for p in &patterns {
            let p: Vec<usize> = p.iter().map(|&v| v as usize).collect();
            if !distinct.contains(&p) {
                distinct.push(p);
            }
        }
        prop_assert_eq!(patterns_of(&plain), distinct.clone());
        let space = Space::new(&task);
        let h_star = space.h_star(&task);
        for state in &space.states {
            let h = plain.evaluate(state);
            prop_assert_eq!(h, reference_canonical(&task, &distinct, state), "in {:?}", state);
            // Dominance pruning never changes a value.
            prop_assert_eq!(pruned.evaluate(state), h);
        }
        check_admissible(&task, &space, &h_star, &mut plain)?;
        let s = pruned.statistics();
        prop_assert_eq!(s.patterns, pruned.pdbs().len());
        prop_assert_eq!(s.cliques, pruned.cliques().count());
        prop_assert_eq!(s.patterns + s.pruned_patterns, distinct.len());
    }

    #[test]
    fn ipdb_is_admissible_deterministic_and_astar_with_it_optimal(task in tasks(), seed in 0u32..4) {
        let space = Space::new(&task);
        let h_star = space.h_star(&task);
        let config = small_ipdb(seed);
        let mut h = ipdb(&task, &config, &SearchLimits::default()).unwrap();
        let climb = h.statistics().hill_climbing.clone().unwrap();
        // The collection stays within its limit (unless the goal variables' databases
        // alone exceed it).
        let goal_vars: u64 = task.goal.iter().map(|f| u64::from(task.variables[f.var.index()].domain_size())).sum();
        prop_assert!(climb.total_size <= config.collection_max_size.max(goal_vars));
        // The value is the canonical heuristic of the collection it found.
        let patterns = patterns_of(&h);
        for state in &space.states {
            prop_assert_eq!(h.evaluate(state), reference_canonical(&task, &patterns, state));
        }
        check_admissible(&task, &space, &h_star, &mut h)?;
        // The same options give the same collection.
        let again = ipdb(&task, &config, &SearchLimits::default()).unwrap();
        prop_assert_eq!(patterns_of(&again), patterns);
        let mut again_climb = again.statistics().hill_climbing.clone().unwrap();
        again_climb.time = climb.time;
        again_climb.pdb_time = climb.pdb_time;
        again_climb.sampling_time = climb.sampling_time;
        again_climb.evaluation_time = climb.evaluation_time;
        prop_assert_eq!(again_climb, climb);

        let optimal = space.optimal_cost(&task);
        let result = run(&task, &mut h);
        prop_assert_eq!(cost(&result), optimal);
        check_plan(&task, &result);
    }

    #[test]
    fn pattern_database_configurations_are_admissible(task in tasks()) {
        let space = Space::new(&task);
        let h_star = space.h_star(&task);
        for s in ["astar(cpdbs(systematic(2)))", "astar(cpdbs())", "astar(ipdb(num_samples=20))"] {
            let mut h = parse_search(s).unwrap().heuristic.build_with_limits(&task, &SearchLimits::default()).unwrap().into_heuristic().unwrap();
            check_admissible(&task, &space, &h_star, &mut h)?;
        }
    }

    #[test]
    fn search_is_deterministic(task in tasks()) {
        for _ in 0..2 {
            let mut first = run(&task, &mut HMax::new(&task).unwrap());
            let mut second = run(&task, &mut HMax::new(&task).unwrap());
            first.statistics.search_time = Default::default();
            second.statistics.search_time = Default::default();
            prop_assert_eq!(first, second);
        }
    }
}

/// A tiny task with a zero-cost cycle and a cheaper path that is found late.
#[test]
fn zero_cost_cycles_and_reopening() {
    let op = |name: &str, pre: u32, eff: u32, cost: u64| Operator {
        name: name.into(),
        preconditions: vec![Fact::new(VarId(0), pre)],
        effects: vec![Fact::new(VarId(0), eff)],
        cost,
    };
    let task = Task {
        variables: vec![Variable {
            name: "at".into(),
            value_names: (0..4).map(|i| format!("p{i}")).collect(),
        }],
        mutexes: vec![],
        initial_state: vec![0],
        goal: vec![Fact::new(VarId(0), 3)],
        operators: vec![
            op("loop-a", 0, 1, 0),
            op("loop-b", 1, 0, 0),
            op("expensive", 0, 2, 3),
            op("cheap-1", 1, 2, 2),
            op("finish", 2, 3, 2),
        ],
        use_costs: true,
    };
    let result = run(&task, &mut Blind::new(&task));
    let Outcome::Solved(plan) = result.outcome else {
        panic!("solvable")
    };
    assert_eq!(plan.cost, 4);
    assert_eq!(plan.operators, vec![OpId(0), OpId(3), OpId(4)]);

    // With a heuristic that is admissible but not consistent (h(p1) high, h(p2) low),
    // p2 is first closed through the expensive path and then reopened.
    struct Table;
    impl Heuristic for Table {
        fn name(&self) -> &str {
            "table"
        }
        fn evaluate(&mut self, state: &[u32]) -> Option<u64> {
            Some([0, 4, 0, 0][state[0] as usize])
        }
    }
    let result = run(&task, &mut Table);
    let Outcome::Solved(plan) = result.outcome else {
        panic!("solvable")
    };
    assert_eq!(plan.cost, 4);
    assert_eq!(result.statistics.reopened, 1);
}

/// Random explicit graphs (states of three 4-valued variables, operators from one state
/// to another, goals among the reachable states) searched with an inconsistent heuristic:
/// A* must reopen states to stay optimal, and does so in many of them.
#[test]
fn reopening_keeps_astar_optimal_on_random_graphs() {
    let mut seed = 99u64;
    let mut next = |n: u64| {
        seed = seed
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        (seed >> 33) % n
    };
    let facts = |code: u64| {
        (0..3)
            .map(|v| Fact::new(VarId(v), (code >> (2 * v)) as u32 % 4))
            .collect::<Vec<_>>()
    };
    let mut reopened_tasks = 0;
    for round in 0..1000 {
        let operators = (0..40 + next(80))
            .map(|i| Operator {
                name: format!("e{i}"),
                preconditions: facts(next(64)),
                effects: facts(next(64)),
                cost: next(10),
            })
            .collect();
        let mut task = Task {
            variables: (0..3)
                .map(|i| Variable {
                    name: format!("v{i}"),
                    value_names: (0..4).map(|x| format!("x{x}")).collect(),
                })
                .collect(),
            mutexes: vec![],
            initial_state: facts(next(64)).iter().map(|f| f.value).collect(),
            goal: vec![],
            operators,
            use_costs: true,
        };
        let space = Space::new(&task);
        let forward = space.forward(&task);
        let reachable: Vec<usize> = (0..space.states.len())
            .filter(|&s| forward[s].is_some())
            .collect();
        let goal = reachable[next(reachable.len() as u64) as usize];
        task.goal = space.states[goal]
            .iter()
            .enumerate()
            .map(|(v, &x)| Fact::new(VarId(v as u32), x))
            .collect();
        let result = run(&task, &mut Erratic::new(&space, &task, round));
        assert_eq!(cost(&result), forward[goal], "round {round}");
        check_plan(&task, &result);
        if result.statistics.reopened > 0 {
            reopened_tasks += 1;
        }
    }
    assert!(
        reopened_tasks >= 10,
        "only {reopened_tasks} searches reopened a state"
    );
}
