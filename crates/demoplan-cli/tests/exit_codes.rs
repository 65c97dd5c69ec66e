//! The README's exit code table is what the binary does: the test reads the table and
//! runs, for every code it names, a case that must end with that code; a code without a
//! case, or a case whose code the table does not name, fails it. Codes that
//! `docs/reliability.md` names (`exit 23`) must be in the table too.

#![allow(clippy::unwrap_used, clippy::expect_used)] // tests fail loudly by design

use std::path::{Path, PathBuf};
use std::process::{Command, Output, Stdio};

mod common;
use common::{demoplan, fixtures, workspace};

fn scratch() -> PathBuf {
    let dir =
        Path::new(env!("CARGO_TARGET_TMPDIR")).join(format!("exit-codes-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

/// The codes of the README's `## Exit codes` table, in its order: the first cell of
/// each row (`N` for validate's count of invalid plans), with the row's text.
fn readme_codes() -> Vec<(String, String)> {
    let readme = std::fs::read_to_string(workspace().join("README.md")).unwrap();
    let section = readme
        .split("\n## Exit codes\n")
        .nth(1)
        .expect("README has an `## Exit codes` section");
    let section = section.split("\n## ").next().unwrap_or(section);
    section
        .lines()
        .filter(|l| l.starts_with('|'))
        .filter_map(|l| {
            let first = l.trim_matches('|').split('|').next()?.trim().to_string();
            let numeric = first.bytes().all(|b| b.is_ascii_digit()) && !first.is_empty();
            (numeric || first == "N").then(|| (first, l.to_string()))
        })
        .collect()
}

/// A generated task: `(on ?s)` for `switches` switches, the goal all on; `unreachable`
/// adds a goal no action gives.
fn switches(dir: &Path, unreachable: bool) {
    std::fs::write(
        dir.join("domain.pddl"),
        "(define (domain switches) (:requirements :strips :negative-preconditions)
           (:predicates (on ?s) (broken ?s))
           (:action turn-on :parameters (?s) :precondition (not (on ?s)) :effect (on ?s)))\n",
    )
    .unwrap();
    let extra = if unreachable { " (broken s0)" } else { "" };
    std::fs::write(
        dir.join("problem.pddl"),
        format!(
            "(define (problem p) (:domain switches) (:objects s0 s1) (:init) (:goal (and (on s0) (on s1){extra})))\n"
        ),
    )
    .unwrap();
}

fn run(cmd: &mut Command) -> Output {
    cmd.output().unwrap()
}

/// The case for `code`: runs it and returns what it did. `None` for a code no correct
/// run gives (32: a plan that fails validation is a bug of demoplan's).
fn case(code: &str, dir: &Path) -> Option<Output> {
    let fixtures = fixtures();
    let d = dir.join("domain.pddl");
    let p = dir.join("problem.pddl");
    Some(match code {
        "0" => run(demoplan().arg("check").args([&d, &p])),
        "1" => {
            let messy = dir.join("messy.pddl");
            std::fs::write(&messy, "(define (domain D) (:predicates (P)))").unwrap();
            run(demoplan().args(["fmt", "--check"]).arg(messy))
        }
        "N" => {
            // Two invalid plans: validate exits 2.
            let wrong = dir.join("wrong.plan");
            std::fs::write(&wrong, "(turn-on s0)\n").unwrap();
            run(demoplan().arg("validate").args([&d, &p, &wrong, &wrong]))
        }
        "11" => {
            let unsolvable = dir.join("unsolvable");
            std::fs::create_dir_all(&unsolvable).unwrap();
            switches(&unsolvable, true);
            run(demoplan().current_dir(&unsolvable).args([
                "plan",
                "domain.pddl",
                "problem.pddl",
                "--search",
                "astar(blind())",
            ]))
        }
        "12" => {
            let library = workspace().join("crates/slim/tests/fixtures/widening-library.json");
            let goal = dir.join("goal.pddl");
            let made = run(demoplan()
                .args(["problem", "--paper-goal", "1", "-o"])
                .arg(&goal));
            assert!(made.status.success(), "{made:?}");
            run(demoplan()
                .arg("solve")
                .arg(library)
                .arg(goal)
                .args(["--time-limit", "0s"]))
        }
        "45" => {
            // Its only way to pick a cube up is an Idle that adds inHand: the plan fails
            // in the cube world, and without that operator there is none.
            let library =
                workspace().join("crates/closed-loop/tests/fixtures/no-executable-library.json");
            let goal = dir.join("goal-45.pddl");
            let made = run(demoplan()
                .args(["problem", "--paper-goal", "1", "--cubes", "3", "-o"])
                .arg(&goal));
            assert!(made.status.success(), "{made:?}");
            run(demoplan()
                .current_dir(dir)
                .arg("solve")
                .arg(library)
                .arg(goal))
        }
        "22" => {
            let wide = dir.join("wide");
            std::fs::create_dir_all(&wide).unwrap();
            write_switches(&wide, 32);
            let pattern: Vec<String> = (0..30).map(|v| v.to_string()).collect();
            run(demoplan().current_dir(&wide).args([
                "plan",
                "domain.pddl",
                "problem.pddl",
                "--search",
                &format!("astar(pdb([{}]))", pattern.join(", ")),
                "--overall-memory-limit",
                "200M",
            ]))
        }
        "23" => run(demoplan().current_dir(dir).args([
            "plan",
            "domain.pddl",
            "problem.pddl",
            "--search",
            "astar(blind())",
            "--overall-time-limit",
            "0s",
        ])),
        "31" => {
            let broken = dir.join("broken.pddl");
            std::fs::write(&broken, "(define (domain d) (:predicates (p ?x)").unwrap();
            run(demoplan().arg("check").arg(broken))
        }
        "32" => return None,
        "33" => run(demoplan().current_dir(dir).args([
            "plan",
            "domain.pddl",
            "problem.pddl",
            "--search",
            "astar(nonsense())",
        ])),
        "34" => {
            let forall = dir.join("forall.pddl");
            std::fs::write(
                &forall,
                "(define (domain d) (:predicates (p ?x))
                   (:action a :parameters () :precondition (forall (?x) (p ?x)) :effect (p x)))",
            )
            .unwrap();
            run(demoplan().arg("check").arg(forall))
        }
        "35" => run(demoplan()
            .args(["fmt", "--stdout"])
            .arg(&d)
            .stdout(std::fs::File::create("/dev/full").unwrap())),
        "36" => run(demoplan().args(["plan", "--no-such-option"])),
        "75" => {
            let library = dir.join("library.json");
            let lock = std::fs::File::create(dir.join("library.json.lock")).unwrap();
            lock.lock().unwrap();
            let out = run(demoplan()
                .arg("learn")
                .arg(fixtures.join("demonstrations/hand-state.arff"))
                .arg("-o")
                .arg(&library)
                .args(["--lock-timeout", "0.1s"]));
            lock.unlock().unwrap();
            out
        }
        "141" => {
            // Far more than a pipe holds, to a reader that has gone away.
            let mut child = demoplan()
                .args(["fmt", "--stdout"])
                .args(std::iter::repeat_n(&d, 5000))
                .stdout(Stdio::piped())
                .stderr(Stdio::piped())
                .spawn()
                .unwrap();
            drop(child.stdout.take());
            child.wait_with_output().unwrap()
        }
        _ => panic!("the README names exit code {code}, and this test has no case for it"),
    })
}

/// `n` switches, for a task of `n` binary variables.
fn write_switches(dir: &Path, n: usize) {
    std::fs::write(
        dir.join("domain.pddl"),
        "(define (domain switches) (:requirements :strips :negative-preconditions)
           (:predicates (on ?s))
           (:action turn-on :parameters (?s) :precondition (not (on ?s)) :effect (on ?s)))\n",
    )
    .unwrap();
    let names: Vec<String> = (0..n).map(|i| format!("s{i}")).collect();
    let goal: Vec<String> = names.iter().map(|s| format!("(on {s})")).collect();
    std::fs::write(
        dir.join("problem.pddl"),
        format!(
            "(define (problem p) (:domain switches) (:objects {}) (:init) (:goal (and {})))\n",
            names.join(" "),
            goal.join(" ")
        ),
    )
    .unwrap();
}

