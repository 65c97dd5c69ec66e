//! LM-cut on real tasks: on states sampled by random walks from the initial state of
//! benchmark instances, LM-cut equals the from-scratch reference, dominates h^max, and is
//! 0 exactly on goal states.

#![allow(clippy::unwrap_used, clippy::expect_used)] // tests fail loudly by design

mod common;

use search::{HMax, Heuristic, LmCut};
use task::Task;

fn translated(domain: &str, instance: &str) -> Task {
    let suite = benchmarks::Suite::locate().unwrap();
    let i = suite
        .instances()
        .unwrap()
        .into_iter()
        .find(|i| i.domain == domain && i.name == instance)
        .unwrap();
    let d = pddl::parse_domain(&std::fs::read_to_string(&i.domain_file).unwrap()).unwrap();
    let p = pddl::parse_problem(&std::fs::read_to_string(&i.problem_file).unwrap()).unwrap();
    match translate::translate(&d, &p).unwrap() {
        translate::Translation::Task(t) => t.task,
        translate::Translation::Unsolvable { reason, .. } => {
            panic!("{domain}/{instance}: {reason}")
        }
    }
}

/// States on random walks from the initial state (a fixed-seed generator: reproducible).
fn sample_states(task: &Task, walks: usize, length: usize) -> Vec<Vec<u32>> {
    let mut seed = 0x9e37_79b9_7f4a_7c15u64;
    let mut out = Vec::new();
    for _ in 0..walks {
        let mut state = task.initial_state.clone();
        out.push(state.clone());
        for _ in 0..length {
            let applicable: Vec<&task::Operator> = task
                .operators
                .iter()
                .filter(|o| task.is_applicable(o, &state))
                .collect();
            if applicable.is_empty() {
                break;
            }
            seed ^= seed << 13;
            seed ^= seed >> 7;
            seed ^= seed << 17;
            let op = applicable[(seed % applicable.len() as u64) as usize];
            for e in &op.effects {
                state[e.var.index()] = e.value;
            }
            out.push(state.clone());
        }
    }
    out
}

#[test]
fn lmcut_equals_the_reference_on_sampled_states_of_benchmark_tasks() {
    let instances = [
        ("blocks", "probBLOCKS-5-1"),
        ("gripper", "prob02"),
        ("logistics00", "probLOGISTICS-4-0"),
        ("depot", "p01"),
        ("elevators-opt08-strips", "p01"),
        ("parcprinter-08-strips", "p01"),
        ("openstacks-opt08-strips", "p01"),
        ("pegsol-08-strips", "p02"),
        ("sokoban-opt08-strips", "p01"),
        ("visitall-opt11-strips", "problem03-full"),
        ("miconic", "s3-0"),
        ("storage", "p05"),
    ];
    for (domain, instance) in instances {
        let task = translated(domain, instance);
        let mut lmcut = LmCut::new(&task).unwrap();
        let mut hmax = HMax::new(&task).unwrap();
        let states = sample_states(&task, 8, 25);
        for state in &states {
            let h = lmcut.evaluate(state);
            assert_eq!(
                h,
                common::reference_lmcut(&task, state),
                "{domain}/{instance} {state:?}"
            );
            if let (Some(h), Some(m)) = (h, hmax.evaluate(state)) {
                assert!(h >= m, "{domain}/{instance}: lmcut {h} < hmax {m}");
            }
            if task.is_goal(state) {
                assert_eq!(h, Some(0));
            }
        }
    }
}
