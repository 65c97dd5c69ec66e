//! Drives the real `demoplan` executable: exit codes, diagnostics and printed artefacts.
//! Snapshots (insta) pin the messages; `cargo insta review` updates them on purpose.

#![allow(clippy::unwrap_used, clippy::expect_used)] // tests fail loudly by design

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

fn demoplan() -> Command {
    let mut cmd = Command::new(env!("CARGO_BIN_EXE_demoplan"));
    cmd.env("NO_COLOR", "1");
    cmd
}

fn fixtures() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/fixtures")
}

fn workspace() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../..")
}

/// Exit code, standard output and standard error, as one text to snapshot.
fn transcript(out: &Output) -> String {
    format!(
        "exit: {}\n--- stdout\n{}--- stderr\n{}",
        out.status
            .code()
            .map_or("signal".to_string(), |c| c.to_string()),
        String::from_utf8_lossy(&out.stdout),
        String::from_utf8_lossy(&out.stderr)
    )
}

/// Each folder under `fixtures/malformed` holds one mistake: a `domain.pddl`, and a
/// `problem.pddl` when the mistake is in the problem. The folder name's first word says
/// which exit code a user gets: syntax, semantic and problem mistakes 31 (Fast Downward's
/// input error), unsupported constructs 34, except where a problem uses an unsupported
/// construct (named `problem-...` but exiting 34, pinned by its snapshot).
#[test]
fn malformed_inputs_give_diagnostics_and_exit_codes() {
    let dir = fixtures().join("malformed");
    let mut cases: Vec<String> = std::fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    cases.sort();
    assert!(cases.len() >= 25, "only {} malformed fixtures", cases.len());
    for case in &cases {
        let file = if dir.join(case).join("problem.pddl").exists() {
            format!("{case}/problem.pddl")
        } else {
            format!("{case}/domain.pddl")
        };
        let out = demoplan()
            .current_dir(&dir)
            .args(["check", &file])
            .output()
            .unwrap();
        let code = out.status.code();
        let stderr = String::from_utf8_lossy(&out.stderr);
        match case.split('-').next() {
            Some("syntax" | "semantic") => assert_eq!(code, Some(31), "{case}: {stderr}"),
            Some("unsupported") => assert_eq!(code, Some(34), "{case}: {stderr}"),
            Some("problem") => assert!(matches!(code, Some(31 | 34)), "{case}: {stderr}"),
            _ => panic!(
                "fixture {case} does not start with syntax-, semantic-, unsupported- or problem-"
            ),
        }
        assert!(
            stderr.contains(&format!("[{file}:")),
            "{case}: no file:line:col in\n{stderr}"
        );
        assert!(
            out.stdout.is_empty(),
            "{case}: printed a summary despite the error"
        );
        insta::assert_snapshot!(format!("malformed-{case}"), transcript(&out));
    }
}

#[test]
fn check_summarises_the_example_task() {
    let out = demoplan()
        .current_dir(workspace())
        .args([
            "check",
            "examples/cubes/domain.pddl",
            "examples/cubes/tower-3.pddl",
        ])
        .output()
        .unwrap();
    insta::assert_snapshot!(transcript(&out));
}

#[test]
fn check_finds_the_domain_by_fast_downward_naming_rules() {
    let tmp = tempdir("naming");
    let domain = std::fs::read_to_string(workspace().join("examples/cubes/domain.pddl")).unwrap();
    let problem = std::fs::read_to_string(workspace().join("examples/cubes/tower-3.pddl")).unwrap();
    // Airport's rule: the first three characters of the problem's name, then -domain.pddl.
    std::fs::write(tmp.join("p01-domain.pddl"), &domain).unwrap();
    std::fs::write(tmp.join("p01-task.pddl"), &problem).unwrap();
    let out = demoplan()
        .current_dir(&tmp)
        .args(["check", "p01-task.pddl"])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(0), "{}", transcript(&out));
    assert!(String::from_utf8_lossy(&out.stdout).contains("(p01-domain.pddl)"));

    std::fs::remove_file(tmp.join("p01-domain.pddl")).unwrap();
    let out = demoplan()
        .current_dir(&tmp)
        .args(["check", "p01-task.pddl"])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(36), "{}", transcript(&out));
    insta::assert_snapshot!(transcript(&out));
}

