//! What `learn` reads (folders expanded, the simulator's files skipped) and its two
//! phases: a recording counted once however often it is given, and one that vanished from
//! the library between the phases segmented again.

#![allow(clippy::unwrap_used, clippy::expect_used)]

use std::path::{Path, PathBuf};

use grounding::GroundingConfig;
use learn::{learning_inputs, Batch, InputsError, Library, Segmented};
use segment::ActivityTree;

fn scratch(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("learn-inputs-{}-{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

/// The simulator's first demonstration, written as `demoplan simulate` writes it.
fn simulated(dir: &Path) -> PathBuf {
    let study = simulate::study(&simulate::SimParams::default(), 7, 1, 1).unwrap();
    let demo = &study.demonstrations[0];
    let path = dir.join(demo.recording_name());
    let mut bytes = Vec::new();
    let mut writer = recording::Writer::new(&mut bytes, demo.header()).unwrap();
    let mut frame = recording::Frame::default();
    let mut truth = simulate::TruthFrame::default();
    let mut frames = demo.frames();
    while frames.next_into(&mut frame, &mut truth) {
        writer.write_frame(&frame).unwrap();
    }
    writer.finish().unwrap();
    std::fs::write(&path, bytes).unwrap();
    path
}

fn segment_file(path: &Path) -> Result<Segmented, String> {
    let file = std::fs::File::open(path).map_err(|e| e.to_string())?;
    let mut reader =
        recording::Reader::new(std::io::BufReader::new(file)).map_err(|e| e.to_string())?;
    learn::segment_reader(
        &mut reader,
        &GroundingConfig::default(),
        &ActivityTree::table_one(),
        &mut (),
    )
    .map_err(|e| e.to_string())
}

fn hash_file(path: &Path) -> Result<String, String> {
    std::fs::File::open(path)
        .and_then(learn::content_hash)
        .map_err(|e| e.to_string())
}

#[test]
fn folders_are_expanded_sorted_and_the_simulators_files_skipped() {
    let dir = scratch("expand");
    for name in [
        "b.jsonl",
        "a.jsonl",
        "a.truth.jsonl",
        "simulation.json",
        "notes.md",
    ] {
        std::fs::write(dir.join(name), "{}\n").unwrap();
    }
    std::fs::write(dir.join("table.txt"), "% a table\n@relation hands\n").unwrap();
    let given = dir.join("a.truth.jsonl");
    let inputs = learning_inputs(&[dir.clone(), given]).unwrap();
    let names: Vec<String> = inputs
        .files
        .iter()
        .map(|p| p.file_name().unwrap().to_string_lossy().into_owned())
        .collect();
    assert_eq!(names, ["a.jsonl", "b.jsonl", "table.txt"]);
    assert_eq!(inputs.notes.len(), 2, "{:?}", inputs.notes);
    assert!(inputs.notes[0].contains("3 recording(s)"));
    assert!(inputs.notes[0].contains("skipped 2 file(s) of the simulator"));
    assert!(inputs.notes[0].contains("not recordings: notes.md"));
    assert!(inputs.notes[1].starts_with("skipped 1 file(s) of the simulator"));
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn a_folder_without_recordings_and_only_truth_files_are_errors() {
    let dir = scratch("empty");
    std::fs::write(dir.join("notes.md"), "hello").unwrap();
    let e = learning_inputs(std::slice::from_ref(&dir)).unwrap_err();
    assert!(matches!(e, InputsError::EmptyFolder(_)), "{e:?}");
    assert!(e.to_string().contains("holds no recording"));
    let e = learning_inputs(&[dir.join("x.truth.jsonl")]).unwrap_err();
    assert!(matches!(e, InputsError::Nothing), "{e:?}");
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn a_recording_given_twice_is_segmented_and_counted_once() {
    let dir = scratch("twice");
    let path = simulated(&dir);
    let files = vec![path.clone(), path.clone()];
    let mut segmented = 0;
    let batch = Batch::prepare(&files, None, hash_file, |p: &Path| {
        segmented += 1;
        segment_file(p)
    })
    .unwrap();
    assert_eq!(segmented, 1);
    let mut library = Library::default();
    let log = batch.add_to(&mut library, segment_file).unwrap();
    let lines: Vec<&str> = log.lines().collect();
    assert_eq!(lines.len(), 2);
    assert!(lines[0].contains("activities"), "{log}");
    assert!(lines[1].contains("already in the library"), "{log}");
    assert_eq!(library.recordings().count(), 1);
    assert!(library.segments() > 0);
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn a_recording_known_at_first_but_gone_at_the_write_is_segmented_then() {
    let dir = scratch("gone");
    let path = simulated(&dir);
    let files = vec![path];
    // The library as first read already counts the recording: phase one skips it.
    let mut first = Library::default();
    Batch::prepare(&files, None, hash_file, segment_file)
        .unwrap()
        .add_to(&mut first, segment_file)
        .unwrap();
    let mut segmented = 0;
    let batch = Batch::prepare(&files, Some(&first), hash_file, |p: &Path| {
        segmented += 1;
        segment_file(p)
    })
    .unwrap();
    assert_eq!(segmented, 0);
    // Meanwhile the library was replaced by an empty one: phase two segments it.
    let mut replaced = Library::default();
    let log = batch.add_to(&mut replaced, segment_file).unwrap();
    assert!(log.contains("activities"), "{log}");
    assert_eq!(replaced.segments(), first.segments());
    std::fs::remove_dir_all(&dir).unwrap();
}
