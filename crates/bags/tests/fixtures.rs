//! The committed bags of `tests/fixtures`, written by Python's `rosbags`
//! (`tools/make-bag-fixtures`) from the recordings beside them: every container and
//! compression decodes, to the values of the recording it came from; broken copies of
//! them are errors naming the file and the byte.

#![allow(clippy::unwrap_used, clippy::expect_used)]

use std::path::{Path, PathBuf};

use bags::{BagError, Format, Value};

fn fixtures() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/fixtures")
}

/// Each fixture bag with its format.
const BAGS: [(&str, Format); 3] = [
    ("p01-d01.bz2.bag", Format::Ros1),
    ("p01-d01.lz4.bag", Format::Ros1),
    ("p01-d01-ros2", Format::Ros2Folder),
];

fn recording_frames(stem: &str) -> Vec<serde_json::Value> {
    let text = std::fs::read_to_string(fixtures().join("recordings").join(format!("{stem}.jsonl")))
        .unwrap();
    text.lines()
        .skip(1)
        .map(|l| serde_json::from_str(l).unwrap())
        .collect()
}

/// The recording's name of a bag's entity (the bags call the hands `Hand_L`, `Hand_R`).
fn native(source: &str) -> &str {
    match source {
        "Hand_L" => "left_hand",
        "Hand_R" => "right_hand",
        other => other,
    }
}

fn f64_at(value: &Value, path: &str) -> f64 {
    value.lookup_one(path).unwrap().as_f64().unwrap()
}

#[test]
fn every_format_lists_the_three_topics_with_their_counts() {
    let frames = recording_frames("p01-d01").len() as u64;
    for (name, format) in BAGS {
        let bag = bags::open(&fixtures().join(name)).unwrap();
        assert_eq!(bag.format(), format, "{name}");
        let topics = bag.topics().unwrap();
        let listed: Vec<(&str, Option<u64>)> = topics
            .iter()
            .map(|t| (t.name.as_str(), t.message_count))
            .collect();
        assert_eq!(
            listed,
            [
                ("/demoplan/objects", Some(frames)),
                ("/tf", Some(frames)),
                ("/tf_static", Some(1))
            ],
            "{name}"
        );
        let objects = &topics[0];
        assert!(
            objects.type_name.ends_with("ObjectArray"),
            "{name}: {}",
            objects.type_name
        );
        assert!(
            objects.definition.contains("MSG: demoplan_msgs/Object"),
            "{name}"
        );
    }
}

#[test]
fn the_custom_message_decodes_to_the_recording_it_came_from() {
    let frames = recording_frames("p01-d01");
    for (name, _) in BAGS {
        let bag = bags::open(&fixtures().join(name)).unwrap();
        let mut seen = 0;
        for (message, frame) in bag
            .messages(|t| t == "/demoplan/objects")
            .unwrap()
            .zip(&frames)
        {
            let message = message.unwrap();
            assert_eq!(message.index, seen as u64);
            let stamp = message
                .value
                .lookup_one("header.stamp")
                .unwrap()
                .as_nanos()
                .unwrap();
            let t = frame["t"].as_f64().unwrap();
            assert!(
                ((stamp - 1_700_000_000_000_000_000) as f64 / 1e9 - t).abs() < 1e-9,
                "{name}: stamp {stamp} vs {t}"
            );
            assert_eq!(message.receive_time, stamp, "{name}");
            let entities = frame["entities"].as_object().unwrap();
            let objects = message.value.lookup("objects[]").unwrap();
            assert_eq!(
                objects.len(),
                entities.len() + 1,
                "{name} message {seen}: the entities and the table"
            );
            for object in objects {
                let source_name = object.lookup_one("name").unwrap().as_str().unwrap();
                let entity_name = native(source_name);
                let Some(state) = entities.get(entity_name) else {
                    // The fixed table, listed in every message but never in frames.
                    assert_eq!(entity_name, "table");
                    continue;
                };
                for (axis, at) in ["x", "y", "z"].iter().zip(0..) {
                    let want = state["pos"][at].as_f64().unwrap();
                    assert_eq!(
                        f64_at(object, &format!("pose.position.{axis}")),
                        want,
                        "{name} {entity_name}"
                    );
                }
                assert_eq!(
                    f64_at(object, "pose.orientation.w"),
                    state["rot"][3].as_f64().unwrap()
                );
                let velocity = object.lookup("velocity[].y").unwrap();
                assert_eq!(velocity.len(), usize::from(state.get("vel").is_some()));
                if let Some(grip) = state.get("grip") {
                    // float32 on the wire: the recording's f32 value exactly.
                    assert_eq!(
                        f64_at(object, "grip[0]") as f32,
                        grip.as_f64().unwrap() as f32
                    );
                }
                let held = object.lookup_one("held").unwrap().as_str().unwrap();
                assert_eq!(
                    held,
                    state.get("holding").and_then(|h| h.as_str()).unwrap_or("")
                );
                let touching = object
                    .lookup_one("contacts")
                    .unwrap()
                    .as_array()
                    .unwrap()
                    .len();
                let pairs = frame.get("contacts").and_then(|c| c.as_array());
                let expected = pairs.map_or(0, |pairs| {
                    pairs
                        .iter()
                        .filter(|pair| pair[0] == entity_name || pair[1] == entity_name)
                        .count()
                });
                assert_eq!(touching, expected, "{name} {entity_name}");
            }
            seen += 1;
        }
        assert_eq!(seen, frames.len(), "{name}");
    }
}