#[test]
fn command_line_mistakes_exit_36_and_help_exits_0() {
    for args in [
        &["frobnicate"][..],
        &["check"],
        &["check", "a", "b", "c"],
        &["fmt", "--check", "--stdout", "x"],
    ] {
        let out = demoplan().args(args).output().unwrap();
        assert_eq!(
            out.status.code(),
            Some(36),
            "{args:?}: {}",
            transcript(&out)
        );
    }
    let out = demoplan()
        .args(["check", "/nonexistent/domain.pddl", "/nonexistent/p.pddl"])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(36));
    insta::assert_snapshot!(transcript(&out));
    for args in [&["--help"][..], &["--version"], &["check", "--help"]] {
        let out = demoplan().args(args).output().unwrap();
        assert_eq!(out.status.code(), Some(0), "{args:?}");
    }
}

#[test]
fn binary_input_is_an_input_error_not_a_panic() {
    let tmp = tempdir("binary");
    std::fs::write(tmp.join("domain.pddl"), [0xff, 0xfe, 0x28, 0x00, 0x81]).unwrap();
    let out = demoplan()
        .current_dir(&tmp)
        .args(["check", "domain.pddl"])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(31), "{}", transcript(&out));
}

#[test]
fn fmt_rewrites_in_place_keeps_the_header_and_is_idempotent() {
    let tmp = tempdir("fmt");
    let file = tmp.join("domain.pddl");
    std::fs::write(
        &file,
        "; Licence header\n;; kept\n(DEFINE (Domain D) (:PREDICATES (P ?X)) ; inner\n (:action A :parameters (?x) :precondition (and (P ?x) (and)) :effect (not (P ?x))))",
    )
    .unwrap();
    let out = demoplan()
        .args(["fmt", file.to_str().unwrap()])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(0), "{}", transcript(&out));
    assert!(
        String::from_utf8_lossy(&out.stderr).contains("1 comment inside the definition dropped")
    );
    let first = std::fs::read_to_string(&file).unwrap();
    insta::assert_snapshot!(first);
    let check = demoplan()
        .args(["fmt", "--check", file.to_str().unwrap()])
        .output()
        .unwrap();
    assert_eq!(check.status.code(), Some(0), "{}", transcript(&check));
    let again = demoplan()
        .args(["fmt", file.to_str().unwrap()])
        .output()
        .unwrap();
    assert_eq!(again.status.code(), Some(0));
    assert_eq!(std::fs::read_to_string(&file).unwrap(), first);
}

#[test]
fn fmt_check_reports_files_not_in_canonical_form() {
    let tmp = tempdir("fmt-check");
    let file = tmp.join("domain.pddl");
    std::fs::write(&file, "(define (domain d) (:predicates (p)))").unwrap();
    let out = demoplan()
        .args(["fmt", "--check", file.to_str().unwrap()])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(1));
    assert_eq!(
        std::fs::read_to_string(&file).unwrap(),
        "(define (domain d) (:predicates (p)))"
    );
}

#[test]
fn fmt_leaves_a_malformed_file_untouched() {
    let tmp = tempdir("fmt-bad");
    let file = tmp.join("domain.pddl");
    std::fs::write(&file, "(define (domain d) (:predicates (p))").unwrap();
    let out = demoplan()
        .args(["fmt", file.to_str().unwrap()])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(31));
    assert_eq!(
        std::fs::read_to_string(&file).unwrap(),
        "(define (domain d) (:predicates (p))"
    );
    assert_eq!(
        std::fs::read_dir(&tmp).unwrap().count(),
        1,
        "left a temporary file behind"
    );
}

