//! The simulator against its promises: deterministic per seed, cubes that follow the hand
//! and settle on what is below, ground truth with every activity of the paper, files the
//! recording reader accepts, and a parameter table in the docs that lists every parameter.

#![allow(clippy::unwrap_used, clippy::expect_used)]

use std::collections::{BTreeMap, BTreeSet};

use recording::{EntityId, EntityKind, Frame, Reader, Recording, Writer};
use simulate::*;

/// The recording and the truth of a demonstration, written as the CLI writes them.
fn write(demo: &Demonstration) -> (Vec<u8>, Vec<u8>) {
    let mut rec = Writer::new(Vec::new(), demo.header()).unwrap();
    let mut truth = TruthWriter::new(Vec::new(), &demo.truth_header(), demo.header()).unwrap();
    for (frame, t) in demo.frames() {
        rec.write_frame(&frame).unwrap();
        truth.write(&t).unwrap();
    }
    (rec.finish().unwrap(), truth.finish().unwrap())
}

fn rendered(demo: &Demonstration) -> (Vec<Frame>, Vec<TruthFrame>) {
    demo.frames().unzip()
}

#[test]
fn same_seed_same_bytes_other_seed_other_bytes() {
    let params = SimParams::default();
    let a = study(&params, 7, 1, 2).unwrap();
    let b = study(&params, 7, 1, 2).unwrap();
    let c = study(&params, 8, 1, 2).unwrap();
    for i in 0..2 {
        let wa = write(&a.demonstrations[i]);
        assert_eq!(wa, write(&b.demonstrations[i]), "demonstration {i}");
        assert_ne!(wa.0, write(&c.demonstrations[i]).0, "demonstration {i}");
    }
    // A demonstration does not depend on how many others are made with it.
    let more = study(&params, 7, 2, 4).unwrap();
    assert_eq!(write(&a.demonstrations[1]), write(&more.demonstrations[1]));
}

#[test]
fn the_default_study_is_the_papers_design() {
    let s = default_study();
    assert_eq!(s.seed, 7);
    assert_eq!(s.demonstrations.len(), 12);
    assert_eq!(s.participants.len(), 3);
    for p in &s.participants {
        let mine: Vec<&Demonstration> = s
            .demonstrations
            .iter()
            .filter(|d| d.participant.code == p.code)
            .collect();
        // Each person stacks one cube and two cubes, with each hand.
        let tasks: BTreeSet<(usize, Side)> = mine
            .iter()
            .map(|d| (d.placements.len(), d.hand.unwrap()))
            .collect();
        assert_eq!(tasks.len(), 4, "{}", p.code);
        assert!(tasks.iter().all(|&(n, _)| n == 1 || n == 2));
    }
    let d = &s.demonstrations[0];
    assert_eq!(d.id, "p01-d01");
    let h = d.header();
    assert_eq!(h.ids_of(EntityKind::Cube).count(), 6);
    assert_eq!(h.ids_of(EntityKind::Hand).count(), 2);
    assert_eq!(h.frame_rate, 90.0);
    assert_eq!(h.meta("seed"), Some("7"));
}

#[test]
fn every_activity_of_the_paper_occurs_in_the_default_study() {
    let s = default_study();
    let mut counts: BTreeMap<Activity, usize> = BTreeMap::new();
    let mut phases = BTreeSet::new();
    for demo in &s.demonstrations {
        let (frames, truth) = rendered(demo);
        assert_eq!(frames.len(), truth.len());
        for (f, t) in frames.iter().zip(&truth) {
            assert_eq!(f.time, t.time);
            for h in &t.hands {
                *counts.entry(h.activity).or_default() += 1;
                phases.insert(h.phase);
                assert_eq!(
                    h.activity,
                    Activity::classify(h.moving, h.acted_on.is_some(), h.in_hand.is_some())
                );
                // The truth's held cube is what the grab system reports.
                assert_eq!(f.state(h.hand).unwrap().holding, h.in_hand);
            }
        }
    }
    for a in Activity::ALL {
        assert!(
            counts.get(&a).copied().unwrap_or(0) > 0,
            "no {a:?} in {counts:?}"
        );
    }
    for p in Phase::ALL {
        assert!(phases.contains(&p), "no phase {p:?}");
    }
}

