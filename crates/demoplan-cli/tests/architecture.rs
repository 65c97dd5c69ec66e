//! ARCHITECTURE.md's invariants that a machine can check, read from the crates'
//! manifests and the CLI's sources: lower crates never depend on higher ones, no library
//! crate draws on the terminal or depends on the CLI, and the CLI stays a thin shell.

#![allow(clippy::unwrap_used, clippy::expect_used)] // tests fail loudly by design

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

fn crates_dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("..")
}

/// Every workspace crate (folder name) with the names of its normal dependencies.
fn dependencies() -> BTreeMap<String, Vec<String>> {
    let mut out = BTreeMap::new();
    for entry in std::fs::read_dir(crates_dir()).unwrap() {
        let path = entry.unwrap().path().join("Cargo.toml");
        let Ok(text) = std::fs::read_to_string(&path) else {
            continue;
        };
        let manifest: toml::Table = toml::from_str(&text).unwrap();
        let name = manifest["package"]["name"].as_str().unwrap().to_string();
        let deps = manifest
            .get("dependencies")
            .and_then(|d| d.as_table())
            .map(|d| d.keys().cloned().collect())
            .unwrap_or_default();
        out.insert(name, deps);
    }
    out
}

#[test]
fn lower_crates_never_depend_on_higher_ones() {
    let all = dependencies();
    let project: Vec<&String> = all.keys().collect();
    let on_project = |krate: &str| -> Vec<String> {
        all[krate]
            .iter()
            .filter(|d| project.contains(d))
            .cloned()
            .collect()
    };
    // Exactly these project crates, as ARCHITECTURE.md's invariants state.
    for (krate, allowed) in [
        ("pddl", &[][..]),
        ("task", &[]),
        ("geometry", &[]),
        ("atomic-write", &[]),
        ("recording", &["geometry"]),
        ("bags", &[]),
        ("report", &["recording"]),
        ("translate", &["pddl", "task"]),
        ("search", &["task"]),
        ("validate", &["pddl"]),
        ("simulate", &["atomic-write", "geometry", "recording"]),
        ("import", &["atomic-write", "bags", "recording"]),
        ("grounding", &["recording"]),
        ("segment", &["recording", "grounding"]),
        // Execution in the loop: above Algorithm 1 and the cube world, which never meet
        // below it.
        ("closed-loop", &["pddl", "learn", "slim", "cubeworld"]),
    ] {
        let mut found = on_project(krate);
        found.sort();
        let mut allowed: Vec<String> = allowed.iter().map(|s| s.to_string()).collect();
        allowed.sort();
        assert_eq!(found, allowed, "{krate} depends on {found:?}");
    }
    // The demonstration side knows no planner; the planner side reads no recordings.
    for (krate, never) in [
        ("learn", &["task", "translate", "search", "slim"][..]),
        ("import", &["task", "translate", "search", "slim", "learn"]),
        (
            "slim",
            &[
                "recording",
                "import",
                "simulate",
                "grounding",
                "cubeworld",
                "closed-loop",
            ],
        ),
        ("cubeworld", &["slim", "learn", "closed-loop"]),
    ] {
        for n in never {
            assert!(
                !all[krate].contains(&n.to_string()),
                "{krate} depends on {n}"
            );
        }
    }
}

fn manifest(krate: &str) -> toml::Table {
    let text = std::fs::read_to_string(crates_dir().join(krate).join("Cargo.toml")).unwrap();
    toml::from_str(&text).unwrap()
}

#[test]
fn no_library_crate_touches_the_terminal_or_depends_on_the_cli() {
    for (krate, deps) in dependencies() {
        // The two shells: the command line, and the Python extension, which runs it.
        if krate == "demoplan-cli" || krate == "demoplan-py" {
            continue;
        }
        let manifest = manifest(&krate);
        for terminal in ["clap", "miette", "indicatif", "demoplan-cli"] {
            if !deps.iter().any(|d| d == terminal) {
                continue;
            }
            // One rule: a library crate may derive clap's traits on its own option types,
            // so that each option is declared once, beside what it switches on (the
            // doc comments are the help texts; it parses nothing): only as an optional
            // dependency behind a feature `clap`, which only the CLI turns on (below).
            assert_eq!(terminal, "clap", "{krate} depends on {terminal}: only the CLI parses arguments, renders diagnostics and draws progress");
            assert_eq!(
                manifest["dependencies"]["clap"]["optional"].as_bool(),
                Some(true),
                "{krate}: clap must be optional"
            );
            assert_eq!(
                manifest["features"]["clap"].as_array().unwrap(),
                &vec![toml::Value::from("dep:clap")],
                "{krate}: the feature `clap` turns on clap and nothing else"
            );
        }
    }
}

#[test]
fn only_the_cli_turns_on_the_clap_features() {
    for krate in dependencies().keys().filter(|k| *k != "demoplan-cli") {
        let manifest = manifest(krate);
        let Some(deps) = manifest.get("dependencies").and_then(|d| d.as_table()) else {
            continue;
        };
        for (dep, spec) in deps {
            let features = spec.get("features").and_then(|f| f.as_array());
            assert!(
                !features.is_some_and(|f| f.contains(&toml::Value::from("clap"))),
                "{krate} turns on {dep}'s clap feature: only the CLI declares options"
            );
        }
    }
}

/// The line count of the CLI's sources, a budget: a command that grows past it is
/// computing something that belongs in a library crate. The budget is 2,500, issue 21's
/// aim, from 2,833 (2,495 lines after its last cut: the grid commands' options and
/// settings, the study's conditions, `classify --learn`'s choice, the problem's goal, the
/// domain file's search, the label errors, the value enums of `--activities` and
/// `--planner` moved to their crates; then `solve --alias` and `demoplan-opt` in
/// `plan --help`, issue 25, whose resolution is `slim`'s). What is left: the option
/// declarations of the CLI's own commands and their help texts (`cli.rs`, their wording
/// pinned by the `--help` snapshots), diagnostics (`diagnostic.rs`, `recording_input.rs`,
/// `demo_input.rs`: library errors rendered with miette, which no library crate may use,
/// and mapped to exit codes; every `recording::TextError` through one renderer), file
/// handling (`input.rs`, `output.rs`), terminal plumbing (`progress.rs`, indicatif; the
/// SIGPIPE hook in `lib.rs`), and each command's calls and printing.
#[test]
fn the_cli_stays_a_thin_shell() {
    fn lines(dir: &Path) -> usize {
        std::fs::read_dir(dir)
            .unwrap()
            .map(|e| e.unwrap().path())
            .map(|p| {
                if p.is_dir() {
                    lines(&p)
                } else if p.extension().is_some_and(|e| e == "rs") {
                    std::fs::read_to_string(&p).unwrap().lines().count()
                } else {
                    0
                }
            })
            .sum()
    }
    let total = lines(&Path::new(env!("CARGO_MANIFEST_DIR")).join("src"));
    assert!(total <= 2_500, "crates/demoplan-cli/src has {total} lines");
}
