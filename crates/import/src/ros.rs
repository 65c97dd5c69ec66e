//! ROS 1 bags and ROS 2 bags (MCAP) as an import source (`docs/import.md`, "ROS bags").
//!
//! The `bags` crate reads the container and decodes each message by the definition the
//! bag carries; this module turns messages into [`Event`]s:
//!
//! - **tf.** `/tf` and `/tf_static` (`tf2_msgs/TFMessage`), and `TransformStamped` topics
//!   the mapping names, are edges of the tf tree (parent `header.frame_id`, child
//!   `child_frame_id`, a tf `N:` prefix and a leading `/` stripped). At each frame every
//!   frame of the tree is composed up to the root with the latest transform of each edge,
//!   and observed at the time of the oldest edge on its way (edges from `/tf_static` never
//!   age). The root is what the whole bag's tree leads to: several roots are an error
//!   naming them, and so is a frame whose transforms go round in a circle.
//! - **Frames.** One per message of the clock topic (default `/tf`), at its header stamp
//!   (a `TFMessage`: its latest transform's stamp; a message without header: its receive
//!   time). Times are seconds after the first message read (the core then subtracts the
//!   first frame's time).
//! - **Other topics** are read only when the mapping names them: `geometry_msgs/PoseStamped`
//!   topics give the pose of an entity named after the topic (`/vrpn/cube_1/pose` is
//!   `cube_1`), and the `[bag.objects]` topic gives per list element a name, a pose and
//!   the optional fields the mapping names (velocity, grip, held object, "grabbed by",
//!   contacts). A path reaching an empty array (`velocity[]` of a `Vector3[]` left empty)
//!   means the field is not reported. Poses with a `header.frame_id` are placed in the
//!   root through the tf tree when tf is read.
//! - tf is read unless the mapping names an object list, a clock topic other than `/tf`
//!   and neither `/tf` nor `/tf_static` among its topics.
//!
//! Time going backwards within a topic (per edge, for tf) is an error, as are a topic the
//! mapping names that the bag lacks, a field path its message type does not have, an
//! empty bag and one with no topic that gives poses. Everything is checked before the
//! first pass where the bag's definitions allow it.

// A reader of untrusted input (issue 23): no arithmetic that can wrap or panic, no
// cast that can truncate; each such operation is checked, saturating or proved in range.
#![deny(clippy::arithmetic_side_effects, clippy::cast_possible_truncation)]

use std::collections::{BTreeMap, HashMap};
use std::path::{Path, PathBuf};
use std::sync::atomic::AtomicU64;
use std::sync::Arc;

use bags::{Bag, BagError, Message, Schema, Value};

use crate::assemble::{Event, Held, Observation, Sink, Source};
use crate::error::{ImportError, Location, Problem};
use crate::mapping::{strip_prefix, Format, Mapping, ObjectListFields};
use crate::QuaternionOrder;

const TF: &str = "/tf";
const TF_STATIC: &str = "/tf_static";

/// What a topic the import reads is for.
#[derive(Debug, Clone, PartialEq)]
enum Role {
    /// `tf2_msgs/TFMessage`: edges of the tf tree; `fixed` for `/tf_static`.
    Tf { fixed: bool },
    /// `geometry_msgs/TransformStamped`: one edge.
    Transform,
    /// `geometry_msgs/PoseStamped`: the pose of the entity named after the topic.
    Pose { entity: String },
    /// The mapping's object list.
    Objects,
    /// Only the clock (a message type that gives no poses).
    ClockOnly,
}

/// A ROS bag opened for import: the container, and what each topic read is for.
#[derive(Debug)]
pub struct RosBag {
    bag: Bag,
    format: Format,
    roles: BTreeMap<String, Role>,
    clock: String,
    objects: Option<ObjectListFields>,
    read_tf: bool,
    quaternion: QuaternionOrder,
    /// The tf tree's root, once a pass has seen the whole tree.
    root: Option<String>,
    meta: BTreeMap<String, String>,
}

/// The format of a bag, from the first bytes of a file or a folder with `metadata.yaml`.
pub fn bag_format(path: &Path, start: &[u8]) -> Option<Format> {
    if path.is_dir() {
        return path.join("metadata.yaml").is_file().then_some(Format::Ros2);
    }
    match bags::sniff(start)? {
        bags::Format::Ros1 => Some(Format::Ros1),
        bags::Format::Mcap | bags::Format::Ros2Folder => Some(Format::Ros2),
    }
}

