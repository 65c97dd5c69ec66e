//! The translation has Fast Downward's variables, values and operators in Fast Downward's
//! order, on benchmark instances whose Fast Downward translation is recorded in
//! `tests/fixtures/fd-order` (one `var` line per variable with its value names, one `op`
//! line per operator, both in the order of Fast Downward's output.sas, or only `ops N`,
//! the number of operators, where there are thousands).
//!
//! LM-cut breaks ties by this order, so a translator change that keeps the task but
//! changes the order changes LM-cut's values and its expansions (satellite p09: 344
//! against 1,681 in the order the translator used before). `bench/translator-vars`
//! compares against a live Fast Downward on whole lists.

#![allow(clippy::unwrap_used, clippy::expect_used)] // tests fail loudly by design

use std::path::Path;

fn translate(domain: &str, instance: &str) -> task::Task {
    let i = benchmarks::Suite::locate()
        .and_then(|suite| suite.instance(domain, instance))
        .unwrap();
    let d = pddl::parse_domain(&std::fs::read_to_string(&i.domain_file).unwrap()).unwrap();
    let p = pddl::parse_problem(&std::fs::read_to_string(&i.problem_file).unwrap()).unwrap();
    match translate::translate(&d, &p).unwrap() {
        translate::Translation::Task(t) => t.task,
        translate::Translation::Unsolvable { reason, .. } => {
            panic!("{domain}/{instance}: {reason}")
        }
        translate::Translation::Stopped { limit, .. } => {
            panic!("{domain}/{instance}: {limit} without limits")
        }
    }
}

#[test]
fn translations_have_fast_downwards_order() {
    let fixtures = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/fixtures/fd-order");
    let mut files: Vec<_> = std::fs::read_dir(&fixtures)
        .unwrap()
        .map(|e| e.unwrap().path())
        .collect();
    files.sort();
    assert!(
        files.len() >= 5,
        "fixtures missing in {}",
        fixtures.display()
    );
    for file in files {
        let stem = file.file_stem().unwrap().to_str().unwrap();
        let (domain, instance) = stem.split_once("__").unwrap();
        let text = std::fs::read_to_string(&file).unwrap();
        let expected_vars: Vec<&str> = text
            .lines()
            .filter_map(|l| l.strip_prefix("var "))
            .collect();
        let expected_ops: Vec<&str> = text.lines().filter_map(|l| l.strip_prefix("op ")).collect();
        let task = translate(domain, instance);
        let vars: Vec<String> = task
            .variables
            .iter()
            .map(|v| v.value_names.join(" | "))
            .collect();
        assert_eq!(vars, expected_vars, "{domain}/{instance}: variables");
        if !expected_ops.is_empty() {
            let ops: Vec<&str> = task.operators.iter().map(|o| o.name.as_str()).collect();
            assert_eq!(ops, expected_ops, "{domain}/{instance}: operators");
        }
        if let Some(count) = text.lines().find_map(|l| l.strip_prefix("ops ")) {
            assert_eq!(
                task.operators.len(),
                count.parse::<usize>().unwrap(),
                "{domain}/{instance}: operators"
            );
        }
        assert!(
            !expected_ops.is_empty() || text.lines().any(|l| l.starts_with("ops ")),
            "{}: records no operators",
            file.display()
        );
    }
}
