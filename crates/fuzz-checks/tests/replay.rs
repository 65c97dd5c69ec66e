//! Every input that ever crashed a fuzz target, replayed as an ordinary test: the files
//! of `fuzz/regressions/TARGET/` (one folder per target of `fuzz_checks::TARGETS`) run
//! through the target's check, which must not panic. A crash found by fuzzing is fixed,
//! then its input (minimised with `cargo fuzz tmin`) is committed there; the file's name
//! says what it found.

#![allow(clippy::unwrap_used, clippy::expect_used)] // tests fail loudly by design

use std::path::{Path, PathBuf};

fn regressions() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../../fuzz/regressions")
}

#[test]
fn every_input_that_ever_crashed_a_fuzz_target_is_handled() {
    let mut folders: Vec<PathBuf> = std::fs::read_dir(regressions())
        .unwrap()
        .map(|e| e.unwrap().path())
        .collect();
    folders.sort();
    let mut replayed = 0;
    let mut failures = Vec::new();
    for folder in &folders {
        let target = folder.file_name().unwrap().to_string_lossy().into_owned();
        assert!(
            fuzz_checks::TARGETS.iter().any(|(n, _)| *n == target),
            "fuzz/regressions/{target} is no fuzz target"
        );
        let mut inputs: Vec<PathBuf> = std::fs::read_dir(folder)
            .unwrap()
            .map(|e| e.unwrap().path())
            .collect();
        inputs.sort();
        for input in inputs {
            let data = std::fs::read(&input).unwrap();
            let name = format!("{target}/{}", input.file_name().unwrap().to_string_lossy());
            if std::panic::catch_unwind(|| fuzz_checks::check(&target, &data)).is_err() {
                failures.push(name);
            }
            replayed += 1;
        }
    }
    assert!(replayed > 0, "no regression inputs found");
    assert!(failures.is_empty(), "crashed again: {failures:?}");
}

/// Every target has a committed corpus to start from (its seeds, `fuzz/corpus-seeds`,
/// and what earlier runs found, `fuzz/corpus`), which the CI's fuzz smoke starts from,
/// and its cargo-fuzz target.
#[test]
fn every_target_has_a_committed_corpus() {
    let fuzz = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../fuzz");
    let inputs = |folder: &Path| std::fs::read_dir(folder).map_or(0, |d| d.count());
    for (target, _) in fuzz_checks::TARGETS {
        let count = inputs(&fuzz.join("corpus-seeds").join(target))
            + inputs(&fuzz.join("corpus").join(target));
        assert!(count > 0, "{target} has no committed inputs to start from");
        assert!(
            fuzz.join("fuzz_targets")
                .join(format!("{target}.rs"))
                .is_file(),
            "fuzz/fuzz_targets/{target}.rs is missing"
        );
    }
}