/// A bag's error as an import error: a message's topic and index as its location.
pub fn bag_error(error: BagError) -> ImportError {
    match &error {
        BagError::Io { source, .. } => {
            ImportError::Io(std::io::Error::new(source.kind(), error.to_string()))
        }
        BagError::Decode {
            topic,
            index,
            offset,
            source,
            ..
        } => ImportError::input(
            Location {
                topic: Some(topic.clone()),
                message: Some(*index),
                ..Location::default()
            },
            Problem {
                entity: None,
                field: Some(source.field.clone()),
                message: format!(
                    "byte {} of the message (its record at byte {offset} of the file): {}",
                    source.offset, source.what
                ),
            },
        ),
        BagError::MessageTooLarge {
            topic,
            index,
            offset,
            size,
            ..
        } => ImportError::input(
            Location {
                topic: Some(topic.clone()),
                message: Some(*index),
                ..Location::default()
            },
            Problem::new(format!(
                "the message (its record at byte {offset} of the file) has {size} bytes, more \
                 than the {} a decoded message may have",
                bags::MAX_MESSAGE
            )),
        ),
        BagError::Definition { topic, .. } => ImportError::input(
            Location {
                topic: Some(topic.clone()),
                ..Location::default()
            },
            Problem::new(
                error
                    .detail()
                    .split_once(": ")
                    .map_or(error.detail(), |(_, rest)| rest.to_string()),
            ),
        ),
        _ => ImportError::input(Location::default(), Problem::new(error.detail())),
    }
}

fn at_topic(topic: &str, problem: Problem) -> ImportError {
    ImportError::input(
        Location {
            topic: Some(topic.to_string()),
            ..Location::default()
        },
        problem,
    )
}

fn is_type(type_name: &str, package: &str, name: &str) -> bool {
    type_name == format!("{package}/{name}") || type_name == format!("{package}/msg/{name}")
}

/// The entity a `PoseStamped` topic gives: its last segment other than `pose`.
fn entity_of_topic(topic: &str) -> String {
    let segments: Vec<&str> = topic.split('/').filter(|s| !s.is_empty()).collect();
    match segments.as_slice() {
        [.., entity, last] if last.eq_ignore_ascii_case("pose") => entity.to_string(),
        [.., last] => last.to_string(),
        [] => topic.to_string(),
    }
}

/// A tf frame id as an entity name: without a tf `N:` prefix or leading `/`.
fn frame_name(id: &str) -> &str {
    strip_prefix(id.trim_start_matches('/'))
}

/// The bytes one pass over the bag at `path` reads: the file's size, or the sum of a
/// ROS 2 folder's MCAP files (what a progress bar counts to, per pass).
pub fn bag_size(path: &Path) -> Result<u64, ImportError> {
    bags::open(path)
        .and_then(|bag| bag.size())
        .map_err(bag_error)
}

impl RosBag {
    /// Opens `path` (a ROS 1 bag, an MCAP file, a ROS 2 bag folder) and checks the
    /// mapping's `[bag]` section against the bag's topics and definitions.
    pub fn open(path: &Path, mapping: &Mapping) -> Result<RosBag, ImportError> {
        RosBag::open_counting(path, mapping, None)
    }

    /// [`RosBag::open`], adding every byte read from the bag, now (the topic listing) and
    /// in the import's passes, to `bytes_read` when given: progress for a caller to show.
    pub fn open_counting(
        path: &Path,
        mapping: &Mapping,
        bytes_read: Option<Arc<AtomicU64>>,
    ) -> Result<RosBag, ImportError> {
        let mut bag = bags::open(path).map_err(bag_error)?;
        if let Some(counter) = bytes_read {
            bag.count_bytes_read(counter);
        }
        RosBag::from_bag(bag, mapping)
    }

