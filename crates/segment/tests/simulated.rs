//! Segmentation of simulated demonstrations against the simulator's ground truth (from
//! its noise-free state and intent), on a fixed set of seeds; and C4.5 trained on
//! simulated frames against Table 1 on held-out ones. `bench/segmentation-accuracy`
//! measures the same over 100 seeds.

#![allow(clippy::unwrap_used, clippy::expect_used)]

mod common;

use grounding::GroundingConfig;
use segment::{dataset, Activity, ActivityTree, Feature, C45};
use simulate::{study, SimParams};

/// Seeds of the fixed set: the embedded default study (7) and two more.
const SEEDS: [u64; 3] = [7, 11, 12];

#[test]
fn segments_agree_with_the_ground_truth() {
    let config = GroundingConfig::default();
    let tree = ActivityTree::table_one();
    let (mut agree, mut counted, mut sequences, mut demos) = (0, 0, 0, 0);
    let mut report = String::new();
    for seed in SEEDS {
        let s = study(&SimParams::default(), seed, 3, 4).unwrap();
        for demo in &s.demonstrations {
            let m = common::measure(demo, &config, &tree);
            assert!(
                m.agreement() >= 0.9,
                "seed {seed} {}: frame agreement {:.3}",
                m.id,
                m.agreement()
            );
            agree += m.agree;
            counted += m.counted;
            demos += 1;
            if m.all_sequences_equal() {
                sequences += 1;
            } else {
                for (ours, theirs) in &m.sequences {
                    if ours != theirs {
                        report.push_str(&format!(
                            "seed {seed} {}:\n  ours  {ours:?}\n  truth {theirs:?}\n",
                            m.id
                        ));
                    }
                }
            }
        }
    }
    let agreement = agree as f64 / counted as f64;
    let fraction = sequences as f64 / demos as f64;
    eprintln!("frame agreement {agreement:.4}, sequences equal {sequences} of {demos}\n{report}");
    // The bars: frames, and per-hand sequences (truth runs lying wholly within
    // the ignored 0.1 s around their boundaries may be missing, see `common::measure`).
    assert!(agreement >= 0.95, "frame agreement {agreement:.4}");
    assert!(
        fraction >= 0.9,
        "sequences equal on {sequences} of {demos}\n{report}"
    );
}

#[test]
fn c45_trained_on_simulated_frames_does_at_least_as_well_as_table_one() {
    let config = GroundingConfig::default();
    let frames = |seed: u64| -> Vec<(grounding::HandFacts, Activity)> {
        let s = study(&SimParams::default(), seed, 2, 4).unwrap();
        s.demonstrations
            .iter()
            .flat_map(|d| common::labelled_frames(d, &config))
            .collect()
    };
    let train = frames(21);
    let test = frames(22);
    let classes: Vec<String> = Activity::ALL.iter().map(|a| a.name().to_string()).collect();
    let features = [
        Feature::HandMove,
        Feature::ActedOn,
        Feature::InHand,
        Feature::HandOpen,
    ];
    let data = dataset(
        &features,
        &classes,
        train.iter().map(|(h, a)| (*h, a.index())),
    );
    let learned = ActivityTree::new(C45::default().learn(&data)).unwrap();
    let table_one = ActivityTree::table_one();
    let score = |t: &ActivityTree| test.iter().filter(|(h, a)| t.classify(h) == *a).count();
    let (l, t) = (score(&learned), score(&table_one));
    eprintln!(
        "held-out frames {}: learned {l}, Table 1 {t}\n{}",
        test.len(),
        learned.tree()
    );
    assert!(l >= t, "learned {l} < Table 1 {t} of {}", test.len());
}
