//! Translation under the run's limits (`translate_within`): a grounding that would not
//! end in any reasonable time, or not fit in memory, stops at the limit instead.

#![allow(clippy::unwrap_used)] // tests fail loudly by design

use std::time::{Duration, Instant};

use task::{Limit, Limits};
use translate::Translation;

/// An action schema with five parameters over `objects` objects, each binding reachable:
/// `objects^5` ground actions (60 objects: 777,600,000).
fn blow_up(objects: usize) -> (pddl::Domain, pddl::Problem) {
    let domain = pddl::parse_domain(
        "(define (domain blow-up) (:predicates (p ?x) (q ?a ?b ?c ?d ?e))
           (:action join :parameters (?a ?b ?c ?d ?e)
             :precondition (and (p ?a) (p ?b) (p ?c) (p ?d) (p ?e))
             :effect (q ?a ?b ?c ?d ?e)))",
    )
    .unwrap();
    let names: Vec<String> = (0..objects).map(|i| format!("o{i}")).collect();
    let init: Vec<String> = names.iter().map(|n| format!("(p {n})")).collect();
    let problem = pddl::parse_problem(&format!(
        "(define (problem p) (:domain blow-up) (:objects {}) (:init {}) (:goal (q o0 o1 o2 o1 o0)))",
        names.join(" "),
        init.join(" ")
    ))
    .unwrap();
    pddl::check_problem(&domain, &problem).unwrap();
    (domain, problem)
}

fn stopped(translation: Translation) -> Option<Limit> {
    match translation {
        Translation::Stopped { limit, .. } => Some(limit),
        _ => None,
    }
}

#[test]
fn a_grounding_blow_up_stops_at_the_deadline() {
    let (domain, problem) = blow_up(60);
    let limits = Limits {
        deadline: Some(Instant::now() + Duration::from_millis(200)),
        ..Limits::default()
    };
    let translation = translate::translate_within(&domain, &problem, &limits).unwrap();
    assert_eq!(stopped(translation), Some(Limit::Time));
}

#[test]
fn a_grounding_blow_up_stops_at_the_memory_limit() {
    // A probe that reads more than the limit as soon as it is read.
    fn probe() -> u64 {
        u64::MAX
    }
    let (domain, problem) = blow_up(60);
    let limits = Limits {
        memory_limit_bytes: Some(1 << 30),
        memory_usage: Some(probe),
        ..Limits::default()
    };
    let translation = translate::translate_within(&domain, &problem, &limits).unwrap();
    assert_eq!(stopped(translation), Some(Limit::Memory));
}

#[test]
fn limits_that_are_not_reached_change_nothing() {
    let (domain, problem) = blow_up(3);
    let limits = Limits {
        deadline: Some(Instant::now() + Duration::from_secs(3600)),
        memory_limit_bytes: Some(u64::MAX),
        memory_usage: None,
        cancel: None,
    };
    let Translation::Task(within) =
        translate::translate_within(&domain, &problem, &limits).unwrap()
    else {
        panic!("a task")
    };
    let Translation::Task(free) = translate::translate(&domain, &problem).unwrap() else {
        panic!("a task")
    };
    assert_eq!(within.task, free.task);
    assert_eq!(within.stats, free.stats);
    assert_eq!(free.stats.ground_actions, 243);
}

/// h²'s matrix of fact pairs is checked against the memory limit before it is allocated:
/// without a probe translation counts no bytes of its own, so a limit of 8 bytes lets
/// translation finish and stops h² (its rows take a word at least).
#[test]
fn h2_stops_at_the_memory_limit_its_pairs_would_exceed() {
    let (domain, problem) = blow_up(3);
    let options = translate::TranslateOptions {
        h2_mutexes: true,
        ..Default::default()
    };
    let small = Limits {
        memory_limit_bytes: Some(8),
        ..Limits::default()
    };
    let translation = translate::translate_with_options(&domain, &problem, &small, &options);
    assert_eq!(stopped(translation.unwrap()), Some(Limit::Memory));
    let plain = translate::translate_within(&domain, &problem, &small).unwrap();
    assert!(
        matches!(plain, Translation::Task(_)),
        "only h² needs the bytes"
    );
    let free = translate::translate_with_options(&domain, &problem, &Limits::default(), &options);
    let Translation::Task(t) = free.unwrap() else {
        panic!("a task")
    };
    assert!(t.stats.h2.is_some());
}
