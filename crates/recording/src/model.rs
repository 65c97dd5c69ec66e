//! The recording model: a header naming the tracked entities, and frames of their states.
//!
//! Conventions are those of ROS REP 103: metres, seconds, a right-handed frame with z up,
//! quaternions written (x, y, z, w). Poses and sizes are `f32` (a tenth of a millimetre
//! is far below any tracker's noise); time is `f64`, so that long recordings keep
//! microsecond resolution.

use std::fmt;

/// Index of an entity in [`Header::entities`], and of its state in [`Frame::states`].
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct EntityId(pub u32);

impl EntityId {
    /// As an index into a vector.
    pub fn index(self) -> usize {
        self.0 as usize
    }
}

/// What a tracked entity is.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum EntityKind {
    /// A hand: has a grip (closure 0..1) and may hold an object.
    Hand,
    /// A cube that can be grasped and stacked.
    Cube,
    /// The table the cubes stand on.
    Table,
    /// Anything else in the scene.
    Other,
}

impl EntityKind {
    /// Every kind, in the order of the format's documentation.
    pub const ALL: [EntityKind; 4] = [
        EntityKind::Hand,
        EntityKind::Cube,
        EntityKind::Table,
        EntityKind::Other,
    ];

    /// The name used in the file: `hand`, `cube`, `table`, `other`.
    pub fn name(self) -> &'static str {
        match self {
            EntityKind::Hand => "hand",
            EntityKind::Cube => "cube",
            EntityKind::Table => "table",
            EntityKind::Other => "other",
        }
    }

    /// The kind with this name in the file.
    pub fn from_name(name: &str) -> Option<EntityKind> {
        EntityKind::ALL.into_iter().find(|k| k.name() == name)
    }
}

impl fmt::Display for EntityKind {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

/// A point or a vector in metres (or metres per second).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Vec3 {
    /// Forward (REP 103).
    pub x: f32,
    /// Left.
    pub y: f32,
    /// Up.
    pub z: f32,
}

impl Vec3 {
    /// The `f64` vector rounded to the storage type (the nearest `f32` per component).
    pub fn from_f64(v: geometry::V3) -> Vec3 {
        let [x, y, z] = v.to_array().map(|c| c as f32);
        Vec3 { x, y, z }
    }

    /// As the `f64` vector computations use (exact).
    pub fn to_f64(self) -> geometry::V3 {
        geometry::V3::new(f64::from(self.x), f64::from(self.y), f64::from(self.z))
    }

    /// The zero vector.
    pub const ZERO: Vec3 = Vec3 {
        x: 0.0,
        y: 0.0,
        z: 0.0,
    };

    /// A vector from its components.
    pub const fn new(x: f32, y: f32, z: f32) -> Vec3 {
        Vec3 { x, y, z }
    }

    /// The components as an array `[x, y, z]`.
    pub fn to_array(self) -> [f32; 3] {
        [self.x, self.y, self.z]
    }

    /// A vector from an array `[x, y, z]`.
    pub fn from_array(a: [f32; 3]) -> Vec3 {
        Vec3::new(a[0], a[1], a[2])
    }

    /// Euclidean length.
    pub fn norm(self) -> f32 {
        self.dot(self).sqrt()
    }

    /// Dot product.
    pub fn dot(self, other: Vec3) -> f32 {
        self.x * other.x + self.y * other.y + self.z * other.z
    }

    /// Euclidean distance to another point.
    pub fn distance(self, other: Vec3) -> f32 {
        (self - other).norm()
    }

    /// Whether every component is finite.
    pub fn is_finite(self) -> bool {
        self.x.is_finite() && self.y.is_finite() && self.z.is_finite()
    }
}

impl std::ops::Add for Vec3 {
    type Output = Vec3;
    fn add(self, o: Vec3) -> Vec3 {
        Vec3::new(self.x + o.x, self.y + o.y, self.z + o.z)
    }
}

impl std::ops::Sub for Vec3 {
    type Output = Vec3;
    fn sub(self, o: Vec3) -> Vec3 {
        Vec3::new(self.x - o.x, self.y - o.y, self.z - o.z)
    }
}

impl std::ops::Mul<f32> for Vec3 {
    type Output = Vec3;
    fn mul(self, s: f32) -> Vec3 {
        Vec3::new(self.x * s, self.y * s, self.z * s)
    }
}

/// A rotation as a unit quaternion, written (x, y, z, w) as in ROS.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Quaternion {
    /// The x component of the vector part.
    pub x: f32,
    /// The y component of the vector part.
    pub y: f32,
    /// The z component of the vector part.
    pub z: f32,
    /// The scalar part.
    pub w: f32,
}

impl Default for Quaternion {
    fn default() -> Quaternion {
        Quaternion::IDENTITY
    }
}

impl Quaternion {
    /// The `f64` quaternion rounded to the storage type (the nearest `f32` per
    /// component).
    pub fn from_f64(q: geometry::Quat) -> Quaternion {
        Quaternion {
            x: q.x as f32,
            y: q.y as f32,
            z: q.z as f32,
            w: q.w as f32,
        }
    }

