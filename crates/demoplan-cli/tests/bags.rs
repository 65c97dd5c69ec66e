//! `demoplan import` and `inspect` on ROS bags: the committed fixtures of
//! `crates/bags/tests/fixtures` import; broken copies of them exit 31 with a message naming
//! the file and the place, and leave no output behind. Snapshots (insta) pin the messages.

#![allow(clippy::unwrap_used, clippy::expect_used)] // tests fail loudly by design

use std::path::{Path, PathBuf};
use std::process::Output;

mod common;
use common::demoplan;

fn bag_fixtures() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../bags/tests/fixtures")
}

/// A temporary folder, removed when dropped.
struct TempDir(PathBuf);

impl TempDir {
    fn new(case: &str) -> TempDir {
        let dir = std::env::temp_dir().join(format!("demoplan-bags-{}-{case}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir_all(&dir).unwrap();
        TempDir(dir)
    }
}

impl Drop for TempDir {
    fn drop(&mut self) {
        let _ = std::fs::remove_dir_all(&self.0);
    }
}

/// Exit code, standard output and standard error, with the temporary folder as `[TMP]`.
fn transcript(out: &Output, tmp: &Path) -> String {
    common::transcript(out).replace(&tmp.display().to_string(), "[TMP]")
}

#[test]
fn every_container_imports_with_its_report() {
    let tmp = TempDir::new("good");
    let out_dir = tmp.0.join("out");
    let sources =
        ["p01-d01.bz2.bag", "p01-d01.lz4.bag", "p01-d01-ros2"].map(|s| bag_fixtures().join(s));
    let out = demoplan()
        .arg("import")
        .args(&sources)
        .arg("-o")
        .arg(&out_dir)
        .output()
        .unwrap();
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert_eq!(
        stdout.matches("1150 frames over 12.844 s").count(),
        3,
        "{stdout}"
    );
    assert!(stdout.contains("Hand_R -> right_hand"), "{stdout}");
    assert!(
        stdout.contains("tracker_origin (glob \"*origin*\" says ignore)"),
        "{stdout}"
    );
    for stem in ["p01-d01.bz2", "p01-d01.lz4", "p01-d01-ros2"] {
        let text = std::fs::read_to_string(out_dir.join(format!("{stem}.jsonl"))).unwrap();
        assert_eq!(text.lines().count(), 1151, "{stem}: header and 1150 frames");
    }
    // inspect takes the bag itself.
    let out = demoplan()
        .arg("inspect")
        .arg(bag_fixtures().join("p01-d01.lz4.bag"))
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(0));
    assert!(String::from_utf8_lossy(&out.stdout).contains("tf_root=world"));
}

/// Writes `bytes` as `name` in `dir`.
fn write(dir: &Path, name: &str, bytes: &[u8]) -> PathBuf {
    let path = dir.join(name);
    std::fs::write(&path, bytes).unwrap();
    path
}

#[test]
fn broken_bags_exit_31_naming_file_and_place_and_write_nothing() {
    let tmp = TempDir::new("broken");
    let good = std::fs::read(bag_fixtures().join("p01-d01.bz2.bag")).unwrap();
    let mcap = std::fs::read(bag_fixtures().join("p01-d01-ros2/p01-d01-ros2.mcap")).unwrap();
    let mut unknown = good.clone();
    let field = b"compression=bz2";
    let at = unknown
        .windows(field.len())
        .position(|w| w == field)
        .unwrap()
        + "compression=".len();
    unknown[at..at + 3].copy_from_slice(b"xz9");
    let mut damaged = good.clone();
    for byte in &mut damaged[4500..4600] {
        *byte ^= 0x5a;
    }
    let objects = "[bag]\nclock_topic = \"/demoplan/objects\"\n[bag.objects]\ntopic = \"/demoplan/objects\"\nlist = \"objects\"\nname = \"name\"\npose = \"pos\"\n";
    let cases: Vec<(&str, PathBuf, Option<&str>)> = vec![
        (
            "cut-bag",
            write(&tmp.0, "cut.bag", &good[..good.len() / 2]),
            None,
        ),
        (
            "cut-mcap",
            write(&tmp.0, "cut.mcap", &mcap[..mcap.len() / 2]),
            None,
        ),
        (
            "unknown-compression",
            write(&tmp.0, "unknown.bag", &unknown),
            None,
        ),
        (
            "damaged-chunk",
            write(&tmp.0, "damaged.bag", &damaged),
            None,
        ),
        (
            "empty-file",
            write(&tmp.0, "empty.bag", b"#ROSBAG V2.0\n"),
            None,
        ),
        (
            "missing-topic",
            bag_fixtures().join("p01-d01.bz2.bag"),
            Some("[bag]\ntopics = [\"/cameras/pose\"]\n"),
        ),
        (
            "missing-field",
            bag_fixtures().join("p01-d01-ros2"),
            Some(objects),
        ),
    ];
    for (case, source, mapping) in cases {
        let out_dir = tmp.0.join(format!("out-{case}"));
        let mut cmd = demoplan();
        cmd.arg("import").arg(&source).arg("-o").arg(&out_dir);
        if let Some(text) = mapping {
            cmd.arg("--mapping")
                .arg(write(&tmp.0, &format!("{case}.toml"), text.as_bytes()));
        }
        let out = cmd.output().unwrap();
        assert_eq!(
            out.status.code(),
            Some(31),
            "{case}: {}",
            String::from_utf8_lossy(&out.stderr)
        );
        let stderr = String::from_utf8_lossy(&out.stderr);
        let name = source.file_name().unwrap().to_string_lossy();
        assert!(
            stderr.contains(&*name),
            "{case}: the message names the file: {stderr}"
        );
        let written: Vec<_> = std::fs::read_dir(&out_dir)
            .map(|d| d.flatten().collect())
            .unwrap_or_default();
        assert!(written.is_empty(), "{case}: left {written:?}");
        let text =
            transcript(&out, &tmp.0).replace(&bag_fixtures().display().to_string(), "[FIXTURES]");
        insta::assert_snapshot!(format!("bag-{case}"), text);
    }
}

/// The two-handed fixture: a recording of the simulator's `two-handed` style written by
/// Python's `rosbags` as real labs' bags are, `/tf` poses alone (no grip, no held
/// object, no contacts). With the default mapping the import finds each hand's grasp
/// from geometry, and its segments show both hands at work at once: a segment of one hand
/// with a cube in hand (Put, Stack, Take) overlaps a Reach or a held cube of the other.
#[test]
fn a_two_handed_bag_with_poses_alone_imports_with_grasps_from_geometry() {
    let tmp = TempDir::new("two-handed");
    let out = demoplan()
        .arg("import")
        .arg(bag_fixtures().join("two-handed.bz2.bag"))
        .arg("-o")
        .arg(&tmp.0)
        .output()
        .unwrap();
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert_eq!(out.status.code(), Some(0), "{}", transcript(&out, &tmp.0));
    assert!(stdout.contains("grasps = \"geometry\""), "{stdout}");
    let grasps: usize = stdout
        .lines()
        .find_map(|l| l.trim().strip_prefix("grasps found: "))
        .and_then(|n| n.trim().parse().ok())
        .unwrap_or_else(|| panic!("no grasp count in {stdout}"));
    assert!(grasps >= 2, "{stdout}");

    let imported = tmp.0.join("two-handed.bz2.jsonl");
    let text = std::fs::read_to_string(&imported).unwrap();
    // Poses alone came in: the grips are the import's (0 or 1, from geometry).
    assert!(!text.contains("\"contacts\""));
    let segmented = demoplan()
        .args(["segment", "--json"])
        .arg(&imported)
        .output()
        .unwrap();
    assert_eq!(segmented.status.code(), Some(0));
    let doc: serde_json::Value = serde_json::from_slice(&segmented.stdout).unwrap();
    let segments = doc["files"][0]["segments"].as_array().unwrap();
    struct Seg<'a> {
        hand: &'a str,
        start: f64,
        end: f64,
        activity: &'a str,
        in_hand: Option<&'a str>,
    }
    let segs: Vec<Seg<'_>> = segments
        .iter()
        .map(|s| Seg {
            hand: s["hand"].as_str().unwrap(),
            start: s["start"].as_f64().unwrap(),
            end: s["end"].as_f64().unwrap(),
            activity: s["activity"].as_str().unwrap(),
            in_hand: s["in_hand"].as_str(),
        })
        .collect();
    // Each hand holds a cube at some time, and they hold different cubes.
    let held = |hand: &str| -> Vec<&str> {
        let mut cubes: Vec<&str> = (segs.iter())
            .filter(|s| s.hand == hand)
            .filter_map(|s| s.in_hand)
            .collect();
        cubes.dedup();
        cubes
    };
    let (left, right) = (held("left_hand"), held("right_hand"));
    assert!(!left.is_empty() && !right.is_empty(), "{left:?} {right:?}");
    assert!(
        left.iter().all(|c| !right.contains(c)),
        "{left:?} {right:?}"
    );
    // One hand carries (a cube in hand, moving it: Put or Stack) while the other reaches
    // or holds its own.
    let overlap = segs.iter().any(|a| {
        matches!(a.activity, "Put" | "Stack")
            && segs.iter().any(|b| {
                b.hand != a.hand
                    && (b.activity == "Reach" || b.in_hand.is_some())
                    && b.start < a.end
                    && a.start < b.end
            })
    });
    assert!(overlap, "no overlapping activities of the two hands");
}