    /// A bag already opened (a file, or bytes in memory through [`bags::from_bytes`]),
    /// checked against the mapping's `[bag]` section as [`RosBag::open`] does.
    pub fn from_bag(bag: Bag, mapping: &Mapping) -> Result<RosBag, ImportError> {
        let format = match bag.format() {
            bags::Format::Ros1 => Format::Ros1,
            bags::Format::Mcap | bags::Format::Ros2Folder => Format::Ros2,
        };
        let topics = bag.topics().map_err(bag_error)?;
        let listing = || {
            topics
                .iter()
                .map(|t| format!("{} ({})", t.name, t.type_name))
                .collect::<Vec<_>>()
                .join(", ")
        };
        if topics.iter().all(|t| t.message_count == Some(0)) {
            return Err(ImportError::input(
                Location::default(),
                Problem::new("the bag has no messages"),
            ));
        }
        let by_name: HashMap<&str, &bags::Topic> =
            topics.iter().map(|t| (t.name.as_str(), t)).collect();
        let settings = &mapping.bag;
        let objects = settings.objects.clone();
        let names_tf = settings.topics.iter().any(|t| t == TF || t == TF_STATIC);
        let read_tf = objects.is_none() || settings.clock_topic == TF || names_tf;
        let mut named: Vec<String> = settings.topics.clone();
        named.extend(objects.iter().map(|o| o.topic.clone()));
        if settings.clock_topic != TF {
            named.push(settings.clock_topic.clone());
        }
        for topic in &named {
            if !by_name.contains_key(topic.as_str()) {
                return Err(at_topic(
                    topic,
                    Problem {
                        entity: None,
                        field: Some("bag.topics".into()),
                        message: format!("the mapping names this topic, but the bag has no such topic (it has: {})", listing()),
                    },
                ));
            }
        }
        let mut roles = BTreeMap::new();
        if read_tf {
            for (topic, fixed) in [(TF, false), (TF_STATIC, true)] {
                if by_name.contains_key(topic) {
                    roles.insert(topic.to_string(), Role::Tf { fixed });
                }
            }
        }
        for topic in &named {
            let type_name = &by_name[topic.as_str()].type_name;
            let role = if objects.as_ref().is_some_and(|o| &o.topic == topic) {
                Role::Objects
            } else if is_type(type_name, "tf2_msgs", "TFMessage") {
                Role::Tf {
                    fixed: topic == TF_STATIC,
                }
            } else if is_type(type_name, "geometry_msgs", "TransformStamped") {
                Role::Transform
            } else if is_type(type_name, "geometry_msgs", "PoseStamped") {
                Role::Pose {
                    entity: entity_of_topic(topic),
                }
            } else if topic == &settings.clock_topic {
                Role::ClockOnly
            } else {
                return Err(at_topic(
                    topic,
                    Problem {
                        entity: None,
                        field: Some("bag.topics".into()),
                        message: format!(
                            "its type {type_name} gives no poses: tf2_msgs/TFMessage, geometry_msgs/TransformStamped and PoseStamped do, or an object list named in [bag.objects]"
                        ),
                    },
                ));
            };
            roles.insert(topic.clone(), role);
        }
        if !roles.values().any(|r| *r != Role::ClockOnly)
            || (settings.clock_topic == TF && !by_name.contains_key(TF))
        {
            return Err(ImportError::input(
                Location::default(),
                Problem::new(format!(
                    "no usable topic: the bag has {}; poses come from /tf and /tf_static (one frame per /tf message), or from the topics and object list the mapping's [bag] section names",
                    listing()
                )),
            ));
        }
        if let Some(fields) = &objects {
            let topic = by_name[fields.topic.as_str()];
            let schema = Schema::parse(&topic.type_name, &topic.definition).map_err(|e| {
                at_topic(
                    &topic.name,
                    Problem::new(format!(
                        "the definition of {} does not parse: {e}",
                        topic.type_name
                    )),
                )
            })?;
            check_fields(&schema, fields).map_err(|(key, message)| {
                at_topic(
                    &topic.name,
                    Problem {
                        entity: None,
                        field: Some(format!("bag.objects.{key}")),
                        message,
                    },
                )
            })?;
        }
        let mut meta = BTreeMap::new();
        meta.insert("source_format".to_string(), format.name().to_string());
        Ok(RosBag {
            bag,
            format,
            roles,
            clock: settings.clock_topic.clone(),
            objects,
            read_tf,
            quaternion: mapping.quaternion,
            root: None,
            meta,
        })
    }

