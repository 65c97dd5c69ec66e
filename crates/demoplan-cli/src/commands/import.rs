//! `demoplan import SOURCE... [--mapping FILE] -o DIR`: real recordings (Unity VR logs)
//! to native recordings `DIR/STEM.jsonl`, with a report per file and the mapping used.

use std::collections::BTreeMap;

use crate::cli::ImportArgs;
use crate::diagnostic::Failure;
use crate::output;
use crate::progress::BytesBar;
use crate::recording_input;
use slim::ExitCode;

/// Sources this large show a progress bar on a terminal.
const PROGRESS_FROM: u64 = 16 << 20;

/// An import refused before anything was written: a source it cannot tell apart (its
/// own failure), a native recording (31), two sources with one output name (36).
fn plan_failure(e: import::PlanError) -> Failure {
    match e {
        import::PlanError::Open { path, error } => recording_input::open_failure(&path, error),
        e @ import::PlanError::Native(_) => Failure::plain(ExitCode::INPUT_ERROR, e),
        e @ import::PlanError::Clash { .. } => Failure::plain(ExitCode::USAGE, e),
    }
}

pub fn run(args: ImportArgs) -> Result<ExitCode, Failure> {
    // Every output name first: a clash writes nothing.
    let plan = import::plan_import(&args.sources, &args.out).map_err(plan_failure)?;
    // The mapping of each source format met (a file's keys over that format's defaults).
    let mut mappings: BTreeMap<&'static str, import::Mapping> = BTreeMap::new();
    for format in import::formats(&plan) {
        let mapping = recording_input::mapping(args.mapping.as_deref(), format)?;
        mappings.insert(format.name(), mapping);
    }
    std::fs::create_dir_all(&args.out).map_err(|e| {
        Failure::plain(
            ExitCode::CRITICAL_ERROR,
            format!("cannot create {}: {e}", args.out.display()),
        )
    })?;

    let mut text = String::new();
    for planned in &plan {
        let (source, out) = (&planned.source, &planned.out);
        let mapping = &mappings[planned.format().name()];
        let size = planned.size();
        let passes = import::SOURCE_PASSES;
        // Opening a bag lists its topics (a read through an MCAP bag, the index of a
        // ROS 1 bag); then each pass reads the whole source.
        let progress = BytesBar::new(
            &format!("importing {}", source.display()),
            (passes + 1) * size,
            size >= PROGRESS_FROM,
        );
        let mut source_of_events = planned
            .open(mapping, progress.counter())
            .map_err(|e| recording_input::import_failure(source, &e))?;
        let opened = progress
            .counter()
            .load(std::sync::atomic::Ordering::Relaxed);
        progress.set_total(opened + passes * size);
        let stem = &planned.stem;
        let mut failure = None;
        let mut result = None;
        let written = output::write_atomically_with(out, |w| {
            match import::import(source_of_events.as_mut(), mapping, stem, w) {
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
        text.push_str(&planned.imported(&header, &report));
    }
    text.push_str(&import::mappings_used(&mappings));
    print!("{text}");
    if args.peak_heap {
        eprintln!("peak heap: {} bytes", crate::memory::peak_heap());
    }
    Ok(ExitCode::SUCCESS)
}
