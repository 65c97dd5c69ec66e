//! Drives the real `demoplan` executable: exit codes, diagnostics and printed artefacts.
//! Snapshots (insta) pin the messages; `cargo insta review` updates them on purpose.

#![allow(clippy::unwrap_used, clippy::expect_used)] // tests fail loudly by design

use std::path::{Path, PathBuf};
use std::process::Output;

mod common;
use common::{
    demoplan, entry_names, exits, exits_saying, fixtures, logged_number, simulated_study,
    stderr_text, stdout_text, succeeds, tempdir, transcript, workspace,
};

/// Each folder under `fixtures/malformed` holds one mistake: a `domain.pddl`, and a
/// `problem.pddl` when the mistake is in the problem. The folder name's first word says
/// which exit code a user gets: syntax, semantic and problem mistakes 31 (Fast Downward's
/// input error), unsupported constructs 34, except where a problem uses an unsupported
/// construct (named `problem-...` but exiting 34, pinned by its snapshot).
#[test]
fn malformed_inputs_give_diagnostics_and_exit_codes() {
    let dir = fixtures().join("malformed");
    let cases = entry_names(&dir);
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
        let stderr = stderr_text(&out);
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
    let out = succeeds(
        demoplan()
            .current_dir(&tmp)
            .args(["check", "p01-task.pddl"]),
    );
    assert!(stdout_text(&out).contains("(p01-domain.pddl)"));

    std::fs::remove_file(tmp.join("p01-domain.pddl")).unwrap();
    let out = exits(
        36,
        demoplan()
            .current_dir(&tmp)
            .args(["check", "p01-task.pddl"]),
    );
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
    let out = exits(
        36,
        demoplan().args(["check", "/nonexistent/domain.pddl", "/nonexistent/p.pddl"]),
    );
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
    exits(
        31,
        demoplan().current_dir(&tmp).args(["check", "domain.pddl"]),
    );
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
    let out = succeeds(demoplan().args(["fmt", file.to_str().unwrap()]));
    assert!(stderr_text(&out).contains("1 comment inside the definition dropped"));
    let first = std::fs::read_to_string(&file).unwrap();
    insta::assert_snapshot!(first);
    succeeds(demoplan().args(["fmt", "--check", file.to_str().unwrap()]));
    succeeds(demoplan().args(["fmt", file.to_str().unwrap()]));
    assert_eq!(std::fs::read_to_string(&file).unwrap(), first);
}

#[test]
fn fmt_check_reports_files_not_in_canonical_form() {
    let tmp = tempdir("fmt-check");
    let file = tmp.join("domain.pddl");
    std::fs::write(&file, "(define (domain d) (:predicates (p)))").unwrap();
    exits(
        1,
        demoplan().args(["fmt", "--check", file.to_str().unwrap()]),
    );
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
    exits(31, demoplan().args(["fmt", file.to_str().unwrap()]));
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
    let stdout = stdout_text(&out);
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
    let out = exits(
        36,
        demoplan()
            .current_dir(&tmp)
            .arg("validate")
            .arg(cubes.join("domain.pddl"))
            .arg(cubes.join("tower-3.pddl"))
            .args(["tower.plan", "missing.plan"]),
    );
    assert!(out.stdout.is_empty(), "{}", transcript(&out));
    // Malformed PDDL: 31, with the diagnostic of `check`.
    std::fs::write(tmp.join("problem.pddl"), "(define (problem p) (:domain d)").unwrap();
    let out = exits(
        31,
        demoplan()
            .current_dir(&tmp)
            .arg("validate")
            .arg(cubes.join("domain.pddl"))
            .args(["problem.pddl", "tower.plan"]),
    );
    assert!(stderr_text(&out).contains("[problem.pddl:"));
    // No plan at all: the usage error of clap, 36.
    exits(
        36,
        demoplan()
            .arg("validate")
            .arg(cubes.join("domain.pddl"))
            .arg(cubes.join("tower-3.pddl")),
    );
}

// ---------------------------------------------------------------------------------------
// The planner: `demoplan plan` on tasks the tests write, protocol and exit codes (the IPC
// suite is `tests/ipc.rs`, behind the `ipc` feature).

/// A gripper task written by the test (a robot with two grippers carries `balls` balls
/// from room a to room b; the state space grows exponentially with the balls), as domain
/// and problem files in `dir`. The planner tests need no benchmark suite.
struct Gripper {
    domain_file: PathBuf,
    problem_file: PathBuf,
}

fn gripper(dir: &Path, balls: usize) -> Gripper {
    const DOMAIN: &str = "(define (domain gripper-typed)
  (:requirements :strips :typing)
  (:types room ball gripper)
  (:predicates (at-robby ?r - room) (at ?b - ball ?r - room) (free ?g - gripper)
               (carry ?b - ball ?g - gripper))
  (:action move :parameters (?from ?to - room)
    :precondition (at-robby ?from)
    :effect (and (at-robby ?to) (not (at-robby ?from))))
  (:action pick :parameters (?b - ball ?r - room ?g - gripper)
    :precondition (and (at ?b ?r) (at-robby ?r) (free ?g))
    :effect (and (carry ?b ?g) (not (at ?b ?r)) (not (free ?g))))
  (:action drop :parameters (?b - ball ?r - room ?g - gripper)
    :precondition (and (carry ?b ?g) (at-robby ?r))
    :effect (and (at ?b ?r) (free ?g) (not (carry ?b ?g)))))
";
    let names: Vec<String> = (1..=balls).map(|i| format!("ball{i}")).collect();
    let problem = format!(
        "(define (problem gripper-{balls})\n  (:domain gripper-typed)\n  \
         (:objects rooma roomb - room left right - gripper {} - ball)\n  \
         (:init (at-robby rooma) (free left) (free right)\n    {})\n  \
         (:goal (and {})))\n",
        names.join(" "),
        names
            .iter()
            .map(|b| format!("(at {b} rooma)"))
            .collect::<Vec<_>>()
            .join("\n    "),
        names
            .iter()
            .map(|b| format!("(at {b} roomb)"))
            .collect::<Vec<_>>()
            .join(" "),
    );
    let task = Gripper {
        domain_file: dir.join("gripper-domain.pddl"),
        problem_file: dir.join(format!("gripper-{balls}.pddl")),
    };
    std::fs::write(&task.domain_file, DOMAIN).unwrap();
    std::fs::write(&task.problem_file, problem).unwrap();
    task
}

fn plan_run(args: &[&str], task: &Gripper, dir: &Path) -> Output {
    demoplan()
        .current_dir(dir)
        .arg("plan")
        .arg(&task.domain_file)
        .arg(&task.problem_file)
        .args(args)
        .output()
        .unwrap()
}

#[test]
fn planning_is_deterministic() {
    let tmp = tempdir("determinism");
    let instance = gripper(&tmp, 4);
    let mut seen = Vec::new();
    for _ in 0..2 {
        let out = plan_run(&["--search", "astar(hmax())"], &instance, &tmp);
        assert_eq!(out.status.code(), Some(0));
        let log = stdout_text(&out);
        let expanded = logged_number(&log, "Expanded ");
        seen.push((
            std::fs::read_to_string(tmp.join("sas_plan")).unwrap(),
            expanded,
        ));
    }
    assert_eq!(seen[0], seen[1]);
}

/// `plan` on Fast Downward's translation of examples/cubes/tower-3.pddl (the task
/// crate's fixture) with `search`, in a fresh folder of the test's: the folder and the run.
fn plan_fast_downwards_task(test: &str, search: &str) -> (PathBuf, Output) {
    let sas = workspace().join("crates/task/tests/fixtures/cubes-tower-3.sas");
    let tmp = tempdir(test);
    let out = succeeds(demoplan().current_dir(&tmp).arg("plan").arg(&sas).args([
        "--search",
        search,
        "--stats-json",
        "stats.json",
    ]));
    (tmp, out)
}

#[test]
fn plan_reads_fast_downwards_output_sas() {
    let (tmp, out) = plan_fast_downwards_task("sas-input", "astar(blind())");
    assert_eq!(logged_number(&stdout_text(&out), "Plan cost: "), Some(6));
    // The plan written from Fast Downward's task validates against the PDDL.
    succeeds(
        demoplan()
            .current_dir(&tmp)
            .arg("validate")
            .arg(workspace().join("examples/cubes/domain.pddl"))
            .arg(workspace().join("examples/cubes/tower-3.pddl"))
            .arg("sas_plan"),
    );
}

/// The translator's options change a translation; on a translated task (`output.sas`)
/// there is none, so asking for them is a mistake on the command line (exit 36), never
/// silently ignored.
#[test]
fn translator_options_on_output_sas_are_a_usage_error() {
    let sas = workspace().join("crates/task/tests/fixtures/cubes-tower-3.sas");
    let tmp = tempdir("sas-translator-options");
    for option in ["--h2-mutexes", "--remove-dominated-operators"] {
        exits_saying(
            36,
            "the translator options act on PDDL, not on a translated task",
            demoplan().current_dir(&tmp).arg("plan").arg(&sas).args([
                option,
                "--search",
                "astar(blind())",
            ]),
        );
        assert!(!tmp.join("sas_plan").exists());
    }
}

/// Issue 8: `plan` reports what building a pattern-database heuristic did (the hill
/// climbing of `ipdb()`) before the search, in Fast Downward's words, so that the
/// benchmark script can split the time between climb and search.
#[test]
fn plan_reports_the_hill_climbing_of_ipdb_before_the_search() {
    let (_, out) = plan_fast_downwards_task("ipdb-statistics", "astar(ipdb())");
    let log = stdout_text(&out);
    assert_eq!(logged_number(&log, "Plan cost: "), Some(6));
    let at = |line: &str| {
        log.find(line)
            .unwrap_or_else(|| panic!("no {line:?} in\n{log}"))
    };
    let climb = at("\nHill climbing iterations: ");
    at("\nHill climbing generated patterns: ");
    at("\nHill climbing time: ");
    at("\nCanonical PDB heuristic number of patterns: ");
    let built = at("\nCanonical PDB heuristic computation time: ");
    let search = at("\nSearch time: ");
    assert!(climb < built && built < search, "{log}");
}

/// Saturated cost partitioning reports what its construction did before the search
/// (projections, orders, the construction time that bench/compare-fd reads as the
/// heuristic's time), and the counts are those of a real construction; `--stats-json`
/// has the same counts (issue 25).
#[test]
fn plan_reports_the_construction_of_scp_before_the_search() {
    let (tmp, out) = plan_fast_downwards_task(
        "scp-statistics",
        "astar(scp([projections(systematic(2))], max_orders=3))",
    );
    let log = stdout_text(&out);
    assert_eq!(logged_number(&log, "Plan cost: "), Some(6));
    assert!(
        logged_number(&log, "Number of abstractions: ").is_some_and(|n| n > 0),
        "{log}"
    );
    assert!(
        logged_number(&log, "Orders stored: ").is_some_and(|n| (1..=3).contains(&n)),
        "{log}"
    );
    let at = |line: &str| {
        log.find(line)
            .unwrap_or_else(|| panic!("no {line:?} in\n{log}"))
    };
    let built = at("\nSaturated cost partitioning heuristic computation time: ");
    assert!(built < at("\nSearch time: "), "{log}");
    let json = std::fs::read_to_string(tmp.join("stats.json")).unwrap();
    for (field, line) in [
        ("abstractions", "Number of abstractions: "),
        ("orders", "Orders stored: "),
        ("orders_computed", "Orders computed: "),
        ("abstract_states", "Abstract states: "),
    ] {
        let count = logged_number(&log, line).unwrap();
        let field = format!("\"{field}\": {count},");
        assert!(json.contains(&field), "{field} missing in {json}");
    }
    // Other heuristics have none.
    let (tmp, _) = plan_fast_downwards_task("scp-statistics-none", "astar(lmcut())");
    let json = std::fs::read_to_string(tmp.join("stats.json")).unwrap();
    assert!(json.contains("\"scp\": null"), "{json}");
}

#[test]
fn translate_writes_output_sas_that_plan_reads_back() {
    let tmp = tempdir("translate");
    let out = succeeds(
        demoplan()
            .current_dir(&tmp)
            .arg("translate")
            .arg(workspace().join("examples/cubes/tower-3.pddl")),
    );
    assert!(stdout_text(&out).contains("Translator variables: 18"));
    let out = demoplan()
        .current_dir(&tmp)
        .args(["plan", "output.sas", "--alias", "seq-opt-hmax"])
        .output()
        .unwrap();
    // seq-opt-hmax is no alias: exit 36 with the known ones listed.
    assert_eq!(out.status.code(), Some(36), "{}", transcript(&out));
    let out = succeeds(demoplan().current_dir(&tmp).args([
        "plan",
        "output.sas",
        "--search",
        "astar(hmax())",
    ]));
    assert_eq!(logged_number(&stdout_text(&out), "Plan cost: "), Some(6));
}

/// Issue 25 item 6: `--alias demoplan-opt` is a search and both translator options, on
/// PDDL; options given besides only switch on; on a translated task its search runs and
/// the log says the translator options were not applied.
#[test]
fn alias_demoplan_opt_switches_the_translator_options_on() {
    let tmp = tempdir("alias-opt");
    let tower = workspace().join("examples/cubes/tower-3.pddl");
    for extra in [&[][..], &["--h2-mutexes"][..]] {
        let out = succeeds(
            demoplan()
                .current_dir(&tmp)
                .arg("plan")
                .arg(&tower)
                .args([
                    "--alias",
                    "demoplan-opt",
                    "--stats-json",
                    "stats.json",
                    "--validate",
                ])
                .args(extra),
        );
        let log = stdout_text(&out);
        for line in [
            "Translator option h2_mutexes: true",
            "Translator option remove_dominated_operators: true",
            "pruning method: atom-centric stubborn sets",
            "Plan cost: 6",
        ] {
            assert!(log.contains(line), "{line} missing in {log}");
        }
        let json = std::fs::read_to_string(tmp.join("stats.json")).unwrap();
        assert!(
            json.contains("\"remove_dominated_operators\": true"),
            "{json}"
        );
    }
    let out = succeeds(demoplan().current_dir(&tmp).arg("translate").arg(&tower));
    assert!(stdout_text(&out).contains("Translator variables: 18"));
    let out = succeeds(demoplan().current_dir(&tmp).args([
        "plan",
        "output.sas",
        "--alias",
        "demoplan-opt",
    ]));
    let log = stdout_text(&out);
    assert!(
        log.contains("Translator options of the alias not applied: the task is translated"),
        "{log}"
    );
    assert_eq!(logged_number(&log, "Plan cost: "), Some(6));
    let both = [
        "plan",
        "output.sas",
        "--alias",
        "demoplan-opt",
        "--search",
        "astar(blind())",
    ];
    exits(36, demoplan().current_dir(&tmp).args(both));
}

