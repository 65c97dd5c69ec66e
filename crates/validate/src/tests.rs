//! Unit tests of the validator on small hand-written tasks. Every test goes through one
//! helper per boundary: `run` (PDDL and plan text in, report out).

#![allow(clippy::unwrap_used, clippy::expect_used)] // tests fail loudly by design

use crate::*;
use pddl::parse_plan;

/// Trucks and cars (vehicles) drive between places; `depot` is a constant. Costs come from
/// the static function `road-length`; `refresh` deletes and adds the same atom; `stay`
/// needs equality and costs nothing; `mark` takes an `either` type and a negative
/// precondition.
const DOMAIN: &str = "
(define (domain roads)
  (:requirements :strips :typing :negative-preconditions :equality :action-costs)
  (:types truck car - vehicle
          place)
  (:constants depot - place)
  (:predicates (at ?v - vehicle ?p - place) (road ?a ?b - place) (visited ?p - place)
               (marked ?x - (either truck place)))
  (:functions (total-cost) - number (road-length ?a ?b - place) - number)
  (:action drive
    :parameters (?v - vehicle ?from ?to - place)
    :precondition (and (at ?v ?from) (road ?from ?to) (not (= ?from ?to)))
    :effect (and (not (at ?v ?from)) (at ?v ?to) (visited ?to)
                 (increase (total-cost) (road-length ?from ?to))))
  (:action refresh
    :parameters (?v - vehicle ?p - place)
    :precondition (at ?v ?p)
    :effect (and (not (at ?v ?p)) (at ?v ?p) (increase (total-cost) 2)))
  (:action stay
    :parameters (?a ?b - place)
    :precondition (= ?a ?b)
    :effect (visited ?a))
  (:action mark
    :parameters (?x - (either truck place))
    :precondition (not (marked ?x))
    :effect (and (marked ?x) (increase (total-cost) 1))))";

/// `INIT_COST` and `METRIC` are replaced, to test a missing `total-cost` and no metric.
const PROBLEM: &str = "
(define (problem trip) (:domain roads)
  (:objects t1 - truck c1 - car a b - place x)
  (:init (at t1 depot) (at c1 a) (road depot a) (road a b) (road b depot)
         (= (road-length depot a) 5) (= (road-length a b) 7) INIT_COST)
  (:goal (and (at t1 b) (not (at t1 depot)) (visited a)))
  METRIC)";

fn problem(init_cost: &str, metric: &str) -> String {
    PROBLEM
        .replace("INIT_COST", init_cost)
        .replace("METRIC", metric)
}

fn with_costs() -> String {
    problem("(= (total-cost) 0)", "(:metric minimize (total-cost))")
}

fn run(domain: &str, problem: &str, plan: &str) -> Result<Report, ValidateError> {
    let domain = pddl::parse_domain(domain).unwrap();
    let problem = pddl::parse_problem(problem).unwrap();
    pddl::check_problem(&domain, &problem).unwrap();
    validate(&domain, &problem, &parse_plan(plan).unwrap())
}

fn report(plan: &str) -> Report {
    run(DOMAIN, &with_costs(), plan).unwrap()
}

/// The failure of a plan that fails at a step.
fn step_failure(plan: &str) -> StepFailure {
    match report(plan).verdict {
        Verdict::StepFailed(f) => f,
        v => panic!("{plan}: expected a failed step, got {v:?}"),
    }
}

fn lit(positive: bool, predicate: &str, args: &[&str]) -> GroundLiteral {
    GroundLiteral {
        positive,
        atom: GroundAtom::new(predicate, args.iter().copied()),
    }
}

const TRIP: &str = "(drive t1 depot a)\n(drive t1 a b)\n";

#[test]
fn a_valid_plan_reports_its_cost_from_static_functions() {
    let r = report(TRIP);
    assert_eq!(
        r,
        Report {
            verdict: Verdict::Valid,
            value: 12,
            cost_model: CostModel::ActionCosts,
            steps_executed: 2,
        }
    );
}

#[test]
fn a_missing_total_cost_starts_at_zero_and_a_given_one_counts() {
    let missing = problem("", "(:metric minimize (total-cost))");
    assert_eq!(run(DOMAIN, &missing, TRIP).unwrap().value, 12);
    let three = problem("(= (total-cost) 3)", "(:metric minimize (total-cost))");
    assert_eq!(run(DOMAIN, &three, TRIP).unwrap().value, 15);
}

