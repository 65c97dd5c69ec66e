//! Every domain and problem file of the IPC benchmark suite parses, checks against its
//! domain, and survives the writer: `parse(write(x)) == x`.

#![allow(clippy::unwrap_used, clippy::expect_used)] // tests fail loudly by design

use std::path::Path;

fn read(path: &Path) -> String {
    std::fs::read_to_string(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()))
}

fn round_trip(path: &Path, source: &str) {
    let parsed = pddl::parse_file(source).unwrap_or_else(|e| {
        let (line, col) = e.span.line_col(source);
        panic!("{}:{line}:{col}: {}", path.display(), e.message)
    });
    let (written, reparsed) = match &parsed.content {
        pddl::PddlFile::Domain(d) => {
            let w = d.to_string();
            let r = pddl::parse_domain(&w).map(pddl::PddlFile::Domain);
            (w, r)
        }
        pddl::PddlFile::Problem(p) => {
            let w = p.to_string();
            let r = pddl::parse_problem(&w).map(pddl::PddlFile::Problem);
            (w, r)
        }
    };
    let reparsed = reparsed.unwrap_or_else(|e| {
        panic!(
            "{}: written form does not parse: {e}\n{written}",
            path.display()
        )
    });
    assert_eq!(
        reparsed,
        parsed.content,
        "{}: round trip changed the file",
        path.display()
    );
}

#[test]
fn every_benchmark_file_parses_and_round_trips() {
    let suite = benchmarks::Suite::locate().unwrap();
    let files = suite.pddl_files().unwrap();
    assert!(
        files.len() > 400,
        "expected the whole suite, found {} files",
        files.len()
    );
    for path in &files {
        round_trip(path, &read(path));
    }
}

#[test]
fn every_benchmark_problem_checks_against_its_domain() {
    let suite = benchmarks::Suite::locate().unwrap();
    let instances = suite.instances().unwrap();
    assert!(instances.len() > 400);
    for i in &instances {
        let dsrc = read(&i.domain_file);
        let psrc = read(&i.problem_file);
        let domain = pddl::parse_domain(&dsrc).unwrap();
        let problem = pddl::parse_problem(&psrc).unwrap();
        if let Err(e) = pddl::check_problem(&domain, &problem) {
            let (line, col) = e.span.line_col(&psrc);
            panic!("{}:{line}:{col}: {}", i.problem_file.display(), e.message);
        }
    }
}