/// h² proves `both` never applies (`p` is gone for good once `q` holds), which neither
/// relaxed reachability nor invariant synthesis sees (`make-q` adds `q` deleting nothing).
#[test]
fn translator_options_prune_log_and_go_into_output_sas_and_stats_json() {
    let tmp = tempdir("translator-options");
    let (d, p) = write_task(
        &tmp,
        "(define (domain h) (:requirements :strips :negative-preconditions :action-costs)
           (:predicates (p) (q) (g)) (:functions (total-cost) - number)
           (:action drop-p :parameters () :precondition (p) :effect (and (not (p)) (increase (total-cost) 1)))
           (:action make-q :parameters () :precondition (not (p)) :effect (and (q) (increase (total-cost) 1)))
           (:action both :parameters () :precondition (and (p) (q)) :effect (and (g) (increase (total-cost) 1)))
           (:action one :parameters () :precondition (q) :effect (and (g) (increase (total-cost) 5))))",
        "(define (problem h1) (:domain h) (:init (p) (= (total-cost) 0)) (:goal (g))
           (:metric minimize (total-cost)))",
    );
    let translate = |options: &[&str]| {
        let out = succeeds(
            demoplan()
                .current_dir(&tmp)
                .arg("translate")
                .args([&d, &p])
                .args(options),
        );
        (
            stdout_text(&out),
            std::fs::read_to_string(tmp.join("output.sas")).unwrap(),
        )
    };
    let (log, sas) = translate(&[]);
    assert!(
        log.contains("Translator operators: 4") && !log.contains("h2:"),
        "{log}"
    );
    assert!(
        !sas.contains(" ; "),
        "Fast Downward's translation carries no comment"
    );
    let (log, sas) = translate(&["--h2-mutexes"]);
    for line in [
        "Translator option h2_mutexes: true",
        "Translator option remove_dominated_operators: false",
        "h2: removed 1 unreachable operator(s)",
        "h2: removed 0 unreachable fact(s)",
        "Translator operators: 3",
    ] {
        assert!(log.contains(line), "{line} missing in {log}");
    }
    assert!(
        sas.contains(" ; translated by demoplan with --h2-mutexes; h2 removed 1 operator(s)"),
        "{sas}"
    );
    let out = succeeds(demoplan().current_dir(&tmp).args([
        "plan",
        "output.sas",
        "--search",
        "astar(blind())",
    ]));
    assert_eq!(logged_number(&stdout_text(&out), "Plan cost: "), Some(7));
    let out = succeeds(
        demoplan()
            .current_dir(&tmp)
            .arg("plan")
            .args([&d, &p])
            .args([
                "--search",
                "astar(lmcut())",
                "--h2-mutexes",
                "--remove-dominated-operators",
                "--stats-json",
                "stats.json",
            ]),
    );
    assert!(stdout_text(&out).contains("Removed 0 dominated operator(s)"));
    let json = std::fs::read_to_string(tmp.join("stats.json")).unwrap();
    for field in [
        "\"h2_mutexes\": true",
        "\"h2_operators_removed\": 1",
        "\"remove_dominated_operators\": true",
        "\"dominated_operators_removed\": 0",
        "\"plan_cost\": 7",
    ] {
        assert!(json.contains(field), "{field} missing in {json}");
    }
}

fn write_task(dir: &Path, domain: &str, problem: &str) -> (PathBuf, PathBuf) {
    let d = dir.join("domain.pddl");
    let p = dir.join("problem.pddl");
    std::fs::write(&d, domain).unwrap();
    std::fs::write(&p, problem).unwrap();
    (d, p)
}

#[test]
fn unsolvable_tasks_exit_11_and_leave_no_plan() {
    let tmp = tempdir("unsolvable");
    // Reachable when deletes are ignored, but `a` and `b` each consume `p`.
    let (d, p) = write_task(
        &tmp,
        "(define (domain u) (:predicates (p) (q) (r))
           (:action a :parameters () :precondition (p) :effect (and (q) (not (p))))
           (:action b :parameters () :precondition (p) :effect (and (r) (not (p)))))",
        "(define (problem u1) (:domain u) (:init (p)) (:goal (and (q) (r))))",
    );
    let unsolvable = |d: &Path, p: &Path, search: &str| {
        let plan = [std::ffi::OsStr::new("plan"), d.as_os_str(), p.as_os_str()];
        let out = exits(
            11,
            demoplan()
                .current_dir(&tmp)
                .args(plan)
                .args(["--search", search]),
        );
        stdout_text(&out)
    };
    std::fs::write(tmp.join("sas_plan"), "(stale)\n").unwrap();
    assert!(unsolvable(&d, &p, "astar(blind())")
        .contains("Completely explored state space -- no solution!"));
    assert!(!tmp.join("sas_plan").exists(), "a stale plan file survived");
    // Not even reachable when deletes are ignored: decided before search.
    let (d, p) = write_task(
        &tmp,
        "(define (domain u) (:predicates (p) (q)) (:action a :parameters () :precondition (q) :effect (p)))",
        "(define (problem u2) (:domain u) (:init) (:goal (p)))",
    );
    assert!(unsolvable(&d, &p, "astar(hmax())").contains("Goal violated by relaxed reachability"));
}

#[test]
fn limits_stop_the_search_with_exit_23_and_22_and_statistics() {
    let tmp = tempdir("limits");
    let instance = gripper(&tmp, 20);
    let stats = tmp.join("stats.json");
    let out = plan_run(
        &[
            "--search",
            "astar(blind())",
            "--overall-time-limit",
            "0.3s",
            "--stats-json",
            stats.to_str().unwrap(),
        ],
        &instance,
        &tmp,
    );
    assert_eq!(out.status.code(), Some(23), "{}", transcript(&out));
    let log = stdout_text(&out);
    assert!(log.contains("Time limit reached. Abort search."));
    assert!(logged_number(&log, "Expanded ").unwrap() > 0);
    let json = std::fs::read_to_string(&stats).unwrap();
    assert!(json.contains("\"outcome\": \"out_of_time\""), "{json}");

    let out = plan_run(
        &[
            "--search",
            "astar(blind())",
            "--overall-memory-limit",
            "20M",
        ],
        &instance,
        &tmp,
    );
    assert_eq!(out.status.code(), Some(22), "{}", transcript(&out));
    assert!(stdout_text(&out).contains("Memory limit has been reached."));
}

#[test]
fn stats_json_reports_the_solved_run() {
    let tmp = tempdir("stats");
    succeeds(
        demoplan()
            .current_dir(&tmp)
            .arg("plan")
            .arg(workspace().join("examples/cubes/tower-3.pddl"))
            .args([
                "--search",
                "astar(blind())",
                "--stats-json",
                "stats.json",
                "--plan-file",
                "my.plan",
            ]),
    );
    let json = std::fs::read_to_string(tmp.join("stats.json")).unwrap();
    for field in [
        "\"outcome\": \"solved\"",
        "\"plan_cost\": 6",
        "\"plan_length\": 6",
        "\"expanded\":",
        "\"variables\": 18",
    ] {
        assert!(json.contains(field), "{field} missing in {json}");
    }
    assert!(tmp.join("my.plan").exists());
}

#[test]
fn pruning_prints_fast_downwards_lines_and_goes_into_stats_json() {
    let tmp = tempdir("pruning");
    let out = demoplan()
        .current_dir(&tmp)
        .arg("plan")
        .arg(workspace().join("examples/cubes/tower-3.pddl"))
        .args([
            "--search",
            "astar(lmcut(), pruning=limited_pruning(pruning=atom_centric_stubborn_sets(), \
             min_required_pruning_ratio=0.99, expansions_before_checking_pruning_ratio=2))",
            "--stats-json",
            "stats.json",
        ])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(0), "{}", transcript(&out));
    let log = stdout_text(&out);
    for line in [
        "pruning method: atom-centric stubborn sets",
        "pruning method: limited",
        "Pruning ratio after 2 calls: ",
        "-- pruning ratio is lower than minimum pruning ratio (0.990000) -> switching off pruning",
        "total successors before pruning: ",
        "total successors after pruning: ",
        "Pruning ratio: ",
        "Plan cost: 6",
    ] {
        assert!(log.contains(line), "{line} missing in {log}");
    }
    let before = logged_number(&log, "total successors before pruning: ").unwrap();
    let after = logged_number(&log, "total successors after pruning: ").unwrap();
    assert_eq!(Some(after), logged_number(&log, "Generated "));
    let json = std::fs::read_to_string(tmp.join("stats.json")).unwrap();
    for field in [
        format!("\"successors_before\": {before}"),
        format!("\"successors_after\": {after}"),
        "\"checked_after_calls\": 2".to_string(),
        "\"switched_off\": true".to_string(),
    ] {
        assert!(json.contains(&field), "{field} missing in {json}");
    }
}

#[test]
fn bad_pruning_options_are_named_with_exit_33() {
    let tmp = tempdir("bad-pruning");
    let problem = workspace().join("examples/cubes/tower-3.pddl");
    for (search, named) in [
        (
            "astar(blind(), pruning=atom_centric_stubborn_sets(atom_selection_strategy=best))",
            "`atom_selection_strategy` must be one of fast_downward, quick_skip, static_small, dynamic_small, not `best`",
        ),
        (
            "astar(blind(), pruning=limited_pruning(pruning=atom_centric_stubborn_sets(), min_required_pruning_ratio=2))",
            "`min_required_pruning_ratio` must be a number from 0 to 1, not `2`",
        ),
        (
            "astar(blind(), pruning=atom_centric_stubborn_sets(use_sibling=true))",
            "does not take the argument `use_sibling=`",
        ),
    ] {
        let out = demoplan()
            .current_dir(&tmp)
            .arg("plan")
            .arg(&problem)
            .args(["--search", search])
            .output()
            .unwrap();
        assert_eq!(out.status.code(), Some(33), "{}", transcript(&out));
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert!(stderr.contains(named), "{named} missing in {stderr}");
    }
    assert!(!tmp.join("sas_plan").exists());
}

#[test]
fn bad_search_strings_and_limits_are_rejected_before_any_work() {
    let tmp = tempdir("bad-search");
    let problem = workspace().join("examples/cubes/tower-3.pddl");
    let run = |args: &[&str]| {
        demoplan()
            .current_dir(&tmp)
            .arg("plan")
            .arg(&problem)
            .args(args)
            .output()
            .unwrap()
    };
    let out = run(&["--search", "astar(goalcount())"]);
    assert_eq!(out.status.code(), Some(33));
    insta::assert_snapshot!("plan-unknown-heuristic", transcript(&out));
    assert_eq!(run(&["--search", "astar(blind()"]).status.code(), Some(33));
    assert_eq!(
        run(&["--search", "astar(blind())", "--overall-time-limit", "soon"])
            .status
            .code(),
        Some(36)
    );
    assert_eq!(
        run(&["--search", "astar(blind())", "--overall-memory-limit", "3X"])
            .status
            .code(),
        Some(36)
    );
    assert_eq!(run(&[]).status.code(), Some(36));
    assert!(!tmp.join("sas_plan").exists());
}

#[test]
fn malformed_output_sas_is_a_search_input_error() {
    let tmp = tempdir("bad-sas");
    std::fs::write(
        tmp.join("bad.sas"),
        "begin_version\n3\nend_version\nbegin_metric\n7\nend_metric\n",
    )
    .unwrap();
    exits_saying(
        33,
        "bad.sas:5",
        demoplan()
            .current_dir(&tmp)
            .args(["plan", "bad.sas", "--search", "astar(blind())"]),
    );
}

/// A plan whose cost does not fit the search's 32-bit g is refused as unsupported (exit
/// 34), not reported with a wrapped cost, and no plan file is written.
#[test]
fn path_costs_beyond_32_bits_are_unsupported() {
    let tmp = tempdir("huge-costs");
    std::fs::write(
        tmp.join("domain.pddl"),
        "(define (domain steps) (:requirements :strips :action-costs)
           (:predicates (at ?p) (next ?p ?q))
           (:functions (total-cost))
           (:action step :parameters (?p ?q) :precondition (and (at ?p) (next ?p ?q))
             :effect (and (not (at ?p)) (at ?q) (increase (total-cost) 3000000000))))",
    )
    .unwrap();
    std::fs::write(
        tmp.join("problem.pddl"),
        "(define (problem two) (:domain steps) (:objects a b c)
           (:init (at a) (next a b) (next b c) (= (total-cost) 0))
           (:goal (at c)) (:metric minimize (total-cost)))",
    )
    .unwrap();
    exits_saying(
        34,
        "6000000000",
        demoplan().current_dir(&tmp).args([
            "plan",
            "domain.pddl",
            "problem.pddl",
            "--search",
            "astar(blind())",
        ]),
    );
    assert!(!tmp.join("sas_plan").exists());
}

/// Each file under `fixtures/recordings` is a recording with one mistake, named after it.
/// `inspect` reports it naming the file, the line and the field, prints no summary, and
/// exits 31 (input error).
#[test]
fn malformed_recordings_name_file_line_and_field() {
    let dir = fixtures().join("recordings");
    let cases = entry_names(&dir);
    assert!(
        cases.len() >= 7,
        "only {} malformed recordings",
        cases.len()
    );
    for case in &cases {
        let out = demoplan()
            .current_dir(&dir)
            .args(["inspect", case])
            .output()
            .unwrap();
        let stderr = stderr_text(&out);
        assert_eq!(out.status.code(), Some(31), "{case}: {stderr}");
        assert!(
            stderr.contains(&format!("[{case}:")),
            "{case}: no file:line:col in\n{stderr}"
        );
        assert!(
            stderr.contains("field `") || stderr.contains("the whole line"),
            "{case}: no field in\n{stderr}"
        );
        assert!(out.stdout.is_empty(), "{case}: printed a summary");
        let name = case.trim_end_matches(".jsonl");
        insta::assert_snapshot!(format!("recording-{name}"), transcript(&out));
    }
}

#[test]
fn inspect_summarises_the_example_recording() {
    let out = succeeds(
        demoplan()
            .current_dir(workspace())
            .args(["inspect", "docs/examples/two-cubes.jsonl"]),
    );
    insta::assert_snapshot!(transcript(&out));
}

