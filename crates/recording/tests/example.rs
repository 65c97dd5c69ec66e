//! The example recording of `docs/recording-format.md` reads as the page describes it, and
//! is in the writer's canonical layout (writing what was read gives the same bytes).

#![allow(clippy::unwrap_used, clippy::expect_used)]

use recording::*;

#[test]
fn the_documented_example_reads_and_is_canonical() {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../../docs/examples/two-cubes.jsonl");
    let bytes = std::fs::read(path).unwrap();
    let r = Recording::read(&bytes[..]).unwrap();
    let h = &r.header;
    assert_eq!(h.id, "two-cubes");
    assert_eq!(h.frame_rate, 2.0);
    let names: Vec<&str> = h.entities.iter().map(|e| e.name.as_str()).collect();
    assert_eq!(names, ["right_hand", "cube_a", "cube_b", "table"]);
    let (hand, a, b, table) = (EntityId(0), EntityId(1), EntityId(2), EntityId(3));
    assert!(h.entity(table).fixed.is_some());
    assert_eq!(r.frames.len(), 7);
    assert_eq!(r.duration(), 3.0);
    // The hand holds cube_a from 1 s to 2 s, and puts it on cube_b.
    let held: Vec<f64> = r
        .frames
        .iter()
        .filter(|f| f.state(hand).unwrap().holding == Some(a))
        .map(|f| f.time)
        .collect();
    assert_eq!(held, [1.0, 1.5, 2.0]);
    let last = r.frames.last().unwrap();
    let za = last.state(a).unwrap().pose.position.z;
    let zb = last.state(b).unwrap().pose.position.z;
    assert!((za - zb - 0.05).abs() < 1e-6);
    assert!(last.contacts.contains(&Contact { a, b }));
    // cube_b was not tracked at 2.5 s.
    assert!(r.frames[5].state(b).is_none());
    assert_eq!(last.pose(h, table).unwrap().position.z, 0.375);
    // Canonical: writing it again gives the same bytes.
    assert_eq!(r.write(Vec::new()).unwrap(), bytes);
}
