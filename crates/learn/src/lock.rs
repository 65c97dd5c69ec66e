//! The advisory lock that keeps two learners from writing one library at once
//! (`docs/reliability.md`): held from reading the library to renaming its new content
//! into place, so that writers that read, change and write one file take turns and no
//! count is lost.

use std::fs::{File, OpenOptions, TryLockError};
use std::io::Write;
use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};

/// An advisory lock on `PATH.lock` (an exclusive `flock` on Unix, `LockFileEx` on
/// Windows), held by a writer of `PATH` from reading it until its new content is renamed
/// into place. The lock file holds the holder's pid (for messages); it is left in place
/// when the lock is released, since removing it would let two writers lock two different
/// files. The operating system releases the lock when its holder dies, so a killed writer
/// never blocks the next one.
///
/// The lock belongs to the file, not to the name it was given: it is taken on the
/// target's canonical path ([`resolve_target`]), so a library named through a symlink or
/// a relative path shares one lock with the same library named otherwise, and
/// [`WriteLock::target`] is where the holder reads and writes.
#[derive(Debug)]
pub struct WriteLock {
    _file: File,
    target: PathBuf,
}

/// Why a [`WriteLock`] was not taken.
#[derive(Debug, thiserror::Error)]
pub enum LockError {
    /// The lock file could not be opened or created.
    #[error("cannot write {}: cannot open its lock file {}: {source}", path.display(), lock.display())]
    Open {
        path: PathBuf,
        lock: PathBuf,
        source: std::io::Error,
    },
    /// The operating system refused the lock.
    #[error("cannot write {}: cannot lock {}: {source}", path.display(), lock.display())]
    Lock {
        path: PathBuf,
        lock: PathBuf,
        source: std::io::Error,
    },
    /// Another process still held the lock when the wait ran out.
    #[error(
        "{} is being written by another process{}: its lock {} was still held after {:.1} s",
        path.display(), holder_text(*holder), lock.display(), waited.as_secs_f64()
    )]
    Held {
        path: PathBuf,
        lock: PathBuf,
        /// The holder's pid, as its lock file says.
        holder: Option<u32>,
        waited: Duration,
    },
}

/// Another holder of the lock, met by [`WriteLock::acquire`] before it waits.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Waiting {
    pub path: PathBuf,
    pub lock: PathBuf,
    /// The holder's pid, as its lock file says.
    pub holder: Option<u32>,
}

impl std::fmt::Display for Waiting {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(
            f,
            "waiting for {} to be released: another process{} is writing {}",
            self.lock.display(),
            holder_text(self.holder),
            self.path.display()
        )
    }
}

/// ` (pid N)`, or nothing.
fn holder_text(holder: Option<u32>) -> String {
    holder
        .map(|pid| format!(" (pid {pid})"))
        .unwrap_or_default()
}

/// The lock file of `path`: `PATH.lock`.
pub fn lock_path(path: &Path) -> PathBuf {
    let mut name = path.as_os_str().to_owned();
    name.push(".lock");
    PathBuf::from(name)
}

/// The file a write to `path` lands on: `path` with every symlink resolved and made
/// absolute; for a file that does not exist yet, its folder resolved and its name. A
/// library named through a symlink is written where the link points (the link stays), so
/// every name of one library is one file with one lock. A folder that cannot be resolved
/// (it does not exist) leaves `path` as given, for the write to fail on.
pub fn resolve_target(path: &Path) -> PathBuf {
    if let Ok(real) = std::fs::canonicalize(path) {
        return real;
    }
    let dir = path
        .parent()
        .filter(|d| !d.as_os_str().is_empty())
        .unwrap_or(Path::new("."));
    match (std::fs::canonicalize(dir), path.file_name()) {
        (Ok(dir), Some(name)) => dir.join(name),
        _ => path.to_path_buf(),
    }
}

/// Opens (or creates) the lock file `lock` of `target` for `flock`. A lock file created
/// here gets the target's permission bits, so that whoever may write the library may
/// lock it. A lock file this user may not write (created by another user, or on a
/// read-only file system) is opened read-only: `flock` needs no write access, and the
/// write of the library itself then decides.
fn open_lock_file(lock: &Path, target: &Path) -> std::io::Result<File> {
    match OpenOptions::new()
        .read(true)
        .write(true)
        .create_new(true)
        .open(lock)
    {
        Ok(file) => {
            if let Ok(library) = std::fs::metadata(target) {
                file.set_permissions(library.permissions())?;
            }
            return Ok(file);
        }
        Err(e) if e.kind() == std::io::ErrorKind::AlreadyExists => {}
        Err(e) => return Err(e),
    }
    match OpenOptions::new().read(true).write(true).open(lock) {
        Ok(file) => Ok(file),
        Err(e)
            if matches!(
                e.kind(),
                std::io::ErrorKind::PermissionDenied | std::io::ErrorKind::ReadOnlyFilesystem
            ) =>
        {
            OpenOptions::new().read(true).open(lock)
        }
        Err(e) => Err(e),
    }
}