#[test]
fn inspect_of_a_missing_file_is_a_command_line_error() {
    exits(
        36,
        demoplan().args(["inspect", "/nonexistent/recording.jsonl"]),
    );
}

/// `simulate` with no options but `-o` writes the embedded default (the paper's 3 x 4
/// demonstrations, seed 7): the same bytes every time, each recording readable, each with
/// its ground truth. The snapshot pins the default study: a change to it is deliberate.
#[test]
fn simulate_writes_the_default_study_deterministically() {
    let tmp = tempdir("simulate");
    let run = |args: &[&str]| {
        demoplan()
            .current_dir(&tmp)
            .arg("simulate")
            .args(args)
            .output()
            .unwrap()
    };
    let first = run(&["-o", "a"]);
    assert_eq!(first.status.code(), Some(0), "{}", transcript(&first));
    let second = run(&[
        "--participants",
        "3",
        "--per-participant",
        "4",
        "--seed",
        "7",
        "-o",
        "b",
    ]);
    assert_eq!(second.status.code(), Some(0), "{}", transcript(&second));
    let other = run(&[
        "--seed",
        "8",
        "--participants",
        "1",
        "--per-participant",
        "1",
        "-o",
        "c",
    ]);
    assert_eq!(other.status.code(), Some(0), "{}", transcript(&other));
    insta::assert_snapshot!(transcript(&first));
    let names = entry_names(&tmp.join("a"));
    assert_eq!(names.len(), 25, "{names:?}");
    assert!(names.contains(&"simulation.json".to_string()));
    for name in &names {
        let a = std::fs::read(tmp.join("a").join(name)).unwrap();
        let b = std::fs::read(tmp.join("b").join(name)).unwrap();
        assert!(a == b, "{name} differs between two runs with the same seed");
    }
    assert_ne!(
        std::fs::read(tmp.join("a/p01-d01.jsonl")).unwrap(),
        std::fs::read(tmp.join("c/p01-d01.jsonl")).unwrap()
    );
    for name in names
        .iter()
        .filter(|n| n.ends_with(".jsonl") && !n.ends_with(".truth.jsonl"))
    {
        assert!(
            names.contains(&name.replace(".jsonl", ".truth.jsonl")),
            "{name}: no truth"
        );
        let out = demoplan()
            .current_dir(tmp.join("a"))
            .args(["inspect", name])
            .output()
            .unwrap();
        assert_eq!(out.status.code(), Some(0), "{name}: {}", transcript(&out));
    }
    let manifest: serde_json::Value =
        serde_json::from_slice(&std::fs::read(tmp.join("a/simulation.json")).unwrap()).unwrap();
    assert_eq!(manifest["seed"], 7);
    assert_eq!(manifest["recordings"].as_array().unwrap().len(), 12);
    // No temporary file is left behind.
    assert!(!names.iter().any(|n| n.contains("demoplan-tmp")));
}

#[test]
fn simulate_rejects_bad_arguments_with_exit_36() {
    let tmp = tempdir("simulate-bad");
    std::fs::write(tmp.join("bad.json"), "{\"cubez\": 4}").unwrap();
    std::fs::write(tmp.join("wrong.json"), "{\"release_grip\": 0.9}").unwrap();
    for args in [
        &["simulate"][..],
        &["simulate", "-o", "out", "--participants", "0"],
        &["simulate", "-o", "out", "--cubes", "2"],
        &["simulate", "-o", "out", "--seed", "-1"],
        &["simulate", "-o", "out", "--params", "missing.json"],
        &["simulate", "-o", "out", "--params", "bad.json"],
        &["simulate", "-o", "out", "--params", "wrong.json"],
        &["simulate", "-o", "out", "--style", "three-handed"],
        &[
            "simulate",
            "-o",
            "out",
            "--style",
            "two-handed",
            "--params",
            "bad.json",
        ],
    ] {
        refused_in(&tmp, args);
    }
    assert!(
        !tmp.join("out").exists(),
        "wrote output despite bad arguments"
    );
}

/// `simulate --style two-handed`: recordings of both hands at once, poses only (no held
/// object, no contacts, no velocities), 100 Hz, the style in the headers and the
/// manifest; a `--params` file's fields go over the style's, and the file may name the
/// style itself.
#[test]
fn simulate_two_handed_writes_the_style() {
    let tmp = tempdir("simulate-two-handed");
    std::fs::write(tmp.join("four.json"), "{\"cubes\": 4}").unwrap();
    std::fs::write(tmp.join("named.json"), "{\"style\": \"two-handed\"}").unwrap();
    let run = |args: &[&str]| {
        let out = demoplan()
            .current_dir(&tmp)
            .args(["simulate", "--participants", "1", "--per-participant", "1"])
            .args(args)
            .output()
            .unwrap();
        assert_eq!(out.status.code(), Some(0), "{}", transcript(&out));
        String::from_utf8(out.stdout).unwrap()
    };
    let listing = run(&["--style", "two-handed", "-o", "a"]);
    assert!(listing.contains("both  hand  2 cubes"), "{listing}");
    let text = std::fs::read_to_string(tmp.join("a/p01-d01.jsonl")).unwrap();
    let header: serde_json::Value = serde_json::from_str(text.lines().next().unwrap()).unwrap();
    assert_eq!(header["meta"]["style"], "two-handed");
    assert_eq!(header["frame_rate"], 100);
    for field in ["\"holding\"", "\"contacts\"", "\"vel\""] {
        assert!(!text.contains(field), "{field} in a two-handed recording");
    }
    let manifest: serde_json::Value =
        serde_json::from_slice(&std::fs::read(tmp.join("a/simulation.json")).unwrap()).unwrap();
    assert_eq!(manifest["params"]["style"], "two-handed");
    assert_eq!(manifest["recordings"][0]["hand"], "both");

    run(&["--style", "two-handed", "--params", "four.json", "-o", "b"]);
    let manifest: serde_json::Value =
        serde_json::from_slice(&std::fs::read(tmp.join("b/simulation.json")).unwrap()).unwrap();
    assert_eq!(manifest["params"]["cubes"], 4);
    assert_eq!(manifest["params"]["held"], false);

    run(&["--params", "named.json", "-o", "c"]);
    assert_eq!(
        std::fs::read(tmp.join("a/p01-d01.jsonl")).unwrap(),
        std::fs::read(tmp.join("c/p01-d01.jsonl")).unwrap()
    );
}

fn demonstrations() -> PathBuf {
    fixtures().join("demonstrations")
}

/// `segment` on the example recording (2 frames a second): the right hand reaches for
/// cube_a, takes it, carries it and stacks it on cube_b.
#[test]
fn segment_prints_the_segments_of_the_example_recording() {
    let out = succeeds(
        demoplan()
            .current_dir(workspace())
            .args(["segment", "docs/examples/two-cubes.jsonl"]),
    );
    insta::assert_snapshot!(transcript(&out));
    let json = succeeds(demoplan().current_dir(workspace()).args([
        "segment",
        "--json",
        "docs/examples/two-cubes.jsonl",
    ]));
    let doc: serde_json::Value = serde_json::from_slice(&json.stdout).unwrap();
    let segments = doc["files"][0]["segments"].as_array().unwrap();
    let table = stdout_text(&out);
    assert_eq!(table.lines().count(), segments.len() + 2);
    for s in segments {
        for key in [
            "hand",
            "start",
            "end",
            "activity",
            "in_hand",
            "acted_on",
            "start_state",
            "end_state",
        ] {
            assert!(s.get(key).is_some(), "no {key} in {s}");
        }
    }
    // The Stack segment starts from holding cube_a and ends with it on cube_b.
    let stack = segments.iter().find(|s| s["activity"] == "Stack").unwrap();
    assert!(stack["start_state"]
        .as_array()
        .unwrap()
        .contains(&"inHand(right_hand, cube_a)".into()));
    assert!(stack["end_state"]
        .as_array()
        .unwrap()
        .contains(&"onTop(cube_a, cube_b)".into()));
}

/// Simulated demonstrations segment into the paper's activities, and their ground truth
/// beside them lets `classify` measure the tree and `timeline` draw both.
#[test]
fn segment_classify_and_timeline_on_a_simulated_demonstration() {
    let tmp = tempdir("segment-simulated");
    succeeds(demoplan().current_dir(&tmp).args([
        "simulate",
        "--participants",
        "1",
        "--per-participant",
        "2",
        "-o",
        "demos",
    ]));
    let out = succeeds(demoplan().current_dir(&tmp).args([
        "segment",
        "demos/p01-d01.jsonl",
        "demos/p01-d02.jsonl",
    ]));
    let text = stdout_text(&out);
    for activity in ["Reach", "Take", "Put", "Stack", "Idle"] {
        assert!(text.contains(activity), "no {activity} in\n{text}");
    }
    let classify = succeeds(
        demoplan()
            .current_dir(&tmp)
            .args(["classify", "demos/p01-d01.jsonl"]),
    );
    assert!(stdout_text(&classify).contains("agree with the tree"));
    succeeds(demoplan().current_dir(&tmp).args([
        "classify",
        "--learn",
        "demos/p01-d01.jsonl",
        "-o",
        "tree.json",
    ]));
    succeeds(demoplan().current_dir(&tmp).args([
        "segment",
        "--tree",
        "tree.json",
        "demos/p01-d02.jsonl",
    ]));
    succeeds(demoplan().current_dir(&tmp).args([
        "timeline",
        "demos/p01-d01.jsonl",
        "-o",
        "p01-d01.svg",
    ]));
    let svg = std::fs::read_to_string(tmp.join("p01-d01.svg")).unwrap();
    // The timeline is a `report` figure: a standalone SVG document, XML prolog first.
    assert!(svg.starts_with("<?xml") && svg.contains("<svg") && svg.trim_end().ends_with("</svg>"));
    for label in [
        "left_hand",
        "right_hand",
        "speed (m/s)",
        "ground truth",
        "handMove 0.1",
    ] {
        assert!(svg.contains(label), "no {label} in the timeline");
    }
    let names = entry_names(&tmp);
    assert!(
        !names.iter().any(|n| n.contains("demoplan-tmp")),
        "{names:?}"
    );
}

#[test]
fn classify_prints_table_one_and_learns_the_weather_tree() {
    let tmp = tempdir("classify-weather");
    let table_one = succeeds(demoplan().args(["classify"]));
    insta::assert_snapshot!("classify-table-one", transcript(&table_one));
    let weather = demonstrations().join("weather.nominal.arff");
    let tree = tmp.join("weather.json");
    let learn = succeeds(
        demoplan()
            .args(["classify", "--learn"])
            .arg(&weather)
            .arg("-o")
            .arg(&tree),
    );
    let text = stdout_text(&learn).replace(&tree.display().to_string(), "TREE");
    insta::assert_snapshot!("classify-learn-weather", text);
    // The tree file prints as it was learned.
    let printed = succeeds(demoplan().args(["classify", "--tree"]).arg(&tree));
    assert!(stdout_text(&learn).starts_with(&*stdout_text(&printed)));
}

#[test]
fn arff_hand_state_tables_segment_and_say_what_they_accepted() {
    let out = succeeds(demoplan().current_dir(demonstrations()).args([
        "segment",
        "hand-state.arff",
        "messy-hand-state.arff",
    ]));
    insta::assert_snapshot!(transcript(&out));
    let learn = succeeds(demoplan().current_dir(demonstrations()).args([
        "classify",
        "--learn",
        "hand-state.arff",
    ]));
    assert!(stdout_text(&learn).contains("25 of 25"));
}

/// Malformed configuration, tree and ARFF files: exit 31 with file, line and field.
#[test]
fn malformed_demonstration_inputs_name_file_line_and_field() {
    let cases: [(&str, &[&str]); 9] = [
        (
            "unknown-field.toml",
            &[
                "segment",
                "--config",
                "unknown-field.toml",
                "hand-state.arff",
            ],
        ),
        (
            "open-above-close.toml",
            &[
                "segment",
                "--config",
                "open-above-close.toml",
                "hand-state.arff",
            ],
        ),
        (
            "unknown-attribute-tree.json",
            &[
                "segment",
                "--tree",
                "unknown-attribute-tree.json",
                "hand-state.arff",
            ],
        ),
        ("short-row.arff", &["segment", "short-row.arff"]),
        // ARFF by content, tab-separated, with a value that is not a number.
        ("tab-not-a-number.txt", &["segment", "tab-not-a-number.txt"]),
        (
            "sparse-out-of-order.arff",
            &[
                "learn",
                "sparse-out-of-order.arff",
                "-o",
                "never-written.json",
            ],
        ),
        (
            "unknown-activity.toml",
            &[
                "classify",
                "--mapping",
                "unknown-activity.toml",
                "hand-state.arff",
            ],
        ),
        (
            "unquoted-activity.toml",
            &[
                "classify",
                "--mapping",
                "unquoted-activity.toml",
                "hand-state.arff",
            ],
        ),
        (
            "unknown-mapping-key.toml",
            &[
                "classify",
                "--mapping",
                "unknown-mapping-key.toml",
                "hand-state.arff",
            ],
        ),
    ];
    for (file, args) in cases {
        let out = demoplan()
            .current_dir(demonstrations())
            .args(args)
            .output()
            .unwrap();
        let stderr = stderr_text(&out);
        assert_eq!(out.status.code(), Some(31), "{file}: {stderr}");
        assert!(
            stderr.contains(&format!("[{file}:")),
            "{file}: no file:line in\n{stderr}"
        );
        assert!(stderr.contains("field `"), "{file}: no field in\n{stderr}");
        assert!(out.stdout.is_empty(), "{file}: printed output");
        insta::assert_snapshot!(format!("demonstration-{file}"), transcript(&out));
    }
}

