//! Reads a recording to the end, frame by frame, and reports the time: `read_speed FILE
//! [RUNS]`. One line per run: `frames seconds bytes`. Used by `bench/recording-speed`.

use std::io::BufReader;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let args: Vec<String> = std::env::args().collect();
    let path = args.get(1).ok_or("usage: read_speed FILE [RUNS]")?;
    let runs: usize = args.get(2).map_or(Ok(5), |s| s.parse())?;
    let bytes = std::fs::metadata(path)?.len();
    for _ in 0..runs {
        let start = std::time::Instant::now();
        let file = std::fs::File::open(path)?;
        let mut reader = recording::Reader::new(BufReader::with_capacity(1 << 20, file))?;
        let mut frame = recording::Frame::default();
        let mut frames = 0u64;
        let mut check = 0.0f64;
        while reader.read_frame(&mut frame)? {
            frames += 1;
            check += frame.time;
        }
        let seconds = start.elapsed().as_secs_f64();
        println!("{frames} {seconds:.6} {bytes} {check:.3}");
    }
    Ok(())
}
