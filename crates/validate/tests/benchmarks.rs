//! Every reference plan of the benchmark suite validates with its known optimal cost as
//! final value, and the same plan with one step in the middle dropped does not.

#![allow(clippy::unwrap_used, clippy::expect_used)] // tests fail loudly by design

use std::path::Path;

fn read(path: &Path) -> String {
    std::fs::read_to_string(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()))
}

#[test]
fn every_reference_plan_is_valid_at_its_optimal_cost_and_dropping_a_step_breaks_it() {
    let suite = benchmarks::Suite::locate().unwrap();
    let instances = suite.instances().unwrap();
    assert!(
        instances.len() > 400,
        "expected the whole suite, found {} instances",
        instances.len()
    );
    let mut mutated = 0;
    for i in &instances {
        let domain = pddl::parse_domain(&read(&i.domain_file)).unwrap();
        let problem = pddl::parse_problem(&read(&i.problem_file)).unwrap();
        let plan_file = suite
            .root()
            .join("reference-plans")
            .join(&i.domain)
            .join(format!("{}.plan", i.name));
        let text = read(&plan_file);
        let header = format!(";; Optimal cost: {}", i.optimal_cost);
        assert_eq!(
            text.lines().next(),
            Some(header.as_str()),
            "{}",
            plan_file.display()
        );
        let plan = pddl::parse_plan(&text)
            .unwrap_or_else(|e| panic!("{}:{}: {}", plan_file.display(), e.line, e.kind));
        let report = validate::validate(&domain, &problem, &plan)
            .unwrap_or_else(|e| panic!("{}: {e}", plan_file.display()));
        assert_eq!(
            (&report.verdict, report.value),
            (&validate::Verdict::Valid, i.optimal_cost as i64),
            "{}",
            plan_file.display()
        );

        if plan.steps.is_empty() {
            continue;
        }
        let mut shorter = plan.clone();
        shorter.steps.remove(plan.steps.len() / 2);
        let report = validate::validate(&domain, &problem, &shorter)
            .unwrap_or_else(|e| panic!("{}: {e}", plan_file.display()));
        assert!(
            !report.is_valid(),
            "{}: still valid without step {} {}",
            plan_file.display(),
            plan.steps.len() / 2 + 1,
            plan.steps[plan.steps.len() / 2]
        );
        mutated += 1;
    }
    assert_eq!(mutated, instances.len(), "a reference plan is empty");
}
