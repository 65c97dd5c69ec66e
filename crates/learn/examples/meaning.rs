//! Activities whose effects contradict their class (`learn::breaches`), tallied over
//! simulated studies: what mending has to answer.
//!
//! ```text
//! cargo run --release -p learn --example meaning -- [FIRST_SEED] [COUNT] [settled|runs] [mend] [two-handed]
//! ```

use std::collections::BTreeMap;

use grounding::GroundingConfig;
use learn::{activities, breaches, changes, Grouping, OtherHands};
use segment::ActivityTree;

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let first: u64 = args.get(1).and_then(|s| s.parse().ok()).unwrap_or(1);
    let count: u64 = args.get(2).and_then(|s| s.parse().ok()).unwrap_or(20);
    let grouping = match args.get(3).map(String::as_str) {
        Some("runs") => Grouping::Runs,
        _ => Grouping::Settled,
    };
    let config = GroundingConfig::default();
    let tree = ActivityTree::table_one();
    let mended = args.iter().any(|a| a == "mend");
    let mut all_counts = learn::MendCounts::default();
    let mut tally: BTreeMap<(String, &str), u64> = BTreeMap::new();
    let mut total = 0u64;
    let mut agree: BTreeMap<(String, String), u64> = BTreeMap::new();
    let mut shown = 0;
    for seed in first..first + count {
        let params = if args.iter().any(|a| a == "two-handed") {
            simulate::Style::TwoHanded.params()
        } else {
            simulate::SimParams::default()
        };
        let Ok(study) = simulate::study(&params, seed, 3, 4) else {
            continue;
        };
        for demo in &study.demonstrations {
            let (frames, truths): (Vec<_>, Vec<_>) = demo.frames().unzip();
            let seg = learn::segment_frames(demo.header(), frames.clone(), &config, &tree);
            let acts = activities(&seg.segments, grouping);
            if std::env::var("SHOW").is_ok_and(|d| d == demo.id) {
                for a in &acts {
                    let others = OtherHands::during(a, &acts, &seg.space);
                    let ch = changes(a, &a.start_state, &a.end_state, &others, &seg.space);
                    println!(
                        "  {:?} {:?} {:.3}-{:.3} held {:?} own {:?}",
                        a.hand,
                        a.activity,
                        a.start,
                        a.end,
                        a.held,
                        ch.own
                            .iter()
                            .map(|f| f.display(demo.header()).to_string())
                            .collect::<Vec<_>>()
                    );
                }
            }
            let (acts, counts) = if mended {
                learn::mend(&acts, grouping, &seg.space)
            } else {
                (acts, learn::MendCounts::default())
            };
            all_counts.add(&counts);
            let truth_frames = truths.iter().map(|t| {
                let facts = t
                    .hands
                    .iter()
                    .map(|h| grounding::HandFacts {
                        moving: h.moving,
                        open: None,
                        acted_on: h.acted_on,
                        in_hand: h.in_hand,
                    })
                    .collect();
                (t.time, facts)
            });
            let truth = learn::truth_activities(
                seg.space.hands(),
                truth_frames,
                &tree,
                config.min_duration,
                grouping,
            );
            let classes = learn::truth_classes(&acts, &truth);
            for (i, a) in acts.iter().enumerate() {
                total += 1;
                let truth = classes[i].unwrap_or(segment::Activity::Idle);
                *agree
                    .entry((a.activity.name().to_string(), truth.name().to_string()))
                    .or_default() += 1;
                let others = OtherHands::during(a, &acts, &seg.space);
                let ch = changes(a, &a.start_state, &a.end_state, &others, &seg.space);
                for b in breaches(a, &ch.own, &seg.space) {
                    *tally
                        .entry((a.activity.name().to_string(), b.name()))
                        .or_default() += 1;
                    if shown < 12 {
                        shown += 1;
                        let next = acts.get(i + 1).filter(|n| n.hand == a.hand);
                        let prev = i
                            .checked_sub(1)
                            .and_then(|j| acts.get(j))
                            .filter(|n| n.hand == a.hand);
                        println!(
                            "seed {seed} {} hand {:?} {:?} {:.3}-{:.3} prev {:?} next {:?}: {}; own {:?}",
                            demo.id,
                            a.hand,
                            a.activity,
                            a.start,
                            a.end,
                            prev.map(|p| p.activity),
                            next.map(|n| n.activity),
                            b.name(),
                            ch.own.iter().map(|f| f.display(demo.header()).to_string()).collect::<Vec<_>>()
                        );
                    }
                }
            }
        }
    }
    println!(
        "{total} activities; mended {:?}; dropped {:?}",
        all_counts.mended, all_counts.dropped
    );
    let same: u64 = agree
        .iter()
        .filter(|((a, b), _)| a == b)
        .map(|(_, n)| n)
        .sum();
    println!("agreement with the truth's activities: {same} of {total}");
    for ((class, truth), n) in &agree {
        if class != truth {
            println!("  class {class:6} truth {truth:6} {n}");
        }
    }
    for ((class, breach), n) in &tally {
        println!("{class:6} {breach:36} {n}");
    }
}