impl WriteLock {
    /// Takes the lock of `path` (of its canonical path, [`resolve_target`]), waiting at
    /// most `timeout` (`None`: as long as it takes) for another holder; `waiting` hears
    /// once, before the wait, who holds it.
    pub fn acquire(
        path: &Path,
        timeout: Option<Duration>,
        waiting: impl FnOnce(&Waiting),
    ) -> Result<WriteLock, LockError> {
        let target = resolve_target(path);
        let lock = lock_path(&target);
        let file = open_lock_file(&lock, &target).map_err(|source| LockError::Open {
            path: path.to_path_buf(),
            lock: lock.clone(),
            source,
        })?;
        let start = Instant::now();
        let mut waiting = Some(waiting);
        loop {
            match file.try_lock() {
                Ok(()) => break,
                Err(TryLockError::WouldBlock) => {}
                Err(TryLockError::Error(source)) => {
                    return Err(LockError::Lock {
                        path: path.to_path_buf(),
                        lock,
                        source,
                    })
                }
            }
            let waited = start.elapsed();
            if timeout.is_some_and(|t| waited >= t) {
                return Err(LockError::Held {
                    path: path.to_path_buf(),
                    holder: holder(&lock),
                    lock,
                    waited,
                });
            }
            if let Some(tell) = waiting.take() {
                tell(&Waiting {
                    path: path.to_path_buf(),
                    lock: lock.clone(),
                    holder: holder(&lock),
                });
            }
            let pause = Duration::from_millis(20);
            let pause = timeout.map_or(pause, |t| pause.min(t.saturating_sub(waited)));
            std::thread::sleep(pause);
        }
        // For messages only: who holds it. A failure here (a read-only lock file)
        // changes nothing.
        let _ = file
            .set_len(0)
            .and_then(|()| (&file).write_all(format!("{}\n", std::process::id()).as_bytes()));
        Ok(WriteLock {
            _file: file,
            target,
        })
    }

    /// The file the lock guards, by its canonical path: read and write the library
    /// there, so that the lock covers whatever name it was given.
    pub fn target(&self) -> &Path {
        &self.target
    }
}

/// The pid written in a lock file, if any.
fn holder(lock: &Path) -> Option<u32> {
    std::fs::read_to_string(lock)
        .ok()
        .and_then(|t| t.trim().parse::<u32>().ok())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn scratch(name: &str) -> PathBuf {
        let dir = std::env::temp_dir().join(format!("learn-lock-{}-{name}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir_all(&dir).unwrap_or_else(|e| panic!("{e}"));
        dir
    }

    #[test]
    fn a_held_lock_makes_the_next_writer_wait_and_then_give_up() {
        let dir = scratch("held");
        let library = dir.join("lib.json");
        let first = WriteLock::acquire(&library, None, |_| {}).unwrap_or_else(|e| panic!("{e}"));
        assert_eq!(first.target(), resolve_target(&library));
        let mut told = None;
        let second = WriteLock::acquire(&library, Some(Duration::from_millis(50)), |w| {
            told = Some(w.clone())
        });
        let told = told.unwrap_or_else(|| panic!("the waiting writer was not told"));
        assert_eq!(told.holder, Some(std::process::id()));
        assert!(
            told.to_string().contains("lib.json.lock to be released"),
            "{told}"
        );
        match second {
            Err(LockError::Held { holder, lock, .. }) => {
                assert_eq!(holder, Some(std::process::id()));
                assert_eq!(lock, lock_path(&resolve_target(&library)));
            }
            other => panic!("expected Held, got {other:?}"),
        }
        drop(first);
        let third = WriteLock::acquire(&library, Some(Duration::ZERO), |_| {
            panic!("a released lock needs no wait")
        });
        assert!(third.is_ok(), "{third:?}");
        let _ = std::fs::remove_dir_all(&dir);
    }

    #[test]
    fn a_name_through_a_symlink_locks_the_file_it_points_to() {
        let dir = scratch("symlink");
        let real = dir.join("real.json");
        std::fs::write(&real, "{}").unwrap_or_else(|e| panic!("{e}"));
        #[cfg(unix)]
        {
            let link = dir.join("link.json");
            std::os::unix::fs::symlink(&real, &link).unwrap_or_else(|e| panic!("{e}"));
            assert_eq!(resolve_target(&link), resolve_target(&real));
        }
        let missing = dir.join("new.json");
        assert_eq!(resolve_target(&missing).file_name(), missing.file_name());
        assert_eq!(
            lock_path(Path::new("a/b.json")),
            PathBuf::from("a/b.json.lock")
        );
        let _ = std::fs::remove_dir_all(&dir);
    }
}