#[test]
fn every_exit_code_of_the_readme_table_is_what_a_case_gives() {
    let codes = readme_codes();
    assert!(codes.len() >= 14, "only {} codes in the table", codes.len());
    let dir = scratch();
    switches(&dir, false);
    for (code, row) in &codes {
        let Some(out) = case(code, &dir) else {
            assert!(
                row.contains("a bug in demoplan"),
                "exit {code} has no case, so its row must say only a bug gives it: {row}"
            );
            continue;
        };
        let expected = if code == "N" {
            2
        } else {
            code.parse().unwrap()
        };
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert_eq!(
            out.status.code(),
            Some(expected),
            "README: {row}\n--- stdout\n{}\n--- stderr\n{stderr}",
            String::from_utf8_lossy(&out.stdout)
        );
        assert!(!stderr.contains("panicked"), "exit {code}: {stderr}");
    }
}

#[test]
fn the_exit_codes_reliability_names_are_in_the_readme_table() {
    let codes: Vec<String> = readme_codes().into_iter().map(|(c, _)| c).collect();
    let reliability = std::fs::read_to_string(workspace().join("docs/reliability.md")).unwrap();
    let mut named = Vec::new();
    for (at, _) in reliability.match_indices("exit ") {
        let digits: String = reliability[at + 5..]
            .chars()
            .take_while(char::is_ascii_digit)
            .collect();
        if !digits.is_empty() {
            named.push(digits);
        }
    }
    assert!(!named.is_empty(), "docs/reliability.md names no exit code");
    for code in named {
        assert!(
            codes.contains(&code),
            "docs/reliability.md names exit {code}, which the README's table does not"
        );
    }
}