    /// As the `f64` quaternion computations use (exact).
    pub fn to_f64(self) -> geometry::Quat {
        geometry::Quat {
            x: f64::from(self.x),
            y: f64::from(self.y),
            z: f64::from(self.z),
            w: f64::from(self.w),
        }
    }

    /// No rotation.
    pub const IDENTITY: Quaternion = Quaternion {
        x: 0.0,
        y: 0.0,
        z: 0.0,
        w: 1.0,
    };

    /// How far a quaternion's norm may be from 1 and still count as a rotation. Files
    /// round components to a few decimals, so an exact unit norm cannot be asked for.
    pub const NORM_TOLERANCE: f32 = 0.01;

    /// A quaternion from its components in file order (x, y, z, w).
    pub const fn new(x: f32, y: f32, z: f32, w: f32) -> Quaternion {
        Quaternion { x, y, z, w }
    }

    /// A rotation by `yaw` radians about the z axis.
    pub fn from_yaw(yaw: f32) -> Quaternion {
        let (s, c) = (yaw * 0.5).sin_cos();
        Quaternion::new(0.0, 0.0, s, c)
    }

    /// The components in file order `[x, y, z, w]`.
    pub fn to_array(self) -> [f32; 4] {
        [self.x, self.y, self.z, self.w]
    }

    /// A quaternion from components in file order `[x, y, z, w]`.
    pub fn from_array(a: [f32; 4]) -> Quaternion {
        Quaternion::new(a[0], a[1], a[2], a[3])
    }

    /// Euclidean norm of the four components.
    pub fn norm(self) -> f32 {
        (self.x * self.x + self.y * self.y + self.z * self.z + self.w * self.w).sqrt()
    }

    /// Whether every component is finite.
    pub fn is_finite(self) -> bool {
        self.x.is_finite() && self.y.is_finite() && self.z.is_finite() && self.w.is_finite()
    }

    /// Whether the norm is 1 within [`Quaternion::NORM_TOLERANCE`].
    pub fn is_unit(self) -> bool {
        (self.norm() - 1.0).abs() <= Quaternion::NORM_TOLERANCE
    }

    /// The rotation about z (heading) in radians, in (-pi, pi].
    pub fn yaw(self) -> f32 {
        let siny = 2.0 * (self.w * self.z + self.x * self.y);
        let cosy = 1.0 - 2.0 * (self.y * self.y + self.z * self.z);
        siny.atan2(cosy)
    }

    /// Rotates a vector.
    pub fn rotate(self, v: Vec3) -> Vec3 {
        // v' = v + 2w (q x v) + 2 q x (q x v), with q the vector part.
        let q = Vec3::new(self.x, self.y, self.z);
        let t = cross(q, v) * 2.0;
        v + t * self.w + cross(q, t)
    }
}

fn cross(a: Vec3, b: Vec3) -> Vec3 {
    Vec3::new(
        a.y * b.z - a.z * b.y,
        a.z * b.x - a.x * b.z,
        a.x * b.y - a.y * b.x,
    )
}

/// Position and orientation of an entity's box centre in the world frame.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Pose {
    /// The centre of the entity's box (for a hand: the palm), in metres.
    pub position: Vec3,
    /// The orientation of the box.
    pub orientation: Quaternion,
}

/// A tracked thing: a hand, a cube, the table, or something else.
#[derive(Debug, Clone, PartialEq)]
pub struct Entity {
    /// Unique name: an ASCII letter, then letters, digits, `_` or `-` (at most 64 bytes),
    /// distinct from every other name also when case is ignored (names become PDDL
    /// objects, and PDDL ignores case).
    pub name: String,
    /// What it is.
    pub kind: EntityKind,
    /// Extent of its box along its own x, y, z axes, in metres (full lengths, not halves).
    pub size: Vec3,
    /// The pose of an entity that never moves (the table). Such an entity is never listed
    /// in frames.
    pub fixed: Option<Pose>,
}

/// The first line of a recording: what was recorded, and what is tracked.
#[derive(Debug, Clone, PartialEq)]
pub struct Header {
    /// Identifies the recording (e.g. `p01-d03`).
    pub id: String,
    /// Who demonstrated (an anonymous code).
    pub participant: String,
    /// The task as told to the participant.
    pub task: String,
    /// Nominal frames per second of the tracker. Frames carry their own times; this is
    /// what the tracker aimed for.
    pub frame_rate: f64,
    /// The tracked entities; [`EntityId`] indexes this list.
    pub entities: Vec<Entity>,
    /// Free-form key-value notes (device, software, simulator seed), sorted by key.
    pub meta: std::collections::BTreeMap<String, String>,
}

impl Header {
    /// The entity with this id.
    ///
    /// # Panics
    /// If the id is not below `entities.len()`.
    pub fn entity(&self, id: EntityId) -> &Entity {
        &self.entities[id.index()]
    }