    /// The bag's path.
    pub fn path(&self) -> PathBuf {
        self.bag.path().to_path_buf()
    }
}

/// Checks the object list's field paths against its message type: the key of the
/// mapping and what is wrong.
fn check_fields(schema: &Schema, fields: &ObjectListFields) -> Result<(), (String, String)> {
    use bags::definition::{Arity, ElementType};
    match schema.resolve_path(&fields.list) {
        Ok((ElementType::Message(_), Arity::Sequence | Arity::Fixed(_))) => {}
        Ok(_) => {
            return Err((
                "list".into(),
                format!("`{}` is not an array of messages", fields.list),
            ))
        }
        Err(e) => return Err(("list".into(), format!("`{}`: {e}", fields.list))),
    }
    let element = |path: &str| format!("{}[].{path}", fields.list.trim_end_matches("[]"));
    let mut paths = vec![("name", Some(&fields.name)), ("pose", Some(&fields.pose))];
    paths.extend([
        ("velocity", fields.velocity.as_ref()),
        ("grip", fields.grip.as_ref()),
        ("held", fields.held.as_ref()),
        ("grabbed_by", fields.grabbed_by.as_ref()),
        ("contacts", fields.contacts.as_ref()),
    ]);
    for (key, path) in paths {
        let Some(path) = path else { continue };
        if let Err(e) = schema.resolve_path(&element(path)) {
            return Err((key.into(), format!("`{path}`: {e}")));
        }
    }
    Ok(())
}

/// One edge of the tf tree: the child's pose in the parent's frame.
#[derive(Debug, Clone)]
struct Edge {
    parent: String,
    pose: Pose,
    /// Nanoseconds on the bag's clock.
    time: i64,
    /// From `/tf_static`: never ages.
    fixed: bool,
}

/// A rigid transform: translation and unit quaternion (x, y, z, w).
#[derive(Debug, Clone, Copy, PartialEq)]
struct Pose {
    position: [f64; 3],
    rotation: [f64; 4],
}

impl Pose {
    const IDENTITY: Pose = Pose {
        position: [0.0; 3],
        rotation: [0.0, 0.0, 0.0, 1.0],
    };

    /// `self` then `child`: the child's pose in the frame `self` is expressed in.
    fn then(&self, child: &Pose) -> Pose {
        let moved = rotate(self.rotation, child.position);
        Pose {
            position: [
                self.position[0] + moved[0],
                self.position[1] + moved[1],
                self.position[2] + moved[2],
            ],
            rotation: multiply(self.rotation, child.rotation),
        }
    }
}

fn multiply(a: [f64; 4], b: [f64; 4]) -> [f64; 4] {
    let [ax, ay, az, aw] = a;
    let [bx, by, bz, bw] = b;
    [
        aw * bx + ax * bw + ay * bz - az * by,
        aw * by - ax * bz + ay * bw + az * bx,
        aw * bz + ax * by - ay * bx + az * bw,
        aw * bw - ax * bx - ay * by - az * bz,
    ]
}

fn rotate(q: [f64; 4], v: [f64; 3]) -> [f64; 3] {
    let p = multiply(
        multiply(q, [v[0], v[1], v[2], 0.0]),
        [-q[0], -q[1], -q[2], q[3]],
    );
    [p[0], p[1], p[2]]
}

/// A field's numbers: `x`, `y`, `z` (and `w`) of a message.
fn components<const N: usize>(
    value: &Value,
    names: [&str; N],
    field: &str,
) -> Result<[f64; N], String> {
    let mut out = [0.0; N];
    for (slot, name) in out.iter_mut().zip(names) {
        *slot = value
            .field(name)
            .and_then(Value::as_f64)
            .ok_or_else(|| format!("`{field}` has no number `{name}`"))?;
    }
    Ok(out)
}

/// A `geometry_msgs/Pose` (`position`, `orientation`) or `Transform` (`translation`,
/// `rotation`).
fn pose_of(value: &Value, field: &str) -> Result<Pose, String> {
    let (position, rotation) = match (value.field("position"), value.field("orientation")) {
        (Some(p), Some(r)) => (p, r),
        _ => match (value.field("translation"), value.field("rotation")) {
            (Some(p), Some(r)) => (p, r),
            _ => {
                return Err(format!(
                "`{field}` is not a pose (position and orientation, or translation and rotation)"
            ))
            }
        },
    };
    Ok(Pose {
        position: components(position, ["x", "y", "z"], field)?,
        rotation: components(rotation, ["x", "y", "z", "w"], field)?,
    })
}