#[test]
fn tf_decodes_the_same_from_every_container() {
    let transforms = |name: &str| -> Vec<(i64, String, String, f64)> {
        let bag = bags::open(&fixtures().join(name)).unwrap();
        let mut out = Vec::new();
        for message in bag.messages(|t| t == "/tf" || t == "/tf_static").unwrap() {
            let message = message.unwrap();
            for transform in message.value.lookup("transforms[]").unwrap() {
                out.push((
                    transform
                        .lookup_one("header.stamp")
                        .unwrap()
                        .as_nanos()
                        .unwrap(),
                    transform
                        .lookup_one("header.frame_id")
                        .unwrap()
                        .as_str()
                        .unwrap()
                        .to_string(),
                    transform
                        .lookup_one("child_frame_id")
                        .unwrap()
                        .as_str()
                        .unwrap()
                        .to_string(),
                    f64_at(transform, "transform.rotation.z"),
                ));
            }
        }
        out
    };
    let ros1 = transforms("p01-d01.bz2.bag");
    assert!(ros1.len() > 1000);
    assert_eq!(ros1[0].1, "world");
    assert_eq!(ros1[0].2, "tracker_origin");
    assert_eq!(transforms("p01-d01.lz4.bag"), ros1);
    assert_eq!(transforms("p01-d01-ros2"), ros1);
}

/// A temporary folder, removed when dropped.
struct TempDir(PathBuf);

impl Drop for TempDir {
    fn drop(&mut self) {
        let _ = std::fs::remove_dir_all(&self.0);
    }
}

/// A copy of a fixture, changed by `patch`, in a temporary folder.
fn broken(name: &str, patch: impl FnOnce(&mut Vec<u8>)) -> (TempDir, PathBuf) {
    let dir = std::env::temp_dir().join(format!(
        "bags-test-{}-{}",
        std::process::id(),
        rand_suffix()
    ));
    std::fs::create_dir_all(&dir).unwrap();
    let mut bytes = std::fs::read(fixtures().join(name)).unwrap();
    patch(&mut bytes);
    let path = dir.join(Path::new(name).file_name().unwrap());
    std::fs::write(&path, bytes).unwrap();
    (TempDir(dir), path)
}

fn rand_suffix() -> u64 {
    use std::sync::atomic::{AtomicU64, Ordering};
    static NEXT: AtomicU64 = AtomicU64::new(0);
    NEXT.fetch_add(1, Ordering::Relaxed)
}

/// Reads everything, returning the first error.
fn read_all(path: &Path) -> Result<usize, BagError> {
    let bag = bags::open(path)?;
    let mut n = 0;
    for message in bag.messages(|_| true)? {
        message?;
        n += 1;
    }
    Ok(n)
}

fn find(bytes: &[u8], needle: &[u8]) -> usize {
    bytes
        .windows(needle.len())
        .position(|w| w == needle)
        .unwrap()
}

#[test]
fn a_truncated_ros1_bag_is_an_error_naming_the_byte() {
    let (_dir, path) = broken("p01-d01.bz2.bag", |b| b.truncate(b.len() / 2));
    let err = read_all(&path).unwrap_err().to_string();
    assert!(err.contains("p01-d01.bz2.bag"), "{err}");
    assert!(
        err.contains("truncated: the bag header puts the index at byte"),
        "{err}"
    );
}