/// The Weka-style tables of `crates/segment/tests/fixtures` (whose tests hold what Weka
/// reads for each): `segment` reads them whatever their separators, quotes, sparse rows
/// or extension; `classify` maps their labels, leaves out the frames of labels it does
/// not know, says how many, and names those labels once with their counts.
#[test]
fn weka_tables_segment_and_classify_through_the_label_map() {
    let tables = workspace().join("crates/segment/tests/fixtures");
    // Without a minimum duration, so that every row of these short tables shows.
    let out = succeeds(
        demoplan()
            .current_dir(&tables)
            .arg("segment")
            .arg("--config")
            .arg(demonstrations().join("no-minimum-duration.toml"))
            .args([
                "tabs.arff",
                "quoted.arff",
                "sparse.arff",
                "recogniser-labels.txt",
            ]),
    );
    insta::assert_snapshot!("segment-weka-tables", transcript(&out));

    // recogniser-labels.txt: 14 frames, 3 labelled Pour (unknown). Of the other 11, the
    // tree gives the label's activity for all but Release_2 (a still, empty, open hand:
    // Idle by Table 1, Put by the label map).
    let classify = succeeds(
        demoplan()
            .current_dir(&tables)
            .args(["classify", "recogniser-labels.txt"]),
    );
    let stdout = stdout_text(&classify);
    assert!(
        stdout.starts_with(
            "recogniser-labels.txt: 11 labelled hand frames, 10 agree with the tree (90.91%); \
             3 left out, their labels not in the label map\n"
        ),
        "{stdout}"
    );
    assert_eq!(
        stderr_text(&classify),
        "warning: recogniser-labels.txt:17: labels the label map does not know, left out: Pour (3 frames)\n"
    );
    // With Pour mapped to Put every frame counts; ToolUse with the object in hand is Put
    // by Table 1 too.
    let mapped = succeeds(
        demoplan()
            .current_dir(&tables)
            .args(["classify", "recogniser-labels.txt", "--mapping"])
            .arg(demonstrations().join("pour-is-put.toml")),
    );
    assert!(stdout_text(&mapped).starts_with(
        "recogniser-labels.txt: 14 labelled hand frames, 13 agree with the tree (92.86%)\n"
    ));
    assert!(mapped.stderr.is_empty(), "{}", transcript(&mapped));
}

/// `learn` reads ARFF hand-state tables directly: operators over the hand's own facts.
#[test]
fn learn_reads_hand_state_tables() {
    let tmp = tempdir("learn-arff");
    let library = tmp.join("library.json");
    let out = succeeds(
        demoplan()
            .current_dir(demonstrations())
            .args(["learn", "hand-state.arff", "-o"])
            .arg(&library),
    );
    let stdout = stdout_text(&out);
    assert!(
        stdout.starts_with("hand-state.arff: 5 activities, 5 new operator(s)\n"),
        "{stdout}"
    );
    let cards = demoplan().arg("operators").arg(&library).output().unwrap();
    let cards = stdout_text(&cards);
    // The Take closes the hand on the object it reached: its effects are the hand's.
    let take = cards
        .split("\n\n")
        .find(|c| c.starts_with("take "))
        .unwrap_or_else(|| panic!("no take in\n{cards}"));
    assert!(take.contains("?h - hand, ?x - thing"), "{take}");
    assert!(
        take.contains("inHand(?h, ?x)     false         true"),
        "{take}"
    );
    assert!(
        take.contains("actedOn(?h, ?x)    true          false"),
        "{take}"
    );
}

/// `learn DIR` learns every recording of a simulation folder, as listing them does;
/// the simulator's truth files, given by a glob, are skipped and said so.
#[test]
fn learn_takes_a_folder_and_skips_the_simulators_truth() {
    let tmp = tempdir("learn-folder");
    let sim = tmp.join("sim");
    succeeds(
        demoplan()
            .args([
                "simulate",
                "--participants",
                "1",
                "--per-participant",
                "3",
                "-o",
            ])
            .arg(&sim),
    );
    let mut all: Vec<PathBuf> = std::fs::read_dir(&sim)
        .unwrap()
        .map(|e| e.unwrap().path())
        .collect();
    all.sort();
    let recordings: Vec<&PathBuf> = all
        .iter()
        .filter(|p| {
            let name = p.file_name().unwrap().to_string_lossy();
            name.ends_with(".jsonl") && !name.ends_with(".truth.jsonl")
        })
        .collect();
    assert_eq!(recordings.len(), 3);
    let learn = |args: &[&Path], out: &Path| {
        let o = succeeds(demoplan().arg("learn").args(args).arg("-o").arg(out));
        o
    };
    let listed = tmp.join("listed.json");
    learn(
        &recordings.iter().map(|p| p.as_path()).collect::<Vec<_>>(),
        &listed,
    );
    let folder = tmp.join("folder.json");
    let o = learn(&[sim.as_path()], &folder);
    assert_eq!(
        stderr_text(&o),
        format!(
            "{}: 3 recording(s); skipped 4 file(s) of the simulator (*.truth.jsonl, simulation.json)\n",
            sim.display()
        )
    );
    assert_eq!(
        std::fs::read(&folder).unwrap(),
        std::fs::read(&listed).unwrap()
    );
    // `sim/*` as a shell expands it: truth files and simulation.json among them.
    let globbed = tmp.join("globbed.json");
    let o = learn(
        &all.iter().map(|p| p.as_path()).collect::<Vec<_>>(),
        &globbed,
    );
    let stderr = stderr_text(&o);
    assert!(
        stderr.starts_with("skipped 4 file(s) of the simulator, not recordings: "),
        "{stderr}"
    );
    assert_eq!(
        std::fs::read(&globbed).unwrap(),
        std::fs::read(&listed).unwrap()
    );
    // A folder with no recording is a command line error.
    let empty = tmp.join("empty");
    std::fs::create_dir_all(&empty).unwrap();
    std::fs::write(empty.join("notes.md"), "nothing here\n").unwrap();
    exits(
        36,
        demoplan()
            .arg("learn")
            .arg(&empty)
            .arg("-o")
            .arg(tmp.join("never.json")),
    );
    assert!(!tmp.join("never.json").exists());
}

#[test]
fn demonstration_commands_reject_bad_command_lines_with_exit_36() {
    let tmp = tempdir("demonstration-bad");
    for args in [
        &["segment"][..],
        &["segment", "missing.jsonl"],
        &["classify", "--learn"],
        &["classify", "--class", "play"],
        &["classify", "-o", "tree.json"],
        &["timeline", "missing.jsonl", "-o", "t.svg"],
        &["timeline", "x.jsonl", "-o", "t.png"],
        &["segment", "--config", "missing.toml", "x.jsonl"],
    ] {
        refused_in(&tmp, args);
    }
}

/// A small demoplan-style domain for `execute`: take, lift, stack and let go, and a
/// reach corrupted to claim a grasp.
const CUBE_WORLD_DOMAIN: &str = "(define (domain demoplan)
  (:requirements :strips :typing :negative-preconditions)
  (:types hand thing - object cube table - thing)
  (:predicates (handmove ?h - hand) (handopen ?h - hand) (actedon ?h - hand ?x - thing)
    (graspable ?h - hand ?x - thing) (inhand ?h - hand ?x - thing)
    (intouch ?x - thing ?y - thing) (ontop ?x - thing ?y - thing))
  (:action take :parameters (?h - hand ?c1 - cube)
    :precondition (handopen ?h) :effect (and (not (handopen ?h)) (inhand ?h ?c1)))
  (:action put :parameters (?h - hand ?c1 - cube ?t - table)
    :precondition (inhand ?h ?c1)
    :effect (and (not (ontop ?c1 ?t)) (not (intouch ?c1 ?t)) (not (intouch ?t ?c1))))
  (:action stack :parameters (?h - hand ?c1 - cube ?c2 - cube)
    :precondition (inhand ?h ?c1)
    :effect (and (handopen ?h) (not (inhand ?h ?c1)) (ontop ?c1 ?c2) (intouch ?c1 ?c2)
      (intouch ?c2 ?c1)))
  (:action reach :parameters (?h - hand ?c1 - cube)
    :precondition (handopen ?h) :effect (and (not (handopen ?h)) (inhand ?h ?c1))))";

const CUBE_WORLD_PROBLEM: &str = "(define (problem two) (:domain demoplan)
  (:objects left_hand right_hand - hand cube_1 cube_2 - cube table - table)
  (:init (handopen left_hand) (handopen right_hand) (ontop cube_1 table)
    (intouch cube_1 table) (intouch table cube_1) (ontop cube_2 table)
    (intouch cube_2 table) (intouch table cube_2))
  (:goal (ontop cube_2 cube_1)))";

fn execute_cubes(test: &str, plan: &str, extra: &[&str]) -> (Output, PathBuf) {
    let tmp = tempdir(test);
    let (d, p) = write_task(&tmp, CUBE_WORLD_DOMAIN, CUBE_WORLD_PROBLEM);
    std::fs::write(tmp.join("plan"), plan).unwrap();
    let out = demoplan()
        .current_dir(&tmp)
        .arg("execute")
        .arg(d)
        .arg(p)
        .arg("plan")
        .args(extra)
        .output()
        .unwrap();
    (out, tmp)
}

#[test]
fn execute_checks_each_step_in_the_cube_world() {
    let plan = "(take left_hand cube_2)\n(put left_hand cube_2 table)\n\
                (stack left_hand cube_2 cube_1)\n";
    let (out, tmp) = execute_cubes(
        "execute-ok",
        plan,
        &["--json", "x.json", "--frames", "x.jsonl"],
    );
    let text = stdout_text(&out);
    assert_eq!(out.status.code(), Some(0), "{}", transcript(&out));
    assert!(
        text.contains("step 1 (take left_hand cube_2): ok\n"),
        "{text}"
    );
    assert!(
        text.contains("step 3 (stack left_hand cube_2 cube_1): ok\n"),
        "{text}"
    );
    assert!(text.ends_with("goal reached\n"), "{text}");
    let json: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(tmp.join("x.json")).unwrap()).unwrap();
    assert_eq!(json["format"], "demoplan-execution");
    assert_eq!(json["version"], 1);
    assert_eq!(json["steps"][0]["gripper"], "close");
    assert_eq!(
        json["steps"][2]["hands"][0]["holding"],
        serde_json::Value::Null
    );
    // The frames are a recording demoplan reads.
    succeeds(demoplan().arg("inspect").arg(tmp.join("x.jsonl")));
}

#[test]
fn execute_names_the_first_step_whose_geometry_fails_and_exits_1() {
    // The corrupted reach claims a grasp that no reach makes.
    let plan = "(reach left_hand cube_2)\n(put left_hand cube_2 table)\n\
                (stack left_hand cube_2 cube_1)\n";
    let (out, _) = execute_cubes("execute-fails", plan, &[]);
    let text = stdout_text(&out);
    assert_eq!(out.status.code(), Some(1), "{}", transcript(&out));
    assert!(
        text.contains(
            "step 1 (reach left_hand cube_2): FAILED: expected (inhand left_hand cube_2)"
        ),
        "{text}"
    );
    assert!(
        text.contains("first failing step: 1 (reach left_hand cube_2)"),
        "{text}"
    );
    assert!(text.contains("goal not reached"), "{text}");
}

#[test]
fn execute_input_errors_exit_31_and_command_line_mistakes_36() {
    let (out, _) = execute_cubes("execute-malformed", "(take left_hand\n", &[]);
    assert_eq!(out.status.code(), Some(31), "{}", transcript(&out));
    let (out, _) = execute_cubes("execute-unknown", "(fly left_hand cube_2)\n", &[]);
    assert_eq!(out.status.code(), Some(31), "{}", transcript(&out));
    let (out, _) = execute_cubes("execute-missing", "", &["--frames"]);
    assert_eq!(out.status.code(), Some(36), "{}", transcript(&out));
    exits(
        36,
        demoplan().args(["execute", "no-domain.pddl", "no-problem.pddl", "no-plan"]),
    );
}

/// The library of the embedded default study, learned through the command line.
fn learned_library(test: &str) -> PathBuf {
    let tmp = tempdir(test);
    let recordings = simulated_study(&tmp.join("sim"));
    let library = tmp.join("library.json");
    // Half first, then the rest added to the library: incremental learning.
    succeeds(
        demoplan()
            .arg("learn")
            .args(&recordings[..6])
            .arg("-o")
            .arg(&library),
    );
    let rest = demoplan()
        .arg("learn")
        .args(&recordings[5..])
        .arg("--library")
        .arg(&library)
        .arg("-o")
        .arg(&library)
        .output()
        .unwrap();
    let text = stdout_text(&rest);
    assert_eq!(rest.status.code(), Some(0), "{}", transcript(&rest));
    // The sixth recording was in both batches and is counted once.
    assert!(
        text.contains("already in the library (same content), not counted again"),
        "{text}"
    );
    // The same as learning all at once.
    let batch = tmp.join("batch.json");
    succeeds(
        demoplan()
            .arg("learn")
            .args(&recordings)
            .arg("-o")
            .arg(&batch),
    );
    assert_eq!(
        std::fs::read(&batch).unwrap(),
        std::fs::read(&library).unwrap()
    );
    library
}