/// The value at an optional field path: none when the path reaches an empty array.
fn optional<'v>(value: &'v Value, path: &str) -> Result<Option<&'v Value>, String> {
    let found = value.lookup(path)?;
    match found.as_slice() {
        [] => Ok(None),
        [one] => match one {
            Value::Array(items) if items.is_empty() => Ok(None),
            Value::Array(items) if items.len() == 1 => Ok(items.first()),
            other => Ok(Some(other)),
        },
        _ => Err(format!("`{path}` gives {} values, not one", found.len())),
    }
}

fn text<'v>(value: &'v Value, path: &str) -> Result<&'v str, String> {
    value
        .lookup_one(path)?
        .as_str()
        .ok_or_else(|| format!("`{path}` is not a string"))
}

/// One pass's state: the tf tree, per-topic times, the clock's origin.
struct Pass<'b> {
    bag: &'b RosBag,
    /// Nanoseconds of the first message read: the source clock's zero.
    origin: Option<i64>,
    /// Per topic (per edge for tf: `topic child`), the latest time seen.
    latest: HashMap<String, i64>,
    edges: BTreeMap<String, Edge>,
    /// Per tf frame, the time of its last observation sent.
    sent: HashMap<String, i64>,
    observation: Observation,
}

/// `to - from` in nanoseconds: in 128 bits, since stamps of a damaged bag may be any
/// two `i64`s, whose difference need not fit one.
fn nanoseconds_between(from: i64, to: i64) -> f64 {
    i128::from(to).saturating_sub(i128::from(from)) as f64
}

