//! Segmentation accuracy on simulated studies: `accuracy FIRST_SEED COUNT [PARTICIPANTS
//! PER_PARTICIPANT [GROUNDING.toml]]`. One line per demonstration: `seed id agree counted
//! tolerant_equal merged_equal strict_equal`, then the sequences that differ on stderr.
//! Used by `bench/segmentation-accuracy`; `examples/diagnose.rs` shows why they differ.

#[path = "../tests/common/mod.rs"]
mod common;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let args: Vec<String> = std::env::args().collect();
    let first: u64 = args.get(1).map_or(Ok(1), |s| s.parse())?;
    let count: u64 = args.get(2).map_or(Ok(100), |s| s.parse())?;
    let participants: u32 = args.get(3).map_or(Ok(3), |s| s.parse())?;
    let per: u32 = args.get(4).map_or(Ok(4), |s| s.parse())?;
    let params = simulate::SimParams::default();
    let config = match args.get(5) {
        Some(path) => grounding::GroundingConfig::from_toml(&std::fs::read_to_string(path)?)?,
        None => grounding::GroundingConfig::default(),
    };
    let tree = segment::ActivityTree::table_one();
    for seed in first..first + count {
        let study = simulate::study(&params, seed, participants, per)?;
        for demo in &study.demonstrations {
            let m = common::measure(demo, &config, &tree);
            println!(
                "{seed} {} {} {} {} {} {}",
                m.id,
                m.agree,
                m.counted,
                u8::from(m.all_sequences_equal()),
                u8::from(m.merged_equal.iter().all(|&x| x)),
                u8::from(m.strict_equal.iter().all(|&x| x))
            );
            for (h, (ours, theirs)) in m.sequences.iter().enumerate() {
                if !m.sequence_equal[h] {
                    eprintln!(
                        "{seed} {} hand {h}: ours {ours:?}\n{:>width$} truth {theirs:?}",
                        m.id,
                        "",
                        width = 0
                    );
                }
            }
        }
    }
    Ok(())
}
