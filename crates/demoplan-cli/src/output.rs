//! Writing output files: through the `atomic-write` crate (a temporary file and a rename,
//! never half-written; durable for the operator library), with its errors as exit codes.

use std::io::Write;
use std::path::Path;

use crate::diagnostic::Failure;
use slim::ExitCode;

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