/// Starts of Put segments (moving while holding), classified by what came before the
/// grasp: a rest while holding (Take, the paper's `Put`) or a reach (`Put2`).
#[test]
fn people_sometimes_lift_without_resting_the_hand() {
    let s = default_study();
    let (mut after_take, mut after_reach) = (0, 0);
    for demo in &s.demonstrations {
        let hand = demo.hand.unwrap().entity().index();
        let (_, truth) = rendered(demo);
        let mut previous = Activity::Idle;
        for t in &truth {
            let a = t.hands[hand].activity;
            if a != previous {
                if a == Activity::Put && previous == Activity::Take {
                    after_take += 1;
                }
                if a == Activity::Put && previous == Activity::Reach {
                    after_reach += 1;
                }
                previous = a;
            }
        }
    }
    assert!(after_take >= 8, "{after_take} Take-Put");
    assert!(after_reach >= 1, "{after_reach} Reach-Put");
}

#[test]
fn grasped_cubes_follow_the_hand() {
    let s = default_study();
    let mut checked = 0;
    for demo in &s.demonstrations {
        let (frames, _) = rendered(demo);
        // Per hold (hand, cube, first frame): the cube's position in the hand's frame.
        let mut hold: Option<(EntityId, EntityId, recording::Vec3)> = None;
        for f in &frames {
            for hand in [Side::Left.entity(), Side::Right.entity()] {
                let hs = f.state(hand).unwrap();
                match (hs.holding, hold) {
                    (Some(c), Some((h, c0, offset))) if h == hand && c == c0 => {
                        let cs = f.state(c).unwrap();
                        let now = local(hs.pose, cs.pose.position);
                        assert!(
                            (now - offset).norm() < 0.001,
                            "{} t={}: the held cube moved {} m in the hand",
                            demo.id,
                            f.time,
                            (now - offset).norm()
                        );
                        checked += 1;
                    }
                    (Some(c), _) => {
                        let cs = f.state(c).unwrap();
                        let offset = local(hs.pose, cs.pose.position);
                        // The palm is close to the cube it holds.
                        assert!(
                            offset.norm() < 0.1,
                            "{} grasped from {} m",
                            demo.id,
                            offset.norm()
                        );
                        hold = Some((hand, c, offset));
                    }
                    (None, Some((h, _, _))) if h == hand => hold = None,
                    _ => {}
                }
            }
        }
    }
    assert!(checked > 1000, "only {checked} held frames");
}

/// A point in the frame of a pose.
fn local(pose: recording::Pose, p: recording::Vec3) -> recording::Vec3 {
    let q = pose.orientation;
    let inv = recording::Quaternion::new(-q.x, -q.y, -q.z, q.w);
    inv.rotate(p - pose.position)
}

#[test]
fn released_cubes_rest_on_what_is_below() {
    let s = default_study();
    let table_top = s.params.table_height as f32;
    let size = s.params.cube_size as f32;
    for demo in &s.demonstrations {
        let (frames, _) = rendered(demo);
        let last = frames.last().unwrap();
        let pos = |id: EntityId| last.state(id).unwrap().pose.position;
        let mut stacked = BTreeSet::new();
        for pl in &demo.placements {
            let Target::Cube(below) = pl.onto else {
                panic!("the study stacks on cubes")
            };
            let (a, b) = (pos(pl.cube), pos(below));
            // On top: one cube size higher (within the physics jitter and rounding), and
            // over the lower cube's top face.
            assert!(
                ((a.z - b.z) - size).abs() < 0.002,
                "{}: {} over {}",
                demo.id,
                a.z,
                b.z
            );
            assert!(
                (a.x - b.x).abs() < size / 2.0 && (a.y - b.y).abs() < size / 2.0,
                "{}",
                demo.id
            );
            // Flat: no roll or pitch left.
            let q = last.state(pl.cube).unwrap().pose.orientation;
            assert!(
                q.x.abs() < 0.002 && q.y.abs() < 0.002,
                "{}: tilted {q:?}",
                demo.id
            );
            // The contact is reported.
            assert!(
                last.contacts.iter().any(|c| c.a == pl.cube && c.b == below),
                "{}",
                demo.id
            );
            stacked.insert(pl.cube);
        }
        for c in demo.header().ids_of(EntityKind::Cube) {
            if !stacked.contains(&c) {
                assert!(
                    (pos(c).z - table_top - size / 2.0).abs() < 0.002,
                    "{}: {:?}",
                    demo.id,
                    pos(c)
                );
            }
        }
        // No hand holds anything at the end.
        assert!(last.states[..2]
            .iter()
            .all(|s| s.unwrap().holding.is_none()));
    }
}