#[test]
fn a_damaged_chunk_is_an_error_naming_its_offset() {
    for name in ["p01-d01.bz2.bag", "p01-d01.lz4.bag"] {
        let mut chunk_at = 0;
        let (_dir, path) = broken(name, |b| {
            // Damage the compressed data of the first chunk, well inside it.
            chunk_at = find(b, b"compression=");
            let inside = chunk_at + 400;
            for byte in &mut b[inside..inside + 64] {
                *byte ^= 0x5a;
            }
        });
        let err = read_all(&path).unwrap_err();
        let text = err.to_string();
        assert!(matches!(err, BagError::Corrupt { .. }), "{name}: {text}");
        assert!(text.contains("chunk"), "{name}: {text}");
        assert!(text.contains(name), "{text}");
    }
}

#[test]
fn an_unknown_chunk_compression_is_named() {
    let (_dir, path) = broken("p01-d01.bz2.bag", |b| {
        let at = find(b, b"compression=bz2") + "compression=".len();
        b[at..at + 3].copy_from_slice(b"xz9");
    });
    let err = read_all(&path).unwrap_err().to_string();
    assert!(
        err.contains("chunk compression `xz9` is not supported (supported: none, bz2, lz4)"),
        "{err}"
    );
    let mcap = "p01-d01-ros2/p01-d01-ros2.mcap";
    let (_dir, path) = broken(mcap, |b| {
        let at = find(b, b"zstd");
        b[at..at + 4].copy_from_slice(b"zstx");
    });
    let err = read_all(&path).unwrap_err().to_string();
    assert!(
        err.contains("chunk compression `zstx` is not supported (supported: none, zstd, lz4)"),
        "{err}"
    );
}

#[test]
fn a_truncated_mcap_file_is_an_error() {
    let (_dir, path) = broken("p01-d01-ros2/p01-d01-ros2.mcap", |b| {
        b.truncate(b.len() / 2)
    });
    let err = read_all(&path).unwrap_err();
    assert!(matches!(err, BagError::Corrupt { .. }), "{err}");
    assert!(err.to_string().contains("truncated"), "{err}");
}

#[test]
fn empty_and_foreign_files_are_refused() {
    let (_dir, path) = broken("p01-d01.bz2.bag", |b| b.clear());
    assert_eq!(
        bags::open(&path).unwrap_err().to_string(),
        format!("{}: the file is empty", path.display())
    );
    let (_dir, path) = broken("recordings/p01-d01.jsonl", |_| {});
    assert!(bags::open(&path)
        .unwrap_err()
        .to_string()
        .contains("not a ROS 1 bag"));
}

