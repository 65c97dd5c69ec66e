//! Writing output files.

use std::path::Path;

use crate::diagnostic::Failure;
use crate::exit::ExitCode;

/// Writes through a temporary file in the same folder and a rename, so that a crash never
/// leaves a half-written file.
pub fn write_atomically(path: &Path, text: &str) -> Result<(), Failure> {
    write_atomically_with(path, |out| out.write_all(text.as_bytes()))
}

/// Like [`write_atomically`], for output produced piece by piece: `produce` writes into a
/// buffered temporary file that replaces `path` only once all of it is written.
pub fn write_atomically_with(
    path: &Path,
    produce: impl FnOnce(&mut dyn std::io::Write) -> std::io::Result<()>,
) -> Result<(), Failure> {
    use std::io::Write;
    let dir = path
        .parent()
        .filter(|d| !d.as_os_str().is_empty())
        .unwrap_or(Path::new("."));
    let name = path
        .file_name()
        .map(|n| n.to_string_lossy().into_owned())
        .unwrap_or_default();
    let tmp = dir.join(format!(".{name}.demoplan-tmp-{}", std::process::id()));
    let fail = |e: std::io::Error| {
        let _ = std::fs::remove_file(&tmp);
        Failure::plain(
            ExitCode::CRITICAL_ERROR,
            format!("cannot write {}: {e}", path.display()),
        )
    };
    let file = std::fs::File::create(&tmp).map_err(fail)?;
    let mut out = std::io::BufWriter::with_capacity(1 << 20, file);
    produce(&mut out).map_err(fail)?;
    out.flush().map_err(fail)?;
    drop(out);
    std::fs::rename(&tmp, path).map_err(fail)
}
