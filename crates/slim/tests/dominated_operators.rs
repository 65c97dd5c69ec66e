//! Dominated operators in a learned domain: the paper's study's priority-6 domain (seed 7,
//! calibrated costs) has `put2`-style variants, the same effects as another operator with
//! more preconditions and a higher cost. Removing them (`TranslateOptions`) keeps the
//! optimal cost, says how many went, and leaves a smaller task; with h² before it too.

#![allow(clippy::unwrap_used, clippy::expect_used)] // tests fail loudly by design

use std::path::Path;
use std::time::Instant;

fn fixture(name: &str) -> String {
    let path = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../cubeworld/tests/fixtures")
        .join(name);
    std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display()))
}

#[test]
fn removing_dominated_operators_of_a_learned_domain_keeps_the_optimal_cost() {
    let domain = pddl::parse_domain(&fixture("seed7-calibrated-prio-6.pddl")).unwrap();
    let problem = pddl::parse_problem(&fixture("goal-2.pddl")).unwrap();
    pddl::check_problem(&domain, &problem).unwrap();
    let config = search::parse_search("astar(lmcut())").unwrap();
    let run = |options: translate::TranslateOptions| {
        let mut lines = Vec::new();
        let input = slim::PlanInput::Pddl {
            domain: &domain,
            problem: &problem,
            options,
        };
        let logged = slim::plan_logged(
            input,
            &config,
            &task::Limits::default(),
            Instant::now(),
            &mut |l| lines.push(l.to_string()),
        )
        .unwrap();
        (logged, lines)
    };
    let dominated = translate::TranslateOptions {
        remove_dominated_operators: true,
        ..Default::default()
    };
    let (full, full_log) = run(Default::default());
    let (pruned, pruned_log) = run(dominated);
    assert!(!full_log.iter().any(|l| l.contains("dominated")));
    let removed: usize = pruned_log
        .iter()
        .find_map(|l| {
            l.strip_prefix("Removed ")?
                .strip_suffix(" dominated operator(s)")
        })
        .expect("the removal is reported")
        .parse()
        .unwrap();
    assert!(removed > 0, "no dominated operators in a learned domain");
    let operators = |log: &[String]| -> usize {
        log.iter()
            .find_map(|l| l.strip_prefix("Translator operators: "))
            .unwrap()
            .parse()
            .unwrap()
    };
    assert_eq!(operators(&pruned_log) + removed, operators(&full_log));
    assert_eq!(full.run.outcome, slim::Outcome::Solved);
    assert_eq!(pruned.run.cost, full.run.cost);
    // With h² first, the cost stays too.
    let (both, both_log) = run(translate::TranslateOptions {
        h2_mutexes: true,
        ..dominated
    });
    assert!(both_log.iter().any(|l| l.starts_with("h2: added ")));
    assert_eq!(both.run.cost, full.run.cost);
    for (name, run) in [
        ("full", &full),
        ("pruned", &pruned),
        ("h2 and pruned", &both),
    ] {
        let s = run.statistics.unwrap();
        eprintln!(
            "{name}: {} operators, {} expanded, {} generated, search {:?}",
            run.sizes.unwrap().operators,
            s.expanded,
            s.generated,
            s.search_time
        );
    }
}
