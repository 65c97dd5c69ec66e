//! `demoplan simulate -o DIR`: simulated demonstrations of people stacking cubes, each a
//! recording in the native format with its ground truth beside it, and a manifest.

use crate::cli::SimulateArgs;
use crate::diagnostic::Failure;
use crate::input;
use slim::ExitCode;

pub fn run(args: SimulateArgs) -> Result<ExitCode, Failure> {
    let mut params = input::sim_params(args.params.as_deref(), args.style)?;
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
    print!("{}", simulate::written_listing(&study, &written, &args.out));
    Ok(ExitCode::SUCCESS)
}
