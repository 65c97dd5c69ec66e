//! What every test binary of the CLI shares: the executable, the folders it reads from
//! and writes to, and what a run printed, as one text.
//!
//! Each test binary includes this module (`mod common;`) and uses what it needs, so an
//! item one binary leaves unused is not dead code.
#![allow(dead_code)]

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

/// The `demoplan` executable under test, without colours (snapshots compare text).
pub fn demoplan() -> Command {
    let mut cmd = Command::new(env!("CARGO_BIN_EXE_demoplan"));
    cmd.env("NO_COLOR", "1");
    cmd
}

/// The CLI's test fixtures (`crates/demoplan-cli/tests/fixtures`).
pub fn fixtures() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/fixtures")
}

/// The root of the workspace (for `examples/`, `README.md`, other crates' fixtures).
pub fn workspace() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../..")
}

/// A fresh folder under the target directory for one test, named after the test binary
/// and `name` so that binaries and tests never share one.
pub fn tempdir(name: &str) -> PathBuf {
    let dir =
        Path::new(env!("CARGO_TARGET_TMPDIR")).join(format!("{}-{name}", env!("CARGO_CRATE_NAME")));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

/// The names of the entries of `dir`, sorted.
pub fn entry_names(dir: &Path) -> Vec<String> {
    let mut names = Vec::new();
    for entry in std::fs::read_dir(dir).unwrap() {
        names.push(entry.unwrap().file_name().to_string_lossy().into_owned());
    }
    names.sort();
    names
}

/// Exit code, standard output and standard error, as one text to snapshot.
pub fn transcript(out: &Output) -> String {
    format!(
        "exit: {}\n--- stdout\n{}--- stderr\n{}",
        out.status
            .code()
            .map_or("signal".to_string(), |c| c.to_string()),
        String::from_utf8_lossy(&out.stdout),
        String::from_utf8_lossy(&out.stderr)
    )
}

/// Runs `cmd` to its end; it must exit 0 (else the test fails with its transcript).
#[track_caller]
pub fn succeeds(cmd: &mut Command) -> Output {
    exits(0, cmd)
}

/// Runs `cmd` to its end; it must exit `code` (else the test fails with its transcript).
#[track_caller]
pub fn exits(code: i32, cmd: &mut Command) -> Output {
    let out = cmd.output().unwrap();
    assert_eq!(out.status.code(), Some(code), "{}", transcript(&out));
    out
}

/// Runs `cmd` to its end; it must exit `code` and say `needle` on standard error.
#[track_caller]
pub fn exits_saying(code: i32, needle: &str, cmd: &mut Command) -> Output {
    let out = exits(code, cmd);
    assert!(stderr_text(&out).contains(needle), "{}", transcript(&out));
    out
}

/// What a run printed on standard output, as text.
pub fn stdout_text(out: &Output) -> String {
    String::from_utf8_lossy(&out.stdout).into_owned()
}

/// What a run printed on standard error, as text.
pub fn stderr_text(out: &Output) -> String {
    String::from_utf8_lossy(&out.stderr).into_owned()
}

/// The number after `prefix` in a log (`Plan cost: N`).
pub fn logged_number(log: &str, prefix: &str) -> Option<u64> {
    log.lines()
        .find_map(|l| l.strip_prefix(prefix))
        .and_then(|rest| rest.split_whitespace().next())
        .and_then(|n| n.parse().ok())
}

/// Simulates the paper's study into `dir`; its 12 recordings, sorted by name (the truth
/// files beside them left out).
pub fn simulated_study(dir: &Path) -> Vec<PathBuf> {
    succeeds(demoplan().args(["simulate", "-o"]).arg(dir));
    let mut recordings: Vec<PathBuf> = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| {
            let name = p.file_name().unwrap().to_string_lossy().into_owned();
            name.ends_with(".jsonl") && !name.ends_with(".truth.jsonl")
        })
        .collect();
    recordings.sort();
    assert_eq!(recordings.len(), 12);
    recordings
}
