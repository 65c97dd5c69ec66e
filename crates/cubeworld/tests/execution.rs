//! The execution check on demoplan's own plans: every plan found for the paper's goals 1
//! and 2 on the priority-2 and priority-3 domains of the library learned from the
//! default study (seed 7) executes in the cube world, and a corrupted operator whose plan
//! is valid in PDDL does not. (Goal 3 and beyond take minutes to plan in the test
//! profile; `docs/execution.md` reports the whole grid, run with the release binary.)

#![allow(clippy::unwrap_used, clippy::expect_used)]

use grounding::GroundingConfig;
use learn::{domain, operator_subset, DomainOptions, Library, RecordingInfo};
use segment::ActivityTree;

mod common;
use common::paper_problem;

/// The library `demoplan learn` makes of `demoplan simulate`'s default study.
fn default_library() -> Library {
    let mut library = Library::default();
    for (i, demo) in simulate::default_study().demonstrations.iter().enumerate() {
        let header = demo.header().clone();
        let frames: Vec<recording::Frame> = demo.frames().map(|(f, _)| f).collect();
        let segmented = learn::segment_frames(
            &header,
            frames,
            &GroundingConfig::default(),
            &ActivityTree::table_one(),
        );
        let info = RecordingInfo {
            hash: format!("{i:016x}"),
            id: header.id.clone(),
            participant: header.participant.clone(),
            source: String::new(),
            frames: segmented.frames,
            segments: 0,
            ..Default::default()
        };
        library.add_recording(info, &header, &segmented.space, &segmented.segments);
    }
    library
}

/// demoplan's plan for a task (A* with LM-cut), as plan steps.
fn plan(domain: &pddl::Domain, problem: &pddl::Problem) -> Option<Vec<pddl::Step>> {
    pddl::check_problem(domain, problem).unwrap();
    let translate::Translation::Task(t) = translate::translate(domain, problem).unwrap() else {
        return None;
    };
    let config = search::parse_search("astar(lmcut())").unwrap();
    let result = search::search(&t.task, &config, &search::SearchLimits::default(), None).unwrap();
    let search::Outcome::Solved(p) = result.outcome else {
        return None;
    };
    Some(translate::plan_steps(&t.task, &p.operators))
}

fn domain_of(library: &Library, prio: usize) -> pddl::Domain {
    let ops = operator_subset(library, prio, DomainOptions::default());
    pddl::parse_domain(&domain("demoplan", &ops).to_string()).unwrap()
}

fn describe(report: &cubeworld::ExecutionReport) -> String {
    let mut s = String::new();
    for step in &report.steps {
        s.push_str(&format!(
            "{} {} {:?} {:?}\n",
            step.index,
            step.action_text(),
            step.failed,
            step.grounded
        ));
    }
    s.push_str(&format!("goal {:?}\n", report.goal));
    s
}

#[test]
fn every_plan_for_goals_1_and_2_on_priorities_2_and_3_executes() {
    let library = default_library();
    let mut executed = 0;
    for prio in [2, 3] {
        let d = domain_of(&library, prio);
        for goal in 1..=2 {
            let p = paper_problem(goal);
            let steps = plan(&d, &p).unwrap_or_else(|| panic!("no plan: prio {prio}, goal {goal}"));
            let report = cubeworld::execute(&d, &p, &steps).unwrap();
            assert!(
                report.success(),
                "prio {prio}, goal {goal}:\n{}",
                describe(&report)
            );
            assert_eq!(report.steps.len(), steps.len());
            assert!(report.initial_missing.is_empty());
            executed += 1;
        }
    }
    assert_eq!(executed, 4);
}

#[test]
fn a_reach_that_grasps_is_valid_in_pddl_but_fails_in_the_cube_world() {
    let library = default_library();
    let mut d = domain_of(&library, 2);
    // A corrupted reach, cheap so that plans use it: it also closes the hand on the cube
    // (`handopen` deleted, `inhand` added).
    let mut reach = d
        .actions
        .iter()
        .find(|a| a.name.as_str() == "reach")
        .unwrap()
        .clone();
    reach.name = pddl::Name::new("reach9");
    let atom = |p: &str, args: &[&str]| pddl::Atom {
        predicate: pddl::Name::new(p),
        args: args
            .iter()
            .map(|a| pddl::Term::Variable(pddl::Name::new(*a)))
            .collect(),
        span: pddl::Span::NONE,
    };
    reach
        .effects
        .retain(|e| !matches!(e, pddl::Effect::IncreaseCost(_)));
    reach
        .effects
        .push(pddl::Effect::Delete(atom("handopen", &["?h"])));
    reach
        .effects
        .push(pddl::Effect::Add(atom("inhand", &["?h", "?c1"])));
    // (A hand never acts on the cube it holds.)
    reach
        .effects
        .retain(|e| !matches!(e, pddl::Effect::Add(a) if a.predicate.as_str() == "actedon"));
    reach
        .effects
        .push(pddl::Effect::Delete(atom("actedon", &["?h", "?c1"])));
    reach
        .effects
        .push(pddl::Effect::IncreaseCost(pddl::CostExpr::Constant(
            pddl::Number {
                value: 1,
                span: pddl::Span::NONE,
            },
        )));
    d.actions.push(reach);
    let d = pddl::parse_domain(&d.to_string()).unwrap();
    let p = paper_problem(1);
    let steps = plan(&d, &p).unwrap();
    let at = steps
        .iter()
        .position(|s| s.action == "reach9")
        .unwrap_or_else(|| panic!("the plan does not use the corrupted reach: {steps:?}"));
    let report = validate::validate(&d, &p, &pddl::Plan::new(steps.clone())).unwrap();
    assert!(report.is_valid());
    let execution = cubeworld::execute(&d, &p, &steps).unwrap();
    assert!(!execution.success());
    assert_eq!(
        execution.first_failure(),
        Some(at),
        "{}",
        describe(&execution)
    );
    let failed = &execution.steps[at].failed;
    assert!(failed
        .iter()
        .any(|f| f.expected && f.fact.starts_with("(inhand ")));
}

#[test]
fn the_same_plan_gives_the_same_frames() {
    let library = default_library();
    let d = domain_of(&library, 2);
    let p = paper_problem(1);
    let steps = plan(&d, &p).unwrap();
    let a = cubeworld::execute(&d, &p, &steps).unwrap();
    let b = cubeworld::execute(&d, &p, &steps).unwrap();
    assert_eq!(a.recording, b.recording);
    assert_eq!(cubeworld::export(&a), cubeworld::export(&b));
}
