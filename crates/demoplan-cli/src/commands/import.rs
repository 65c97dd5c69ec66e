//! `demoplan import SOURCE... [--mapping FILE] -o DIR`: real recordings (Unity VR logs)
//! to native recordings `DIR/STEM.jsonl`, with a report per file and the mapping used.

use std::collections::BTreeMap;
use std::fmt::Write as _;
use std::io::{IsTerminal, Read, Write};
use std::path::{Path, PathBuf};

use crate::diagnostic::Failure;
use crate::exit::ExitCode;
use crate::output;
use crate::recording_input::{self, SourceKind};

pub struct ImportArgs {
    pub sources: Vec<PathBuf>,
    pub mapping: Option<PathBuf>,
    pub out: PathBuf,
    pub peak_heap: bool,
}

/// Sources this large show progress on a terminal.
const PROGRESS_FROM: u64 = 16 << 20;

pub fn run(args: ImportArgs) -> Result<ExitCode, Failure> {
    // Every output name first: a clash writes nothing.
    let mut outputs: BTreeMap<PathBuf, &Path> = BTreeMap::new();
    let mut plan = Vec::new();
    for source in &args.sources {
        let kind = recording_input::source_kind(source)?;
        if kind != SourceKind::Unity {
            return Err(Failure::plain(
                ExitCode::INPUT_ERROR,
                format!(
                    "{}: not a source import reads (a Unity playback log: a JSON object with \
                     `playbackTimestepMilliseconds` and `log`)",
                    source.display()
                ),
            ));
        }
        let stem = source
            .file_stem()
            .map(|s| s.to_string_lossy().into_owned())
            .unwrap_or_default();
        let out = args.out.join(format!("{stem}.jsonl"));
        if let Some(other) = outputs.insert(out.clone(), source) {
            return Err(Failure::plain(
                ExitCode::USAGE,
                format!(
                    "{} and {} would both be written to {}: import them into different \
                     folders (nothing was written)",
                    other.display(),
                    source.display(),
                    out.display()
                ),
            ));
        }
        plan.push((source, stem, out));
    }
    let mapping = recording_input::mapping(args.mapping.as_deref(), import::Format::Unity)?;
    std::fs::create_dir_all(&args.out).map_err(|e| {
        Failure::plain(
            ExitCode::CRITICAL_ERROR,
            format!("cannot create {}: {e}", args.out.display()),
        )
    })?;

    let mut text = String::new();
    for (source, stem, out) in &plan {
        let size = std::fs::metadata(source).map(|m| m.len()).unwrap_or(0);
        let progress = Progress::new(source, size);
        let mut unity = import::unity::UnityLog::new(|| {
            let file = std::fs::File::open(source)?;
            Ok(progress.reader(file))
        });
        let mut failure = None;
        let mut result = None;
        let written = output::write_atomically_with(out, |w| {
            match import::import(&mut unity, &mapping, stem, w) {
                Ok((_, header, report)) => {
                    result = Some((header, report));
                    Ok(())
                }
                Err(e) => {
                    failure = Some(recording_input::import_failure(source, &e));
                    Err(std::io::Error::other("import failed"))
                }
            }
        });
        progress.finish();
        if let Some(f) = failure {
            return Err(f);
        }
        written?;
        let Some((header, report)) = result else {
            continue;
        };
        let _ = writeln!(text, "{} -> {}", source.display(), out.display());
        for line in report.render(&header).lines() {
            let _ = writeln!(text, "  {line}");
        }
    }
    let _ = writeln!(
        text,
        "\nmapping used (save it, edit it and pass it with --mapping):\n"
    );
    text.push_str(&mapping.to_toml());
    print!("{text}");
    if args.peak_heap {
        eprintln!("peak heap: {} bytes", crate::memory::peak_heap());
    }
    Ok(ExitCode::SUCCESS)
}

/// Progress on standard error, for long imports when it is a terminal: bytes read of the
/// two passes.
struct Progress<'a> {
    name: &'a Path,
    total: u64,
    read: std::cell::Cell<u64>,
    shown: std::cell::Cell<u64>,
    on: bool,
}

impl<'a> Progress<'a> {
    fn new(name: &'a Path, size: u64) -> Progress<'a> {
        Progress {
            name,
            total: size.saturating_mul(2).max(1),
            read: Default::default(),
            shown: Default::default(),
            on: size >= PROGRESS_FROM && std::io::stderr().is_terminal(),
        }
    }

    fn reader<R: Read>(&self, inner: R) -> Counting<'_, 'a, R> {
        Counting {
            inner,
            progress: self,
        }
    }

    fn advance(&self, n: usize) {
        if !self.on {
            return;
        }
        let read = self.read.get() + n as u64;
        self.read.set(read);
        let percent = read * 100 / self.total;
        if percent != self.shown.get() {
            self.shown.set(percent);
            let mut err = std::io::stderr();
            let _ = write!(err, "\rimporting {}: {percent:3}%", self.name.display());
            let _ = err.flush();
        }
    }

    fn finish(&self) {
        if self.on {
            eprintln!();
        }
    }
}

struct Counting<'p, 'a, R> {
    inner: R,
    progress: &'p Progress<'a>,
}

impl<R: Read> Read for Counting<'_, '_, R> {
    fn read(&mut self, buf: &mut [u8]) -> std::io::Result<usize> {
        let n = self.inner.read(buf)?;
        self.progress.advance(n);
        Ok(n)
    }
}
