//! The Unity reader and the import core on small logs written here: poses convert to
//! REP 103, tables, grasps, gaps and velocities come out as documented, and a source
//! written in a dozen lines (native frames replayed as events) plugs into the core.

#![allow(clippy::unwrap_used, clippy::expect_used)] // tests fail loudly by design

use grounding::{Grounder, GroundingConfig};
use import::{
    import, unity::UnityLog, Event, Format, GraspSource, ImportError, Mapping, Observation, Report,
    Sink, Source,
};
use recording::{Quaternion, Recording, Vec3};

/// A record of a step: name, Unity position, [w, x, y, z], velocity, events (JSON).
fn record(name: &str, p: [f64; 3], q: [f64; 4], v: [f64; 3], events: &str) -> String {
    format!(
        r#"{{"name":"{name}","position":{p:?},"orientation":{q:?},"velocity":{v:?},"events":[{events}]}}"#
    )
}

fn log(steps: &[(f64, Vec<String>)]) -> String {
    let steps: Vec<String> = steps
        .iter()
        .map(|(t, records)| format!("{{\"time\":{t},\"logStep\":[\n{}\n]}}", records.join(",\n")))
        .collect();
    format!(
        "{{\"playbackTimestepMilliseconds\":20,\"log\":[\n{}\n]}}\n",
        steps.join(",\n")
    )
}

fn run(text: &str, mapping: &Mapping) -> Result<(Recording, Report), ImportError> {
    let mut source = UnityLog::new(|| Ok(text.as_bytes()));
    let (bytes, _, report) = import(&mut source, mapping, "test", Vec::new())?;
    Ok((Recording::read(&bytes[..]).unwrap(), report))
}

const ID: [f64; 4] = [1.0, 0.0, 0.0, 0.0];
const STILL: [f64; 3] = [0.0; 3];

fn close(a: [f32; 3], b: [f32; 3]) -> bool {
    a.iter().zip(b).all(|(x, y)| (x - y).abs() < 1e-5)
}

#[test]
fn stated_poses_convert_to_rep_103() {
    let h = std::f64::consts::FRAC_PI_4;
    let turn_y = [h.cos(), 0.0, h.sin(), 0.0]; // +90 degrees about Unity's y
    let text = log(&[(
        0.0,
        vec![
            record("Cube_a", [1.0, 2.0, 3.0], turn_y, STILL, ""),
            record("Cube_b", [0.0, 0.8, 0.4], ID, STILL, ""),
        ],
    )]);
    let (rec, _) = run(&text, &Mapping::default_for(Format::Unity)).unwrap();
    let a = rec.frames[0]
        .state(rec.header.find("Cube_a").unwrap())
        .unwrap();
    assert!(
        close(a.pose.position.to_array(), [3.0, -1.0, 2.0]),
        "{:?}",
        a.pose
    );
    // -90 degrees about z: (x, y, z, w) = (0, 0, -sin 45, cos 45).
    let q = a.pose.orientation;
    let s = (h.sin()) as f32;
    assert!(
        close([q.x, q.y, q.z], [0.0, 0.0, -s]) && (q.w - s).abs() < 1e-5,
        "{q:?}"
    );
    assert!((q.yaw() + std::f32::consts::FRAC_PI_2).abs() < 1e-5);
}

/// Rotations stay proper: the converted rotation acting on converted vectors is the
/// conversion of the Unity rotation acting on Unity vectors, and its matrix has
/// determinant +1.
#[test]
fn converted_rotations_are_proper_and_agree_with_converted_vectors() {
    let m = |v: Vec3| Vec3::new(v.z, -v.x, v.y); // Unity to REP 103
    for (w, x, y, z) in [
        (0.9, 0.1, -0.3, 0.2),
        (0.2, 0.7, 0.1, -0.6),
        (0.5, -0.5, 0.5, 0.5),
        (0.0, 0.0, 1.0, 0.0),
    ] {
        let n = f64::sqrt(w * w + x * x + y * y + z * z);
        let q = [w / n, x / n, y / n, z / n];
        let text = log(&[(0.0, vec![record("Cube_a", [0.0, 1.0, 0.0], q, STILL, "")])]);
        let (rec, _) = run(&text, &Mapping::default_for(Format::Unity)).unwrap();
        let converted = rec.frames[0].states[0].unwrap().pose.orientation;
        // Unity's rotation, applied with the same quaternion algebra in Unity's axes.
        let unity = Quaternion::new(q[1] as f32, q[2] as f32, q[3] as f32, q[0] as f32);
        let basis = [
            Vec3::new(1.0, 0.0, 0.0),
            Vec3::new(0.0, 1.0, 0.0),
            Vec3::new(0.0, 0.0, 1.0),
        ];
        let mut columns = Vec::new();
        for u in [
            Vec3::new(0.3, -1.2, 0.7),
            Vec3::new(1.0, 0.0, 0.0),
            Vec3::new(0.0, 0.0, 2.0),
        ] {
            let expected = m(unity.rotate(u));
            let got = converted.rotate(m(u));
            assert!(
                close(expected.to_array(), got.to_array()),
                "{q:?}: {expected:?} vs {got:?}"
            );
        }
        for b in basis {
            columns.push(converted.rotate(b));
        }
        let det = columns[0].dot(Vec3::new(
            columns[1].y * columns[2].z - columns[1].z * columns[2].y,
            columns[1].z * columns[2].x - columns[1].x * columns[2].z,
            columns[1].x * columns[2].y - columns[1].y * columns[2].x,
        ));
        assert!((det - 1.0).abs() < 1e-4, "{q:?}: det {det}");
    }
}

