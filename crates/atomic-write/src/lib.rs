//! Writing output files so that they are never half-written.
//!
//! Every file is written to a temporary file in the same folder (`.NAME.demoplan-tmp-PID`)
//! and renamed over its target, so a process killed at any moment leaves either the old
//! file or the new one: the rename is atomic. That guarantee is about the process; against
//! a power loss or a kernel crash the data must also reach the disk before the rename,
//! which only [`write_durably`] (the operator library) pays for with `fsync` of the file
//! and of its folder. Other outputs (plans, figures, recordings, experiment results) can
//! be made again and skip the `fsync`s.
//!
//! The crate does only this: it never prints, and locking a file against other writers
//! is the caller's (`learn::WriteLock`, for the operator library).
//!
//! ```
//! let dir = std::env::temp_dir().join(format!("atomic-write-doc-{}", std::process::id()));
//! std::fs::create_dir_all(&dir)?;
//! let path = dir.join("plan");
//! atomic_write::write_atomically(&path, "(a o)\n")?;
//! assert_eq!(std::fs::read_to_string(&path)?, "(a o)\n");
//! # std::fs::remove_dir_all(&dir)?;
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

use std::fs::File;
use std::io::Write;
use std::path::{Path, PathBuf};

/// A file that could not be written; the target is unchanged and no temporary file is
/// left behind. The message says which: `cannot write PATH: WHAT; it is unchanged` when
/// there was a file, `...; nothing was written` when there was none.
#[derive(Debug, thiserror::Error)]
#[error("cannot write {}: {source}; {}", path.display(), if *replaced { "it is unchanged" } else { "nothing was written" })]
pub struct WriteError {
    /// The file that was to be written.
    pub path: PathBuf,
    /// What failed.
    #[source]
    pub source: std::io::Error,
    /// Whether a file was there to replace (and so is still there, unchanged).
    pub replaced: bool,
}

/// Writes `contents` through a temporary file in the same folder and a rename, so that a
/// killed process never leaves a half-written file.
pub fn write_atomically(path: &Path, contents: impl AsRef<[u8]>) -> Result<(), WriteError> {
    write_via_temporary(path, false, |out| out.write_all(contents.as_ref()))
}

/// Like [`write_atomically`], and durable: the temporary file is flushed to the disk
/// (`fsync`) before the rename and the folder after it, so that after a power loss the
/// path holds the old or the new content too.
pub fn write_durably(path: &Path, contents: impl AsRef<[u8]>) -> Result<(), WriteError> {
    write_via_temporary(path, true, |out| out.write_all(contents.as_ref()))
}

/// Like [`write_atomically`], for output produced piece by piece: `produce` writes into a
/// buffered temporary file that replaces `path` only once all of it is written. An error
/// from `produce` leaves `path` as it was.
pub fn write_atomically_with(
    path: &Path,
    produce: impl FnOnce(&mut dyn Write) -> std::io::Result<()>,
) -> Result<(), WriteError> {
    write_via_temporary(path, false, produce)
}

/// The folder of `path` and its file name.
fn folder_and_name(path: &Path) -> (&Path, String) {
    let dir = path
        .parent()
        .filter(|d| !d.as_os_str().is_empty())
        .unwrap_or(Path::new("."));
    let name = path
        .file_name()
        .map(|n| n.to_string_lossy().into_owned())
        .unwrap_or_default();
    (dir, name)
}

/// The prefix of the temporary files of writers of `path`, before the writer's pid.
fn temporary_prefix(name: &str) -> String {
    format!(".{name}.demoplan-tmp-")
}

fn write_via_temporary(
    path: &Path,
    durable: bool,
    produce: impl FnOnce(&mut dyn Write) -> std::io::Result<()>,
) -> Result<(), WriteError> {
    let (dir, name) = folder_and_name(path);
    let tmp = dir.join(format!("{}{}", temporary_prefix(&name), std::process::id()));
    // The file replaced keeps its permission bits (a group-writable library stays so).
    let replaced = std::fs::metadata(path).ok().filter(|m| m.is_file());
    let fail = |source: std::io::Error| {
        let _ = std::fs::remove_file(&tmp);
        WriteError {
            path: path.to_path_buf(),
            source,
            replaced: replaced.is_some(),
        }
    };
    let file = File::create(&tmp).map_err(fail)?;
    if let Some(old) = &replaced {
        file.set_permissions(old.permissions()).map_err(fail)?;
    }
    let mut out = std::io::BufWriter::with_capacity(1 << 20, file);
    produce(&mut out).map_err(fail)?;
    let file = out.into_inner().map_err(|e| fail(e.into_error()))?;
    if durable {
        file.sync_all().map_err(fail)?;
    }
    drop(file);
    std::fs::rename(&tmp, path).map_err(fail)?;
    if durable {
        sync_folder(dir);
    }
    Ok(())
}

