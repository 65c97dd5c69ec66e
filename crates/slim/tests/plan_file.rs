//! The plan file of a planning run says `unit cost` if and only if every operator of the
//! task costs 1, as `demoplan plan` and Fast Downward say it (issue 21: `slim` used to
//! write `general cost` always).

#![allow(clippy::unwrap_used, clippy::expect_used)]

use slim::{Backend, Outcome};

/// One truck drives from `a` to `c` through `b`; `costs` is `None` for a domain without
/// action costs, or the cost of each drive.
fn check(costs: Option<[u64; 2]>, expect_text: &str) {
    let (requirements, functions, increase, metric, init_costs) = match costs {
        None => ("", "", "", "", String::new()),
        Some([ab, bc]) => (
            " :action-costs",
            "(:functions (total-cost) - number (road ?x ?y - place) - number)",
            "(increase (total-cost) (road ?from ?to))",
            "(:metric minimize (total-cost))",
            format!("(= (total-cost) 0) (= (road a b) {ab}) (= (road b c) {bc})"),
        ),
    };
    let domain = pddl::parse_domain(&format!(
        "(define (domain trucks) (:requirements :strips :typing{requirements}) \
         (:types place) (:predicates (at ?p - place) (road-to ?x ?y - place)) {functions} \
         (:action drive :parameters (?from ?to - place) \
          :precondition (and (at ?from) (road-to ?from ?to)) \
          :effect (and (not (at ?from)) (at ?to) {increase})))"
    ))
    .unwrap();
    let problem = pddl::parse_problem(&format!(
        "(define (problem go) (:domain trucks) (:objects a b c - place) \
         (:init (at a) (road-to a b) (road-to b c) {init_costs}) (:goal (at c)) {metric})"
    ))
    .unwrap();
    let backend = Backend::Demoplan(search::parse_search("astar(blind())").unwrap().into());
    let run = backend.plan(&domain, &problem, &slim::RunLimits::default());
    assert_eq!(run.outcome, Outcome::Solved);
    assert_eq!(run.plan_text().as_deref(), Some(expect_text));
    // The plan file reads back as the run's steps.
    assert_eq!(
        pddl::parse_plan(expect_text).unwrap().steps,
        run.plan,
        "{expect_text}"
    );
}

#[test]
fn a_task_without_action_costs_is_unit_cost() {
    check(None, "(drive a b)\n(drive b c)\n; cost = 2 (unit cost)\n");
}

#[test]
fn action_costs_of_one_are_unit_cost() {
    check(
        Some([1, 1]),
        "(drive a b)\n(drive b c)\n; cost = 2 (unit cost)\n",
    );
}

#[test]
fn any_other_cost_is_general_cost() {
    check(
        Some([1, 5]),
        "(drive a b)\n(drive b c)\n; cost = 6 (general cost)\n",
    );
}