impl Pass<'_> {
    fn seconds(&mut self, ns: i64) -> f64 {
        let origin = *self.origin.get_or_insert(ns);
        nanoseconds_between(origin, ns) / 1e9
    }

    /// Checks that `time` is not before the latest of `key`.
    fn forward(&mut self, key: &str, time: i64, field: &str) -> Result<(), Problem> {
        if let Some(&last) = self.latest.get(key) {
            if time < last {
                let origin = self.origin.unwrap_or(last);
                return Err(Problem {
                    entity: None,
                    field: Some(field.to_string()),
                    message: format!(
                        "time goes backwards: {} s after {} s on the same topic",
                        nanoseconds_between(origin, time) / 1e9,
                        nanoseconds_between(origin, last) / 1e9
                    ),
                });
            }
        }
        self.latest.insert(key.to_string(), time);
        Ok(())
    }

    /// The header stamp of a message, or its receive time when it has no header.
    fn stamp(message: &Message) -> i64 {
        message
            .value
            .field("header")
            .and_then(|h| h.field("stamp"))
            .and_then(Value::as_nanos)
            .unwrap_or(message.receive_time)
    }

    fn message(&mut self, message: &Message, sink: &mut dyn Sink) -> Result<(), Problem> {
        let bag = self.bag;
        let Some(role) = bag.roles.get(&*message.topic) else {
            return Ok(());
        };
        let mut time = Pass::stamp(message);
        match role {
            Role::Tf { fixed } => {
                let transforms = message.value.lookup("transforms[]").map_err(Problem::new)?;
                let mut latest = None;
                for (i, transform) in transforms.into_iter().enumerate() {
                    let stamp = self.edge(
                        transform,
                        *fixed,
                        &format!("transforms[{i}]"),
                        &message.topic,
                    )?;
                    latest = latest.max(Some(stamp));
                }
                time = latest.unwrap_or(message.receive_time);
            }
            Role::Transform => {
                time = self.edge(&message.value, false, "", &message.topic)?;
            }
            Role::Pose { entity } => {
                self.forward(&message.topic, time, "header.stamp")?;
                let pose = pose_of(
                    message.value.field("pose").unwrap_or(&Value::Bool(false)),
                    "pose",
                )
                .map_err(|m| Problem::at(entity, "pose", m))?;
                let frame = text(&message.value, "header.frame_id").unwrap_or("");
                let pose = self
                    .in_root(frame)
                    .map_err(|m| Problem::at(entity, "header.frame_id", m))?
                    .then(&pose);
                let seconds = self.seconds(time);
                self.observe(entity, seconds, pose, None, sink)?;
            }
            Role::Objects => {
                self.forward(&message.topic, time, "header.stamp")?;
                self.objects(message, time, sink)?;
            }
            Role::ClockOnly => self.forward(&message.topic, time, "header.stamp")?,
        }
        if *message.topic == *bag.clock {
            self.tick(time, sink)?;
        }
        Ok(())
    }

    /// Records one `TransformStamped`; returns its stamp.
    fn edge(&mut self, value: &Value, fixed: bool, at: &str, topic: &str) -> Result<i64, Problem> {
        let field = |name: &str| {
            if at.is_empty() {
                name.to_string()
            } else {
                format!("{at}.{name}")
            }
        };
        let child = frame_name(text(value, "child_frame_id").map_err(|m| Problem {
            entity: None,
            field: Some(field("child_frame_id")),
            message: m,
        })?)
        .to_string();
        let parent = frame_name(
            text(value, "header.frame_id")
                .map_err(|m| Problem::at(&child, &field("header.frame_id"), m))?,
        )
        .to_string();
        let stamp = value
            .lookup_one("header.stamp")
            .ok()
            .and_then(Value::as_nanos)
            .ok_or_else(|| Problem::at(&child, &field("header.stamp"), "no time stamp"))?;
        let pose = value
            .field("transform")
            .ok_or_else(|| "no `transform`".to_string())
            .and_then(|t| pose_of(t, &field("transform")))
            .map_err(|m| Problem::at(&child, &field("transform"), m))?;
        if parent == child {
            return Err(Problem::at(
                &child,
                &field("header.frame_id"),
                "a transform from a frame to itself",
            ));
        }
        if !fixed {
            self.forward(&format!("{topic} {child}"), stamp, &field("header.stamp"))
                .map_err(|p| Problem {
                    entity: Some(child.clone()),
                    ..p
                })?;
        }
        self.edges.insert(
            child,
            Edge {
                parent,
                pose,
                time: stamp,
                fixed,
            },
        );
        Ok(stamp)
    }

    /// The pose of tf frame `frame` in the root, and the time of the oldest moving edge on
    /// the way (`None` when every edge is static).
    fn compose(&self, frame: &str) -> Result<(Pose, Option<i64>, String), String> {
        let mut pose = Pose::IDENTITY;
        let mut oldest: Option<i64> = None;
        let mut at = frame;
        let mut steps = 0usize;
        while let Some(edge) = self.edges.get(at) {
            pose = edge.pose.then(&pose);
            if !edge.fixed {
                oldest = Some(oldest.map_or(edge.time, |o| o.min(edge.time)));
            }
            at = &edge.parent;
            steps = steps.saturating_add(1);
            if steps > self.edges.len() {
                return Err(format!("frame `{frame}` has no transform to the root: its transforms go round in a circle"));
            }
        }
        Ok((pose, oldest, at.to_string()))
    }

    /// Where poses given in `frame` sit in the root (identity for the root, no frame, or
    /// when tf is not read).
    fn in_root(&self, frame: &str) -> Result<Pose, String> {
        let frame = frame_name(frame);
        if !self.bag.read_tf || frame.is_empty() || self.bag.root.as_deref() == Some(frame) {
            return Ok(Pose::IDENTITY);
        }
        if !self.edges.contains_key(frame) && self.edges.values().any(|e| e.parent == frame) {
            return Ok(Pose::IDENTITY); // the root, before the pass has named it
        }
        if !self.edges.contains_key(frame) {
            return Err(format!(
                "frame `{frame}` has no transform to the root of the tf tree"
            ));
        }
        let (pose, _, top) = self.compose(frame)?;
        match &self.bag.root {
            Some(root) if *root != top => Err(format!(
                "frame `{frame}` has no transform to the root `{root}` (it leads to `{top}`)"
            )),
            _ => Ok(pose),
        }
    }

    fn observe(
        &mut self,
        name: &str,
        time: f64,
        pose: Pose,
        velocity: Option<[f64; 3]>,
        sink: &mut dyn Sink,
    ) -> Result<(), Problem> {
        let o = &mut self.observation;
        o.time = time;
        o.name.clear();
        o.name.push_str(name);
        o.position = pose.position;
        let [x, y, z, w] = pose.rotation;
        o.orientation = match self.bag.quaternion {
            QuaternionOrder::WLast => [x, y, z, w],
            QuaternionOrder::WFirst => [w, x, y, z],
        };
        o.velocity = velocity;
        o.grip = None;
        o.held = None;
        o.grabbed_by = None;
        o.contacts.clear();
        sink.event(Event::Observe(&self.observation))
    }

    /// A frame tick: every tf frame composed to the root, then the frame.
    fn tick(&mut self, time: i64, sink: &mut dyn Sink) -> Result<(), Problem> {
        if self.bag.read_tf {
            let frames: Vec<String> = self.edges.keys().cloned().collect();
            for frame in frames {
                let (pose, oldest, top) = self
                    .compose(&frame)
                    .map_err(|m| Problem::at(&frame, "", m))?;
                if self
                    .bag
                    .root
                    .as_deref()
                    .is_some_and(|root| root != top.as_str())
                {
                    continue;
                }
                let observed = oldest.unwrap_or(time);
                if oldest.is_some() && self.sent.get(&frame) == Some(&observed) {
                    continue; // nothing new since the last frame
                }
                self.sent.insert(frame.clone(), observed);
                let seconds = self.seconds(observed);
                self.observe(&frame, seconds, pose, None, sink)?;
            }
        }
        let seconds = self.seconds(time);
        sink.event(Event::Frame(seconds))
    }

    fn objects(
        &mut self,
        message: &Message,
        time: i64,
        sink: &mut dyn Sink,
    ) -> Result<(), Problem> {
        let bag = self.bag;
        let Some(fields) = &bag.objects else {
            return Ok(());
        };
        let frame = message
            .value
            .field("header")
            .and_then(|h| h.field("frame_id"))
            .and_then(Value::as_str)
            .unwrap_or("");
        let placed = self.in_root(frame).map_err(|m| Problem {
            entity: None,
            field: Some("header.frame_id".into()),
            message: m,
        })?;
        let list = format!("{}[]", fields.list.trim_end_matches("[]"));
        let elements = message.value.lookup(&list).map_err(|m| Problem {
            entity: None,
            field: Some(fields.list.clone()),
            message: m,
        })?;
        let seconds = self.seconds(time);
        let mut names: Vec<String> = Vec::with_capacity(elements.len());
        for (i, element) in elements.into_iter().enumerate() {
            let at = |path: &str| format!("{}[{i}].{path}", fields.list.trim_end_matches("[]"));
            let name = text(element, &fields.name).map_err(|m| Problem {
                entity: None,
                field: Some(at(&fields.name)),
                message: m,
            })?;
            let name = strip_prefix(name).to_string();
            if names.contains(&name) {
                return Err(Problem::at(
                    &name,
                    &at(&fields.name),
                    "listed twice in one message",
                ));
            }
            let problem = |path: &str| {
                let name = name.clone();
                let field = at(path);
                move |m: String| Problem::at(&name, &field, m)
            };
            let pose_value = element
                .lookup_one(&fields.pose)
                .map_err(problem(&fields.pose))?;
            let pose =
                placed.then(&pose_of(pose_value, &fields.pose).map_err(problem(&fields.pose))?);
            let velocity = match &fields.velocity {
                Some(path) => match optional(element, path).map_err(problem(path))? {
                    Some(v) => Some(rotate(
                        placed.rotation,
                        components(v, ["x", "y", "z"], path).map_err(problem(path))?,
                    )),
                    None => None,
                },
                None => None,
            };
            self.observe(&name, seconds, pose, velocity, &mut NoSink)?;
            let o = &mut self.observation;
            if let Some(path) = &fields.grip {
                o.grip = match optional(element, path).map_err(problem(path))? {
                    Some(v) => Some(
                        v.as_f64()
                            .ok_or_else(|| problem(path)(format!("`{path}` is not a number")))?,
                    ),
                    None => None,
                };
            }
            if let Some(path) = &fields.held {
                let held = text(element, path).map_err(problem(path))?;
                o.held = Some(if held.is_empty() {
                    Held::Nothing
                } else {
                    Held::Object(strip_prefix(held).to_string())
                });
            }
            if let Some(path) = &fields.grabbed_by {
                o.grabbed_by =
                    Some(strip_prefix(text(element, path).map_err(problem(path))?).to_string());
            }
            if let Some(path) = &fields.contacts {
                for value in element.lookup(path).map_err(problem(path))? {
                    match value {
                        Value::String(other) => o.contacts.push(strip_prefix(other).to_string()),
                        Value::Array(items) => {
                            for item in items {
                                let other = item.as_str().ok_or_else(|| {
                                    problem(path)(format!("`{path}` is not a list of names"))
                                })?;
                                o.contacts.push(strip_prefix(other).to_string());
                            }
                        }
                        _ => return Err(problem(path)(format!("`{path}` is not a list of names"))),
                    }
                }
            }
            sink.event(Event::Observe(&self.observation))?;
            names.push(name);
        }
        Ok(())
    }
}

