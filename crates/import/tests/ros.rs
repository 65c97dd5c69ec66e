//! ROS bags through the import, on the committed fixtures of `crates/bags/tests/fixtures`
//! (written by Python's `rosbags` from the simulated recordings beside them): the custom
//! object-list message gives back every field of the recording, `/tf` alone its poses.

#![allow(clippy::unwrap_used, clippy::expect_used)]

use std::path::{Path, PathBuf};

use import::ros::RosBag;
use import::{import, Format, Mapping};
use recording::{EntityId, Header, Recording};

fn fixtures() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../bags/tests/fixtures")
}

fn original(stem: &str) -> Recording {
    let text = std::fs::read(fixtures().join("recordings").join(format!("{stem}.jsonl"))).unwrap();
    Recording::read(&text[..]).unwrap()
}

/// The fixture bags of one recording: ROS 1 with bz2 and lz4 chunks, ROS 2 with MCAP.
fn bags_of(stem: &str) -> [(PathBuf, Format); 3] {
    [
        (fixtures().join(format!("{stem}.bz2.bag")), Format::Ros1),
        (fixtures().join(format!("{stem}.lz4.bag")), Format::Ros1),
        (fixtures().join(format!("{stem}-ros2")), Format::Ros2),
    ]
}

fn import_bag(path: &Path, mapping: &Mapping) -> Recording {
    let mut source = RosBag::open(path, mapping).unwrap();
    let (bytes, _, _) = import(&mut source, mapping, "imported", Vec::new()).unwrap();
    Recording::read(&bytes[..]).unwrap()
}

/// The mapping of the fixtures' object list: every field it has. Grasps and contacts
/// then come from its fields (`held`, `grabbed_by`, `contacts`) without saying so.
const OBJECTS_MAPPING: &str = r#"
entity = [{ name = "table", role = "table", size = [0.8, 1.2, 0.75] }]

[bag]
clock_topic = "/demoplan/objects"

[bag.objects]
topic = "/demoplan/objects"
list = "objects"
name = "name"
pose = "pose"
velocity = "velocity[]"
grip = "grip[]"
held = "held"
grabbed_by = "grabbed_by"
contacts = "contacts"
"#;

/// Whether two orientations are the same rotation: equal up to sign within 1e-6 once
/// normalised (the import normalises quaternions; the recordings' have four decimals).
fn same_rotation(a: recording::Quaternion, b: recording::Quaternion) -> bool {
    let unit = |q: recording::Quaternion| {
        let a = q.to_array().map(f64::from);
        let n = a.iter().map(|c| c * c).sum::<f64>().sqrt();
        a.map(|c| c / n)
    };
    let (a, b) = (unit(a), unit(b));
    let off = |sign: f64| {
        a.iter()
            .zip(&b)
            .map(|(x, y)| (x - sign * y).abs())
            .fold(0.0, f64::max)
    };
    off(1.0).min(off(-1.0)) <= 1e-6
}

/// The id in `imported` of `original`'s entity `id`, by name.
fn same(original: &Header, imported: &Header, id: EntityId) -> EntityId {
    let name = &original.entity(id).name;
    imported
        .find(name)
        .unwrap_or_else(|| panic!("{name} is not imported"))
}

#[test]
fn the_object_list_gives_back_every_field_of_the_recording() {
    for stem in ["p01-d01", "p01-d02"] {
        let want = original(stem);
        for (path, format) in bags_of(stem) {
            let mapping = Mapping::from_toml(OBJECTS_MAPPING, format).unwrap();
            let got = import_bag(&path, &mapping);
            let at = path.display();
            let (wh, gh) = (&want.header, &got.header);
            assert_eq!(
                gh.entities.len(),
                wh.entities.len(),
                "{at}: {:?}",
                gh.entities
            );
            for id in wh.ids() {
                let (w, g) = (wh.entity(id), gh.entity(same(wh, gh, id)));
                assert_eq!(
                    (g.kind, g.size, g.fixed),
                    (w.kind, w.size, w.fixed),
                    "{at}: entity {}",
                    w.name
                );
            }
            assert_eq!(got.frames.len(), want.frames.len(), "{at}");
            for (i, (w, g)) in want.frames.iter().zip(&got.frames).enumerate() {
                let t0 = want.frames[0].time;
                assert!(
                    (g.time - (w.time - t0)).abs() < 1e-6,
                    "{at}: frame {i} at {} s, not {} s",
                    g.time,
                    w.time
                );
                for id in wh.ids() {
                    let gid = same(wh, gh, id);
                    let (ws, gs) = (w.state(id), g.state(gid));
                    let holding = |s: &recording::EntityState, h: &Header| {
                        s.holding.map(|x| h.entity(x).name.clone())
                    };
                    match (ws, gs) {
                        (None, None) => {}
                        (Some(ws), Some(gs)) => {
                            let name = &wh.entity(id).name;
                            assert_eq!(
                                gs.pose.position, ws.pose.position,
                                "{at}: frame {i}, {name}"
                            );
                            assert!(
                                same_rotation(gs.pose.orientation, ws.pose.orientation),
                                "{at}: frame {i}, {name}: {:?} vs {:?}",
                                gs.pose.orientation,
                                ws.pose.orientation
                            );
                            assert_eq!(
                                gs.velocity,
                                ws.velocity,
                                "{at}: frame {i}, {}",
                                wh.entity(id).name
                            );
                            assert_eq!(gs.grip, ws.grip, "{at}: frame {i}, {}", wh.entity(id).name);
                            assert_eq!(
                                holding(gs, gh),
                                holding(ws, wh),
                                "{at}: frame {i}, {}",
                                wh.entity(id).name
                            );
                        }
                        _ => panic!(
                            "{at}: frame {i}, {}: {ws:?} became {gs:?}",
                            wh.entity(id).name
                        ),
                    }
                }
                let names = |f: &recording::Frame, h: &Header| {
                    let mut pairs: Vec<(String, String)> = f
                        .contacts
                        .iter()
                        .map(|c| {
                            let (a, b) = (h.entity(c.a).name.clone(), h.entity(c.b).name.clone());
                            if a < b {
                                (a, b)
                            } else {
                                (b, a)
                            }
                        })
                        .collect();
                    pairs.sort();
                    pairs
                };
                assert_eq!(names(g, gh), names(w, wh), "{at}: frame {i} contacts");
            }
        }
    }
}

