//! `demoplan simulate -o DIR`: simulated demonstrations of people stacking cubes, each a
//! recording in the native format with its ground truth beside it, and a manifest.

use std::path::Path;

use simulate::MANIFEST;

use crate::cli::SimulateArgs;
use crate::diagnostic::Failure;
use crate::exit::ExitCode;
use crate::input;
use crate::output::{write_atomically, write_atomically_with};

pub fn run(args: SimulateArgs) -> Result<ExitCode, Failure> {
    let mut params = input::sim_params(args.params.as_deref())?;
    if let Some(c) = args.cubes {
        params.cubes = c;
    }
    let study = simulate::study(&params, args.seed, args.participants, args.per_participant)
        .map_err(|e| {
            let flag = match e.field.as_str() {
                "participants" => "--participants: ".to_string(),
                "per_participant" => "--per-participant: ".to_string(),
                "cubes" if args.cubes.is_some() => "--cubes: ".to_string(),
                _ => String::new(),
            };
            Failure::plain(ExitCode::USAGE, format!("{flag}{e}"))
        })?;
    std::fs::create_dir_all(&args.out).map_err(|e| {
        Failure::plain(
            ExitCode::CRITICAL_ERROR,
            format!("cannot create {}: {e}", args.out.display()),
        )
    })?;
    let mut listing = String::new();
    let mut written = Vec::new();
    for demo in &study.demonstrations {
        let path = args.out.join(demo.recording_name());
        let w = write_demonstration(demo, &path, &args.out.join(demo.truth_name()))?;
        listing.push_str(&demo.listing_line(w));
        written.push(w);
    }
    let manifest = simulate::manifest(&study, args.seed, &params, &written);
    write_atomically(&args.out.join(MANIFEST), &manifest)?;
    let total_frames: u64 = written.iter().map(|w| w.frames).sum();
    let total_seconds: f64 = written.iter().map(|w| w.seconds).sum();
    print!("{listing}");
    println!(
        "wrote {} recordings ({total_frames} frames, {total_seconds:.1} s) with their ground truth \
         to {} (listed in {MANIFEST})",
        study.demonstrations.len(),
        args.out.display()
    );
    Ok(ExitCode::SUCCESS)
}

/// Writes the recording and its ground truth, each atomically; says what was written.
fn write_demonstration(
    demo: &simulate::Demonstration,
    path: &Path,
    truth_path: &Path,
) -> Result<simulate::Written, Failure> {
    // The truth is rendered beside the frames, so it is kept until the recording is in
    // place; it is a small part of the recording's size.
    let mut truth = Vec::new();
    let mut written = None;
    write_atomically_with(path, |out| {
        written = Some(demo.write(out, &mut truth)?);
        Ok(())
    })?;
    write_atomically_with(truth_path, |out| out.write_all(&truth))?;
    written.ok_or_else(|| {
        Failure::plain(
            ExitCode::CRITICAL_ERROR,
            format!("cannot write {}", path.display()),
        )
    })
}