#[test]
fn written_files_read_back_and_truth_lines_up() {
    let s = default_study();
    let demo = &s.demonstrations[3];
    let (rec, truth) = write(demo);
    let recording = Recording::read(&rec[..]).unwrap();
    assert_eq!(&recording.header, demo.header());
    let (frames, expected_truth) = rendered(demo);
    assert_eq!(recording.frames, frames);
    let (th, tf) = read_truth(&truth[..], &recording.header).unwrap();
    assert_eq!(th, demo.truth_header());
    assert_eq!(tf, expected_truth);
    // Tracking gaps: a few dropped frames, and timestamps near the nominal rate.
    let dt: Vec<f64> = frames.windows(2).map(|w| w[1].time - w[0].time).collect();
    let nominal = 1.0 / 90.0;
    assert!(dt.iter().all(|&d| d > 0.5 * nominal && d < 10.0 * nominal));
    let median = {
        let mut d = dt.clone();
        d.sort_by(f64::total_cmp);
        d[d.len() / 2]
    };
    assert!((median - nominal).abs() < 0.001);
}

#[test]
fn a_session_has_the_frames_asked_for_and_uses_both_hands() {
    let params = SimParams::default();
    let demo = session(&params, 7, 3000).unwrap();
    let mut reader_input = Vec::new();
    let mut w = Writer::new(&mut reader_input, demo.header()).unwrap();
    let mut hands = BTreeSet::new();
    let mut n = 0;
    for (frame, truth) in demo.frames() {
        w.write_frame(&frame).unwrap();
        for h in &truth.hands {
            if h.in_hand.is_some() {
                hands.insert(h.hand);
            }
        }
        n += 1;
    }
    w.finish().unwrap();
    assert_eq!(n, 3000);
    assert_eq!(hands.len(), 2);
    let mut reader = Reader::new(&reader_input[..]).unwrap();
    let mut f = Frame::default();
    let mut count = 0;
    while reader.read_frame(&mut f).unwrap() {
        count += 1;
    }
    assert_eq!(count, 3000);
}

#[test]
fn bad_parameters_are_refused() {
    let p = SimParams {
        cubes: 40,
        ..SimParams::default()
    };
    let e = study(&p, 7, 1, 1).unwrap_err();
    assert_eq!(e.field, "cubes");
    assert!(study(&SimParams::default(), 7, 0, 1).is_err());
}

/// The parameter table of `docs/recording-format.md` names every parameter, so that the
/// "one documented place" stays complete.
#[test]
fn the_docs_list_every_parameter() {
    let docs = std::fs::read_to_string(
        std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../../docs/recording-format.md"),
    )
    .unwrap();
    // The two-handed style writes the parameters the default leaves out.
    let mut keys: Vec<String> = Vec::new();
    for params in [SimParams::default(), Style::TwoHanded.params()] {
        keys.extend(params.to_json().as_object().unwrap().keys().cloned());
    }
    for key in keys {
        assert!(
            docs.contains(&format!("| `{key}` |")),
            "docs/recording-format.md has no table row for `{key}`"
        );
    }
}