/// Issue 39, end to end on the fixture from another writer: the two-handed bag imported,
/// learned, and Algorithm 1's plans for towers of 2 to 6 cubes, with one hand and two,
/// executed in the cube world (`solve`'s default loop, then `execute` on the plan it
/// wrote). With `--no-execute`, towers of 2 and 3 execute as planned; the taller ones
/// reuse an operator whose effects a grasp known from geometry alone leaves late (the
/// cube lands while the hand is still seen to hold it, docs/operators.md), which the loop
/// sets aside.
#[test]
fn a_two_handed_bag_learns_operators_whose_plans_execute() {
    let tmp = TempDir::new("two-handed-plans");
    let dir = &tmp.0;
    let run = |args: &[&str]| {
        let out = demoplan().args(args).current_dir(dir).output().unwrap();
        (out.status.code(), common::transcript(&out))
    };
    let bag = bag_fixtures().join("two-handed.bz2.bag");
    let (code, text) = run(&["import", bag.to_str().unwrap(), "-o", "imported"]);
    assert_eq!(code, Some(0), "{text}");
    let (code, text) = run(&["learn", "-o", "library.json", "imported"]);
    assert_eq!(code, Some(0), "{text}");
    assert!(text.contains("mended "), "{text}");
    for hands in ["1", "2"] {
        for height in 2..=6 {
            let tower: Vec<String> = (1..=height).map(|i| format!("cube_{i}")).collect();
            let what = format!("{hands} hand(s), tower of {height}");
            let tower = tower.join(",");
            let (code, text) = run(&[
                "problem", "--tower", &tower, "--hands", hands, "-o", "p.pddl",
            ]);
            assert_eq!(code, Some(0), "{what}: {text}");
            let mut modes = vec![true];
            if height <= 3 {
                modes.push(false);
            }
            for execute in modes {
                let mut args = vec!["solve", "library.json", "p.pddl", "--plan-file", "p.plan"];
                if !execute {
                    args.push("--no-execute");
                }
                let (code, text) = run(&args);
                assert_eq!(code, Some(0), "{what}, execute {execute}: {text}");
                let prio = text
                    .lines()
                    .find_map(|l| l.strip_prefix("Solution found at priority "))
                    .and_then(|l| l.split_whitespace().next())
                    .unwrap_or_else(|| panic!("{what}: no priority in {text}"))
                    .to_string();
                let (code, text) =
                    run(&["domain", "library.json", "--prio", &prio, "-o", "d.pddl"]);
                assert_eq!(code, Some(0), "{what}: {text}");
                let (code, text) = run(&["execute", "d.pddl", "p.pddl", "p.plan"]);
                assert_eq!(code, Some(0), "{what}, execute {execute}: {text}");
            }
        }
    }
}
