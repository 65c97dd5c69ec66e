//! The two-handed style against its promises: both hands active at once, recordings cut
//! mid-motion, poses only (no held object, no contacts, no velocities), dropped frames in
//! runs of 1 to 4, towers that stand at the end, and the same bytes for the same seed.

#![allow(clippy::unwrap_used, clippy::expect_used)]

use recording::{Frame, Writer};
use simulate::*;

fn two_handed_study(seed: u64, participants: u32, per_participant: u32) -> Study {
    study(
        &Style::TwoHanded.params(),
        seed,
        participants,
        per_participant,
    )
    .unwrap()
}

fn rendered(demo: &Demonstration) -> (Vec<Frame>, Vec<TruthFrame>) {
    demo.frames().unzip()
}

fn bytes(demo: &Demonstration) -> (Vec<u8>, Vec<u8>) {
    let mut rec = Writer::new(Vec::new(), demo.header()).unwrap();
    let mut truth = TruthWriter::new(Vec::new(), &demo.truth_header(), demo.header()).unwrap();
    for (frame, t) in demo.frames() {
        rec.write_frame(&frame).unwrap();
        truth.write(&t).unwrap();
    }
    (rec.finish().unwrap(), truth.finish().unwrap())
}

fn busy(a: Activity) -> bool {
    a != Activity::Idle
}

/// In every demonstration there are frames where one hand puts or stacks a cube while
/// the other reaches for or takes the next: the two hands' activities overlap.
#[test]
fn both_hands_are_active_at_once() {
    let s = two_handed_study(3, 3, 4);
    for demo in &s.demonstrations {
        assert_eq!(demo.hand, None);
        let hands: Vec<Side> = demo.placements.iter().map(|p| p.hand).collect();
        assert_eq!(hands.len(), 2);
        assert_ne!(hands[0], hands[1], "{}: one hand each", demo.id);
        let (_, truth) = rendered(demo);
        let both = truth
            .iter()
            .filter(|t| busy(t.hands[0].activity) && busy(t.hands[1].activity))
            .count();
        let overlap = truth
            .iter()
            .filter(|t| {
                let (a, b) = (t.hands[0].activity, t.hands[1].activity);
                let carries = |x: Activity| matches!(x, Activity::Put | Activity::Stack);
                let fetches = |x: Activity| matches!(x, Activity::Reach | Activity::Take);
                (carries(a) && fetches(b)) || (carries(b) && fetches(a))
            })
            .count();
        assert!(both > 0, "{}: the hands never work at once", demo.id);
        assert!(
            overlap > 0,
            "{}: no hand fetches while the other puts",
            demo.id
        );
    }
}

/// The recording starts after the first hand started moving and ends before the last is
/// at rest: a hand moves in the first frame and in the last; the truth has exactly the
/// recorded frames.
#[test]
fn recordings_start_and_end_mid_motion() {
    for demo in &two_handed_study(5, 2, 4).demonstrations {
        let (frames, truth) = rendered(demo);
        assert_eq!(frames.len(), truth.len());
        assert!(frames.iter().zip(&truth).all(|(f, t)| f.time == t.time));
        let (first, last) = (&truth[0], &truth[truth.len() - 1]);
        assert!(first.time > 0.0, "{}: not cut at the start", demo.id);
        assert!(
            first
                .hands
                .iter()
                .any(|h| h.moving && h.phase != Phase::Rest),
            "{}: no hand moves in the first frame: {first:?}",
            demo.id
        );
        assert!(
            last.hands
                .iter()
                .any(|h| h.moving && h.phase == Phase::Retreat),
            "{}: no hand on its way back in the last frame: {last:?}",
            demo.id
        );
        let seconds = frames[frames.len() - 1].time - frames[0].time;
        assert!((seconds - demo.duration()).abs() < 0.05, "{}", demo.id);
    }
}

