//! `demoplan simulate -o DIR`: simulated demonstrations of people stacking cubes, each a
//! recording in the native format with its ground truth beside it, and a manifest.

use std::fmt::Write as _;
use std::path::Path;

use serde_json::json;

use crate::cli::SimulateArgs;
use crate::diagnostic::Failure;
use crate::exit::ExitCode;
use crate::input;
use crate::output::{write_atomically, write_atomically_with};

/// Name of the manifest written beside the recordings.
pub const MANIFEST: &str = "simulation.json";

pub fn run(args: SimulateArgs) -> Result<ExitCode, Failure> {
    let mut params = match &args.params {
        None => simulate::SimParams::default(),
        Some(path) => {
            let text = input::read_text(path)?;
            serde_json::from_str(&text).map_err(|e| {
                Failure::plain(
                    ExitCode::USAGE,
                    format!("{}: not a parameter file: {e}", path.display()),
                )
            })?
        }
    };
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
    let mut entries = Vec::new();
    let (mut total_frames, mut total_seconds) = (0u64, 0.0f64);
    for demo in &study.demonstrations {
        let name = format!("{}.jsonl", demo.id);
        let truth_name = format!("{}.truth.jsonl", demo.id);
        let (frames, seconds) =
            write_demonstration(demo, &args.out.join(&name), &args.out.join(&truth_name))?;
        total_frames += frames;
        total_seconds += seconds;
        let hand = demo.hand.map_or("both", |h| h.name());
        let placements: Vec<String> = demo.placements.iter().map(|p| demo.describe(p)).collect();
        let _ = writeln!(
            listing,
            "{:<8} {:<5} hand  {} cube{}  {:>5} frames  {:>6.2} s  {}",
            demo.id,
            hand,
            demo.placements.len(),
            if demo.placements.len() == 1 { " " } else { "s" },
            frames,
            seconds,
            placements.join(", ")
        );
        entries.push(json!({
            "id": demo.id,
            "recording": name,
            "truth": truth_name,
            "participant": demo.participant.code,
            "hand": hand,
            "task": demo.header().task,
            "placements": placements,
            "frames": frames,
            "duration": (seconds * 1000.0).round() / 1000.0,
        }));
    }
    let participants: Vec<serde_json::Value> = study
        .participants
        .iter()
        .map(|p| {
            json!({
                "code": p.code,
                "dominant_hand": p.dominant.name(),
                "mean_speed": (p.mean_speed * 1000.0).round() / 1000.0,
                "rest_after_grasp": (p.rest_after_grasp * 1000.0).round() / 1000.0,
                "hover": (p.hover * 1000.0).round() / 1000.0,
                "return_between": (p.return_between * 1000.0).round() / 1000.0,
                "abort": (p.abort * 1000.0).round() / 1000.0,
                "regrasp": (p.regrasp * 1000.0).round() / 1000.0,
                "adjust": (p.adjust * 1000.0).round() / 1000.0,
                "fidget_rate": (p.fidget_rate * 1000.0).round() / 1000.0,
            })
        })
        .collect();
    let manifest = json!({
        "format": "demoplan-simulation",
        "version": 1,
        "seed": args.seed,
        "participants": participants,
        "params": params.to_json(),
        "recordings": entries,
    });
    let text = serde_json::to_string_pretty(&manifest).unwrap_or_default() + "\n";
    write_atomically(&args.out.join(MANIFEST), &text)?;
    print!("{listing}");
    println!(
        "wrote {} recordings ({total_frames} frames, {total_seconds:.1} s) with their ground truth \
         to {} (listed in {MANIFEST})",
        study.demonstrations.len(),
        args.out.display()
    );
    Ok(ExitCode::SUCCESS)
}

/// Writes the recording and its ground truth; returns the frames written and the seconds
/// from the first to the last.
fn write_demonstration(
    demo: &simulate::Demonstration,
    path: &Path,
    truth_path: &Path,
) -> Result<(u64, f64), Failure> {
    let mut truth = simulate::TruthWriter::new(Vec::new(), &demo.truth_header(), demo.header())
        .map_err(|e| write_failure(truth_path, e))?;
    let (mut frames, mut first, mut last) = (0u64, 0.0, 0.0);
    write_atomically_with(path, |out| {
        let mut writer =
            recording::Writer::new(out, demo.header()).map_err(std::io::Error::other)?;
        let mut frame = recording::Frame::default();
        let mut t = simulate::TruthFrame::default();
        let mut render = demo.frames();
        while render.next_into(&mut frame, &mut t) {
            writer.write_frame(&frame).map_err(std::io::Error::other)?;
            truth.write(&t)?;
            if frames == 0 {
                first = frame.time;
            }
            last = frame.time;
            frames += 1;
        }
        writer.finish().map_err(std::io::Error::other)?;
        Ok(())
    })?;
    let bytes = truth.finish().map_err(|e| write_failure(truth_path, e))?;
    write_atomically_with(truth_path, |out| out.write_all(&bytes))?;
    Ok((frames, last - first))
}

fn write_failure(path: &Path, e: std::io::Error) -> Failure {
    Failure::plain(
        ExitCode::CRITICAL_ERROR,
        format!("cannot write {}: {e}", path.display()),
    )
}