    /// The id of the entity with this name.
    pub fn find(&self, name: &str) -> Option<EntityId> {
        self.entities
            .iter()
            .position(|e| e.name == name)
            .map(|i| EntityId(i as u32))
    }

    /// Every entity id, in order.
    pub fn ids(&self) -> impl Iterator<Item = EntityId> + '_ {
        (0..self.entities.len() as u32).map(EntityId)
    }

    /// The ids of the entities of one kind, in order.
    pub fn ids_of(&self, kind: EntityKind) -> impl Iterator<Item = EntityId> + '_ {
        self.ids().filter(move |&id| self.entity(id).kind == kind)
    }

    /// The value of a `meta` key.
    pub fn meta(&self, key: &str) -> Option<&str> {
        self.meta.get(key).map(String::as_str)
    }
}

/// The state of one entity in one frame.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct EntityState {
    /// Where the entity is.
    pub pose: Pose,
    /// Linear velocity in metres per second, when the tracker reports it.
    pub velocity: Option<Vec3>,
    /// Hand closure, 0 (open) to 1 (closed); present exactly for hands.
    pub grip: Option<f32>,
    /// The object a hand holds, when the tracker knows it (a VR grab system does).
    pub holding: Option<EntityId>,
}

/// Two entities touching, as a physics engine reports it. The pair is unordered.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct Contact {
    /// One entity.
    pub a: EntityId,
    /// The other.
    pub b: EntityId,
}

/// The tracked state of the scene at one moment.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Frame {
    /// Seconds since the start of the recording; strictly increasing from frame to frame.
    pub time: f64,
    /// One entry per entity of the header, indexed by [`EntityId`]: `None` when the entity
    /// was not observed in this frame (tracking lost), and always for fixed entities.
    pub states: Vec<Option<EntityState>>,
    /// Contacts reported in this frame (empty when the tracker reports none).
    pub contacts: Vec<Contact>,
}

impl Frame {
    /// A frame at `time` with no entity observed, for a header with `entities` entities.
    pub fn empty(time: f64, entities: usize) -> Frame {
        Frame {
            time,
            states: vec![None; entities],
            contacts: Vec::new(),
        }
    }

    /// The state of an entity, if observed in this frame.
    pub fn state(&self, id: EntityId) -> Option<&EntityState> {
        self.states.get(id.index()).and_then(Option::as_ref)
    }

    /// The pose of an entity in this frame: its state's pose, or its fixed pose.
    pub fn pose(&self, header: &Header, id: EntityId) -> Option<Pose> {
        self.state(id)
            .map(|s| s.pose)
            .or_else(|| header.entities.get(id.index()).and_then(|e| e.fixed))
    }

    /// Resets to an empty frame for `entities` entities, keeping the allocations.
    pub fn clear(&mut self, entities: usize) {
        self.time = 0.0;
        self.states.clear();
        self.states.resize(entities, None);
        self.contacts.clear();
    }
}

/// A whole recording in memory. Long recordings are better streamed with
/// [`crate::Reader`]; this is for small ones and for tests.
#[derive(Debug, Clone, PartialEq)]
pub struct Recording {
    /// The header.
    pub header: Header,
    /// The frames, in time order.
    pub frames: Vec<Frame>,
}

impl Recording {
    /// Reads a whole recording.
    pub fn read<R: std::io::BufRead>(input: R) -> Result<Recording, crate::ReadError> {
        let mut reader = crate::Reader::new(input)?;
        let mut frames = Vec::new();
        let mut frame = Frame::default();
        while reader.read_frame(&mut frame)? {
            frames.push(frame.clone());
        }
        Ok(Recording {
            header: reader.into_header(),
            frames,
        })
    }

    /// Writes the recording in the native format.
    pub fn write<W: std::io::Write>(&self, output: W) -> Result<W, crate::WriteError> {
        let mut writer = crate::Writer::new(output, &self.header)?;
        for frame in &self.frames {
            writer.write_frame(frame)?;
        }
        writer.finish()
    }

    /// Seconds from the first to the last frame (0 for fewer than two frames).
    pub fn duration(&self) -> f64 {
        match (self.frames.first(), self.frames.last()) {
            (Some(a), Some(b)) => b.time - a.time,
            _ => 0.0,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn yaw_quaternion_rotates_x_towards_y() {
        let q = Quaternion::from_yaw(std::f32::consts::FRAC_PI_2);
        let v = q.rotate(Vec3::new(1.0, 0.0, 0.0));
        assert!((v.x).abs() < 1e-6 && (v.y - 1.0).abs() < 1e-6 && v.z.abs() < 1e-6);
        assert!((q.yaw() - std::f32::consts::FRAC_PI_2).abs() < 1e-6);
        assert!(q.is_unit());
    }

    #[test]
    fn kinds_round_trip_through_their_names() {
        for k in EntityKind::ALL {
            assert_eq!(EntityKind::from_name(k.name()), Some(k));
        }
        assert_eq!(EntityKind::from_name("robot"), None);
    }
}
