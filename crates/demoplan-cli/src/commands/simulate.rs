//! `demoplan simulate -o DIR`: simulated demonstrations of people stacking cubes, each a
//! recording in the native format with its ground truth beside it, and a manifest.

use simulate::MANIFEST;

use crate::cli::SimulateArgs;
use crate::diagnostic::Failure;
use crate::input;
use slim::ExitCode;

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
    let written = simulate::write_study(&study, args.seed, &params, &args.out)
        .map_err(|e| Failure::plain(ExitCode::CRITICAL_ERROR, e))?;
    let listing: String = study
        .demonstrations
        .iter()
        .zip(&written)
        .map(|(demo, w)| demo.listing_line(*w))
        .collect();
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