/// Over a larger study, every kind of variety the simulator promises shows up in its own
/// ground truth: aborted reaches, regrasps, hovering, adjustments of a cube put down,
/// fidgets of the idle hand, dropped frames.
#[test]
fn the_variety_of_behaviour_shows_up() {
    let s = study(&SimParams::default(), 7, 4, 8).unwrap();
    let (mut aborted, mut regrasps, mut hovers, mut fidgets, mut gaps) = (0, 0, 0, 0, 0);
    let mut adjustments = 0;
    for demo in &s.demonstrations {
        let hand = demo.hand.unwrap().entity().index();
        let idle = 1 - hand;
        let moved: BTreeSet<EntityId> = demo.placements.iter().map(|p| p.cube).collect();
        let (frames, truth) = rendered(demo);
        let mut reached: BTreeSet<EntityId> = BTreeSet::new();
        let mut released_in_grasp = false;
        let mut previous_in_hand = None;
        // Cubes released since they were last grasped: grasping one again is an
        // adjustment.
        let mut released: BTreeSet<EntityId> = BTreeSet::new();
        for t in &truth {
            let h = &t.hands[hand];
            if h.phase == Phase::Release {
                released.extend(h.in_hand);
            }
            if let (None, Some(c)) = (previous_in_hand, h.in_hand) {
                if released.remove(&c) {
                    adjustments += 1;
                }
            }
            if h.phase == Phase::Reach {
                reached.extend(h.target);
            }
            if h.phase == Phase::Grasp && previous_in_hand.is_some() && h.in_hand.is_none() {
                released_in_grasp = true;
            }
            if released_in_grasp && h.in_hand.is_some() {
                regrasps += 1;
                released_in_grasp = false;
            }
            previous_in_hand = h.in_hand;
            if matches!(h.phase, Phase::Carry | Phase::Approach) && h.activity == Activity::Take {
                hovers += 1;
            }
            if t.hands[idle].speed > 0.03 {
                fidgets += 1;
            }
        }
        aborted += reached.difference(&moved).count();
        gaps += frames
            .windows(2)
            .filter(|w| w[1].time - w[0].time > 1.5 / 90.0)
            .count();
    }
    assert!(aborted > 0, "no aborted reach");
    assert!(regrasps > 0, "no regrasp");
    assert!(hovers > 0, "no hover");
    assert!(adjustments > 0, "no adjustment");
    assert!(fidgets > 0, "the idle hand never moves");
    assert!(gaps > 0, "no dropped frame");
}

/// A participant is a draw: every style lies in its interval, and the people of a study
/// and of two seeds differ.
#[test]
fn participants_are_draws_of_the_style_distributions() {
    let p = SimParams::default();
    let mut styles = Vec::new();
    for seed in 1..=10 {
        for who in study(&p, seed, 3, 1).unwrap().participants {
            for (value, range) in [
                (who.mean_speed, p.mean_speed),
                (who.rest_after_grasp, p.rest_after_grasp),
                (who.hover, p.hover),
                (who.return_between, p.return_between),
                (who.abort, p.abort),
                (who.regrasp, p.regrasp),
                (who.adjust, p.adjust),
                (who.fidget_rate, p.fidget_rate),
            ] {
                assert!(
                    (range.min..=range.max).contains(&value),
                    "{value} outside {range:?}"
                );
            }
            styles.push((who.adjust, who.regrasp, who.hover, who.return_between));
        }
    }
    styles.sort_by(|a, b| a.0.total_cmp(&b.0));
    styles.dedup();
    assert_eq!(
        styles.len(),
        30,
        "two of 30 participants have the same style"
    );
}

/// FNV-1a, 64 bits.
fn fnv(bytes: &[u8], mut h: u64) -> u64 {
    for &b in bytes {
        h ^= u64::from(b);
        h = h.wrapping_mul(0x0100_0000_01b3);
    }
    h
}

/// The default style's output, byte for byte: the twelve recordings and truths of the
/// embedded default study and a short session hash to the values they had before styles
/// existed (every pinned result downstream depends on them).
#[test]
fn the_default_output_is_unchanged() {
    let mut h = 0xcbf2_9ce4_8422_2325;
    for demo in &default_study().demonstrations {
        let (rec, truth) = write(demo);
        h = fnv(&truth, fnv(&rec, h));
    }
    let session = session(&SimParams::default(), 3, 2000).unwrap();
    let (rec, truth) = write(&session);
    h = fnv(&truth, fnv(&rec, h));
    assert_eq!(
        h, 2265168465235595608,
        "the default simulator's output changed"
    );
}