/// Makes a rename in `dir` durable. Best effort: some systems cannot open or sync a
/// folder, and the file is in place either way.
fn sync_folder(dir: &Path) {
    if cfg!(unix) {
        if let Ok(d) = File::open(dir) {
            let _ = d.sync_all();
        }
    }
}

/// Removes the temporary files that writers of `path` killed before their rename left
/// behind (`.NAME.demoplan-tmp-PID`). They never damage anything (each writer uses its own
/// name and removes it on failure), they only take space. Call it only while no other
/// process writes `path` (the command line holds the library's lock): every other writer
/// of `path` holds that lock while its temporary file exists, so those found then are
/// stale. Returns how many were removed.
pub fn remove_stale_temporaries(path: &Path) -> usize {
    let (dir, name) = folder_and_name(path);
    let prefix = temporary_prefix(&name);
    let own = std::process::id().to_string();
    let Ok(entries) = std::fs::read_dir(dir) else {
        return 0;
    };
    let mut removed = 0;
    for entry in entries.flatten() {
        let file_name = entry.file_name();
        let Some(pid) = file_name.to_str().and_then(|n| n.strip_prefix(&prefix)) else {
            continue;
        };
        if pid.is_empty() || !pid.bytes().all(|b| b.is_ascii_digit()) || pid == own {
            continue;
        }
        if std::fs::remove_file(entry.path()).is_ok() {
            removed += 1;
        }
    }
    removed
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used, clippy::expect_used)]

    use super::*;

    /// A fresh folder for one test.
    fn folder(test: &str) -> PathBuf {
        let dir = std::env::temp_dir().join(format!("atomic-write-{test}-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir_all(&dir).unwrap();
        dir
    }

    fn entries(dir: &Path) -> Vec<String> {
        let mut names: Vec<String> = std::fs::read_dir(dir)
            .unwrap()
            .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
            .collect();
        names.sort();
        names
    }

    #[test]
    fn writes_replace_the_file_and_leave_nothing_else() {
        let dir = folder("replace");
        let path = dir.join("out.txt");
        write_atomically(&path, "old").unwrap();
        write_durably(&path, b"newer").unwrap();
        assert_eq!(std::fs::read_to_string(&path).unwrap(), "newer");
        write_atomically_with(&path, |w| {
            w.write_all(b"piece ")?;
            w.write_all(b"by piece")
        })
        .unwrap();
        assert_eq!(std::fs::read_to_string(&path).unwrap(), "piece by piece");
        assert_eq!(entries(&dir), ["out.txt"]);
        std::fs::remove_dir_all(&dir).unwrap();
    }

    #[test]
    fn a_failed_write_keeps_the_old_file_and_names_the_path() {
        let dir = folder("fail");
        let path = dir.join("out.txt");
        write_atomically(&path, "old").unwrap();
        let e = write_atomically_with(&path, |w| {
            w.write_all(b"half")?;
            Err(std::io::Error::other("disk full"))
        })
        .unwrap_err();
        assert_eq!(
            e.to_string(),
            format!(
                "cannot write {}: disk full; it is unchanged",
                path.display()
            )
        );
        assert_eq!(std::fs::read_to_string(&path).unwrap(), "old");
        assert_eq!(entries(&dir), ["out.txt"]);
        // A folder that does not exist: the error names the target.
        let missing = dir.join("no-such-folder").join("out.txt");
        let e = write_atomically(&missing, "x").unwrap_err();
        assert_eq!(e.path, missing);
        assert!(e.to_string().ends_with("; nothing was written"), "{e}");
        std::fs::remove_dir_all(&dir).unwrap();
    }

    #[test]
    #[cfg(unix)]
    fn a_replaced_file_keeps_its_permission_bits() {
        use std::os::unix::fs::PermissionsExt;
        let dir = folder("permissions");
        let path = dir.join("library.json");
        write_atomically(&path, "{}").unwrap();
        std::fs::set_permissions(&path, std::fs::Permissions::from_mode(0o664)).unwrap();
        write_durably(&path, "{\"v\": 2}").unwrap();
        let mode = std::fs::metadata(&path).unwrap().permissions().mode();
        assert_eq!(mode & 0o777, 0o664);
        std::fs::remove_dir_all(&dir).unwrap();
    }

    #[test]
    fn stale_temporaries_of_other_writers_are_removed() {
        let dir = folder("stale");
        let path = dir.join("library.json");
        write_atomically(&path, "{}").unwrap();
        std::fs::write(dir.join(".library.json.demoplan-tmp-999999999"), "half").unwrap();
        std::fs::write(dir.join(".library.json.demoplan-tmp-x1"), "not ours").unwrap();
        std::fs::write(dir.join(".other.json.demoplan-tmp-12"), "another file's").unwrap();
        assert_eq!(remove_stale_temporaries(&path), 1);
        assert_eq!(
            entries(&dir),
            [
                ".library.json.demoplan-tmp-x1",
                ".other.json.demoplan-tmp-12",
                "library.json"
            ]
        );
        std::fs::remove_dir_all(&dir).unwrap();
    }
}