/// A table whose pivot is on the floor (geometry unknown): the support surface comes
/// from the cube resting on it, and the grounding sees the cube on the table.
#[test]
fn a_cube_resting_on_a_table_with_its_pivot_on_the_floor_grounds_on_top() {
    let steps: Vec<(f64, Vec<String>)> = (0..20)
        .map(|k| {
            (
                f64::from(k) * 50.0,
                vec![
                    record("VR_Controller_R", [0.3, 1.0, 0.1], ID, STILL, ""),
                    record("3DPrintedCube_red", [0.0, 0.775, 0.5], ID, STILL, ""),
                    record("Table_1", [0.0, 0.0, 0.5], ID, STILL, ""),
                    record("Table_2", [3.0, 0.0, 0.5], ID, STILL, ""),
                ],
            )
        })
        .collect();
    let (rec, report) = run(&log(&steps), &Mapping::default_for(Format::Unity)).unwrap();
    let table = rec
        .header
        .find("Table_1")
        .expect("the table is named after the nearest");
    let fixed = rec.header.entity(table).fixed.unwrap();
    let size = rec.header.entity(table).size;
    assert!(
        (fixed.position.z + size.z / 2.0 - 0.75).abs() < 1e-5,
        "{fixed:?} {size:?}"
    );
    assert!(
        report.ignored.iter().any(|i| i.source == "Table_2"),
        "{report:?}"
    );
    let facts = grounded_facts(&rec);
    assert!(
        facts
            .iter()
            .any(|f| f == "onTop(cube_3DPrintedCube_red, Table_1)"),
        "{facts:?}"
    );
}

/// A table whose size the mapping gives, pivot at the bottom: its pose is its first
/// pose, lifted by half its height.
#[test]
fn a_table_of_known_size_keeps_its_pose_with_the_origin_applied() {
    let mapping = Mapping::from_toml(
        "[[entity]]\nname = \"Table_1\"\nrole = \"table\"\nsize = [1.0, 0.8, 0.75]\norigin = \"bottom\"\n",
        Format::Unity,
    )
    .unwrap();
    let text = log(&[(
        0.0,
        vec![
            record("3DPrintedCube_red", [0.0, 0.775, 0.5], ID, STILL, ""),
            record("Table_1", [0.1, 0.0, 0.4], ID, STILL, ""),
        ],
    )]);
    let (rec, report) = run(&text, &mapping).unwrap();
    let t = rec.header.entity(rec.header.find("Table_1").unwrap());
    assert!(
        close(t.fixed.unwrap().position.to_array(), [0.4, -0.1, 0.375]),
        "{t:?}"
    );
    assert!(report.table.contains("first pose"), "{}", report.table);
}

/// Every fact that holds in some frame, with entity names.
fn grounded_facts(rec: &Recording) -> Vec<String> {
    let mut g = Grounder::new(&rec.header, &GroundingConfig::default());
    let space = grounding::FactSpace::new(&rec.header);
    let mut out = Vec::new();
    let mut collect = |f: &grounding::GroundedFrame<'_>| {
        out.extend(
            f.state
                .facts(&space)
                .map(|x| x.display(&rec.header).to_string()),
        );
    };
    for frame in &rec.frames {
        g.push(frame, &mut collect);
    }
    g.finish(&mut collect);
    out.sort();
    out.dedup();
    out
}

