//! Turning library errors into what the terminal shows: file, line, column, an underline.

use miette::{
    Diagnostic, GraphicalReportHandler, GraphicalTheme, LabeledSpan, MietteError, NamedSource,
    SourceCode, SourceSpan, SpanContents,
};
use std::fmt;
use std::path::Path;

use slim::ExitCode;

/// A failed command: what to print on standard error, and the exit code.
#[derive(Debug)]
pub struct Failure {
    /// The exit code.
    pub code: ExitCode,
    /// The rendered message, ending in a newline.
    pub text: String,
}

impl Failure {
    /// A one-line message with no source to show.
    pub fn plain(code: ExitCode, message: impl fmt::Display) -> Failure {
        Failure {
            code,
            text: format!("error: {message}\n"),
        }
    }

    /// The reader of standard output closed it early (`| head`): exit 141 and print
    /// nothing, as a program killed by SIGPIPE does.
    pub fn output_closed() -> Failure {
        Failure {
            code: ExitCode::OUTPUT_CLOSED,
            text: String::new(),
        }
    }

    /// An error in a PDDL file, rendered with the source line and an underline.
    pub fn pddl(path: &Path, source: &str, error: &pddl::PddlError) -> Failure {
        let (code, exit) = match error.kind {
            pddl::ErrorKind::Syntax => ("pddl::syntax", ExitCode::INPUT_ERROR),
            pddl::ErrorKind::Semantic => ("pddl::semantic", ExitCode::INPUT_ERROR),
            pddl::ErrorKind::Unsupported => ("pddl::unsupported", ExitCode::UNSUPPORTED),
        };
        let diagnostic = SourceDiagnostic {
            message: error.message.clone(),
            code: code.to_string(),
            help: error.help.clone(),
            label: error.label.clone(),
            span: (error.span.start as usize, error.span.len()).into(),
            source: NamedSource::new(path.display().to_string(), source.to_string()),
        };
        Failure {
            code: exit,
            text: render(&diagnostic),
        }
    }
}

/// A message about a span of a source text, rendered with the line and an underline:
/// the whole text of a file ([`NamedSource`]), or one line of a recording
/// ([`LineSource`]).
#[derive(Debug)]
pub(crate) struct SourceDiagnostic<S = NamedSource<String>> {
    pub(crate) message: String,
    pub(crate) code: String,
    pub(crate) help: Option<String>,
    pub(crate) label: String,
    pub(crate) span: SourceSpan,
    pub(crate) source: S,
}

impl<S> fmt::Display for SourceDiagnostic<S> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.message)
    }
}

impl<S: fmt::Debug> std::error::Error for SourceDiagnostic<S> {}

impl<S: SourceCode + fmt::Debug> Diagnostic for SourceDiagnostic<S> {
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

/// One line of a file, shown with its real line number: a recording's line is all
/// of it that is kept for its error.
#[derive(Debug)]
pub(crate) struct LineSource {
    pub(crate) name: String,
    /// 0-based line number.
    pub(crate) line: usize,
    pub(crate) text: String,
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

/// Renders without colour unless standard error is a terminal and `NO_COLOR` is unset,
/// at a fixed width, so that output in files and tests is stable.
pub(crate) fn render(diagnostic: &dyn Diagnostic) -> String {
    use std::io::IsTerminal;
    let colour = std::io::stderr().is_terminal() && std::env::var_os("NO_COLOR").is_none();
    let theme = if colour {
        GraphicalTheme::unicode()
    } else {
        GraphicalTheme::unicode_nocolor()
    };
    let handler = GraphicalReportHandler::new_themed(theme)
        .with_width(100)
        .with_context_lines(1);
    let mut out = String::new();
    if handler.render_report(&mut out, diagnostic).is_err() {
        out = format!("error: {diagnostic}");
    }
    if !out.ends_with('\n') {
        out.push('\n');
    }
    out
}