/// A sink that takes nothing: `observe` fills the observation, the caller sends it.
struct NoSink;

impl Sink for NoSink {
    fn event(&mut self, _: Event<'_>) -> Result<(), Problem> {
        Ok(())
    }
}

impl Source for RosBag {
    fn format(&self) -> Format {
        self.format
    }

    fn pass(&mut self, sink: &mut dyn Sink) -> Result<(), ImportError> {
        let wanted: Vec<String> = self.roles.keys().cloned().collect();
        let messages = self
            .bag
            .messages(move |topic| wanted.iter().any(|t| t == topic))
            .map_err(bag_error)?;
        let mut pass = Pass {
            bag: self,
            origin: None,
            latest: HashMap::new(),
            edges: BTreeMap::new(),
            sent: HashMap::new(),
            observation: Observation::default(),
        };
        for message in messages {
            let message = message.map_err(bag_error)?;
            pass.message(&message, sink).map_err(|problem| {
                ImportError::input(
                    Location {
                        topic: Some(message.topic.to_string()),
                        message: Some(message.index),
                        ..Location::default()
                    },
                    problem,
                )
            })?;
        }
        // The root: what the tree's parentless frames are, over the whole bag.
        let mut roots: Vec<String> = pass
            .edges
            .values()
            .filter(|e| !pass.edges.contains_key(&e.parent))
            .map(|e| e.parent.clone())
            .collect();
        drop(pass);
        roots.sort_unstable();
        roots.dedup();
        let root = match roots.as_slice() {
            [] => None,
            [one] => Some(one.clone()),
            several => {
                return Err(at_topic(
                    TF,
                    Problem::new(format!(
                        "the tf tree has several roots: {} (every frame must lead to one root: a transform between them is missing)",
                        several.join(", ")
                    )),
                ))
            }
        };
        self.root = root;
        Ok(())
    }

