//! The command line as users read it: `demoplan --help` and every command's `--help`,
//! pinned by snapshots, so that a change to an option's name, default or text is a
//! deliberate one (`cargo insta review`). And the library entry point the Python package
//! calls, `demoplan_cli::run`, giving the same exit codes as the executable.

#![allow(clippy::unwrap_used, clippy::expect_used)] // tests fail loudly by design

use std::process::Command;

fn help(args: &[&str]) -> String {
    let out = Command::new(env!("CARGO_BIN_EXE_demoplan"))
        .args(args)
        .env("NO_COLOR", "1")
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(0), "{args:?}");
    assert!(out.stderr.is_empty(), "{args:?}");
    String::from_utf8(out.stdout).unwrap()
}

/// The commands the top-level help lists (`Commands:` up to the blank line), without
/// clap's own `help`.
fn commands(top: &str) -> Vec<String> {
    top.lines()
        .skip_while(|l| !l.starts_with("Commands:"))
        .skip(1)
        .take_while(|l| !l.trim().is_empty())
        .filter_map(|l| l.split_whitespace().next())
        .filter(|c| *c != "help")
        .map(str::to_string)
        .collect()
}

#[test]
fn top_level_help_lists_every_command() {
    let top = help(&["--help"]);
    insta::assert_snapshot!("help", top);
    let listed = commands(&top);
    for command in [
        "check",
        "plan",
        "translate",
        "validate",
        "simulate",
        "inspect",
        "segment",
        "learn",
        "solve",
        "reproduce",
        "study",
        "execute",
    ] {
        assert!(
            listed.iter().any(|c| c == command),
            "{command} not in {listed:?}"
        );
    }
}

#[test]
fn every_command_has_its_help_pinned() {
    let top = help(&["--help"]);
    for command in commands(&top) {
        let text = help(&[&command, "--help"]);
        assert!(
            text.contains(&format!("Usage: demoplan {command}")),
            "{command}: {text}"
        );
        insta::assert_snapshot!(format!("help-{command}"), text);
    }
}

#[test]
fn run_as_with_an_empty_program_is_a_usage_error_not_a_panic() {
    use demoplan_cli::{run_as, ExitCode};
    let argv = ["demoplan", "study", "--list-cells"].map(std::ffi::OsString::from);
    assert_eq!(run_as(Vec::new(), argv.to_vec()), ExitCode::USAGE);
}

#[test]
fn the_library_entry_point_gives_the_executables_exit_codes() {
    use demoplan_cli::{run, ExitCode};
    let fixtures = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/fixtures/malformed");
    assert_eq!(run(["demoplan", "--version"]), ExitCode::SUCCESS);
    assert_eq!(
        run(["demoplan", "plan", "--no-such-option"]),
        ExitCode::USAGE
    );
    assert_eq!(
        run(["demoplan", "check", "no-such-problem.pddl"]),
        ExitCode::USAGE
    );
    let malformed = std::fs::read_dir(fixtures)
        .unwrap()
        .map(|e| e.unwrap().path())
        .find(|p| {
            p.file_name()
                .unwrap()
                .to_string_lossy()
                .starts_with("syntax-")
        })
        .unwrap();
    let domain = malformed.join("domain.pddl");
    assert_eq!(
        run(["demoplan", "check", domain.to_str().unwrap()]),
        ExitCode::INPUT_ERROR
    );
}
