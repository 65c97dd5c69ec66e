//! Property test: writing a recording and reading it back gives the same header and frames,
//! bit for bit, for any valid recording (any finite numbers, entities missing from frames,
//! optional velocities, held objects, contacts, names that need no escaping and task texts
//! that do).

#![allow(clippy::unwrap_used, clippy::expect_used)]

use proptest::prelude::*;
use recording::*;

fn finite() -> impl Strategy<Value = f32> {
    prop_oneof![
        4 => -10.0f32..10.0,
        1 => proptest::num::f32::NORMAL | proptest::num::f32::SUBNORMAL | proptest::num::f32::ZERO,
        1 => (-100_000i32..100_000).prop_map(|m| (m as f32) / 1e4),
    ]
}

fn positive() -> impl Strategy<Value = f32> {
    prop_oneof![
        0.001f32..5.0,
        proptest::num::f32::POSITIVE.prop_filter("finite", |v| v.is_finite())
    ]
}

fn vec3() -> impl Strategy<Value = Vec3> {
    (finite(), finite(), finite()).prop_map(|(x, y, z)| Vec3::new(x, y, z))
}

fn rotation() -> impl Strategy<Value = Quaternion> {
    (-1.0f32..1.0, -1.0f32..1.0, -1.0f32..1.0, -1.0f32..1.0)
        .prop_filter("not tiny", |(x, y, z, w)| {
            x * x + y * y + z * z + w * w > 0.01
        })
        .prop_map(|(x, y, z, w)| {
            let n = (x * x + y * y + z * z + w * w).sqrt();
            Quaternion::new(x / n, y / n, z / n, w / n)
        })
}

fn pose() -> impl Strategy<Value = Pose> {
    (vec3(), rotation()).prop_map(|(position, orientation)| Pose {
        position,
        orientation,
    })
}

fn kind() -> impl Strategy<Value = EntityKind> {
    prop_oneof![
        Just(EntityKind::Hand),
        Just(EntityKind::Cube),
        Just(EntityKind::Table),
        Just(EntityKind::Other)
    ]
}

fn header() -> impl Strategy<Value = Header> {
    let entity = (
        kind(),
        (positive(), positive(), positive()),
        proptest::bool::weighted(0.2),
        pose(),
    );
    (
        proptest::collection::vec(entity, 1..7),
        ".{0,12}",
        "[a-z0-9]{1,6}",
        1.0f64..1000.0,
        proptest::collection::vec(("[a-z]{1,5}", ".{0,6}"), 0..3),
    )
        .prop_map(|(entities, task, id, frame_rate, meta)| Header {
            id,
            participant: "p\"1\\".into(),
            task,
            frame_rate,
            entities: entities
                .into_iter()
                .enumerate()
                .map(|(i, (kind, (x, y, z), fixed, pose))| Entity {
                    name: format!("{}_{i}", kind.name()),
                    kind,
                    size: Vec3::new(x, y, z),
                    fixed: (fixed && kind != EntityKind::Hand).then_some(pose),
                })
                .collect(),
            meta: meta.into_iter().collect(),
        })
}

fn state(kind: EntityKind, n: usize) -> impl Strategy<Value = EntityState> {
    (
        pose(),
        proptest::option::of(vec3()),
        0.0f32..=1.0,
        proptest::option::of(0..n),
    )
        .prop_map(move |(pose, velocity, grip, holding)| EntityState {
            pose,
            velocity,
            grip: (kind == EntityKind::Hand).then_some(grip),
            holding: holding
                .filter(|_| kind == EntityKind::Hand)
                .map(|h| EntityId(h as u32)),
        })
}

fn recording() -> impl Strategy<Value = Recording> {
    header()
        .prop_flat_map(|header| {
            let n = header.entities.len();
            let states: Vec<_> = header
                .entities
                .iter()
                .map(|e| proptest::option::weighted(0.8, state(e.kind, n)))
                .collect();
            let frame = (
                prop_oneof![1e-6f64..0.1, 0.1f64..1e4],
                states,
                proptest::collection::vec((0..n, 0..n), 0..4),
            );
            (
                Just(header),
                -100.0f64..100.0,
                proptest::collection::vec(frame, 0..12),
            )
        })
        .prop_map(|(header, start, frames)| {
            let mut time = start;
            let frames = frames
                .into_iter()
                .map(|(dt, states, contacts)| {
                    time += dt;
                    let mut states: Vec<Option<EntityState>> = states;
                    // Fixed entities are never listed in frames.
                    for (s, e) in states.iter_mut().zip(&header.entities) {
                        if e.fixed.is_some() {
                            *s = None;
                        }
                    }
                    // Holding must name a non-hand other than the hand itself.
                    for (i, s) in states.iter_mut().enumerate() {
                        if let Some(s) = s {
                            if let Some(h) = s.holding {
                                if h.index() == i || header.entity(h).kind == EntityKind::Hand {
                                    s.holding = None;
                                }
                            }
                        }
                    }
                    Frame {
                        time,
                        states,
                        contacts: contacts
                            .into_iter()
                            .filter(|(a, b)| a != b)
                            .map(|(a, b)| Contact {
                                a: EntityId(a as u32),
                                b: EntityId(b as u32),
                            })
                            .collect(),
                    }
                })
                .collect();
            Recording { header, frames }
        })
}

fn bits(r: &Recording) -> Vec<u64> {
    let mut out = vec![];
    for f in &r.frames {
        out.push(f.time.to_bits());
        for s in f.states.iter().flatten() {
            let p = s.pose.position.to_array();
            let q = s.pose.orientation.to_array();
            out.extend(p.iter().chain(&q).map(|v| u64::from(v.to_bits())));
        }
    }
    out
}

proptest! {
    // Failures are saved to, and replayed first from, `tests/roundtrip.proptest-regressions`
    // (proptest's default persistence; committed, so every run replays them).
    #![proptest_config(ProptestConfig::with_cases(256))]

    #[test]
    fn write_then_read_gives_the_same_recording(r in recording()) {
        let bytes = r.write(Vec::new()).unwrap();
        let back = Recording::read(&bytes[..]).unwrap();
        prop_assert_eq!(&back, &r);
        prop_assert_eq!(bits(&back), bits(&r));
        // The writer's layout is canonical: writing again gives the same bytes.
        prop_assert_eq!(back.write(Vec::new()).unwrap(), bytes);
    }
}