/// A fresh folder under the target directory for one test.
fn tempdir(name: &str) -> PathBuf {
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join(format!("cli-{name}"));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

/// An optimal plan for `examples/cubes/tower-3.pddl`, as Fast Downward writes it.
const TOWER_PLAN: &str = "(reach left c2)\n(take left c2 table)\n(stack left c2 c1)\n\
                          (reach left c3)\n(take left c3 table)\n(stack left c3 c2)\n\
                          ; cost = 6 (general cost)\n";

/// Runs `demoplan validate` on the example cube task with the given plan files, written
/// into a fresh folder that is the working directory (so the output names them briefly).
fn validate_cubes(test: &str, plans: &[(&str, &str)]) -> Output {
    let tmp = tempdir(test);
    for (name, text) in plans {
        std::fs::write(tmp.join(name), text).unwrap();
    }
    let cubes = workspace().join("examples/cubes");
    demoplan()
        .current_dir(&tmp)
        .arg("validate")
        .arg(cubes.join("domain.pddl"))
        .arg(cubes.join("tower-3.pddl"))
        .args(plans.iter().map(|(name, _)| name))
        .output()
        .unwrap()
}

#[test]
fn validate_accepts_a_valid_plan_with_vals_wording() {
    let out = validate_cubes("validate-valid", &[("tower.plan", TOWER_PLAN)]);
    assert_eq!(out.status.code(), Some(0), "{}", transcript(&out));
    insta::assert_snapshot!(transcript(&out));
}

#[test]
fn validate_exit_status_is_the_number_of_invalid_plans() {
    let steps: Vec<&str> = TOWER_PLAN.lines().collect();
    let goal_missed = steps[..3].join("\n");
    let skipped_take = format!("{}\n{}", steps[0], steps[2]);
    let out = validate_cubes(
        "validate-invalid",
        &[
            ("tower.plan", TOWER_PLAN),
            ("skipped-take.plan", &skipped_take),
            ("half-tower.plan", &goal_missed),
            ("empty.plan", "; nothing\n"),
            ("wrong-type.plan", "(reach c1 left)\n"),
            (
                "malformed.plan",
                ";; header\n(reach left c2)\nstack left c2 c1\n",
            ),
        ],
    );
    assert_eq!(out.status.code(), Some(5), "{}", transcript(&out));
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert_eq!(stdout.matches("Plan valid").count(), 1);
    assert_eq!(stdout.matches("Plan invalid").count(), 5);
    insta::assert_snapshot!(transcript(&out));
}

#[test]
fn validate_input_errors_use_the_pddl_exit_codes() {
    let cubes = workspace().join("examples/cubes");
    // A missing plan file is a command line mistake, found before any plan is judged.
    let tmp = tempdir("validate-errors");
    std::fs::write(tmp.join("tower.plan"), TOWER_PLAN).unwrap();
    let out = demoplan()
        .current_dir(&tmp)
        .arg("validate")
        .arg(cubes.join("domain.pddl"))
        .arg(cubes.join("tower-3.pddl"))
        .args(["tower.plan", "missing.plan"])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(36), "{}", transcript(&out));
    assert!(out.stdout.is_empty(), "{}", transcript(&out));
    // Malformed PDDL: 31, with the diagnostic of `check`.
    std::fs::write(tmp.join("problem.pddl"), "(define (problem p) (:domain d)").unwrap();
    let out = demoplan()
        .current_dir(&tmp)
        .arg("validate")
        .arg(cubes.join("domain.pddl"))
        .args(["problem.pddl", "tower.plan"])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(31), "{}", transcript(&out));
    assert!(String::from_utf8_lossy(&out.stderr).contains("[problem.pddl:"));
    // No plan at all: the usage error of clap, 36.
    let out = demoplan()
        .arg("validate")
        .arg(cubes.join("domain.pddl"))
        .arg(cubes.join("tower-3.pddl"))
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(36), "{}", transcript(&out));
}
