//! Opening recordings named on the command line, and rendering their errors: file, line,
//! column, field, with an excerpt of the offending line ([`recording::Excerpt`]).

use std::fs::File;
use std::io::BufReader;
use std::path::Path;

use crate::diagnostic::{render, Failure, LineSource, SourceDiagnostic};
use slim::ExitCode;

/// Read buffer for re-reading a recording's offending line.
const BUFFER: usize = 1 << 20;

/// What a file on the command line holds, by its content ([`import::SourceKind::of`]). A
/// missing file or a folder that is no bag is a command line error (36).
pub fn source_kind(path: &Path) -> Result<import::SourceKind, Failure> {
    import::SourceKind::of(path).map_err(|e| open_failure(path, e))
}

/// The mapping for a source of `format`: the `--mapping` file over the format's
/// defaults, or the defaults alone. A malformed file is an input error (31) naming its
/// line and key.
pub fn mapping(path: Option<&Path>, format: import::Format) -> Result<import::Mapping, Failure> {
    let Some(path) = path else {
        return Ok(import::Mapping::default_for(format));
    };
    let text = crate::input::read_text(path)?;
    import::Mapping::from_toml(&text, format).map_err(|e| {
        let message = if e.key.is_empty() {
            e.message.clone()
        } else {
            format!("key `{}`: {}", e.key, e.message)
        };
        crate::commands::demo_input::text_failure(
            path,
            &text,
            "import::mapping",
            e.line,
            e.column,
            &e.key,
            &message,
        )
    })
}

/// The failure for an import error of the source at `path`: an input error (31) naming
/// the file, the place in it, the entity and the field.
pub fn import_failure(path: &Path, error: &import::ImportError) -> Failure {
    match error {
        import::ImportError::Input(e) => {
            Failure::plain(ExitCode::INPUT_ERROR, format!("{}: {e}", path.display()))
        }
        import::ImportError::Io(e) => Failure::plain(
            ExitCode::USAGE,
            format!("cannot read {}: {e}", path.display()),
        ),
        import::ImportError::Write(e) => Failure::plain(
            ExitCode::CRITICAL_ERROR,
            format!("cannot write the recording of {}: {e}", path.display()),
        ),
    }
}

/// Opens a recording and reads its header ([`import::open_recording`]): a Unity log or a
/// bag is imported into memory first, with the `--mapping` file (read only for such a
/// source) or the format's defaults. A missing file is a command line error (36); a
/// malformed header, source or mapping an input error (31).
pub fn open(path: &Path, mapping_file: Option<&Path>) -> Result<import::RecordingReader, Failure> {
    let kind = source_kind(path)?;
    let mapping = match kind.format() {
        Some(format) => Some(mapping(mapping_file, format)?),
        None => None,
    };
    import::open_recording(path, kind, mapping.as_ref()).map_err(|e| open_failure(path, e))
}

/// The failure for a recording that could not be opened.
pub fn open_failure(path: &Path, error: import::OpenError) -> Failure {
    match error {
        import::OpenError::Folder(_) | import::OpenError::Read { .. } => {
            Failure::plain(ExitCode::USAGE, error.to_string())
        }
        import::OpenError::Import(e) => import_failure(path, &e),
        import::OpenError::Recording(e) => recording_failure(path, &e),
    }
}

/// The failure for an error reading the recording at `path`.
pub fn recording_failure(path: &Path, error: &recording::ReadError) -> Failure {
    if let recording::ErrorKind::Io(e) = &error.kind {
        return Failure::plain(
            ExitCode::USAGE,
            format!("cannot read {} (line {}): {e}", path.display(), error.line),
        );
    }
    let line = File::open(path)
        .map(|f| recording::offending_line(BufReader::with_capacity(BUFFER, f), error.line))
        .unwrap_or_default();
    let shown = error.excerpt(&line);
    let diagnostic = SourceDiagnostic {
        code: format!("recording::{}", error.kind.code()),
        message: shown.message,
        label: shown.label,
        help: error.kind.help().map(str::to_string),
        span: (shown.offset, shown.width).into(),
        source: LineSource {
            name: path.display().to_string(),
            line: error.line.saturating_sub(1) as usize,
            text: shown.text,
        },
    };
    Failure {
        code: ExitCode::INPUT_ERROR,
        text: render(&diagnostic),
    }
}
