//! Segmentation accuracy on simulated studies: `accuracy FIRST_SEED COUNT [PARTICIPANTS
//! PER_PARTICIPANT [GROUNDING.toml]]`. One line per demonstration: `seed id agree counted
//! tolerant_equal merged_equal strict_equal`, then the sequences that differ on stderr.
//! Used by `bench/segmentation-accuracy`; `examples/diagnose.rs` shows why they differ.

#[path = "../tests/common/mod.rs"]
mod common;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let args = common::StudyArgs::from_env(100)?;
    let config = args.config;
    let params = simulate::SimParams::default();
    let tree = segment::ActivityTree::table_one();
    for seed in args.seeds {
        let study = simulate::study(&params, seed, args.participants, args.per_participant)?;
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