#[test]
fn grab_events_hold_the_named_object_until_released() {
    let press = r#"{"name":"OnGrabPressReplay","property":"3DPrintedCube_red,42"}"#;
    let release = r#"{"name":"OnGrabReleaseReplay","property":""}"#;
    let step = |t: f64, events: &str| {
        (
            t,
            vec![
                record("VR_Controller_L", [0.0, 0.8, 0.5], ID, STILL, events),
                record("3DPrintedCube_red", [0.0, 0.775, 0.5], ID, STILL, ""),
            ],
        )
    };
    let text = log(&[
        step(0.0, ""),
        step(50.0, press),
        step(100.0, ""),
        step(150.0, release),
        step(200.0, ""),
    ]);
    let (rec, report) = run(&text, &Mapping::default_for(Format::Unity)).unwrap();
    let hand = rec.header.find("left_hand").unwrap();
    let cube = rec.header.find("cube_3DPrintedCube_red").unwrap();
    let held: Vec<(Option<f32>, Option<recording::EntityId>)> = rec
        .frames
        .iter()
        .map(|f| {
            let s = f.state(hand).unwrap();
            (s.grip, s.holding)
        })
        .collect();
    assert_eq!(
        held,
        [
            (Some(0.0), None),
            (Some(1.0), Some(cube)),
            (Some(1.0), Some(cube)),
            (Some(0.0), None),
            (Some(0.0), None)
        ]
    );
    assert_eq!(report.grasps, 1);
    let times: Vec<f64> = rec.frames.iter().map(|f| f.time).collect();
    assert_eq!(times, [0.0, 0.05, 0.1, 0.15, 0.2]);
}

/// Entities missing from a step are missing from its frame (`max_age = 0` for Unity),
/// gaps are reported, an entity may first appear mid-log, zero velocities are left out
/// and real ones kept (converted).
#[test]
fn missing_late_entities_gaps_and_velocities() {
    let hand = |x: f64| record("VR_Controller_R", [x, 1.0, 0.2], ID, [0.5, 0.0, 0.0], "");
    let cube = record("Cube_1", [0.0, 0.775, 0.4], ID, STILL, "");
    let late = record("Cube_2", [0.2, 0.775, 0.4], ID, STILL, "");
    let text = log(&[
        (0.0, vec![hand(0.0), cube.clone()]),
        (50.0, vec![cube.clone()]),
        (100.0, vec![cube.clone()]),
        (150.0, vec![hand(0.1), cube.clone(), late.clone()]),
        (200.0, vec![hand(0.2), cube.clone(), late.clone()]),
    ]);
    let (rec, report) = run(&text, &Mapping::default_for(Format::Unity)).unwrap();
    let h = rec.header.find("right_hand").unwrap();
    let c2 = rec.header.find("Cube_2").unwrap();
    let present: Vec<bool> = rec.frames.iter().map(|f| f.state(h).is_some()).collect();
    assert_eq!(present, [true, false, false, true, true]);
    assert_eq!(rec.frames[0].state(c2), None);
    assert!(rec.frames[3].state(c2).is_some());
    assert_eq!((report.gap_count, report.gaps.len()), (1, 1), "{report:?}");
    assert_eq!((report.gaps[0].from, report.gaps[0].to), (0.0, 0.15));
    // Unity velocity (0.5, 0, 0) is REP 103 (0, -0.5, 0); the cubes' zeros are left out.
    assert_eq!(
        rec.frames[0].state(h).unwrap().velocity,
        Some(Vec3::new(0.0, -0.5, 0.0))
    );
    assert_eq!(rec.frames[3].state(c2).unwrap().velocity, None);

    // With max_age 0.1 s the hand's last pose stands in for 0.1 s.
    let mapping = Mapping::from_toml("max_age = 0.1", Format::Unity).unwrap();
    let (rec, _) = run(&text, &mapping).unwrap();
    let present: Vec<bool> = rec.frames.iter().map(|f| f.state(h).is_some()).collect();
    assert_eq!(present, [true, true, true, true, true]);
}

fn problem_of(text: &str) -> String {
    match run(text, &Mapping::default_for(Format::Unity)) {
        Err(ImportError::Input(e)) => e.to_string(),
        other => panic!("expected an input error, got {other:?}"),
    }
}

#[test]
fn bad_logs_name_step_entity_and_field() {
    let ok = |t| (t, vec![record("Cube_1", [0.0, 0.775, 0.4], ID, STILL, "")]);
    let nan = log(&[
        ok(0.0),
        (
            50.0,
            vec![
                r#"{"name":"Cube_1","position":["NaN",0.775,0.4],"orientation":[1,0,0,0]}"#
                    .to_string(),
            ],
        ),
    ]);
    assert_eq!(
        problem_of(&nan),
        "step 1, line 7: entity `Cube_1`, field `logStep[0].position[0]`: NaN is not a finite position"
    );
    let backwards = log(&[ok(0.0), ok(50.0), ok(20.0)]);
    assert!(
        problem_of(&backwards).contains("time goes backwards"),
        "{}",
        problem_of(&backwards)
    );
    let unknown = log(&[(
        0.0,
        vec![
            record(
                "VR_Controller_L",
                [0.0, 0.8, 0.5],
                ID,
                STILL,
                r#"{"name":"OnGrabPressReplay","property":"Cube_9,3"}"#,
            ),
            record("Cube_1", [0.0, 0.775, 0.4], ID, STILL, ""),
        ],
    )]);
    assert!(problem_of(&unknown).contains("names `Cube_9`, which is not an entity of the source"));
    let twice = log(&[(
        0.0,
        vec![
            record("Cube_1", [0.0, 0.775, 0.4], ID, STILL, ""),
            record("Cube_1", [0.1, 0.775, 0.4], ID, STILL, ""),
        ],
    )]);
    assert!(problem_of(&twice).contains("appears twice in one step"));
    let truncated = &log(&[ok(0.0), ok(50.0)])[..60];
    assert!(
        problem_of(truncated).contains("truncated"),
        "{}",
        problem_of(truncated)
    );
}

