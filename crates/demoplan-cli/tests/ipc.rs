//! The planner over the IPC benchmark suite (`--features ipc`; the suite from
//! `DEMOPLAN_BENCHMARKS`, default `../shared/benchmarks`, and a missing suite fails):
//! optimal, validated plans on a quick subset of every domain.

#![allow(clippy::unwrap_used, clippy::expect_used)] // tests fail loudly by design

mod common;
use common::{demoplan, fixtures, logged_number, tempdir, transcript};

/// Each line of `fixtures/quick-instances.txt` names an instance of the benchmark suite
/// and the searches to run on it; every plan must cost the known optimum and validate.
#[test]
fn planner_finds_optimal_validated_plans_on_a_quick_subset_of_every_domain() {
    let suite = benchmarks::Suite::locate().unwrap();
    let instances = suite.instances().unwrap();
    let list = std::fs::read_to_string(fixtures().join("quick-instances.txt")).unwrap();
    let tmp = tempdir("quick");
    let mut domains = std::collections::BTreeSet::new();
    let mut runs = 0;
    for line in list
        .lines()
        .map(|l| l.split('#').next().unwrap_or("").trim())
        .filter(|l| !l.is_empty())
    {
        let (name, searches) = line.split_once(' ').unwrap();
        let instance = instances
            .iter()
            .find(|i| format!("{}/{}", i.domain, i.name) == name)
            .unwrap_or_else(|| panic!("{name} is not in optimal_costs.csv"));
        domains.insert(instance.domain.clone());
        for search in searches.split_whitespace() {
            let plan_file = tmp.join("plan");
            let out = demoplan()
                .arg("plan")
                .arg(&instance.domain_file)
                .arg(&instance.problem_file)
                .args(["--search", search, "--plan-file"])
                .arg(&plan_file)
                .arg("--validate")
                .output()
                .unwrap();
            let log = String::from_utf8_lossy(&out.stdout);
            assert_eq!(
                out.status.code(),
                Some(0),
                "{name} {search}: {}",
                transcript(&out)
            );
            assert_eq!(
                logged_number(&log, "Plan cost: "),
                Some(instance.optimal_cost),
                "{name} {search}"
            );
            assert!(
                log.contains("Plan valid"),
                "{name} {search}: not validated\n{log}"
            );
            let plan = std::fs::read_to_string(&plan_file).unwrap();
            assert!(
                plan.ends_with(&format!(
                    "; cost = {} (general cost)\n",
                    instance.optimal_cost
                )) || plan.ends_with(&format!("; cost = {} (unit cost)\n", instance.optimal_cost)),
                "{name}: {plan}"
            );
            runs += 1;
        }
    }
    let all: std::collections::BTreeSet<String> =
        instances.iter().map(|i| i.domain.clone()).collect();
    assert_eq!(
        domains, all,
        "the quick list must cover every benchmark domain"
    );
    assert!(runs >= all.len());
}
