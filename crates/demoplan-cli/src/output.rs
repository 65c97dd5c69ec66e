//! Writing output files: through the `atomic-write` crate (a temporary file and a rename,
//! never half-written; durable for the operator library), with its errors as exit codes.
//!
//! [`WriteLock`] is the advisory lock that keeps two learners from writing one library at
//! once (`docs/reliability.md`).

use std::fs::{File, OpenOptions, TryLockError};
use std::io::Write;
use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};

use crate::diagnostic::Failure;
use crate::exit::ExitCode;

/// Writes `text` to standard output (or the writer standing for it). A reader that
/// stopped early (`| head`) is no error: exit 141, quietly, as a shell shows for SIGPIPE
/// (`Failure::output_closed`); any other failure to write is an I/O error (35) with its
/// message.
pub fn print(out: &mut impl Write, text: &str) -> Result<(), Failure> {
    out.write_all(text.as_bytes())
        .map_err(|e| stdout_failure(&e))
}

/// The failure for an error writing standard output: see [`print`].
pub fn stdout_failure(e: &std::io::Error) -> Failure {
    if e.kind() == std::io::ErrorKind::BrokenPipe {
        Failure::output_closed()
    } else {
        Failure::plain(
            ExitCode::CRITICAL_ERROR,
            format!("cannot write to standard output: {e}"),
        )
    }
}

/// Writes through a temporary file in the same folder and a rename, so that a killed
/// process never leaves a half-written file ([`atomic_write::write_atomically`]).
pub fn write_atomically(path: &Path, text: &str) -> Result<(), Failure> {
    atomic_write::write_atomically(path, text).map_err(write_failure)
}

/// Like [`write_atomically`], and durable ([`atomic_write::write_durably`]): after a power
/// loss the path holds the old or the new content too.
pub fn write_durably(path: &Path, text: &str) -> Result<(), Failure> {
    atomic_write::write_durably(path, text).map_err(write_failure)
}

/// Like [`write_atomically`], for output produced piece by piece
/// ([`atomic_write::write_atomically_with`]).
pub fn write_atomically_with(
    path: &Path,
    produce: impl FnOnce(&mut dyn Write) -> std::io::Result<()>,
) -> Result<(), Failure> {
    atomic_write::write_atomically_with(path, produce).map_err(write_failure)
}

/// A file that could not be written: an I/O error (35) naming it.
fn write_failure(e: atomic_write::WriteError) -> Failure {
    Failure::plain(ExitCode::CRITICAL_ERROR, e.to_string())
}

pub use atomic_write::remove_stale_temporaries;

/// An advisory lock on `PATH.lock` (an exclusive `flock` on Unix, `LockFileEx` on
/// Windows), held by a writer of `PATH` from reading it until its new content is renamed
/// into place, so that writers that read, change and write one file take turns and no
/// update is lost. The lock file holds the holder's pid (for messages); it is left in
/// place when the lock is released, since removing it would let two writers lock two
/// different files. The operating system releases the lock when its holder dies, so a
/// killed writer never blocks the next one.
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
    /// most `timeout` (`None`: as long as it takes) for another holder. A lock still held
    /// after the wait is [`ExitCode::LOCKED`], with a message naming the lock file and
    /// the holder's pid.
    pub fn acquire(path: &Path, timeout: Option<Duration>) -> Result<WriteLock, Failure> {
        let target = resolve_target(path);
        let lock = lock_path(&target);
        let file = open_lock_file(&lock, &target).map_err(|e| {
            Failure::plain(
                ExitCode::CRITICAL_ERROR,
                format!(
                    "cannot write {}: cannot open its lock file {}: {e}",
                    path.display(),
                    lock.display()
                ),
            )
        })?;
        let start = Instant::now();
        let mut told = false;
        loop {
            match file.try_lock() {
                Ok(()) => break,
                Err(TryLockError::WouldBlock) => {}
                Err(TryLockError::Error(e)) => {
                    return Err(Failure::plain(
                        ExitCode::CRITICAL_ERROR,
                        format!(
                            "cannot write {}: cannot lock {}: {e}",
                            path.display(),
                            lock.display()
                        ),
                    ))
                }
            }
            let waited = start.elapsed();
            if timeout.is_some_and(|t| waited >= t) {
                return Err(Failure::plain(
                    ExitCode::LOCKED,
                    format!(
                        "{} is being written by another process{}: its lock {} was still \
                         held after {:.1} s; try again later or with a longer \
                         --lock-timeout (a lock is held by a running process only, and \
                         released when it ends)",
                        path.display(),
                        holder(&lock),
                        lock.display(),
                        waited.as_secs_f64()
                    ),
                ));
            }
            if !told {
                eprintln!(
                    "waiting for {} to be released: another process{} is writing {}",
                    lock.display(),
                    holder(&lock),
                    path.display()
                );
                told = true;
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

/// ` (pid N)` as written in a lock file, or nothing.
fn holder(lock: &Path) -> String {
    std::fs::read_to_string(lock)
        .ok()
        .and_then(|t| t.trim().parse::<u32>().ok())
        .map(|pid| format!(" (pid {pid})"))
        .unwrap_or_default()
}