/// A step is read whole, so one over `MAX_STEP_BYTES` (here a record whose name pads it
/// out) is an input error naming the step and its line, not a buffer as large as the
/// file; the same for text before the `log` list.
#[test]
fn a_step_over_the_maximum_size_is_an_error_naming_it() {
    let ok = |t| (t, vec![record("Cube_1", [0.0, 0.775, 0.4], ID, STILL, "")]);
    let max = usize::try_from(import::unity::MAX_STEP_BYTES).unwrap();
    let padded = |t, pad: usize| {
        let mut step = ok(t);
        step.1
            .push(record(&"x".repeat(pad), [0.0, 0.8, 0.5], ID, STILL, ""));
        step
    };
    let over = log(&[ok(0.0), ok(20.0), padded(40.0, max)]);
    assert_eq!(
        problem_of(&over),
        "step 2, line 10: the step is longer than 67108864 bytes, the most a Unity log step \
         may have (a step is read whole)"
    );
    let prefix = format!(
        "{{\"notes\":\"{}\",{}",
        "n".repeat(max),
        &log(&[ok(0.0)])[1..]
    );
    assert_eq!(
        problem_of(&prefix),
        "line 1: the text before the `log` list is longer than 67108864 bytes, the most a \
         Unity log step may have (a step is read whole)"
    );
}

/// A source needs only `pass`: here, native frames replayed as observations without
/// their grasps, so that the core finds the grasps from geometry. On a simulated
/// demonstration the grasps found are the simulator's.
struct NativeFrames<'a>(&'a Recording);

impl Source for NativeFrames<'_> {
    fn format(&self) -> Format {
        Format::Ros2
    }

    fn pass(&mut self, sink: &mut dyn Sink) -> Result<(), ImportError> {
        let mut o = Observation::default();
        for (k, frame) in self.0.frames.iter().enumerate() {
            for id in self.0.header.ids() {
                let Some(s) = frame.state(id) else { continue };
                o.time = frame.time;
                o.name.clone_from(&self.0.header.entity(id).name);
                o.position = s.pose.position.to_array().map(f64::from);
                o.orientation = s.pose.orientation.to_array().map(f64::from);
                o.held = None;
                sink.event(Event::Observe(&o)).map_err(|p| {
                    ImportError::input(
                        import::Location {
                            step: Some(k as u64),
                            ..Default::default()
                        },
                        p,
                    )
                })?;
            }
            sink.event(Event::Frame(frame.time)).map_err(|p| {
                ImportError::input(
                    import::Location {
                        step: Some(k as u64),
                        ..Default::default()
                    },
                    p,
                )
            })?;
        }
        Ok(())
    }
}

#[test]
fn grasps_from_geometry_find_the_simulated_grasps() {
    let study = simulate::default_study();
    let demo = &study.demonstrations[0];
    let frames: Vec<recording::Frame> = demo.frames().map(|(f, _)| f).collect();
    let original = Recording {
        header: demo.header().clone(),
        frames,
    };
    let mut mapping = Mapping::default_for(Format::Ros2);
    mapping.grasps = GraspSource::Geometry;
    let mut source = NativeFrames(&original);
    let (bytes, _, report) = import(&mut source, &mapping, "geometry", Vec::new()).unwrap();
    let imported = Recording::read(&bytes[..]).unwrap();
    let grasps_in = |r: &Recording, hand: &str| -> Vec<String> {
        let h = r.header.find(hand).unwrap();
        let mut held = Vec::new();
        let mut last = None;
        for f in &r.frames {
            let now = f.state(h).and_then(|s| s.holding);
            if let Some(cube) = now.filter(|_| now != last) {
                held.push(r.header.entity(cube).name.clone());
            }
            if f.state(h).is_some() {
                last = now;
            }
        }
        held
    };
    for hand in ["left_hand", "right_hand"] {
        assert_eq!(
            grasps_in(&imported, hand),
            grasps_in(&original, hand),
            "{hand}"
        );
    }
    assert!(report.grasps >= 1);
}
