//! Bad ROS bags: each gives an input error that says where (topic, message, field, or
//! byte) and what is wrong. Broken bags are made here: the committed fixtures cut or
//! patched, or small uncompressed ROS 1 bags written by `BagWriter` with the definitions
//! the fixtures carry.

#![allow(clippy::unwrap_used, clippy::expect_used)]

use std::path::{Path, PathBuf};

use import::ros::RosBag;
use import::{import, Format, ImportError, Mapping};

fn fixtures() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../bags/tests/fixtures")
}

/// A temporary folder, removed when dropped.
struct TempDir(PathBuf);

impl TempDir {
    fn new(case: &str) -> TempDir {
        let dir = std::env::temp_dir().join(format!("import-ros-{}-{case}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        TempDir(dir)
    }

    fn write(&self, name: &str, bytes: &[u8]) -> PathBuf {
        let path = self.0.join(name);
        std::fs::write(&path, bytes).unwrap();
        path
    }
}

impl Drop for TempDir {
    fn drop(&mut self) {
        let _ = std::fs::remove_dir_all(&self.0);
    }
}

/// Imports `path`; the input error's message.
fn error_of(path: &Path, mapping: &Mapping) -> String {
    let result = RosBag::open(path, mapping)
        .and_then(|mut source| import(&mut source, mapping, "x", Vec::new()));
    match result {
        Err(ImportError::Input(e)) => e.to_string(),
        Err(other) => panic!("{}: not an input error: {other}", path.display()),
        Ok(_) => panic!("{}: imported", path.display()),
    }
}

/// The definition a fixture bag carries for `topic`.
fn definition(topic: &str) -> (String, String) {
    let bag = bags::open(&fixtures().join("p01-d01.bz2.bag")).unwrap();
    let topic = bag
        .topics()
        .unwrap()
        .into_iter()
        .find(|t| t.name == topic)
        .unwrap();
    (topic.type_name, topic.definition)
}

/// A small ROS 1 bag without chunks: connections, then messages, then the index.
#[derive(Default)]
struct BagWriter {
    connections: Vec<(String, String, String)>,
    messages: Vec<(u32, i64, Vec<u8>)>,
}

fn header(fields: &[(&str, &[u8])]) -> Vec<u8> {
    let mut out = Vec::new();
    for (name, value) in fields {
        out.extend(((name.len() + 1 + value.len()) as u32).to_le_bytes());
        out.extend(name.as_bytes());
        out.push(b'=');
        out.extend(*value);
    }
    out
}

fn record(fields: &[(&str, &[u8])], data: &[u8]) -> Vec<u8> {
    let header = header(fields);
    let mut out = Vec::new();
    out.extend((header.len() as u32).to_le_bytes());
    out.extend(header);
    out.extend((data.len() as u32).to_le_bytes());
    out.extend(data);
    out
}

impl BagWriter {
    fn connection(&mut self, topic: &str, type_name: &str, definition: &str) -> u32 {
        self.connections
            .push((topic.into(), type_name.into(), definition.into()));
        self.connections.len() as u32 - 1
    }

    fn message(&mut self, connection: u32, time_ns: i64, data: Vec<u8>) {
        self.messages.push((connection, time_ns, data));
    }

    fn connection_record(&self, id: u32) -> Vec<u8> {
        let (topic, type_name, definition) = &self.connections[id as usize];
        let data = header(&[
            ("topic", topic.as_bytes()),
            ("type", type_name.as_bytes()),
            ("md5sum", b"*"),
            ("message_definition", definition.as_bytes()),
        ]);
        record(
            &[
                ("op", &[0x07]),
                ("conn", &id.to_le_bytes()),
                ("topic", topic.as_bytes()),
            ],
            &data,
        )
    }

    fn finish(&self) -> Vec<u8> {
        let mut body = Vec::new();
        for id in 0..self.connections.len() as u32 {
            body.extend(self.connection_record(id));
        }
        for (conn, time, data) in &self.messages {
            let stamp = ((time % 1_000_000_000) as u64) << 32 | (time / 1_000_000_000) as u64;
            body.extend(record(
                &[
                    ("op", &[0x02]),
                    ("conn", &conn.to_le_bytes()),
                    ("time", &stamp.to_le_bytes()),
                ],
                data,
            ));
        }
        let magic = b"#ROSBAG V2.0\n";
        let header_len = record(
            &[
                ("op", &[0x03]),
                ("index_pos", &[0; 8]),
                ("conn_count", &[0; 4]),
                ("chunk_count", &[0; 4]),
            ],
            &[],
        )
        .len();
        let index_pos = (magic.len() + header_len + body.len()) as u64;
        let mut out = magic.to_vec();
        out.extend(record(
            &[
                ("op", &[0x03]),
                ("index_pos", &index_pos.to_le_bytes()),
                ("conn_count", &(self.connections.len() as u32).to_le_bytes()),
                ("chunk_count", &0u32.to_le_bytes()),
            ],
            &[],
        ));
        out.extend(body);
        for id in 0..self.connections.len() as u32 {
            out.extend(self.connection_record(id));
        }
        out
    }
}

/// ROS 1 serialization of the pieces of a `tf2_msgs/TFMessage`.
struct Tf(Vec<u8>, u32);

impl Tf {
    fn new() -> Tf {
        Tf(Vec::new(), 0)
    }

    fn string(&mut self, s: &str) {
        self.0.extend((s.len() as u32).to_le_bytes());
        self.0.extend(s.as_bytes());
    }

    /// `child` at `x` in `parent`, stamped `time_ns`.
    fn edge(mut self, parent: &str, child: &str, time_ns: i64, x: f64) -> Tf {
        self.0.extend(0u32.to_le_bytes()); // seq
        self.0
            .extend(((time_ns / 1_000_000_000) as u32).to_le_bytes());
        self.0
            .extend(((time_ns % 1_000_000_000) as u32).to_le_bytes());
        self.string(parent);
        self.string(child);
        for v in [x, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0] {
            self.0.extend(v.to_le_bytes());
        }
        self.1 += 1;
        self
    }

    fn bytes(self) -> Vec<u8> {
        let mut out = self.1.to_le_bytes().to_vec();
        out.extend(self.0);
        out
    }
}

const S: i64 = 1_000_000_000;

/// A bag with one `/tf` message per entry: its edges (parent, child, time, x).
fn tf_bag(messages: &[&[(&str, &str, i64, f64)]]) -> Vec<u8> {
    let (type_name, definition) = definition("/tf");
    let mut bag = BagWriter::default();
    let tf = bag.connection("/tf", &type_name, &definition);
    for (i, edges) in messages.iter().enumerate() {
        let mut message = Tf::new();
        for &(parent, child, time, x) in edges.iter() {
            message = message.edge(parent, child, time, x);
        }
        bag.message(tf, S + i as i64 * S / 100, message.bytes());
    }
    bag.finish()
}

fn ros1() -> Mapping {
    Mapping::default_for(Format::Ros1)
}

#[test]
fn a_written_tf_bag_imports() {
    // The writer itself, so that the cases below fail for their one mistake only.
    let dir = TempDir::new("good");
    let path = dir.write(
        "good.bag",
        &tf_bag(&[
            &[("world", "Hand_R", S, 0.1), ("world", "cube_1", S, 0.5)],
            &[
                ("world", "Hand_R", S + S / 100, 0.2),
                ("world", "cube_1", S + S / 100, 0.5),
            ],
        ]),
    );
    let mut source = RosBag::open(&path, &ros1()).unwrap();
    let (_, header, report) = import(&mut source, &ros1(), "x", Vec::new()).unwrap();
    assert_eq!(report.frames, 2);
    assert!(
        header.find("right_hand").is_some() && header.find("cube_1").is_some(),
        "{header:?}"
    );
}

#[test]
fn container_mistakes_name_the_byte() {
    let dir = TempDir::new("container");
    let good = std::fs::read(fixtures().join("p01-d01.bz2.bag")).unwrap();
    let cut = dir.write("cut.bag", &good[..good.len() / 2]);
    assert_eq!(
        error_of(&cut, &ros1()),
        format!(
            "byte {half}: truncated: the bag header puts the index at byte {}, but the file ends at byte {half}",
            index_pos(&good),
            half = good.len() / 2
        )
    );
    let mut patched = good.clone();
    let at = find(&patched, b"compression=bz2") + "compression=".len();
    patched[at..at + 3].copy_from_slice(b"xz9");
    let unknown = dir.write("unknown.bag", &patched);
    assert_eq!(
        error_of(&unknown, &ros1()),
        "byte 4109: chunk compression `xz9` is not supported (supported: none, bz2, lz4)"
    );
    let mut damaged = good.clone();
    for byte in &mut damaged[4500..4600] {
        *byte ^= 0x5a;
    }
    let damaged = dir.write("damaged.bag", &damaged);
    assert_eq!(
        error_of(&damaged, &ros1()),
        "byte 4109: bz2 chunk does not decompress: bzip2: invalid data"
    );
    let empty = dir.write("empty.bag", b"");
    assert_eq!(error_of(&empty, &ros1()), "the file is empty");
}

fn find(bytes: &[u8], needle: &[u8]) -> usize {
    bytes
        .windows(needle.len())
        .position(|w| w == needle)
        .unwrap()
}

fn index_pos(bag: &[u8]) -> u64 {
    let at = find(bag, b"index_pos=") + "index_pos=".len();
    u64::from_le_bytes(bag[at..at + 8].try_into().unwrap())
}

#[test]
fn a_bag_without_messages_or_without_poses_is_refused() {
    let dir = TempDir::new("topics");
    let (type_name, definition) = definition("/tf");
    let mut bag = BagWriter::default();
    bag.connection("/tf", &type_name, &definition);
    let empty = dir.write("empty.bag", &bag.finish());
    assert_eq!(error_of(&empty, &ros1()), "the bag has no messages");
    let mut bag = BagWriter::default();
    let chatter = bag.connection("/chatter", "std_msgs/String", "string data\n");
    bag.message(chatter, S, b"\x02\0\0\0hi".to_vec());
    let chatter = dir.write("chatter.bag", &bag.finish());
    assert_eq!(
        error_of(&chatter, &ros1()),
        "no usable topic: the bag has /chatter (std_msgs/String); poses come from /tf and /tf_static (one frame per /tf message), or from the topics and object list the mapping's [bag] section names"
    );
}

#[test]
fn mapping_mistakes_name_the_topic_and_field() {
    let bag = fixtures().join("p01-d01.bz2.bag");
    let mapping =
        Mapping::from_toml("[bag]\ntopics = [\"/cameras/pose\"]\n", Format::Ros1).unwrap();
    assert_eq!(
        error_of(&bag, &mapping),
        "topic /cameras/pose: field `bag.topics`: the mapping names this topic, but the bag has no such topic (it has: /demoplan/objects (demoplan_msgs/ObjectArray), /tf (tf2_msgs/TFMessage), /tf_static (tf2_msgs/TFMessage))"
    );
    let objects = "[bag]\nclock_topic = \"/demoplan/objects\"\n[bag.objects]\ntopic = \"/demoplan/objects\"\nlist = \"objects\"\nname = \"name\"\npose = \"pos\"\n";
    let mapping = Mapping::from_toml(objects, Format::Ros1).unwrap();
    assert_eq!(
        error_of(&bag, &mapping),
        "topic /demoplan/objects: field `bag.objects.pose`: `pos`: demoplan_msgs/Object has no field `pos` (its fields: name, pose, velocity, grip, held, grabbed_by, contacts)"
    );
    let mapping = Mapping::from_toml(
        &objects.replace("list = \"objects\"", "list = \"header\""),
        Format::Ros1,
    )
    .unwrap();
    assert_eq!(
        error_of(&bag, &mapping),
        "topic /demoplan/objects: field `bag.objects.list`: `header` is not an array of messages"
    );
}

#[test]
fn tf_tree_mistakes_name_the_frames() {
    let dir = TempDir::new("tree");
    let roots = dir.write(
        "roots.bag",
        &tf_bag(&[&[("world", "cube_1", S, 0.1), ("odom", "Hand_R", S, 0.2)]]),
    );
    assert_eq!(
        error_of(&roots, &ros1()),
        "topic /tf: the tf tree has several roots: odom, world (every frame must lead to one root: a transform between them is missing)"
    );
    let circle = dir.write(
        "circle.bag",
        &tf_bag(&[&[("cube_2", "cube_1", S, 0.1), ("cube_1", "cube_2", S, 0.2)]]),
    );
    assert_eq!(
        error_of(&circle, &ros1()),
        "topic /tf, message 0: entity `cube_1`: frame `cube_1` has no transform to the root: its transforms go round in a circle"
    );
    let backwards = dir.write(
        "backwards.bag",
        &tf_bag(&[
            &[("world", "cube_1", 2 * S, 0.1)],
            &[("world", "cube_1", S, 0.1)],
        ]),
    );
    assert_eq!(
        error_of(&backwards, &ros1()),
        "topic /tf, message 1: entity `cube_1`, field `transforms[0].header.stamp`: time goes backwards: -1 s after 0 s on the same topic"
    );
}

#[test]
fn a_pose_in_a_frame_outside_the_tree_is_refused() {
    let dir = TempDir::new("pose");
    let (tf_type, tf_definition) = definition("/tf");
    // geometry_msgs/PoseStamped, with its dependencies as ROS 1 writes them.
    let pose_definition = "Header header\nPose pose\n\
        ================================================================================\n\
        MSG: std_msgs/Header\nuint32 seq\ntime stamp\nstring frame_id\n\
        ================================================================================\n\
        MSG: geometry_msgs/Pose\nPoint position\nQuaternion orientation\n\
        ================================================================================\n\
        MSG: geometry_msgs/Point\nfloat64 x\nfloat64 y\nfloat64 z\n\
        ================================================================================\n\
        MSG: geometry_msgs/Quaternion\nfloat64 x\nfloat64 y\nfloat64 z\nfloat64 w\n";
    let mut bag = BagWriter::default();
    let tf = bag.connection("/tf", &tf_type, &tf_definition);
    let pose = bag.connection(
        "/vrpn/cube_9/pose",
        "geometry_msgs/PoseStamped",
        pose_definition,
    );
    bag.message(tf, S, Tf::new().edge("world", "cube_1", S, 0.1).bytes());
    let mut data = Vec::new();
    data.extend(0u32.to_le_bytes());
    data.extend(1u32.to_le_bytes());
    data.extend(0u32.to_le_bytes());
    data.extend(6u32.to_le_bytes());
    data.extend(b"camera");
    for v in [0.1f64, 0.2, 0.3, 0.0, 0.0, 0.0, 1.0] {
        data.extend(v.to_le_bytes());
    }
    bag.message(pose, S, data);
    let path = dir.write("pose.bag", &bag.finish());
    let mapping =
        Mapping::from_toml("[bag]\ntopics = [\"/vrpn/cube_9/pose\"]\n", Format::Ros1).unwrap();
    assert_eq!(
        error_of(&path, &mapping),
        "topic /vrpn/cube_9/pose, message 0: entity `cube_9`, field `header.frame_id`: frame `camera` has no transform to the root of the tf tree"
    );
}

#[test]
fn a_message_cut_short_names_its_field() {
    let dir = TempDir::new("short");
    let mut message = Tf::new().edge("world", "cube_1", S, 0.1).bytes();
    message.truncate(message.len() - 12);
    let (type_name, definition) = definition("/tf");
    let mut bag = BagWriter::default();
    let tf = bag.connection("/tf", &type_name, &definition);
    bag.message(tf, S, message);
    let path = dir.write("short.bag", &bag.finish());
    let error = error_of(&path, &ros1());
    assert!(
        error.starts_with("topic /tf, message 0: field `transforms.transform.rotation.z`: byte "),
        "{error}"
    );
    assert!(
        error.contains("needs 8 bytes, the message has 4 left"),
        "{error}"
    );
}