#[test]
fn without_a_metric_every_step_costs_one() {
    let r = run(DOMAIN, &problem("(= (total-cost) 0)", ""), TRIP).unwrap();
    assert!(r.is_valid());
    assert_eq!((r.value, r.cost_model), (2, CostModel::PlanLength));
    // A domain without action costs counts steps even if the problem has a metric.
    let domain = "(define (domain d) (:predicates (p)) (:action a :parameters () \
                  :precondition (and) :effect (p)))";
    let problem = "(define (problem q) (:domain d) (:init) (:goal (p)) \
                   (:metric minimize (total-cost)))";
    let r = run(domain, problem, "(a)\n(a)\n(a)").unwrap();
    assert_eq!((r.value, r.cost_model), (3, CostModel::PlanLength));
}

#[test]
fn an_action_without_a_cost_effect_costs_nothing_under_a_metric() {
    let r = report(&format!("(stay a a)\n{TRIP}(stay b b)"));
    assert!(r.is_valid(), "{r:?}");
    assert_eq!(r.value, 12);
}

#[test]
fn a_missing_function_value_for_a_used_term_is_an_error() {
    let plan = format!("{TRIP}(drive t1 b depot)");
    assert_eq!(
        run(DOMAIN, &with_costs(), &plan),
        Err(ValidateError::MissingFunctionValue {
            step: 3,
            action: "(drive t1 b depot)".into(),
            term: GroundAtom::new("road-length", ["b", "depot"]),
        })
    );
    // Without a metric the cost terms are not looked at.
    let r = run(DOMAIN, &problem("", ""), &plan).unwrap();
    assert_eq!(
        r.verdict,
        Verdict::GoalNotSatisfied {
            unsatisfied: vec![
                lit(true, "at", &["t1", "b"]),
                lit(false, "at", &["t1", "depot"])
            ],
        }
    );
}

#[test]
fn an_inapplicable_step_names_the_false_preconditions() {
    let f = step_failure("(drive t1 depot a)\n(drive t1 depot a)\n(drive t1 a b)");
    assert_eq!(
        f,
        StepFailure {
            step: 2,
            action: "(drive t1 depot a)".into(),
            line: 2,
            reason: Reason::UnsatisfiedPrecondition {
                unsatisfied: vec![lit(true, "at", &["t1", "depot"])],
            },
        }
    );
    assert_eq!(
        f.to_string(),
        "step 2 (drive t1 depot a): unsatisfied precondition: (at t1 depot)"
    );
    // All false literals, in the action's order.
    let f = step_failure("(drive c1 b b)");
    assert_eq!(
        f.reason,
        Reason::UnsatisfiedPrecondition {
            unsatisfied: vec![
                lit(true, "at", &["c1", "b"]),
                lit(true, "road", &["b", "b"]),
                lit(false, "=", &["b", "b"]),
            ],
        }
    );
}

#[test]
fn the_value_of_a_failed_plan_counts_the_steps_before_the_failure() {
    let r = report("(drive t1 depot a)\n(drive t1 depot a)");
    assert_eq!((r.value, r.steps_executed), (5, 1));
}

#[test]
fn deletes_come_before_adds() {
    // refresh deletes and adds (at t1 depot): the atom stays true.
    let r = report(&format!("(refresh t1 depot)\n(refresh t1 depot)\n{TRIP}"));
    assert!(r.is_valid(), "{r:?}");
    assert_eq!(r.value, 16);
}

#[test]
fn equality_and_inequality() {
    assert!(report(&format!("(stay a a)\n{TRIP}")).is_valid());
    assert_eq!(
        step_failure("(stay a b)").reason,
        Reason::UnsatisfiedPrecondition {
            unsatisfied: vec![lit(true, "=", &["a", "b"])],
        }
    );
    // Constants compare like objects.
    assert!(report(&format!("(stay depot depot)\n{TRIP}")).is_valid());
}

#[test]
fn negative_preconditions() {
    assert!(report(&format!("(mark t1)\n(mark a)\n{TRIP}")).is_valid());
    let f = step_failure("(mark t1)\n(mark t1)");
    assert_eq!(f.step, 2);
    assert_eq!(
        f.reason,
        Reason::UnsatisfiedPrecondition {
            unsatisfied: vec![lit(false, "marked", &["t1"])],
        }
    );
    assert_eq!(
        f.to_string(),
        "step 2 (mark t1): unsatisfied precondition: (not (marked t1))"
    );
}

