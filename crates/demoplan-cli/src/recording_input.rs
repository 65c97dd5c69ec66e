//! Opening recordings named on the command line, and rendering their errors: file, line,
//! column, field, with an excerpt of the offending line (long lines are cut around the
//! error, since a frame line can be a kilobyte).

use std::fmt;
use std::fs::File;
use std::io::{BufRead, BufReader, Read};
use std::path::Path;

use miette::{Diagnostic, LabeledSpan, MietteError, SourceCode, SourceSpan, SpanContents};

use crate::diagnostic::{render, Failure};
use crate::exit::ExitCode;

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
    let line = read_line(path, error.line).unwrap_or_default();
    let (text, mut offset) = excerpt(&line, error.column.saturating_sub(1) as usize);
    let mut width = (error.width as usize).min(text.len().saturating_sub(offset));
    if width == 0 && offset >= text.len() {
        // At the end of the line (a truncated line): point at its last character.
        if let Some(c) = text.chars().next_back() {
            offset = text.len() - c.len_utf8();
            width = c.len_utf8();
        }
    }
    let mut message = error.kind.to_string();
    if text.is_empty() && !error.field.is_empty() {
        // No line to underline (an empty file): name the field in the message.
        message.push_str(&format!(" (field `{}`)", error.field));
    }
    let diagnostic = RecordingDiagnostic {
        code: format!("recording::{}", error.kind.code()),
        message,
        label: if error.field.is_empty() {
            "the whole line (no field: not a JSON object of the format)".to_string()
        } else {
            format!("field `{}`", error.field)
        },
        help: error.kind.help().map(str::to_string),
        span: (offset, width).into(),
        source: LineSource {
            name: path.display().to_string(),
            line: error.line.saturating_sub(1) as usize,
            text,
        },
    };
    Failure {
        code: ExitCode::INPUT_ERROR,
        text: render(&diagnostic),
    }
}

/// Line `n` (1-based) of the file, without its line ending; empty if there is none.
fn read_line(path: &Path, n: u64) -> Option<String> {
    let mut input = BufReader::with_capacity(BUFFER, File::open(path).ok()?);
    let mut buf = Vec::new();
    for _ in 0..n {
        buf.clear();
        // No more than the reader takes: a line it refused as too long is shown cut.
        let most = recording::MAX_LINE_BYTES as u64 + 2;
        if (&mut input).take(most).read_until(b'\n', &mut buf).ok()? == 0 {
            return Some(String::new());
        }
    }
    while matches!(buf.last(), Some(b'\n' | b'\r')) {
        buf.pop();
    }
    Some(String::from_utf8_lossy(&buf).into_owned())
}

/// At most about 100 characters of `line` around byte `at`, with `…` where it is cut;
/// returns the excerpt and where `at` is in it.
fn excerpt(line: &str, at: usize) -> (String, usize) {
    const BEFORE: usize = 50;
    const AFTER: usize = 50;
    if line.len() <= BEFORE + AFTER + 20 {
        return (line.to_string(), at.min(line.len()));
    }
    let mut start = at.saturating_sub(BEFORE).min(line.len());
    while !line.is_char_boundary(start) {
        start -= 1;
    }
    let mut end = (at + AFTER).min(line.len());
    while !line.is_char_boundary(end) {
        end += 1;
    }
    let mut text = String::new();
    if start > 0 {
        text.push('…');
    }
    let offset = text.len() + at.min(line.len()) - start;
    text.push_str(&line[start..end]);
    if end < line.len() {
        text.push('…');
    }
    (text, offset)
}

/// One line of a file, shown with its real line number.
#[derive(Debug)]
struct LineSource {
    name: String,
    /// 0-based line number.
    line: usize,
    text: String,
}

impl SourceCode for LineSource {
    fn read_span<'a>(
        &'a self,
        span: &SourceSpan,
        before: usize,
        after: usize,
    ) -> Result<Box<dyn SpanContents<'a> + 'a>, MietteError> {
        let inner = self.text.as_str().read_span(span, before, after)?;
        Ok(Box::new(miette::MietteSpanContents::new_named(
            self.name.clone(),
            inner.data(),
            *inner.span(),
            inner.line() + self.line,
            inner.column(),
            inner.line_count(),
        )))
    }
}

#[derive(Debug)]
struct RecordingDiagnostic {
    code: String,
    message: String,
    label: String,
    help: Option<String>,
    span: SourceSpan,
    source: LineSource,
}

impl fmt::Display for RecordingDiagnostic {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.message)
    }
}

impl std::error::Error for RecordingDiagnostic {}

impl Diagnostic for RecordingDiagnostic {
    fn code<'a>(&'a self) -> Option<Box<dyn fmt::Display + 'a>> {
        Some(Box::new(&self.code))
    }

    fn help<'a>(&'a self) -> Option<Box<dyn fmt::Display + 'a>> {
        self.help
            .as_ref()
            .map(|h| Box::new(h) as Box<dyn fmt::Display>)
    }

    fn source_code(&self) -> Option<&dyn SourceCode> {
        Some(&self.source)
    }

    fn labels(&self) -> Option<Box<dyn Iterator<Item = LabeledSpan> + '_>> {
        Some(Box::new(std::iter::once(LabeledSpan::new_with_span(
            Some(self.label.clone()),
            self.span,
        ))))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn long_lines_are_cut_around_the_error() {
        let line = "x".repeat(500);
        let (text, at) = excerpt(&line, 300);
        assert!(text.starts_with('…') && text.ends_with('…'));
        assert_eq!(&text[at..at + 1], "x");
        assert!(text.chars().count() < 110);
        let (short, at) = excerpt("{\"t\":1}", 5);
        assert_eq!((short.as_str(), at), ("{\"t\":1}", 5));
    }
}
