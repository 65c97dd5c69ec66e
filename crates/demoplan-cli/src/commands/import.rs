//! `demoplan import SOURCE... [--mapping FILE] -o DIR`: real recordings (Unity VR logs)
//! to native recordings `DIR/STEM.jsonl`, with a report per file and the mapping used.

use std::collections::BTreeMap;
use std::fmt::Write as _;
use std::path::{Path, PathBuf};

use crate::cli::ImportArgs;
use crate::diagnostic::Failure;
use crate::exit::ExitCode;
use crate::output;
use crate::progress::BytesBar;
use crate::recording_input;
use import::SourceKind;

/// Sources this large show a progress bar on a terminal.
const PROGRESS_FROM: u64 = 16 << 20;

pub fn run(args: ImportArgs) -> Result<ExitCode, Failure> {
    // Every output name first: a clash writes nothing.
    let mut outputs: BTreeMap<PathBuf, &Path> = BTreeMap::new();
    let mut plan = Vec::new();
    for source in &args.sources {
        let kind = recording_input::source_kind(source)?;
        if kind == SourceKind::Native {
            return Err(Failure::plain(
                ExitCode::INPUT_ERROR,
                format!(
                    "{}: not a source import reads (a Unity playback log: a JSON object with \
                     `playbackTimestepMilliseconds` and `log`; a ROS 1 bag, an MCAP file or a \
                     ROS 2 bag folder)",
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
        plan.push((source, kind, stem, out));
    }
    // The mapping of each source format met (a file's keys over that format's defaults).
    let mut mappings: BTreeMap<&'static str, import::Mapping> = BTreeMap::new();
    for (_, kind, _, _) in &plan {
        let format = kind.format().unwrap_or(import::Format::Unity);
        if !mappings.contains_key(format.name()) {
            let mapping = recording_input::mapping(args.mapping.as_deref(), format)?;
            mappings.insert(format.name(), mapping);
        }
    }
    std::fs::create_dir_all(&args.out).map_err(|e| {
        Failure::plain(
            ExitCode::CRITICAL_ERROR,
            format!("cannot create {}: {e}", args.out.display()),
        )
    })?;

    let mut text = String::new();
    for (source, kind, stem, out) in &plan {
        // A folder's size is its MCAP files' (the bag knows them); a file's is its own.
        let size = std::fs::metadata(source).map(|m| m.len()).unwrap_or(0);
        let what = format!("importing {}", source.display());
        let passes = import::SOURCE_PASSES;
        let mut unity;
        let mut bag;
        let progress;
        let (source_of_events, mapping): (&mut dyn import::Source, &import::Mapping) = match kind {
            SourceKind::Bag(format) => {
                let mapping = &mappings[format.name()];
                let size = import::ros::bag_size(source).unwrap_or(size);
                // Opening lists the topics (a read through an MCAP bag, the index of a
                // ROS 1 bag); then each pass reads the whole bag.
                progress = BytesBar::new(&what, (passes + 1) * size, size >= PROGRESS_FROM);
                bag = import::ros::RosBag::open_counting(source, mapping, Some(progress.counter()))
                    .map_err(|e| recording_input::import_failure(source, &e))?;
                let opened = progress
                    .counter()
                    .load(std::sync::atomic::Ordering::Relaxed);
                progress.set_total(opened + passes * size);
                (&mut bag, mapping)
            }
            _ => {
                progress = BytesBar::new(&what, passes * size, size >= PROGRESS_FROM);
                let counter = progress.counter();
                unity = import::unity::UnityLog::new(move || {
                    let file = std::fs::File::open(source)?;
                    Ok(import::CountingReader::new(file, counter.clone()))
                });
                (&mut unity, &mappings[import::Format::Unity.name()])
            }
        };
        let mut failure = None;
        let mut result = None;
        let written = output::write_atomically_with(out, |w| {
            match import::import(source_of_events, mapping, stem, w) {
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
    for (format, mapping) in &mappings {
        let which = if mappings.len() > 1 {
            format!(" for {format} sources")
        } else {
            String::new()
        };
        let _ = writeln!(
            text,
            "\nmapping used{which} (save it, edit it and pass it with --mapping):\n"
        );
        text.push_str(&mapping.to_toml());
    }
    print!("{text}");
    if args.peak_heap {
        eprintln!("peak heap: {} bytes", crate::memory::peak_heap());
    }
    Ok(ExitCode::SUCCESS)
}