#[test]
fn unsatisfied_goals_positive_and_negative_are_listed_in_order() {
    let r = report("");
    assert_eq!(
        r.verdict,
        Verdict::GoalNotSatisfied {
            unsatisfied: vec![
                lit(true, "at", &["t1", "b"]),
                lit(false, "at", &["t1", "depot"]),
                lit(true, "visited", &["a"]),
            ],
        }
    );
    assert_eq!((r.value, r.steps_executed), (0, 0));
}

#[test]
fn an_empty_plan_is_valid_when_the_goal_holds_initially() {
    let domain = "(define (domain d) (:predicates (p)) (:action a :parameters () \
                  :precondition (p) :effect (not (p))))";
    let problem = "(define (problem q) (:domain d) (:init (p)) (:goal (p)))";
    let r = run(domain, problem, "; cost = 0 (unit cost)\n").unwrap();
    assert!(r.is_valid());
    assert_eq!(r.value, 0);
    let problem = "(define (problem q) (:domain d) (:init (p)) (:goal (not (p))))";
    assert!(run(domain, problem, "(a)").unwrap().is_valid());
    assert_eq!(
        run(domain, problem, "").unwrap().verdict,
        Verdict::GoalNotSatisfied {
            unsatisfied: vec![lit(false, "p", &[])],
        }
    );
}

#[test]
fn types_subtypes_either_and_constants() {
    // A car is a vehicle.
    let r = report(&format!("(drive c1 a b)\n{TRIP}"));
    assert!(r.is_valid(), "{r:?}");
    assert_eq!(r.value, 19);
    let f = step_failure("(drive x depot a)");
    assert_eq!(
        f.reason,
        Reason::WrongType {
            object: "x".into(),
            parameter: "?v".into(),
            expected: "vehicle".into(),
            declared: vec!["object".into()],
        }
    );
    assert_eq!(
        f.reason.to_string(),
        "`x` (of type object) is not of type vehicle, as parameter ?v requires"
    );
    let f = step_failure("(mark c1)");
    assert_eq!(
        f.reason,
        Reason::WrongType {
            object: "c1".into(),
            parameter: "?x".into(),
            expected: "(either truck place)".into(),
            declared: vec!["car".into()],
        }
    );
    assert!(report(&format!("(mark depot)\n(mark t1)\n{TRIP}")).is_valid());
    // A place is not a vehicle, even though both are objects.
    assert!(matches!(
        step_failure("(drive a depot a)").reason,
        Reason::WrongType { .. }
    ));
}

#[test]
fn unknown_actions_objects_and_wrong_argument_counts() {
    assert_eq!(step_failure("(fly t1 a)").reason, Reason::UnknownAction);
    assert_eq!(
        step_failure("(drive t1 depot)").reason,
        Reason::WrongArgumentCount {
            expected: 3,
            found: 2
        }
    );
    assert_eq!(
        step_failure("(drive t1 depot zz)").reason,
        Reason::UnknownObject {
            object: "zz".into()
        }
    );
    // A variable is not an object.
    assert_eq!(
        step_failure("(mark ?x)").reason,
        Reason::UnknownObject {
            object: "?x".into()
        }
    );
    let f = step_failure(&format!("; header\n\n{TRIP}(FLY t1)"));
    assert_eq!((f.step, f.line, f.action.as_str()), (3, 5, "(fly t1)"));
}

#[test]
fn untyped_domains_accept_every_object_and_constant() {
    let domain = "(define (domain d) (:constants k) (:predicates (p ?x) (q ?x ?y)) \
                  (:action a :parameters (?x ?y) :precondition (p ?x) :effect (q ?x ?y)))";
    let problem = "(define (problem q) (:domain d) (:objects o) (:init (p o) (p k)) \
                   (:goal (and (q o k) (q k o))))";
    let r = run(domain, problem, "(a o k)\n(a k o)").unwrap();
    assert!(r.is_valid(), "{r:?}");
}

#[test]
fn a_type_declared_with_two_parents_belongs_to_both() {
    // Storage declares a type twice with two parents.
    let domain = "(define (domain d) (:types box - tool box - cargo) \
                  (:predicates (used ?t - tool) (loaded ?c - cargo)) \
                  (:action use :parameters (?t - tool) :precondition (and) :effect (used ?t)) \
                  (:action load :parameters (?c - cargo) :precondition (and) :effect (loaded ?c)))";
    let problem = "(define (problem q) (:domain d) (:objects b1 - box) (:init) \
                   (:goal (and (used b1) (loaded b1))))";
    assert!(run(domain, problem, "(use b1)\n(load b1)")
        .unwrap()
        .is_valid());
}