/// Poses only, as real trackers report them: no held object, no contacts, no
/// velocities; a grip for each hand (the format needs one), noisy.
#[test]
fn poses_only_no_held_object_no_contacts() {
    let s = two_handed_study(2, 1, 4);
    let mut held_frames = 0;
    for demo in &s.demonstrations {
        assert_eq!(demo.header().frame_rate, 100.0);
        assert_eq!(demo.header().meta("style"), Some("two-handed"));
        let (frames, truth) = rendered(demo);
        for (f, t) in frames.iter().zip(&truth) {
            assert!(f.contacts.is_empty(), "{}: contacts at {}", demo.id, f.time);
            for h in &t.hands {
                let state = f.state(h.hand).unwrap();
                assert_eq!(state.holding, None);
                assert_eq!(state.velocity, None);
                assert!(state.grip.is_some());
                held_frames += usize::from(h.in_hand.is_some());
            }
        }
        let (rec, _) = bytes(demo);
        let text = String::from_utf8(rec).unwrap();
        assert!(!text.contains("\"holding\""), "{}", demo.id);
        assert!(!text.contains("\"contacts\""), "{}", demo.id);
    }
    // The truth still knows what is held: the grasps are there, only not reported.
    assert!(held_frames > 0);
}

/// Dropped frames come in runs of 1 to 4 at 100 Hz, and runs longer than one occur.
#[test]
fn dropped_frames_come_in_runs_of_one_to_four() {
    let s = two_handed_study(4, 3, 4);
    let mut runs = std::collections::BTreeMap::new();
    for demo in &s.demonstrations {
        let (frames, _) = rendered(demo);
        for w in frames.windows(2) {
            let missing = ((w[1].time - w[0].time) * 100.0).round() as i64 - 1;
            if missing > 0 {
                *runs.entry(missing).or_insert(0) += 1;
            }
        }
    }
    let lengths: Vec<i64> = runs.keys().copied().collect();
    assert!(
        lengths.iter().all(|n| (1..=4).contains(n)),
        "runs of dropped frames: {runs:?}"
    );
    assert!(
        lengths.iter().any(|&n| n > 1),
        "no run longer than one: {runs:?}"
    );
}

/// Same seed, same bytes; another seed, other bytes.
#[test]
fn same_seed_same_bytes() {
    let a = two_handed_study(9, 1, 2);
    let b = two_handed_study(9, 1, 2);
    let c = two_handed_study(10, 1, 2);
    for i in 0..2 {
        let wa = bytes(&a.demonstrations[i]);
        assert_eq!(wa, bytes(&b.demonstrations[i]));
        assert_ne!(wa.0, bytes(&c.demonstrations[i]).0);
    }
}

/// The hands never collide on a cube: no cube is in both hands, each hand holds only the
/// cube it places, and at the end the tower stands (each placed cube on its support).
#[test]
fn the_hands_share_the_work_without_colliding() {
    for demo in &two_handed_study(6, 3, 4).demonstrations {
        let (frames, truth) = rendered(demo);
        for t in &truth {
            let (a, b) = (t.hands[0].in_hand, t.hands[1].in_hand);
            assert!(a.is_none() || a != b, "{}: a cube in both hands", demo.id);
            for pl in &demo.placements {
                let h = &t.hands[pl.hand.entity().index()];
                // A hand holds its own cube, or the cube it adjusts: never the other's.
                let others: Vec<_> = demo
                    .placements
                    .iter()
                    .filter(|o| o.hand != pl.hand)
                    .map(|o| o.cube)
                    .collect();
                assert!(
                    h.in_hand.is_none_or(|c| !others.contains(&c)),
                    "{}: {:?} holds the other hand's cube",
                    demo.id,
                    pl.hand
                );
            }
        }
        let last = frames.last().unwrap();
        for pl in &demo.placements {
            let Target::Cube(below) = pl.onto else {
                panic!("a tower")
            };
            let top = last.state(pl.cube).unwrap().pose.position;
            let bottom = last.state(below).unwrap().pose.position;
            let dx = (top.x - bottom.x).hypot(top.y - bottom.y);
            let dz = top.z - bottom.z;
            assert!(
                dx < 0.02 && (dz - 0.05).abs() < 0.005,
                "{}: {} not on its support (dx {dx}, dz {dz})",
                demo.id,
                demo.describe(pl)
            );
        }
    }
}