#[test]
fn a_ros2_folder_with_sqlite_storage_is_refused_by_name() {
    let dir = std::env::temp_dir().join(format!("bags-test-{}-sqlite", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let metadata = std::fs::read_to_string(fixtures().join("p01-d01-ros2/metadata.yaml")).unwrap();
    std::fs::write(
        dir.join("metadata.yaml"),
        metadata.replace("storage_identifier: mcap", "storage_identifier: sqlite3"),
    )
    .unwrap();
    let err = bags::open(&dir).unwrap_err().to_string();
    assert!(
        err.contains("metadata.yaml: storage_identifier: `sqlite3` is not supported"),
        "{err}"
    );
    std::fs::remove_dir_all(&dir).unwrap();
}

/// Every message of a bag in memory, or its first error.
fn read_bytes(bytes: Vec<u8>) -> Result<usize, BagError> {
    let bag = bags::from_bytes(Path::new("mem.bag"), bytes)?;
    bag.topics()?;
    let mut n = 0;
    for message in bag.messages(|_| true)? {
        message?;
        n += 1;
    }
    Ok(n)
}

#[test]
fn a_file_cut_anywhere_is_an_error_never_a_panic() {
    for name in [
        "p01-d02.bz2.bag",
        "p01-d02.lz4.bag",
        "p01-d02-ros2/p01-d02-ros2.mcap",
    ] {
        let bytes = std::fs::read(fixtures().join(name)).unwrap();
        assert!(read_bytes(bytes.clone()).is_ok(), "{name} reads whole");
        for cut in (1..48).map(|k| bytes.len() * k / 48) {
            let result = read_bytes(bytes[..cut].to_vec());
            assert!(
                result.is_err(),
                "{name} cut at byte {cut} read as {result:?}"
            );
        }
    }
}

#[test]
fn flipped_bytes_give_errors_or_messages_never_a_panic() {
    // A fixed xorshift stream: the same flips every run.
    let mut state = 0x9e37_79b9_7f4a_7c15u64;
    let mut next = move || {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        state
    };
    for name in [
        "p01-d02.bz2.bag",
        "p01-d02.lz4.bag",
        "p01-d02-ros2/p01-d02-ros2.mcap",
    ] {
        let bytes = std::fs::read(fixtures().join(name)).unwrap();
        for _ in 0..40 {
            let mut damaged = bytes.clone();
            for _ in 0..4 {
                let at = (next() % damaged.len() as u64) as usize;
                damaged[at] ^= 1 << (next() % 8);
            }
            // Either outcome is fine; a panic fails the test.
            let _ = read_bytes(damaged);
        }
    }
}

/// An MCAP file of one `ros2msg` topic, `/big`, with messages of `sizes` bytes (a
/// `uint8[]` in CDR), written by the `mcap` crate's writer.
fn mcap_with_messages(sizes: &[usize]) -> Vec<u8> {
    mcap_with_messages_compressed(sizes, Some(mcap::Compression::Zstd))
}

/// As `mcap_with_messages`, with the chunks compressed as `compression` says.
fn mcap_with_messages_compressed(
    sizes: &[usize],
    compression: Option<mcap::Compression>,
) -> Vec<u8> {
    let mut out = std::io::Cursor::new(Vec::new());
    let options = mcap::WriteOptions::new().compression(compression);
    let mut writer = mcap::Writer::with_options(&mut out, options).unwrap();
    let schema = writer
        .add_schema("test_msgs/msg/Blob", "ros2msg", b"uint8[] data")
        .unwrap();
    let channel = writer
        .add_channel(schema, "/big", "cdr", &Default::default())
        .unwrap();
    for (i, &size) in sizes.iter().enumerate() {
        // CDR: the encapsulation header (little endian), the length, the bytes.
        let mut data = vec![0, 1, 0, 0];
        data.extend_from_slice(&u32::try_from(size - 8).unwrap().to_le_bytes());
        data.resize(size, 7);
        let header = mcap::records::MessageHeader {
            channel_id: channel,
            sequence: u32::try_from(i).unwrap(),
            log_time: 1_000 * i as u64,
            publish_time: 1_000 * i as u64,
        };
        writer.write_to_known_channel(&header, &data).unwrap();
    }
    writer.finish().unwrap();
    drop(writer);
    out.into_inner()
}

/// A message of a wanted topic over `MAX_MESSAGE` is an error naming its topic and
/// index (it would decode into a tree several times its size); one at the limit decodes,
/// and a large message of a topic nobody wants is skipped.
#[test]
fn a_message_over_the_maximum_size_is_an_error_naming_it() {
    let max = usize::try_from(bags::MAX_MESSAGE).unwrap();
    let bytes = mcap_with_messages(&[100, max, max + 1]);
    let bag = bags::from_bytes(Path::new("big.mcap"), bytes).unwrap();
    let mut messages = bag.messages(|_| true).unwrap();
    assert_eq!(messages.next().unwrap().unwrap().index, 0);
    assert_eq!(messages.next().unwrap().unwrap().index, 1);
    let err = messages.next().unwrap().unwrap_err();
    assert!(
        matches!(err, BagError::MessageTooLarge { index: 2, .. }),
        "{err:?}"
    );
    let text = err.to_string();
    assert!(
        text.starts_with("big.mcap: topic /big: message 2 (byte "),
        "{text}"
    );
    assert!(
        text.ends_with(&format!(
            "has {} bytes, more than the 16777216 a decoded message may have",
            max + 1
        )),
        "{text}"
    );
    assert!(messages.next().is_none());
    let skipped = bag.messages(|topic| topic != "/big").unwrap();
    assert_eq!(skipped.count(), 0);
}

/// Every chunk compression MCAP writers use (none, zstd, lz4) reads to the same messages.
#[test]
fn every_mcap_chunk_compression_reads_the_same_messages() {
    let sizes = [12, 300, 5_000, 70_000];
    let read = |compression| {
        let bytes = mcap_with_messages_compressed(&sizes, compression);
        let bag = bags::from_bytes(Path::new("c.mcap"), bytes).unwrap();
        let messages: Vec<(u64, i64, String)> = bag
            .messages(|_| true)
            .unwrap()
            .map(|m| {
                let m = m.unwrap();
                (m.index, m.receive_time, format!("{:?}", m.value))
            })
            .collect();
        messages
    };
    let plain = read(None);
    assert_eq!(plain.len(), sizes.len());
    assert!(
        plain[3].2.len() > 70_000,
        "the largest message decodes whole"
    );
    assert_eq!(read(Some(mcap::Compression::Zstd)), plain);
    assert_eq!(read(Some(mcap::Compression::Lz4)), plain);
}

/// Where the first chunk of an MCAP file starts, its CRC field, and its first inner record.
struct ChunkAt {
    crc: usize,
    first_record: usize,
}

fn first_chunk(bytes: &[u8]) -> ChunkAt {
    let le = |at: usize| u64::from_le_bytes(bytes[at..at + 8].try_into().unwrap()) as usize;
    let mut at = 8; // the magic
    loop {
        let (opcode, len) = (bytes[at], le(at + 1));
        if opcode == 0x06 {
            // start and end times, uncompressed size, then the CRC and the compression.
            let crc = at + 9 + 24;
            let compression_len =
                u32::from_le_bytes(bytes[crc + 4..crc + 8].try_into().unwrap()) as usize;
            let first_record = crc + 8 + compression_len + 8;
            return ChunkAt { crc, first_record };
        }
        at += 9 + len;
    }
}

/// The overflow the fuzzer found in `mcap`'s own chunk reader: an uncompressed chunk's
/// record claiming more bytes than the chunk holds is an error naming the chunk.
#[test]
fn a_record_longer_than_its_uncompressed_chunk_is_an_error() {
    let mut bytes = mcap_with_messages_compressed(&[100, 200], None);
    let chunk = first_chunk(&bytes);
    // No CRC, so that the length itself is what the reader must catch.
    bytes[chunk.crc..chunk.crc + 4].fill(0);
    bytes[chunk.first_record + 1..chunk.first_record + 9]
        .copy_from_slice(&(u64::MAX - 3).to_le_bytes());
    let bag = bags::from_bytes(Path::new("long.mcap"), bytes).unwrap();
    let err = bag.messages(|_| true).unwrap().next().unwrap().unwrap_err();
    assert!(matches!(err, BagError::Corrupt { .. }), "{err:?}");
    let text = err.to_string();
    assert!(text.starts_with("long.mcap: byte "), "{text}");
    assert!(
        text.contains(&format!(
            "a record (opcode 0x03) of {} bytes, but the chunk has ",
            u64::MAX - 3
        )),
        "{text}"
    );
}

/// A byte changed inside an uncompressed chunk is caught by the chunk's CRC.
#[test]
fn a_damaged_uncompressed_chunk_fails_its_crc() {
    let mut bytes = mcap_with_messages_compressed(&[100, 200], None);
    let chunk = first_chunk(&bytes);
    let last = bytes.len() - 200;
    assert!(last > chunk.first_record);
    bytes[chunk.first_record + 40] ^= 0x10;
    let bag = bags::from_bytes(Path::new("crc.mcap"), bytes).unwrap();
    let err = bag
        .messages(|_| true)
        .unwrap()
        .find_map(Result::err)
        .expect("an error");
    let text = err.to_string();
    assert!(
        text.contains("chunk CRC mismatch: the header says "),
        "{text}"
    );
}

/// The two-handed fixture is written as real labs' bags are: `/tf` and `/tf_static`
/// alone, one `/tf` message per frame of its recording, no object list.
#[test]
fn the_two_handed_bag_has_poses_alone() {
    let frames = recording_frames("two-handed").len() as u64;
    let bag = bags::open(&fixtures().join("two-handed.bz2.bag")).unwrap();
    assert_eq!(bag.format(), Format::Ros1);
    let topics = bag.topics().unwrap();
    let listed: Vec<(&str, Option<u64>)> = topics
        .iter()
        .map(|t| (t.name.as_str(), t.message_count))
        .collect();
    assert_eq!(listed, [("/tf", Some(frames)), ("/tf_static", Some(1))]);
}
