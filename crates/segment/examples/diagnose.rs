//! Why per-hand activity sequences differ from the simulator's truth: `diagnose
//! FIRST_SEED COUNT [PARTICIPANTS PER_PARTICIPANT [GROUNDING.toml]]`. For every hand whose
//! sequence does not match (the tolerant reading of `bench/segmentation-accuracy`), prints
//! the truth's runs (time span, activity, phase, target, acted on, in hand, noise-free
//! speed) and the segments (time span, activity, tuple), side by side in time. With
//! `DIAGNOSE=merged` in the environment, the hands whose sequence differs in the merged
//! reading (the truth's runs shorter than the minimum duration merged as segments are).
//! With `FRAMES=T0,T1`, also every frame from T0 to T1 s: the truth's speed and tuple
//! against the grounded tuple (after hysteresis and the minimum duration).

#[path = "../tests/common/mod.rs"]
mod common;

use recording::{EntityId, Header};

fn name(header: &Header, id: Option<EntityId>) -> String {
    id.map_or_else(|| "-".to_string(), |id| header.entity(id).name.clone())
}

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let args = common::StudyArgs::from_env(10)?;
    let config = args.config;
    let params = simulate::SimParams::default();
    let tree = segment::ActivityTree::table_one();
    let merged = std::env::var("DIAGNOSE").is_ok_and(|v| v == "merged");
    let window: Option<(f64, f64)> = std::env::var("FRAMES").ok().and_then(|v| {
        let (a, b) = v.split_once(',')?;
        Some((a.parse().ok()?, b.parse().ok()?))
    });
    for seed in args.seeds {
        let study = simulate::study(&params, seed, args.participants, args.per_participant)?;
        for demo in &study.demonstrations {
            let m = common::measure(demo, &config, &tree);
            let equal = if merged {
                &m.merged_equal
            } else {
                &m.sequence_equal
            };
            if equal.iter().all(|&x| x) {
                continue;
            }
            let (_, truth, segments) = common::run(demo, &config, &tree);
            let header = demo.header();
            for (h, equal) in equal.iter().enumerate() {
                if *equal {
                    continue;
                }
                let hand = truth[0].hands[h].hand;
                println!(
                    "== seed {seed} {} hand {} (agreement {:.3})",
                    m.id,
                    name(header, Some(hand)),
                    m.agreement()
                );
                println!("  ours  {:?}", m.sequences[h].0);
                println!("  truth {:?}", m.sequences[h].1);
                // Truth runs (by the full hand truth: phase, activity, objects, moving).
                let mut lines: Vec<(f64, String)> = Vec::new();
                let mut k = 0;
                while k < truth.len() {
                    let a = truth[k].hands[h];
                    let mut j = k;
                    let mut vmax: f32 = 0.0;
                    while j < truth.len() {
                        let b = truth[j].hands[h];
                        if (b.activity, b.phase, b.acted_on, b.in_hand, b.target)
                            != (a.activity, a.phase, a.acted_on, a.in_hand, a.target)
                        {
                            break;
                        }
                        vmax = vmax.max(b.speed);
                        j += 1;
                    }
                    let end = truth.get(j).map_or(truth[j - 1].time, |t| t.time);
                    lines.push((
                        truth[k].time,
                        format!(
                            "T {:7.3}-{:7.3} ({:5.3}) {:6} {:8} tgt {:3} on {:3} in {:3} vmax {:.3}",
                            truth[k].time,
                            end,
                            end - truth[k].time,
                            a.activity.name(),
                            a.phase.name(),
                            name(header, a.target),
                            name(header, a.acted_on),
                            name(header, a.in_hand),
                            vmax
                        ),
                    ));
                    k = j;
                }
                for s in segments.iter().filter(|s| s.hand == hand) {
                    lines.push((
                        s.start,
                        format!(
                            "  S {:7.3}-{:7.3} ({:5.3}) {:6} move {} on {:3} in {:3}",
                            s.start,
                            s.end,
                            s.end - s.start,
                            s.activity.name(),
                            u8::from(s.moving),
                            name(header, s.acted_on),
                            name(header, s.in_hand)
                        ),
                    ));
                }
                lines.sort_by(|a, b| a.0.total_cmp(&b.0));
                for (_, l) in lines {
                    println!("  {l}");
                }
                if let Some((t0, t1)) = window {
                    let (grounded, signals) = grounded_hands(demo, &config, h);
                    for (i, t) in truth.iter().enumerate() {
                        if t.time < t0 || t.time > t1 {
                            continue;
                        }
                        let a = t.hands[h];
                        let g = grounded.get(i).copied().unwrap_or_default();
                        // Measured speed, and distance and speed towards each object within
                        // 0.2 m (noisy, before hysteresis).
                        let near: String = signals.get(i).map_or(String::new(), |sig| {
                            let objects: Vec<String> = sig
                                .distances
                                .iter()
                                .zip(&sig.toward)
                                .enumerate()
                                .filter(|(_, (d, _))| **d < 0.2)
                                .map(|(o, (d, v))| format!("o{o} {d:.3}/{v:+.3}"))
                                .collect();
                            format!("v {:.3} {}", sig.speed, objects.join(" "))
                        });
                        println!(
                            "    {:7.3} truth v {:.3} {} {:3} {:3} {:6} | grounded {} {:3} {:3} | {}",
                            t.time,
                            a.speed,
                            u8::from(a.moving),
                            name(header, a.acted_on),
                            name(header, a.in_hand),
                            a.activity.name(),
                            u8::from(g.moving),
                            name(header, g.acted_on),
                            name(header, g.in_hand),
                            near
                        );
                    }
                }
            }
        }
    }
    Ok(())
}

/// Per frame, one hand's grounded facts, and its signals.
fn grounded_hands(
    demo: &simulate::Demonstration,
    config: &grounding::GroundingConfig,
    h: usize,
) -> (Vec<grounding::HandFacts>, Vec<grounding::HandSignals>) {
    let mut grounder = grounding::Grounder::new(demo.header(), config);
    let mut out = Vec::new();
    let mut signals = Vec::new();
    let mut take = |g: &grounding::GroundedFrame<'_>| out.push(g.hands[h]);
    for (f, _) in demo.frames() {
        grounder.push(&f, &mut take);
        signals.push(grounder.signals()[h].clone());
    }
    grounder.finish(&mut take);
    (out, signals)
}
