//! `demoplan timeline RECORDING -o FILE.svg`: the recording segmented with its signals
//! kept (`learn::Signals`), turned into a timeline (`learn::timeline`, with the
//! simulator's truth when it lies beside the recording) and drawn by `report`.

use crate::cli::TimelineArgs;
use crate::commands::demo_input;
use crate::diagnostic::Failure;
use crate::output::write_atomically;
use slim::ExitCode;

pub fn run(args: TimelineArgs) -> Result<ExitCode, Failure> {
    if args
        .out
        .extension()
        .is_none_or(|e| !e.eq_ignore_ascii_case("svg"))
    {
        return Err(Failure::plain(
            ExitCode::USAGE,
            format!(
                "{}: the timeline is an SVG file (name it FILE.svg)",
                args.out.display()
            ),
        ));
    }
    let segmentation = demo_input::segmentation(&args.segmentation)?;
    let mut signals = learn::Signals::default();
    let segmented = demo_input::segment_recording(
        &args.file,
        segmentation.mapping,
        &segmentation.config,
        &segmentation.tree,
        &mut signals,
    )?;
    let truth = if simulate::truth_path(&args.file).is_file() {
        Some(learn::read_truth(&args.file, &segmented.header).map_err(demo_input::file_failure)?)
    } else {
        None
    };
    let source = args.file.display().to_string();
    let timeline = learn::timeline(
        &segmented,
        &signals,
        truth.as_deref(),
        &segmentation.config,
        &source,
    );
    write_atomically(&args.out, &report::timeline_figure(&timeline).svg())?;
    println!(
        "{}: {} frames, {} segments drawn to {}",
        args.file.display(),
        segmented.frames,
        segmented.segments.len(),
        args.out.display()
    );
    Ok(ExitCode::SUCCESS)
}