    fn meta(&self) -> BTreeMap<String, String> {
        let mut meta = self.meta.clone();
        if let Some(root) = &self.root {
            meta.insert("tf_root".to_string(), root.clone());
        }
        meta
    }
}

#[cfg(test)]
#[allow(clippy::arithmetic_side_effects, clippy::cast_possible_truncation)] // tests, not readers
mod tests {
    use super::*;

    #[test]
    fn composing_a_quarter_turn_moves_x_onto_y() {
        let s = std::f64::consts::FRAC_1_SQRT_2;
        let parent = Pose {
            position: [1.0, 0.0, 0.0],
            rotation: [0.0, 0.0, s, s],
        };
        let child = Pose {
            position: [1.0, 0.0, 0.0],
            rotation: [0.0, 0.0, 0.0, 1.0],
        };
        let world = parent.then(&child);
        for (got, want) in world.position.iter().zip([1.0, 1.0, 0.0]) {
            assert!((got - want).abs() < 1e-12, "{:?}", world.position);
        }
        assert_eq!(world.rotation, parent.rotation);
    }

    #[test]
    fn pose_topics_name_their_entity() {
        assert_eq!(entity_of_topic("/vrpn/cube_1/pose"), "cube_1");
        assert_eq!(entity_of_topic("/Hand_R"), "Hand_R");
        assert_eq!(frame_name("/2:cube_3"), "cube_3");
    }
}