#[test]
fn learn_operators_domain_problem_and_solve_work_together() {
    let library = learned_library("library-commands");
    let tmp = library.parent().unwrap().to_path_buf();
    let cards = demoplan()
        .args(["operators", "--markdown"])
        .arg(&library)
        .output()
        .unwrap();
    let md = stdout_text(&cards);
    assert_eq!(cards.status.code(), Some(0), "{}", transcript(&cards));
    assert!(md.contains("## reach (Reach, count "), "{md}");
    assert!(md.contains("| fact | precondition | effect |"), "{md}");
    // Levels, then the priority-2 domain and a problem that parse in demoplan.
    let levels = succeeds(demoplan().arg("domain").arg(&library));
    let levels = stdout_text(&levels);
    let mut rows = levels.lines();
    assert_eq!(
        rows.next(),
        Some(" prio operators  per type (reach, take, put, stack, idle)"),
        "{levels}"
    );
    // A row per level, from priority 1, each with as many operators as its five types.
    for (prio, row) in (1..).zip(rows) {
        let fields: Vec<usize> = row
            .split(|c: char| !c.is_ascii_digit())
            .filter(|f| !f.is_empty())
            .map(|f| f.parse().unwrap())
            .collect();
        assert_eq!(fields.len(), 7, "{row}");
        assert_eq!(fields[0], prio, "{levels}");
        assert_eq!(fields[1], fields[2..].iter().sum::<usize>(), "{row}");
    }
    let domain = tmp.join("prio-2.pddl");
    succeeds(
        demoplan()
            .arg("domain")
            .arg(&library)
            .args(["--prio", "2", "-o"])
            .arg(&domain),
    );
    let problem = tmp.join("goal-1.pddl");
    succeeds(
        demoplan()
            .args(["problem", "--paper-goal", "1", "--hands", "1", "-o"])
            .arg(&problem),
    );
    succeeds(demoplan().arg("check").arg(&domain).arg(&problem));
    // Algorithm 1 on the default (settled) activities: the paper's finding, the five
    // most frequent operators plan.
    let plan = tmp.join("plan");
    let solve = demoplan()
        .arg("solve")
        .arg(&library)
        .arg(&problem)
        .args(["--time-limit", "60", "--plan-file"])
        .arg(&plan)
        .output()
        .unwrap();
    let log = stdout_text(&solve);
    assert_eq!(solve.status.code(), Some(0), "{}", transcript(&solve));
    assert!(log.contains("Solution found at priority 1 "), "{log}");
    // The same with `--alias demoplan-opt` (issue 25 item 6); an alias is demoplan's own.
    let alias = ["--alias", "demoplan-opt", "--time-limit", "60"];
    let opt = succeeds(
        demoplan()
            .current_dir(&tmp)
            .arg("solve")
            .arg(&library)
            .arg(&problem)
            .args(alias),
    );
    assert!(stdout_text(&opt).contains("Solution found at priority 1 "));
    let fd = [
        "--planner",
        "fast-downward",
        "--fd",
        "/nonexistent/fast-downward.py",
    ];
    let mut solve_fd = demoplan();
    solve_fd
        .arg("solve")
        .arg(&library)
        .arg(&problem)
        .args(alias)
        .args(fd);
    exits_saying(36, "give Fast Downward a --search", &mut solve_fd);
    // With every Idle an activity of its own (`--activities runs`), the most frequent
    // operators cannot reach the tower: priority 1 is rejected before search and the
    // loop widens.
    let runs = tmp.join("runs.json");
    let recordings: Vec<String> =
        serde_json::from_str::<serde_json::Value>(&std::fs::read_to_string(&library).unwrap())
            .unwrap()["recordings"]
            .as_array()
            .unwrap()
            .iter()
            .map(|r| r["source"].as_str().unwrap().to_string())
            .collect();
    succeeds(
        demoplan()
            .arg("learn")
            .args(&recordings)
            .args(["--activities", "runs", "-o"])
            .arg(&runs),
    );
    let widened = demoplan()
        .arg("solve")
        .arg(&runs)
        .arg(&problem)
        .args(["--time-limit", "60", "--plan-file"])
        .arg(tmp.join("runs.plan"))
        .output()
        .unwrap();
    let widened_log = stdout_text(&widened);
    assert_eq!(widened.status.code(), Some(0), "{}", transcript(&widened));
    assert!(widened_log.contains("relaxed-unreachable"), "{widened_log}");
    assert!(
        !widened_log.contains("Solution found at priority 1 "),
        "{widened_log}"
    );
    // One library counts one kind of activity.
    let mixed = exits(
        36,
        demoplan()
            .arg("learn")
            .arg(&recordings[0])
            .arg("--library")
            .arg(&runs)
            .args(["--activities", "settled", "-o"])
            .arg(tmp.join("mixed.json")),
    );
    assert!(stderr_text(&mixed).contains("`runs` activities"));
    assert!(!tmp.join("mixed.json").exists());
    // Generalised operators (`learn --generalise`): the file says so, learning into it
    // again keeps them, and a library of specific operators refuses them.
    let general = tmp.join("general.json");
    let learned = succeeds(
        demoplan()
            .arg("learn")
            .args(&recordings)
            .arg("--generalise")
            .arg("-o")
            .arg(&general),
    );
    assert!(
        stdout_text(&learned).contains("generalised: "),
        "{}",
        stdout_text(&learned)
    );
    let text = std::fs::read_to_string(&general).unwrap();
    assert!(text.contains("\"operator_form\": \"generalised\""));
    succeeds(
        demoplan()
            .arg("learn")
            .arg(&recordings[0])
            .arg("--library")
            .arg(&general)
            .arg("-o")
            .arg(&general),
    );
    assert_eq!(std::fs::read_to_string(&general).unwrap(), text);
    let refused = exits(
        36,
        demoplan()
            .arg("learn")
            .arg(&recordings[0])
            .arg("--library")
            .arg(&runs)
            .args(["--activities", "runs", "--generalise", "-o"])
            .arg(tmp.join("refused.json")),
    );
    assert!(stderr_text(&refused).contains("one library holds operators of one form"));
    assert!(!tmp.join("refused.json").exists());
    let planned = succeeds(
        demoplan()
            .arg("solve")
            .arg(&general)
            .arg(&problem)
            .args(["--time-limit", "60", "--plan-file"])
            .arg(tmp.join("general.plan")),
    );
    assert!(stdout_text(&planned).contains("Solution found at priority 1 "));
    // The plan validates on the domain it was found in and executes in the cube world.
    let level: String = log
        .lines()
        .find_map(|l| l.strip_prefix("Solution found at priority "))
        .and_then(|rest| rest.split(' ').next())
        .unwrap()
        .to_string();
    let level_domain = tmp.join(format!("prio-{level}.pddl"));
    succeeds(
        demoplan()
            .arg("domain")
            .arg(&library)
            .args(["--prio", &level, "-o"])
            .arg(&level_domain),
    );
    succeeds(
        demoplan()
            .arg("validate")
            .arg(&level_domain)
            .arg(&problem)
            .arg(&plan),
    );
    succeeds(
        demoplan()
            .arg("execute")
            .arg(&level_domain)
            .arg(&problem)
            .arg(&plan),
    );
    // A damaged library is an input error and is not overwritten.
    let damaged = tmp.join("damaged.json");
    std::fs::write(
        &damaged,
        "{\"format\": \"demoplan-library\", \"version\": 1,\n  \"lambda\": }",
    )
    .unwrap();
    exits_saying(
        31,
        "damaged.json:2",
        demoplan()
            .arg("learn")
            .arg(tmp.join("sim/p01-d01.jsonl"))
            .arg("--library")
            .arg(&damaged)
            .arg("-o")
            .arg(&damaged),
    );
    assert!(std::fs::read_to_string(&damaged)
        .unwrap()
        .ends_with("\"lambda\": }"));
    let newer = tmp.join("newer.json");
    std::fs::write(&newer, "{\"format\": \"demoplan-library\", \"version\": 2}").unwrap();
    let bad = demoplan().arg("operators").arg(&newer).output().unwrap();
    assert_eq!(bad.status.code(), Some(31), "{}", transcript(&bad));
    assert!(stderr_text(&bad).contains("newer than this demoplan reads"));
}

#[test]
fn reproduce_writes_every_artefact_on_a_reduced_grid() {
    let tmp = tempdir("reproduce");
    let out = tmp.join("out");
    let run = demoplan()
        .arg("reproduce")
        .arg("-o")
        .arg(&out)
        .args(["--prios", "1,3", "--goals", "1,2,3", "--time-limit", "5"])
        .output()
        .unwrap();
    let log = stdout_text(&run);
    assert_eq!(run.status.code(), Some(0), "{}", transcript(&run));
    assert!(log.contains("Table 3: A* with iPDB"), "{log}");
    let read = |name: &str| std::fs::read_to_string(out.join(name)).unwrap();
    // The library reads back; domains and problems parse and fit each other.
    let library = read("library.json");
    assert!(library.starts_with("{\n  \"format\": \"demoplan-library\""));
    for prio in [1, 3] {
        let domain = pddl::parse_domain(&read(&format!("domains/prio-{prio}.pddl"))).unwrap();
        for goal in 1..=3 {
            let problem =
                pddl::parse_problem(&read(&format!("problems/goal-{goal}.pddl"))).unwrap();
            pddl::check_problem(&domain, &problem).unwrap();
        }
    }
    // Tables by both measures, the time split and both ratios.
    let tables = read("tables.md");
    for heading in [
        "## Table 4: A* with LM-cut (demoplan), search time",
        "## Table 4: A* with LM-cut (demoplan), total time",
        "## Table 3: A* with iPDB (demoplan), total time",
        "## Time by phase, goal 3",
        "| ratio_p1 search | ratio_p1 total | ratio_alg1 search | ratio_alg1 total |",
    ] {
        assert!(tables.contains(heading), "{heading}\n{tables}");
    }
    // CSV and JSON: one row per planner x domain x goal, and Algorithm 1 per planner x
    // goal; every row has the four times.
    let csv = read("results.csv");
    assert_eq!(csv.lines().count(), 1 + 2 * 2 * 3 + 2 * 3, "{csv}");
    let header: Vec<&str> = csv.lines().next().unwrap().split(',').collect();
    for column in [
        "translate_s",
        "heuristic_s",
        "search_s",
        "total_s",
        "peak_memory_kb",
    ] {
        assert!(header.contains(&column), "{column}");
    }
    let json: serde_json::Value = serde_json::from_str(&read("results.json")).unwrap();
    assert_eq!(json["format"], "demoplan-reproduce");
    let runs = json["runs"].as_array().unwrap();
    assert_eq!(runs.len(), 18);
    assert_eq!(read("results.jsonl").lines().count(), 18);
    // Every plan found executes in the cube world and is written; the phases add up.
    let mut solved = 0;
    for r in runs {
        let t = &r["times"];
        let parts = t["translate_s"].as_f64().unwrap()
            + t["heuristic_s"].as_f64().unwrap()
            + t["search_s"].as_f64().unwrap();
        assert!(parts <= t["total_s"].as_f64().unwrap() + 1e-3, "{r}");
        if r["outcome"] == "solved" {
            solved += 1;
            assert_eq!(r["executed"], true, "{r}");
            if r["level"] == "alg1" {
                assert_eq!(r["widening"].as_array().map(Vec::len), Some(1), "{r}");
                continue;
            }
            assert!(r["peak_memory_kb"].as_u64().unwrap() > 0, "{r}");
            let name = format!(
                "plans/{}-prio-{}-goal-{}.plan",
                r["planner"].as_str().unwrap(),
                r["prio"],
                r["goal"]
            );
            assert!(read(&name).contains("; cost = "), "{name}");
        }
    }
    assert!(solved >= 4, "{csv}");
    // Figures as SVG and PNG, and the page that links them.
    for figure in [
        "search-time-lmcut",
        "search-time-ipdb",
        "total-time-lmcut",
        "total-time-ipdb",
        "operators",
        "goal-1",
        "goal-2",
        "goal-3",
    ] {
        let svg = read(&format!("figures/{figure}.svg"));
        assert!(
            svg.trim_start().starts_with("<svg") || svg.starts_with("<?xml"),
            "{figure}"
        );
        assert!(svg.trim_end().ends_with("</svg>"), "{figure}");
        let png = std::fs::read(out.join(format!("figures/{figure}.png"))).unwrap();
        assert_eq!(&png[..8], b"\x89PNG\r\n\x1a\n", "{figure}");
    }
    let html = read("report.html");
    for link in [
        "figures/search-time-lmcut.svg",
        "figures/operators.svg",
        "tables.md",
        "results.csv",
        "results.json",
        "operators.md",
    ] {
        assert!(html.contains(link), "report.html does not link {link}");
    }
    assert!(read("operators.md").contains("# Operator cards"));
}

/// A reduced study: 2 seeds, towers of 2 and 3 cubes, one hand, both groupings.
fn reduced_study(out: &Path) -> Output {
    demoplan()
        .arg("study")
        .arg("-o")
        .arg(out)
        .args(["--seeds", "1-2", "--hands", "1", "--heights", "2-3"])
        .args(["--activities", "settled,runs", "--time-limit", "5"])
        .output()
        .unwrap()
}

/// `study --generalise` runs every condition with specific and with generalised
/// operators (issue 39), and its files tell the two apart.
#[test]
fn study_generalise_runs_both_forms() {
    let tmp = tempdir("study-generalise");
    let out = tmp.join("out");
    let run = demoplan()
        .arg("study")
        .arg("-o")
        .arg(&out)
        .args(["--seeds", "7", "--hands", "1", "--heights", "3"])
        .args(["--generalise", "--time-limit", "10"])
        .output()
        .unwrap();
    assert_eq!(run.status.code(), Some(0), "{}", transcript(&run));
    let runs = std::fs::read_to_string(out.join("runs.csv")).unwrap();
    let header: Vec<&str> = runs.lines().next().unwrap().split(',').collect();
    let col = header.iter().position(|c| *c == "generalised").unwrap();
    let forms: Vec<&str> = runs
        .lines()
        .skip(1)
        .map(|l| l.split(',').nth(col).unwrap())
        .collect();
    // 2 forms x 2 planners x 3 levels.
    assert_eq!(forms.len(), 12, "{runs}");
    assert_eq!(forms.iter().filter(|f| **f == "true").count(), 6, "{runs}");
    let ratios = std::fs::read_to_string(out.join("ratios.csv")).unwrap();
    assert_eq!(ratios.lines().count(), 1 + 2 * 2 * 2 * 2, "{ratios}");
    let report = std::fs::read_to_string(out.join("report.html")).unwrap();
    assert!(report.contains("operators specific and generalised"));
    assert!(report.contains("<td>generalised</td>"));
}

