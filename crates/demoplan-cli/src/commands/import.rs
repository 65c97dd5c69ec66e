//! `demoplan import SOURCE... [--mapping FILE] -o DIR`: real recordings (Unity VR logs)
//! to native recordings `DIR/STEM.jsonl`, with a report per file and the mapping used.

use std::collections::BTreeMap;

use crate::cli::ImportArgs;
use crate::diagnostic::Failure;
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
        let source = &planned.source;
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
        let imported = planned.import_file(mapping, progress.counter(), |opened| {
            progress.set_total(opened + passes * size);
        });
        progress.finish();
        text.push_str(&imported.map_err(|e| match e {
            import::BatchError::Import(e) => recording_input::import_failure(source, &e),
            import::BatchError::Write(e) => Failure::plain(ExitCode::CRITICAL_ERROR, e),
        })?);
    }
    text.push_str(&import::mappings_used(&mappings));
    print!("{text}");
    if args.peak_heap {
        eprintln!("peak heap: {} bytes", task::memory::peak_heap());
    }
    Ok(ExitCode::SUCCESS)
}