#[test]
fn tf_alone_gives_the_poses_composed_through_the_tracker_frame() {
    for stem in ["p01-d01", "p01-d02"] {
        let want = original(stem);
        for (path, format) in bags_of(stem) {
            let got = import_bag(&path, &Mapping::default_for(format));
            let at = path.display();
            let (wh, gh) = (&want.header, &got.header);
            // tracker_origin is ignored by the default rules, the root `world` is no entity.
            assert!(
                gh.find("tracker_origin").is_none() && gh.find("world").is_none(),
                "{at}: {:?}",
                gh.entities
            );
            assert_eq!(got.frames.len(), want.frames.len(), "{at}");
            let moving: Vec<EntityId> = wh
                .ids()
                .filter(|&id| wh.entity(id).fixed.is_none())
                .collect();
            assert_eq!(moving.len(), 5);
            for (i, (w, g)) in want.frames.iter().zip(&got.frames).enumerate() {
                for &id in &moving {
                    let name = &wh.entity(id).name;
                    let (Some(ws), Some(gs)) = (w.state(id), g.state(same(wh, gh, id))) else {
                        panic!("{at}: frame {i}: {name} missing");
                    };
                    let d = ws.pose.position.distance(gs.pose.position);
                    assert!(d <= 1e-6, "{at}: frame {i}: {name} is {d} m off");
                    let (a, b) = (ws.pose.orientation, gs.pose.orientation);
                    assert!(
                        same_rotation(a, b),
                        "{at}: frame {i}: {name} turned: {a:?} vs {b:?}"
                    );
                }
            }
        }
    }
}

/// What `learn` makes of recordings: per operator (by rank and type) its count and cost.
fn library(recordings: &[Recording]) -> Vec<(String, u32, u64, String)> {
    let mut library = learn::Library::default();
    for r in recordings {
        learn::add_frames(
            &mut library,
            &r.header,
            r.frames.clone(),
            &grounding::GroundingConfig::default(),
            &segment::ActivityTree::table_one(),
            "",
        );
    }
    library
        .ranked()
        .iter()
        .map(|r| {
            (
                r.name(),
                r.cost,
                r.entry.count,
                format!("{:?}", r.entry.operator),
            )
        })
        .collect()
}

#[test]
fn learn_gives_the_same_library_on_the_imported_object_lists() {
    let originals: Vec<Recording> = ["p01-d01", "p01-d02"].map(original).into();
    let want = library(&originals);
    assert!(want.len() >= 4, "{want:?}");
    for container in 0..3 {
        let imported: Vec<Recording> = ["p01-d01", "p01-d02"]
            .map(|stem| {
                let (path, format) = &bags_of(stem)[container];
                import_bag(path, &Mapping::from_toml(OBJECTS_MAPPING, *format).unwrap())
            })
            .into();
        assert_eq!(library(&imported), want, "container {container}");
    }
}

#[test]
fn naming_grasp_and_contact_fields_makes_them_the_source() {
    let mapping = Mapping::from_toml(OBJECTS_MAPPING, Format::Ros2).unwrap();
    assert_eq!(mapping.grasps, import::GraspSource::Field);
    assert_eq!(mapping.contacts, import::ContactSource::Reported);
    let chosen = format!("grasps = \"geometry\"\ncontacts = \"geometry\"\n{OBJECTS_MAPPING}");
    let mapping = Mapping::from_toml(&chosen, Format::Ros2).unwrap();
    assert_eq!(mapping.grasps, import::GraspSource::Geometry);
    assert_eq!(mapping.contacts, import::ContactSource::Geometry);
    let tf_only = Mapping::default_for(Format::Ros1);
    assert_eq!(tf_only.grasps, import::GraspSource::Geometry);
}