#[test]
fn study_writes_every_file_and_resumes() {
    let tmp = tempdir("study");
    let out = tmp.join("out");
    let run = reduced_study(&out);
    assert_eq!(run.status.code(), Some(0), "{}", transcript(&run));
    let stdout = stdout_text(&run);
    // 2 seeds x 2 groupings x 2 heights x 2 planners x 3 levels.
    assert!(stdout.contains("48 runs (48 computed now"), "{stdout}");
    let read = |name: &str| std::fs::read_to_string(out.join(name)).unwrap();

    // runs.csv: one row per run, conditions and the four times.
    let runs = read("runs.csv");
    let mut lines = runs.lines();
    let header: Vec<&str> = lines.next().unwrap().split(',').collect();
    let col = |name: &str| header.iter().position(|h| *h == name).unwrap();
    let rows: Vec<Vec<&str>> = lines.map(|l| l.split(',').collect()).collect();
    assert_eq!(rows.len(), 48);
    let mut levels = std::collections::BTreeSet::new();
    for row in &rows {
        assert_eq!(row.len(), header.len(), "{row:?}");
        levels.insert(row[col("level")]);
        assert_eq!(
            row[col("cubes")].parse::<usize>().unwrap(),
            row[col("height")].parse::<usize>().unwrap()
        );
        let t = |c: &str| row[col(c)].parse::<f64>().unwrap();
        assert!(t("translate_s") + t("heuristic_s") + t("search_s") <= t("total_s") + 1e-3);
        if row[col("outcome")] == "solved" {
            assert_eq!(row[col("executed")], "true", "{row:?}");
        }
    }
    assert_eq!(
        levels.into_iter().collect::<Vec<_>>(),
        ["alg1", "full", "prio-1"]
    );

    // ratios.csv: per condition (2 groupings x 2 heights), planner, measure and ratio.
    let ratios = read("ratios.csv");
    assert!(ratios.starts_with(
        "participants,per_participant,params,hands,height,towers,distractors,cubes,activities,keep_without_effects,generalised,planner,measure,ratio,seeds,bounds,missing,q1,median,q3\n"
    ));
    assert_eq!(ratios.lines().count(), 1 + 2 * 2 * 2 * 2 * 2, "{ratios}");
    for line in ratios.lines().skip(1) {
        let f: Vec<&str> = line.split(',').collect();
        assert_eq!(f[14], "2", "{line}");
        // A ratio for every seed, or the seeds without one counted.
        if f[16] == "0" {
            assert!(!f[18].is_empty(), "{line}");
        }
    }
    // With every Idle apart, priority 1 builds no tower of 3: no ratio_p1, Algorithm 1
    // widens and the page shows its levels with their cumulative time.
    assert!(
        ratios.contains("3,4,default,1,3,1,0,3,runs,false,false,lmcut,search,ratio_p1,2,0,2,,,"),
        "{ratios}"
    );
    let html = read("report.html");
    assert!(html.contains("went past priority 1"), "{html}");
    for link in [
        "runs.csv",
        "ratios.csv",
        "scaling.svg",
        "scaling.png",
        "results.jsonl",
    ] {
        assert!(html.contains(link), "report.html does not link {link}");
    }
    for figure in ["scaling", "scaling-total"] {
        let svg = read(&format!("{figure}.svg"));
        assert!(svg.trim_end().ends_with("</svg>"), "{figure}");
        assert!(
            svg.contains("priority 1") && svg.contains("Algorithm 1"),
            "{figure}"
        );
        assert!(svg.contains("<polygon"), "{figure}: no quartile band");
        let png = std::fs::read(out.join(format!("{figure}.png"))).unwrap();
        assert_eq!(&png[..8], b"\x89PNG\r\n\x1a\n", "{figure}");
    }

    // Run again: nothing to compute, the same results.
    let results = read("results.jsonl");
    let again = reduced_study(&out);
    assert_eq!(again.status.code(), Some(0), "{}", transcript(&again));
    assert!(
        stdout_text(&again).contains("48 runs (0 computed now, 48 from earlier"),
        "{}",
        transcript(&again)
    );
    assert_eq!(read("results.jsonl"), results);
    assert_eq!(read("runs.csv"), runs);

    // A cell's record cut short (never by demoplan, which renames whole files into
    // place) or gone: those cells run again, once each.
    let record = out.join("runs-00001-00100/00007/record.json");
    let text = std::fs::read_to_string(&record).unwrap();
    std::fs::write(&record, &text[..text.len() / 2]).unwrap();
    let resumed = reduced_study(&out);
    assert_eq!(resumed.status.code(), Some(0), "{}", transcript(&resumed));
    assert!(
        stdout_text(&resumed).contains("48 runs (1 computed now"),
        "{}",
        transcript(&resumed)
    );
    assert_eq!(read("results.jsonl").lines().count(), 48);
}

/// A study of one hand, `--seeds SEEDS --heights HEIGHTS` and `extra`, written to
/// `DIR/out`: that folder and the study's options.
fn one_hand_study(
    dir: &Path,
    seeds: &str,
    heights: &str,
    extra: &[&str],
) -> (PathBuf, Vec<String>) {
    let out = dir.join("out");
    let mut args: Vec<String> = [
        "-o",
        out.to_str().unwrap(),
        "--seeds",
        seeds,
        "--hands",
        "1",
    ]
    .map(String::from)
    .to_vec();
    args.extend(
        ["--heights", heights]
            .iter()
            .chain(extra)
            .map(|a| a.to_string()),
    );
    (out, args)
}

/// The cells' ids that `--list-cells` prints for the study `args` (its header left out).
fn listed_cells(args: &[String]) -> Vec<String> {
    let list = succeeds(demoplan().arg("study").args(args).arg("--list-cells"));
    let text = stdout_text(&list);
    let mut lines = text.lines();
    assert_eq!(
        lines.next(),
        Some("task\tid\talgorithm\tdomain\tproblem\tconditions")
    );
    lines
        .map(|l| l.split('\t').nth(1).unwrap().to_string())
        .collect()
}

/// Every cell's record in the grid's folder: it parses, it is of that cell, and
/// results.jsonl holds each cell once, in the order `--list-cells` gives.
fn assert_every_cell_whole(out: &Path, ids: &[String]) {
    for (i, id) in ids.iter().enumerate() {
        let task = i + 1;
        let path = out.join(format!("runs-00001-00100/{task:05}/record.json"));
        let text = std::fs::read_to_string(&path).unwrap();
        let record: serde_json::Value = serde_json::from_str(&text).unwrap();
        assert_eq!(record["id"], id.as_str(), "{}", path.display());
        let props = std::fs::read_to_string(path.with_file_name("properties")).unwrap();
        let props: serde_json::Value = serde_json::from_str(&props).unwrap();
        assert_eq!(props["demoplan_id"], id.as_str());
    }
    let results = std::fs::read_to_string(out.join("results.jsonl")).unwrap();
    let got: Vec<String> = results
        .lines()
        .map(|l| {
            let r: serde_json::Value = serde_json::from_str(l).unwrap();
            r["id"].as_str().unwrap().to_string()
        })
        .collect();
    assert_eq!(got, ids);
}

#[test]
fn a_grid_lists_its_cells_runs_nothing_for_it_and_forces_on_request() {
    let (out, args) = one_hand_study(&tempdir("grid-list"), "3", "2", &[]);
    let ids = listed_cells(&args);
    // 1 seed x 1 hand x 1 height x 2 planners x 3 levels, each once.
    assert_eq!(ids.len(), 6);
    assert_eq!(
        ids.iter().collect::<std::collections::BTreeSet<_>>().len(),
        6
    );
    assert!(!out.exists(), "--list-cells wrote {}", out.display());
    let computed = |extra: &[&str]| {
        let done = succeeds(
            demoplan()
                .arg("study")
                .args(&args)
                .args(["-j", "2"])
                .args(extra),
        );
        stdout_text(&done)
    };
    let ran = "6 runs (6 computed now, 0 from earlier results, 2 at a time)";
    let first = computed(&[]);
    assert!(first.contains(ran), "{first}");
    // Nothing ran, so nothing ran "at a time".
    let again = computed(&[]);
    assert!(
        again.contains("6 runs (0 computed now, 6 from earlier results) in"),
        "{again}"
    );
    let forced = computed(&["--force"]);
    assert!(forced.contains(ran), "{forced}");
    assert_every_cell_whole(&out, &ids);
    // `--cell ID` computes that one cell and prints its record.
    let one = succeeds(
        demoplan()
            .arg("study")
            .args(&args)
            .args(["--cell", &ids[2]]),
    );
    let record: serde_json::Value = serde_json::from_str(stdout_text(&one).trim()).unwrap();
    assert_eq!(record["id"], ids[2].as_str());
    exits_saying(
        36,
        "no cell of this grid has that id",
        demoplan()
            .arg("study")
            .args(&args)
            .args(["--cell", "0123456789abcdef"]),
    );
}

/// A study interrupted as Ctrl-C in a terminal interrupts it (SIGINT to its process
/// group, the cells' processes with it), then killed outright, and run again: it
/// completes, computing only the cells without a record, and every cell's result is
/// whole.
#[test]
fn an_interrupted_study_resumes_with_every_cell_whole() {
    use std::os::unix::process::CommandExt;
    let extra = ["--time-limit", "20"];
    let (out, args) = one_hand_study(&tempdir("grid-interrupt"), "1-2", "2-3", &extra);
    let ids = listed_cells(&args);
    assert_eq!(ids.len(), 24);
    let mut grid = demoplan()
        .arg("study")
        .args(&args)
        .args(["-j", "2"])
        .process_group(0)
        .stdout(std::process::Stdio::null())
        .stderr(std::process::Stdio::null())
        .spawn()
        .unwrap();
    let group = format!("-{}", grid.id());
    // Wait for a cell to have started (its marker), not for a time.
    let started = || {
        (1..=ids.len()).any(|t| {
            out.join(format!("runs-00001-00100/{t:05}/started"))
                .exists()
        })
    };
    let waited = std::time::Instant::now();
    while !started() {
        assert!(
            grid.try_wait().unwrap().is_none(),
            "the grid ended before a cell started"
        );
        assert!(waited.elapsed().as_secs() < 300, "no cell started in 300 s");
        std::thread::sleep(std::time::Duration::from_millis(20));
    }
    let signal = |name: &str| {
        std::process::Command::new("kill")
            .args([name, "--", &group])
            .status()
            .unwrap()
    };
    assert!(signal("-INT").success());
    std::thread::sleep(std::time::Duration::from_millis(200));
    // Whatever is left of the group (nothing, normally) is killed outright.
    signal("-KILL");
    let status = grid.wait().unwrap();
    assert!(!status.success(), "the grid was not interrupted: {status}");
    // Records that are results (a cell whose process the grid saw die in the interrupt
    // may have a record of the crash, which is computed again).
    let whole = (1..=ids.len())
        .filter(|t| {
            let path = out.join(format!("runs-00001-00100/{t:05}/record.json"));
            std::fs::read_to_string(path).is_ok_and(|text| {
                let r: serde_json::Value = serde_json::from_str(&text).unwrap();
                r.get("crashed").is_none()
            })
        })
        .count();
    assert!(
        whole < ids.len(),
        "every cell was done before the interruption"
    );

    let again = succeeds(demoplan().arg("study").args(&args).args(["-j", "2"]));
    let stdout = stdout_text(&again);
    assert!(
        stdout.contains(&format!("24 runs ({} computed now", 24 - whole)),
        "{whole} records were there: {stdout}"
    );
    assert_every_cell_whole(&out, &ids);
}

#[test]
fn a_study_in_child_processes_gives_the_runs_of_one_in_this_process() {
    let tmp = tempdir("study-jobs");
    let run = |jobs: &str| {
        let out = tmp.join(format!("j{jobs}"));
        let done = succeeds(
            demoplan()
                .arg("study")
                .arg("-o")
                .arg(&out)
                // Cells far within their limit: an iPDB climb cut by its deadline would
                // differ with the machine's load, not with how the cells are run.
                .args(["--seeds", "3", "--hands", "1,2", "--heights", "2"])
                .args(["--time-limit", "60", "-j", jobs]),
        );
        let stdout = stdout_text(&done);
        assert!(stdout.contains(&format!("{jobs} at a time")), "{stdout}");
        let text = std::fs::read_to_string(out.join("results.jsonl")).unwrap();
        let mut records: Vec<serde_json::Value> = text
            .lines()
            .map(|l| serde_json::from_str(l).unwrap())
            .collect();
        records.sort_by_key(|r| r["id"].as_str().unwrap().to_string());
        records
    };
    let (alone, parallel) = (run("1"), run("2"));
    assert_eq!(alone.len(), 12);
    assert_eq!(alone.len(), parallel.len());
    let same = |r: &serde_json::Value| {
        let w: Vec<_> = r["widening"]
            .as_array()
            .unwrap()
            .iter()
            .map(|s| (s["prio"].clone(), s["outcome"].clone()))
            .collect();
        (
            r["id"].clone(),
            r["outcome"].clone(),
            r["cost"].clone(),
            r["expansions"].clone(),
            r["plan"].clone(),
            r["executed"].clone(),
            format!("{w:?}"),
        )
    };
    for (a, b) in alone.iter().zip(&parallel) {
        assert_eq!(same(a), same(b));
        assert!(b["peak_memory_kb"].as_u64().unwrap() > 0, "{b}");
    }
    // Algorithm 1 took priority 1's run from the grid: the same time, measured once.
    let by_id: std::collections::HashMap<&str, &serde_json::Value> = parallel
        .iter()
        .map(|r| (r["id"].as_str().unwrap(), r))
        .collect();
    let mut reused = 0;
    for r in parallel.iter().filter(|r| r["level"] == "alg1") {
        let first = &r["widening"][0];
        let p1 = parallel
            .iter()
            .find(|p| {
                p["level"] == "prio-1"
                    && p["planner"] == r["planner"]
                    && p["conditions"] == r["conditions"]
            })
            .unwrap();
        assert!(by_id.contains_key(p1["id"].as_str().unwrap()));
        if p1["outcome"] != "limit" {
            assert_eq!(first["times"], p1["times"], "{r}");
            reused += 1;
        }
    }
    assert_eq!(reused, 4);
}

/// `study --style two-handed`: the cells' conditions name the style (their ids differ
/// from the paper's); `--style paper` is the default, with the same ids as without it.
#[test]
fn study_style_names_the_cells_conditions_only_when_not_the_default() {
    let args = [
        "--seeds",
        "1",
        "--hands",
        "1",
        "--heights",
        "2",
        "-o",
        "unused",
    ];
    let with = |style: &[&str]| {
        let out = succeeds(
            demoplan()
                .arg("study")
                .args(args)
                .args(style)
                .arg("--list-cells"),
        );
        stdout_text(&out)
    };
    let (none, paper, two) = (
        with(&[]),
        with(&["--style", "paper"]),
        with(&["--style", "two-handed"]),
    );
    assert_eq!(none, paper);
    assert!(!none.contains("two-handed"), "{none}");
    assert!(none.contains("params=default;"), "{none}");
    assert!(two.contains("params=two-handed;"), "{two}");
    let ids = |text: &str| -> Vec<String> {
        (text.lines().skip(1))
            .map(|l| l.split('\t').nth(1).unwrap().to_string())
            .collect()
    };
    let (a, b) = (ids(&none), ids(&two));
    assert_eq!(a.len(), b.len());
    assert!(a.iter().all(|id| !b.contains(id)), "{a:?} {b:?}");
}

#[test]
fn study_refuses_bad_options_before_writing_anything() {
    let tmp = tempdir("study-options");
    for (args, what) in [
        (vec!["--heights", "1-3"], "--heights"),
        (vec!["--seeds", "5-1"], "--seeds"),
        (vec!["--seeds", "one"], "--seeds"),
        (vec!["--hands", "3"], "--hands"),
        (vec!["--towers", "0"], "--towers"),
        (vec!["--activities", "settled,sometimes"], "--activities"),
        (vec!["--heights", "8", "--towers", "4"], "cubes"),
        (vec!["--time-limit", "soon"], "--time-limit"),
        (vec!["--style", "one-handed"], "--style"),
    ] {
        let out = refused_in(&tmp, &[&["study", "-o", "out"][..], &args].concat());
        let err = stderr_text(&out);
        assert!(err.contains(what), "{args:?}: {err}");
        assert!(!tmp.join("out").exists(), "{args:?} wrote output");
    }
}

