//! Grounding and segmentation speed: `grounding_speed RECORDING.jsonl [RUNS]`. Parses the
//! whole recording into memory first (timed: the parse rate), then grounds and segments
//! the parsed frames `RUNS` times (timed: frames already parsed), on one thread. Prints
//! one line per run: `parse|ground frames seconds`. Used by `bench/grounding-speed`.

use std::io::BufReader;
use std::time::Instant;

use grounding::{Grounder, GroundingConfig};
use segment::{ActivityTree, Segmenter};

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let args: Vec<String> = std::env::args().collect();
    let path = args
        .get(1)
        .ok_or("usage: grounding_speed RECORDING.jsonl [RUNS]")?;
    let runs: usize = args.get(2).map_or(Ok(5), |s| s.parse())?;
    let start = Instant::now();
    let file = std::fs::File::open(path)?;
    let mut reader = recording::Reader::new(BufReader::with_capacity(1 << 20, file))?;
    let mut frames = Vec::new();
    let mut frame = recording::Frame::default();
    while reader.read_frame(&mut frame)? {
        frames.push(frame.clone());
    }
    println!(
        "parse {} {:.6}",
        frames.len(),
        start.elapsed().as_secs_f64()
    );
    let header = reader.into_header();
    let config = GroundingConfig::default();
    for _ in 0..runs {
        let start = Instant::now();
        let mut grounder = Grounder::new(&header, &config);
        let hands = grounder.space().hands().to_vec();
        let mut segmenter = Segmenter::new(&hands, ActivityTree::table_one(), config.min_duration);
        for f in &frames {
            grounder.push(f, &mut |g| segmenter.push_grounded(g));
        }
        grounder.finish(&mut |g| segmenter.push_grounded(g));
        let segments = segmenter.finish();
        let seconds = start.elapsed().as_secs_f64();
        println!("ground {} {seconds:.6} {}", frames.len(), segments.len());
    }
    Ok(())
}
