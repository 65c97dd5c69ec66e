//! Writes a long simulated recording (one session, both hands, six cubes) for benchmarks:
//! `long_recording FRAMES OUT.jsonl [SEED]`. Used by `bench/recording-speed`.

use std::io::Write;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let args: Vec<String> = std::env::args().collect();
    if args.len() < 3 {
        return Err("usage: long_recording FRAMES OUT.jsonl [SEED]".into());
    }
    let frames: u64 = args[1].parse()?;
    let seed: u64 = args.get(3).map_or(Ok(7), |s| s.parse())?;
    let demo = simulate::session(&simulate::SimParams::default(), seed, frames)?;
    let file = std::fs::File::create(&args[2])?;
    let mut out = recording::Writer::new(
        std::io::BufWriter::with_capacity(1 << 20, file),
        demo.header(),
    )?;
    let mut frame = recording::Frame::default();
    let mut truth = simulate::TruthFrame::default();
    let mut render = demo.frames();
    let start = std::time::Instant::now();
    while render.next_into(&mut frame, &mut truth) {
        out.write_frame(&frame)?;
    }
    out.finish()?.flush()?;
    eprintln!(
        "wrote {frames} frames ({} placements) in {:.1} s",
        demo.placements.len(),
        start.elapsed().as_secs_f64()
    );
    Ok(())
}