#[test]
fn slurm_writes_the_grid_as_jobs_and_runs_nothing() {
    let tmp = tempdir("study-slurm");
    let grid = [
        "study",
        "--seeds",
        "1",
        "--hands",
        "1",
        "--heights",
        "2",
        "-o",
        "out",
    ];
    let out = demoplan()
        .current_dir(&tmp)
        .args(grid)
        .args(["--slurm", "jobs", "--slurm-partition", "short"])
        .output()
        .unwrap();
    assert!(out.status.success(), "{}", transcript(&out));
    assert!(
        stdout_text(&out).contains("jobs/submit.sh"),
        "{}",
        transcript(&out)
    );
    let cells = std::fs::read_to_string(tmp.join("jobs/cells.sh")).unwrap();
    assert!(cells.contains("#SBATCH --partition=short\n"), "{cells}");
    // `auto` on Slurm: 3G per cell, plus the margin.
    assert!(cells.contains("#SBATCH --mem=3584M\n"), "{cells}");
    assert!(
        cells.contains("--memory-limit 3221225472 --cell"),
        "{cells}"
    );
    assert!(tmp.join("jobs/submit.sh").exists() && tmp.join("jobs/collect.sh").exists());
    assert!(!tmp.join("out").exists(), "--slurm ran the grid");
    // Bad options are refused before anything is written.
    for (args, what) in [
        (vec!["--heights", "1-3", "--slurm", "bad"], "--heights"),
        (vec!["--slurm", "bad", "--slurm-mem", "lots"], "--slurm-mem"),
        (
            vec!["--slurm", "bad", "--slurm-max-running", "0"],
            "--slurm-max-running",
        ),
        (vec!["--slurm-partition", "short"], "--slurm"),
    ] {
        let out = refused_in(&tmp, &[&["study", "-o", "out"][..], &args].concat());
        assert!(
            stderr_text(&out).contains(what),
            "{args:?}: {}",
            transcript(&out)
        );
        assert!(
            !tmp.join("bad").exists() && !tmp.join("out").exists(),
            "{args:?}"
        );
    }
}

/// The slim crate's widening library, and a problem (a tower of two) written into `tmp`.
fn widening_library_and_problem(tmp: &Path) -> (PathBuf, PathBuf) {
    let library = workspace().join("crates/slim/tests/fixtures/widening-library.json");
    let problem = tmp.join("p.pddl");
    succeeds(
        demoplan()
            .args(["problem", "--tower", "cube_1,cube_2", "-o"])
            .arg(&problem),
    );
    (library, problem)
}

#[test]
fn an_unknown_planner_is_a_command_line_mistake_that_names_the_planners() {
    let tmp = tempdir("unknown-planner");
    let (library, problem) = widening_library_and_problem(&tmp);
    let out = exits(
        36,
        demoplan()
            .current_dir(&tmp)
            .arg("solve")
            .arg(&library)
            .arg(&problem)
            .args(["--planner", "lama"]),
    );
    let err = stderr_text(&out);
    assert!(
        err.contains("invalid value 'lama' for '--planner <PLANNER>'")
            && err.contains("[possible values: demoplan, fast-downward]"),
        "{err}"
    );
    assert!(!tmp.join("sas_plan").exists());
}

#[test]
fn fast_downward_backends_say_clearly_when_it_is_missing() {
    let tmp = tempdir("fd-missing");
    let (library, problem) = widening_library_and_problem(&tmp);
    let solve: Vec<std::ffi::OsString> = vec![
        "solve".into(),
        library.into(),
        problem.into(),
        "--planner".into(),
        "fast-downward".into(),
    ];
    let reproduce: Vec<std::ffi::OsString> = vec![
        "reproduce".into(),
        "-o".into(),
        "out".into(),
        "--with-fd".into(),
    ];
    for args in [solve, reproduce] {
        let out = demoplan()
            .current_dir(&tmp)
            .env_remove("DEMOPLAN_FD")
            .args(&args)
            .output()
            .unwrap();
        let err = stderr_text(&out);
        assert_eq!(out.status.code(), Some(36), "{}", transcript(&out));
        assert!(err.contains("Fast Downward not found"), "{err}");
        assert!(err.contains("DEMOPLAN_FD"), "{err}");
    }
    let out = exits(
        36,
        demoplan()
            .current_dir(&tmp)
            .env("DEMOPLAN_FD", tmp.join("nowhere/fast-downward.py"))
            .args(["reproduce", "-o", "out", "--with-fd"]),
    );
    assert!(stderr_text(&out).contains("is not a file"));
    // Nothing was written before the check.
    assert!(!tmp.join("out").exists());
}

/// Runs `cmd` in `dir`: a command line error (36), whose transcript names `args`.
#[track_caller]
fn refused_in(dir: &Path, args: &[&str]) -> Output {
    let out = demoplan().current_dir(dir).args(args).output().unwrap();
    assert_eq!(
        out.status.code(),
        Some(36),
        "{args:?}: {}",
        transcript(&out)
    );
    out
}

/// Runs `cmd` with a reader that goes away before reading anything (`| head -0`): it
/// exits with a shell's SIGPIPE code, 141, and says nothing.
#[track_caller]
fn stops_quietly_when_the_reader_goes_away(cmd: &mut std::process::Command) {
    let mut child = cmd
        .stdout(std::process::Stdio::piped())
        .stderr(std::process::Stdio::piped())
        .spawn()
        .unwrap();
    drop(child.stdout.take());
    let out = child.wait_with_output().unwrap();
    assert_eq!(
        out.status.code(),
        Some(141),
        "{:?}: {}",
        cmd,
        transcript(&out)
    );
    assert!(out.stderr.is_empty(), "{:?}: {}", cmd, transcript(&out));
}

#[test]
fn a_closed_or_full_standard_output_stops_demoplan_without_a_panic() {
    // `demoplan fmt --stdout FILE...` prints the formatted PDDL: over 20 KB for this problem,
    // 400 KB for twenty of it, far more than a pipe holds (64 KB), so the writer blocks
    // and meets the closed pipe whenever the reader goes away.
    let tmp = tempdir("closed-stdout");
    let problem = gripper(&tmp, 400).problem_file;
    stops_quietly_when_the_reader_goes_away(
        demoplan()
            .args(["fmt", "--stdout"])
            .args(std::iter::repeat_n(&problem, 20)),
    );

    let full = std::path::Path::new("/dev/full");
    if full.exists() {
        let out = exits(
            35,
            demoplan()
                .args(["fmt", "--stdout"])
                .arg(&problem)
                .stdout(std::fs::File::create(full).unwrap()),
        );
        let stderr = stderr_text(&out);
        assert!(
            stderr.contains("cannot write to standard output"),
            "{stderr}"
        );
        assert!(!stderr.contains("panicked"), "{stderr}");
    }
}

/// A hand-state table of `rows` rows whose activity changes every ten rows (a third of a
/// second at the tables' 30 frames a second): many segments.
fn busy_hand_table(rows: usize) -> String {
    let mut text = String::from(
        "@relation busy\n@attribute Hand {NotMove, Move}\n\
         @attribute ObjectActedOn {None, cube}\n@attribute ObjectInHand {None, cube}\n\
         @attribute Activity {IdleMotion, Reach}\n@data\n",
    );
    for i in 0..rows {
        text.push_str(if (i / 10) % 2 == 0 {
            "NotMove,None,None,IdleMotion\n"
        } else {
            "Move,cube,None,Reach\n"
        });
    }
    text
}

/// `segment FILE | head -1`, `classify FILE... | head -1`: the reader goes away and
/// demoplan stops with a shell's SIGPIPE code, printing nothing (it printed `error: `).
#[test]
fn segment_and_classify_stop_quietly_when_their_reader_goes_away() {
    let tmp = tempdir("closed-pipe");
    std::fs::write(tmp.join("busy.arff"), busy_hand_table(40_000)).unwrap();
    std::fs::write(tmp.join("small.arff"), busy_hand_table(40)).unwrap();
    let many_tables: Vec<&str> = std::iter::repeat_n("small.arff", 1_000).collect();
    let runs: [Vec<&str>; 3] = [
        vec!["segment", "busy.arff"],
        vec!["segment", "--json", "busy.arff"],
        [&["classify"][..], &many_tables].concat(),
    ];
    for args in runs {
        // Far more than a pipe holds (64 KB): the writer meets the closed pipe.
        let full = succeeds(demoplan().current_dir(&tmp).args(&args));
        assert!(
            full.stdout.len() > 128 * 1024,
            "{}: {}",
            args[0],
            full.stdout.len()
        );
        stops_quietly_when_the_reader_goes_away(demoplan().current_dir(&tmp).args(&args));
    }
}

fn unity_fixtures() -> PathBuf {
    fixtures().join("unity")
}

/// `import` on a Unity log (generated by tools/make-unity-fixtures from a simulated
/// demonstration): the report names what was mapped, ignored and found, the mapping
/// used is printed, and the recording written reads back.
#[test]
fn import_reports_each_unity_log_and_prints_the_mapping_used() {
    let tmp = tempdir("import-unity");
    std::fs::copy(
        unity_fixtures().join("p01-d03.json"),
        tmp.join("p01-d03.json"),
    )
    .unwrap();
    let out = succeeds(
        demoplan()
            .current_dir(&tmp)
            .args(["import", "p01-d03.json", "-o", "out"]),
    );
    insta::assert_snapshot!(transcript(&out));
    succeeds(
        demoplan()
            .current_dir(&tmp)
            .args(["inspect", "out/p01-d03.jsonl"]),
    );
    // The printed mapping is a mapping file that reads back.
    let stdout = String::from_utf8(out.stdout).unwrap();
    let toml = &stdout[stdout.find("# demoplan import mapping").unwrap()..];
    std::fs::write(tmp.join("used.toml"), toml).unwrap();
    succeeds(demoplan().current_dir(&tmp).args([
        "import",
        "p01-d03.json",
        "--mapping",
        "used.toml",
        "-o",
        "again",
    ]));
    assert_eq!(
        std::fs::read(tmp.join("out/p01-d03.jsonl")).unwrap(),
        std::fs::read(tmp.join("again/p01-d03.jsonl")).unwrap()
    );
}

/// The Unity logs go straight into `learn`: the library has Reach, Take, Put and Stack
/// operators, `solve` builds a three-cube tower with them, and the plan executes.
#[test]
fn learn_solve_and_execute_on_unity_logs() {
    let tmp = tempdir("unity-learn");
    let mut logs: Vec<PathBuf> = std::fs::read_dir(unity_fixtures())
        .unwrap()
        .map(|e| e.unwrap().path())
        .collect();
    logs.sort();
    assert_eq!(logs.len(), 4);
    let learn = succeeds(
        demoplan()
            .current_dir(&tmp)
            .arg("learn")
            .args(&logs)
            .args(["-o", "lib.json"]),
    );
    let text = stdout_text(&learn);
    for kind in ["Reach", "Take", "Put", "Stack"] {
        let line = text
            .lines()
            .find(|l| l.starts_with(kind))
            .unwrap_or_else(|| panic!("no {kind} line in\n{text}"));
        let operators: u32 = line.split_whitespace().nth(2).unwrap().parse().unwrap();
        assert!(operators > 0, "{line}");
    }
    let run = |args: &[&str]| {
        let out = demoplan().current_dir(&tmp).args(args).output().unwrap();
        assert_eq!(out.status.code(), Some(0), "{args:?}: {}", transcript(&out));
        stdout_text(&out)
    };
    run(&[
        "problem",
        "--tower",
        "cube_1,cube_2,cube_3",
        "--hands",
        "1",
        "-o",
        "tower.pddl",
    ]);
    let solved = run(&["solve", "lib.json", "tower.pddl", "--plan-file", "plan"]);
    let prio = solved
        .split("Solution found at priority ")
        .nth(1)
        .and_then(|s| s.split_whitespace().next())
        .unwrap_or_else(|| panic!("no solution in\n{solved}"));
    run(&["domain", "lib.json", "--prio", prio, "-o", "domain.pddl"]);
    let executed = run(&["execute", "domain.pddl", "tower.pddl", "plan"]);
    assert!(executed.contains("goal reached"), "{executed}");
    let plan = std::fs::read_to_string(tmp.join("plan")).unwrap();
    assert!(plan.contains("(stack"), "{plan}");
}

#[test]
fn inspect_segment_and_timeline_read_unity_logs_directly() {
    let tmp = tempdir("unity-direct");
    let log = unity_fixtures().join("p01-d03.json");
    for args in [
        vec!["inspect".into(), log.display().to_string()],
        vec!["segment".into(), log.display().to_string()],
        vec![
            "timeline".into(),
            log.display().to_string(),
            "-o".into(),
            "t.svg".into(),
        ],
    ] {
        let out = demoplan().current_dir(&tmp).args(&args).output().unwrap();
        assert_eq!(out.status.code(), Some(0), "{args:?}: {}", transcript(&out));
    }
    let segments = demoplan()
        .args(["segment", log.to_str().unwrap()])
        .output()
        .unwrap();
    let text = stdout_text(&segments);
    assert!(text.contains("Stack") && text.contains("Reach"), "{text}");
    // A mapping that ignores the cubes leaves nothing to stack.
    std::fs::write(
        tmp.join("no-cubes.toml"),
        "default_entities = true\n[[entity]]\nglob = \"*cube*\"\nrole = \"ignore\"\n",
    )
    .unwrap();
    let out = demoplan()
        .current_dir(&tmp)
        .args([
            "segment",
            log.to_str().unwrap(),
            "--mapping",
            "no-cubes.toml",
        ])
        .output()
        .unwrap();
    let text = stdout_text(&out);
    assert!(!text.contains("Stack"), "{}", transcript(&out));
}

#[test]
fn import_name_clash_exits_36_before_writing_anything() {
    let tmp = tempdir("import-clash");
    for dir in ["a", "b"] {
        std::fs::create_dir_all(tmp.join(dir)).unwrap();
        std::fs::copy(
            unity_fixtures().join("p01-d03.json"),
            tmp.join(dir).join("log.json"),
        )
        .unwrap();
    }
    std::fs::copy(
        unity_fixtures().join("p01-d02.json"),
        tmp.join("first.json"),
    )
    .unwrap();
    let out = exits(
        36,
        demoplan().current_dir(&tmp).args([
            "import",
            "first.json",
            "a/log.json",
            "b/log.json",
            "-o",
            "out",
        ]),
    );
    insta::assert_snapshot!(transcript(&out));
    assert!(!tmp.join("out").exists(), "something was written");
}

