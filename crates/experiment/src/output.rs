//! Writing the experiment's files: through a temporary file and a rename
//! (`atomic-write`), so that a killed run leaves the old file or the new one, never half
//! of one.

use std::path::Path;

use crate::ExperimentError;

pub(crate) fn io_error(path: &Path, e: std::io::Error) -> ExperimentError {
    ExperimentError::Io {
        path: path.to_path_buf(),
        message: e.to_string(),
    }
}

pub(crate) fn create_dir(path: &Path) -> Result<(), ExperimentError> {
    std::fs::create_dir_all(path).map_err(|e| io_error(path, e))
}

/// Writes `figure`'s PNG to `path` (as [`write_file`]); a figure that cannot be rendered
/// is an error naming the file.
pub(crate) fn write_png(path: &Path, figure: &report::Figure) -> Result<(), ExperimentError> {
    let png = figure.png().map_err(|e| ExperimentError::Io {
        path: path.to_path_buf(),
        message: e.to_string(),
    })?;
    write_file(path, &png)
}

/// Writes `bytes` through a temporary file beside `path` and a rename
/// ([`atomic_write::write_atomically`]).
pub(crate) fn write_file(path: &Path, bytes: &[u8]) -> Result<(), ExperimentError> {
    atomic_write::write_atomically(path, bytes).map_err(|e| io_error(path, e.source))
}

pub(crate) fn write_text(path: &Path, text: &str) -> Result<(), ExperimentError> {
    write_file(path, text.as_bytes())
}

/// Cores, memory and system, from /proc where there is one.
pub(crate) fn machine() -> String {
    let cores = std::thread::available_parallelism().map_or(0, |n| n.get());
    let memory = std::fs::read_to_string("/proc/meminfo")
        .ok()
        .and_then(|m| {
            m.lines()
                .find(|l| l.starts_with("MemTotal:"))
                .and_then(|l| l.split_whitespace().nth(1))
                .and_then(|kb| kb.parse::<u64>().ok())
        })
        .map_or(String::new(), |kb| {
            format!(", {:.0} GB", kb as f64 / 1024.0 / 1024.0)
        });
    format!(
        "{cores} cores{memory}, {} {}",
        std::env::consts::OS,
        std::env::consts::ARCH
    )
}

/// A CSV field: quoted when it holds a comma, quote or newline.
pub(crate) fn csv_field(text: &str) -> String {
    if text.contains([',', '"', '\n']) {
        format!("\"{}\"", text.replace('"', "\"\""))
    } else {
        text.to_string()
    }
}

/// The condition columns `results.csv`, `runs.csv` and `ratios.csv` share, after the seed
/// (which `ratios.csv`, a distribution over seeds, leaves out): participants,
/// per_participant, params, hands, height, towers, distractors, cubes, activities,
/// keep_without_effects, generalised.
pub(crate) fn condition_fields(c: &crate::cell::Conditions) -> String {
    format!(
        "{},{},{},{},{},{},{},{},{},{},{}",
        c.participants,
        c.per_participant,
        csv_field(&c.params),
        c.hands,
        c.height,
        c.towers,
        c.distractors,
        c.cubes(),
        c.activities,
        c.keep_without_effects,
        c.generalised,
    )
}

pub(crate) fn opt<T: ToString>(v: Option<T>) -> String {
    v.map_or(String::new(), |v| v.to_string())
}