/// One mistake per file in `fixtures/import-malformed`: Unity logs (`*.json`) and mapping
/// files (`*.toml`, applied to a good log). Each is exit 31 with the file, the place and
/// what is wrong, and no recording is written.
#[test]
fn malformed_unity_logs_and_mappings_name_file_place_and_field() {
    let dir = fixtures().join("import-malformed");
    let cases = entry_names(&dir);
    assert!(cases.len() >= 18, "only {} cases", cases.len());
    let good = unity_fixtures().join("p01-d03.json");
    for case in &cases {
        let out_dir = tempdir(&format!("import-malformed-{case}"));
        let mut cmd = demoplan();
        cmd.current_dir(&dir).arg("import");
        if case.ends_with(".toml") {
            cmd.arg(&good).args(["--mapping", case]);
        } else {
            cmd.arg(case);
        }
        let out = cmd.arg("-o").arg(&out_dir).output().unwrap();
        let stderr = stderr_text(&out);
        assert_eq!(out.status.code(), Some(31), "{case}: {stderr}");
        assert!(
            stderr.contains(case.as_str()),
            "{case}: no file name in\n{stderr}"
        );
        assert!(out.stdout.is_empty(), "{case}: printed a report");
        assert_eq!(
            std::fs::read_dir(&out_dir).unwrap().count(),
            0,
            "{case}: wrote"
        );
        insta::assert_snapshot!(format!("import-{case}"), transcript(&out));
    }
}

/// A Unity log of `steps` steps (a hand and two cubes moving), as text.
fn long_unity_log(steps: u32) -> String {
    let mut text = String::from("{\"playbackTimestepMilliseconds\": 20, \"log\": [\n");
    for k in 0..steps {
        let t = f64::from(k) * 0.05;
        let x = (t * 0.7).sin() * 0.3;
        if k > 0 {
            text.push_str(",\n");
        }
        text.push_str(&format!(
            "{{\"time\": {ms}, \"logStep\": [\
             {{\"name\":\"VR_Controller_R\",\"position\":[{x:.4},1.0,0.3],\"orientation\":[1,0,0,0],\"velocity\":[0,0,0],\"events\":[]}},\
             {{\"name\":\"Cube_1\",\"position\":[0.0,0.775,0.4],\"orientation\":[1,0,0,0],\"velocity\":[0,0,0],\"events\":[]}},\
             {{\"name\":\"Cube_2\",\"position\":[0.1,0.775,0.4],\"orientation\":[1,0,0,0],\"velocity\":[0,0,0],\"events\":[]}}]}}",
            ms = k * 50
        ));
    }
    text.push_str("\n]}\n");
    text
}

/// Sources stream: the peak heap of an import (counted by the binary's allocator) is the
/// same for a log ten times longer.
#[test]
fn import_peak_heap_does_not_grow_with_the_log() {
    let tmp = tempdir("import-heap");
    let mut peaks = Vec::new();
    for steps in [2_000, 20_000] {
        let name = format!("log-{steps}.json");
        std::fs::write(tmp.join(&name), long_unity_log(steps)).unwrap();
        let out = succeeds(demoplan().current_dir(&tmp).args([
            "import",
            &name,
            "-o",
            "out",
            "--peak-heap",
        ]));
        let stderr = stderr_text(&out);
        let peak: u64 = stderr
            .split("peak heap: ")
            .nth(1)
            .and_then(|s| s.split_whitespace().next())
            .and_then(|s| s.parse().ok())
            .unwrap_or_else(|| panic!("no peak heap in {stderr}"));
        peaks.push(peak);
    }
    assert!(
        peaks[1] as f64 <= peaks[0] as f64 * 1.1,
        "peak heap grew with the log: {peaks:?}"
    );
}

/// A folder of Unity logs is read as the logs in it.
#[test]
fn learn_takes_a_folder_of_unity_logs_like_the_logs_in_it() {
    let tmp = tempdir("learn-unity-folder");
    std::fs::create_dir_all(tmp.join("logs")).unwrap();
    for name in ["p01-d02.json", "p01-d03.json"] {
        std::fs::copy(unity_fixtures().join(name), tmp.join("logs").join(name)).unwrap();
    }
    let learn = |inputs: &[&str], out: &str| {
        let o = demoplan()
            .current_dir(&tmp)
            .arg("learn")
            .args(inputs)
            .args(["-o", out])
            .output()
            .unwrap();
        assert_eq!(o.status.code(), Some(0), "{inputs:?}: {}", transcript(&o));
        std::fs::read_to_string(tmp.join(out)).unwrap()
    };
    let named = learn(&["logs/p01-d02.json", "logs/p01-d03.json"], "named.json");
    assert_eq!(learn(&["logs"], "folder.json"), named);
}

/// One mapping file serves every command: the import crate's keys for Unity logs
/// (`max_age`, `[[entity]]`) and the `[labels]` that `classify` maps ARFF labels with.
#[test]
fn one_mapping_file_serves_classify_and_the_unity_commands() {
    let mapping = demonstrations().join("one-mapping.toml");
    let tables = format!("{}/../segment/tests/fixtures", env!("CARGO_MANIFEST_DIR"));
    let classify = succeeds(
        demoplan()
            .current_dir(&tables)
            .args(["classify", "recogniser-labels.txt", "--mapping"])
            .arg(&mapping),
    );
    // Pour is Put by the file's [labels]: no frame is left out.
    assert!(stdout_text(&classify).starts_with(
        "recogniser-labels.txt: 14 labelled hand frames, 13 agree with the tree (92.86%)\n"
    ));
    assert!(classify.stderr.is_empty(), "{}", transcript(&classify));
    let log = unity_fixtures().join("p01-d03.json");
    let segment = succeeds(
        demoplan()
            .arg("segment")
            .arg(&log)
            .arg("--mapping")
            .arg(&mapping),
    );
    assert!(stdout_text(&segment).contains("Stack"));
}

/// A header of `n` cubes, one line (issue 23).
fn header_of_cubes(n: usize) -> String {
    let size = [0.05; 3];
    let cube = |i| serde_json::json!({"name": format!("c{i}"), "kind": "cube", "size": size});
    serde_json::json!({
        "format": "demoplan-recording", "version": 1, "id": "r", "participant": "p",
        "task": "t", "frame_rate": 90, "entities": (0..n).map(cube).collect::<Vec<_>>(),
    })
    .to_string()
}

/// Issue 23: `grounding` indexes objects in 16 bits, so a recording of 65,535 entities
/// or more is refused when it is read, with exit 31 and its header's line and field
/// named; a recording line over the documented maximum is refused the same way, by its
/// line, without reading more of it than the maximum.
#[test]
fn recordings_over_the_entity_and_line_limits_exit_31_naming_where() {
    let dir = tempdir("reader-limits");
    let many = dir.join("many.jsonl");
    std::fs::write(&many, format!("{}\n{{\"t\":0}}\n", header_of_cubes(65_535))).unwrap();
    for command in ["inspect", "segment"] {
        let out = demoplan().arg(command).arg(&many).output().unwrap();
        let stderr = stderr_text(&out);
        assert_eq!(out.status.code(), Some(31), "{command}: {stderr}");
        assert!(stderr.contains("many.jsonl:1:"), "{command}: {stderr}");
        assert!(stderr.contains("field `entities`"), "{command}: {stderr}");
        assert!(
            stderr.contains("65535 entities: a recording declares at most 65534"),
            "{command}: {stderr}"
        );
    }
    let long = dir.join("long.jsonl");
    let mut text = format!("{}\n{{\"t\":0}}\n{{\"t\":1", header_of_cubes(2));
    text.push_str(&" ".repeat(recording::MAX_LINE_BYTES));
    text.push_str("}\n");
    std::fs::write(&long, text).unwrap();
    let out = demoplan().arg("inspect").arg(&long).output().unwrap();
    let stderr = stderr_text(&out);
    assert_eq!(out.status.code(), Some(31), "{stderr}");
    assert!(stderr.contains("long.jsonl:3:"), "{stderr}");
    assert!(
        stderr.contains("the line is longer than 67108864 bytes"),
        "{stderr}"
    );
}

/// The outcome column of every row of a `runs.csv`, by level.
fn outcomes_by_level(runs_csv: &str) -> Vec<(String, String)> {
    let mut lines = runs_csv.lines();
    let header: Vec<&str> = lines.next().unwrap().split(',').collect();
    let col = |name: &str| header.iter().position(|h| *h == name).unwrap();
    lines
        .map(|l| {
            let row: Vec<&str> = l.split(',').collect();
            (
                row[col("level")].to_string(),
                row[col("outcome")].to_string(),
            )
        })
        .collect()
}

/// Asserts a run stopped by itself: no abort (134, SIGABRT after a failed allocation), no
/// kill (137, SIGKILL from the kernel's OOM killer), no panic.
fn assert_stopped_by_itself(out: &Output) {
    use std::os::unix::process::ExitStatusExt;
    assert_eq!(out.status.signal(), None, "{}", transcript(out));
    assert!(
        !matches!(out.status.code(), Some(134 | 137 | 101)),
        "{}",
        transcript(out)
    );
    assert!(
        !stderr_text(out).contains("panicked"),
        "{}",
        transcript(out)
    );
}

#[test]
fn solve_records_a_level_out_of_memory_and_exits_12() {
    // Issue 23: every level of Algorithm 1 gets the memory limit of its own; a level
    // that reaches it has the outcome `memory`, and with no plan at any level `solve`
    // exits 12, as for a time limit.
    let library = learned_library("solve-memory");
    let tmp = library.parent().unwrap().to_path_buf();
    let problem = tmp.join("goal-5.pddl");
    succeeds(
        demoplan()
            .args(["problem", "--paper-goal", "5", "-o"])
            .arg(&problem),
    );
    let plan = tmp.join("plan");
    let solve = demoplan()
        .arg("solve")
        .arg(&library)
        .arg(&problem)
        .args(["--search", "astar(blind())", "--time-limit", "60"])
        .args(["--memory-limit", "64K", "--plan-file"])
        .arg(&plan)
        .output()
        .unwrap();
    assert_stopped_by_itself(&solve);
    let log = stdout_text(&solve);
    assert_eq!(solve.status.code(), Some(12), "{}", transcript(&solve));
    assert!(
        log.contains("No plan: some level reached its memory limit (exit 12)."),
        "{log}"
    );
    // Every level tried is in the table, each out of memory (none proved unsolvable,
    // none errored).
    let rows: Vec<&str> = log
        .lines()
        .skip(1)
        .take_while(|l| !l.starts_with("Cumulative"))
        .collect();
    assert!(!rows.is_empty(), "{log}");
    for row in &rows {
        assert_eq!(row.split_whitespace().nth(2), Some("memory"), "{log}");
    }
    assert!(!plan.exists(), "no plan file without a plan");
    // Without the limit the same library plans (goal 1: goal 5 takes LM-cut about 40 s
    // in the debug build).
    let goal_1 = tmp.join("goal-1.pddl");
    succeeds(
        demoplan()
            .args(["problem", "--paper-goal", "1", "-o"])
            .arg(&goal_1),
    );
    let unlimited = demoplan()
        .arg("solve")
        .arg(&library)
        .arg(&goal_1)
        .args([
            "--time-limit",
            "60",
            "--memory-limit",
            "infinity",
            "--plan-file",
        ])
        .arg(&plan)
        .output()
        .unwrap();
    assert_eq!(
        unlimited.status.code(),
        Some(0),
        "{}",
        transcript(&unlimited)
    );
    // A memory limit that is not one is a command line error.
    exits_saying(
        36,
        "--memory-limit",
        demoplan()
            .arg("solve")
            .arg(&library)
            .arg(&problem)
            .args(["--memory-limit", "lots"]),
    );
}

#[test]
fn study_and_reproduce_record_runs_out_of_memory() {
    // Issue 23: a run of a study or a reproduction that reaches its memory limit is a
    // record with the outcome `memory` (as one out of time is `limit`), in this process
    // (-j 1, the limit on top of what the process already holds) and in child processes
    // (-j 2, each with its own allocator and the limit the parent resolved).
    let tmp = tempdir("memory-limit-runs");
    let study_out = tmp.join("study");
    let study = demoplan()
        .arg("study")
        .arg("-o")
        .arg(&study_out)
        .args(["--seeds", "1", "--hands", "1", "--heights", "6"])
        .args(["--time-limit", "20", "--memory-limit", "64K", "-j", "1"])
        .output()
        .unwrap();
    assert_stopped_by_itself(&study);
    assert_eq!(study.status.code(), Some(0), "{}", transcript(&study));
    let runs = std::fs::read_to_string(study_out.join("runs.csv")).unwrap();
    let outcomes = outcomes_by_level(&runs);
    // One seed, one height, two planners, three levels (prio-1, full, alg1).
    assert_eq!(outcomes.len(), 6, "{runs}");
    for (level, outcome) in &outcomes {
        assert_eq!(outcome, "memory", "{level}: {runs}");
    }
    let results = std::fs::read_to_string(study_out.join("results.jsonl")).unwrap();
    let records: Vec<serde_json::Value> = results
        .lines()
        .map(|l| serde_json::from_str(l).unwrap())
        .collect();
    assert_eq!(records.len(), 6, "{results}");
    for r in &records {
        assert_eq!(r["outcome"], "memory", "{r}");
    }

    let reproduce_out = tmp.join("reproduce");
    let reproduce = demoplan()
        .arg("reproduce")
        .arg("-o")
        .arg(&reproduce_out)
        .args(["--prios", "1", "--goals", "5", "--time-limit", "20"])
        .args(["--memory-limit", "64K", "-j", "2"])
        .output()
        .unwrap();
    assert_stopped_by_itself(&reproduce);
    assert_eq!(
        reproduce.status.code(),
        Some(0),
        "{}",
        transcript(&reproduce)
    );
    let results = std::fs::read_to_string(reproduce_out.join("results.jsonl")).unwrap();
    let records: Vec<serde_json::Value> = results
        .lines()
        .map(|l| serde_json::from_str(l).unwrap())
        .collect();
    // Two planners, priority 1 and Algorithm 1, goal 5.
    assert_eq!(records.len(), 4, "{results}");
    for r in &records {
        assert_eq!(r["outcome"], "memory", "{r}");
        assert!(r["error"].is_null(), "a child that failed: {r}");
    }
}
