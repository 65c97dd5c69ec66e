//! The mapping file: how a source's names, axes, grasps and contacts become a native
//! recording (`docs/import.md` lists every key).
//!
//! A mapping file is TOML. Every key is optional: what a file leaves out takes the
//! defaults of the source's format ([`Mapping::default_for`]). Unknown keys are errors
//! naming the line and the key. [`Mapping::to_toml`] prints a complete mapping that reads
//! back to the same value, so the mapping `import` used can be saved and edited.

// A reader of untrusted input (issue 23): no arithmetic that can wrap or panic, no
// cast that can truncate; each such operation is checked, saturating or proved in range.
#![deny(clippy::arithmetic_side_effects, clippy::cast_possible_truncation)]

use std::collections::BTreeMap;
use std::fmt;

use serde::{Deserialize, Serialize};

use crate::axes::{Axes, QuaternionOrder};
use crate::glob;

/// The kinds of source the import knows.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Format {
    /// A Unity VR playback log (JSON).
    Unity,
    /// A ROS 1 bag (format 2.0).
    Ros1,
    /// A ROS 2 bag (MCAP storage).
    Ros2,
    /// A Weka ARFF table of hand states (not imported; its labels map through `[labels]`).
    Arff,
}

impl Format {
    /// The name used in mapping files and reports: `unity`, `ros1`, `ros2`, `arff`.
    pub fn name(self) -> &'static str {
        match self {
            Format::Unity => "unity",
            Format::Ros1 => "ros1",
            Format::Ros2 => "ros2",
            Format::Arff => "arff",
        }
    }
}

impl fmt::Display for Format {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

/// What a source entity becomes.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Role {
    /// The left hand (native name `left_hand`).
    LeftHand,
    /// The right hand (native name `right_hand`).
    RightHand,
    /// A cube.
    Cube,
    /// A table (see [`crate::Importer`] for how the support surface is found).
    Table,
    /// Kept as an entity of kind `other`.
    Other,
    /// Left out of the recording.
    Ignore,
}

impl Role {
    /// The name used in mapping files.
    pub fn name(self) -> &'static str {
        match self {
            Role::LeftHand => "left_hand",
            Role::RightHand => "right_hand",
            Role::Cube => "cube",
            Role::Table => "table",
            Role::Other => "other",
            Role::Ignore => "ignore",
        }
    }

    /// The native kind, `None` for [`Role::Ignore`].
    pub fn kind(self) -> Option<recording::EntityKind> {
        use recording::EntityKind as K;
        match self {
            Role::LeftHand | Role::RightHand => Some(K::Hand),
            Role::Cube => Some(K::Cube),
            Role::Table => Some(K::Table),
            Role::Other => Some(K::Other),
            Role::Ignore => None,
        }
    }
}

/// Where an entity's reported position sits on its box.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Origin {
    /// At the centre of the box (the native convention).
    #[default]
    Center,
    /// At the middle of the box's bottom face (a Unity table's pivot on the floor).
    Bottom,
}

/// One rule of `[[entity]]`: a source name (exact, or a glob) and what it becomes.
#[derive(Debug, Clone, PartialEq, Default, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct EntityRule {
    /// An exact source name (after stripping an `N:` prefix). Exact names win over globs.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub name: Option<String>,
    /// A case-insensitive glob (`*`, `?`); the first matching glob wins.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub glob: Option<String>,
    /// What the entity becomes.
    pub role: Option<Role>,
    /// The native name; by default `left_hand`/`right_hand` for hands, else the source
    /// name with characters a native name cannot have replaced by `_`.
    #[serde(skip_serializing_if = "Option::is_none", rename = "as")]
    pub rename: Option<String>,
    /// Box size in metres (full lengths along the entity's x, y, z).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub size: Option<[f64; 3]>,
    /// Where the reported position sits on the box.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub origin: Option<Origin>,
}

/// Where grasps (grip and held object) come from.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum GraspSource {
    /// Grab and release events (Unity's `OnGrabPressReplay`/`OnGrabReleaseReplay`).
    Events,
    /// A grip signal per hand; the held cube is found by geometry while the grip is closed.
    Grip,
    /// A message field naming the held object (or a "grabbed by" relation).
    Field,
    /// Geometry: a hand holds a cube that is near it and moves with it.
    Geometry,
}

/// Where contacts come from.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum ContactSource {
    /// As the source reports them (a physics engine's contacts).
    Reported,
    /// From the boxes' geometry, by the grounding (no contacts are written).
    Geometry,
}

/// Field paths of a custom object-list message (`[bag.objects]`): one message lists
/// objects, each with a name, a pose and optionally more.
#[derive(Debug, Clone, PartialEq, Default, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ObjectListFields {
    /// The topic carrying the list.
    pub topic: String,
    /// Path to the list in the message, e.g. `objects`.
    pub list: String,
    /// Path to an object's name in a list element, e.g. `name`.
    pub name: String,
    /// Path to an object's pose (`geometry_msgs/Pose`), e.g. `pose`.
    pub pose: String,
    /// Path to its linear velocity (`geometry_msgs/Vector3`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub velocity: Option<String>,
    /// Path to a hand's grip (0 open to 1 closed).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub grip: Option<String>,
    /// Path to the name of the object a hand holds (empty: nothing).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub held: Option<String>,
    /// Path to the name of the hand holding this object (a "grabbed by" relation).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub grabbed_by: Option<String>,
    /// Path to the list of names of the objects it touches.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub contacts: Option<String>,
}

/// The `[bag]` section: what to read from ROS bags.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct BagMapping {
    /// One frame per message of this topic.
    pub clock_topic: String,
    /// Topics read besides `/tf` and `/tf_static` (pose topics, the object list).
    pub topics: Vec<String>,
    /// The custom object-list message, if the bag has one.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub objects: Option<ObjectListFields>,
}

impl Default for BagMapping {
    fn default() -> BagMapping {
        BagMapping {
            clock_topic: "/tf".to_string(),
            topics: Vec::new(),
            objects: None,
        }
    }
}

/// A mapping: how one source's data becomes a native recording.
#[derive(Debug, Clone, PartialEq)]
pub struct Mapping {
    /// The format the defaults come from.
    pub format: Format,
    /// Seconds an observation stays valid: an entity is missing from a frame when its
    /// latest observation is older than this.
    pub max_age: f64,
    /// Source length unit in metres (1 for metres, 0.001 for millimetres).
    pub unit: f64,
    /// The source's axes.
    pub axes: Axes,
    /// The source's quaternion component order.
    pub quaternion: QuaternionOrder,
    /// Where grasps come from.
    pub grasps: GraspSource,
    /// Where contacts come from.
    pub contacts: ContactSource,
    /// Entity rules: exact names first, then globs in order.
    pub entities: Vec<EntityRule>,
    /// ARFF activity labels to activity names (the `segment` crate validates them).
    pub labels: BTreeMap<String, String>,
    /// What to read from bags.
    pub bag: BagMapping,
}

/// The file form: every key optional, unknown keys refused.
#[derive(Debug, Default, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
struct MappingFile {
    #[serde(skip_serializing_if = "Option::is_none")]
    format: Option<Format>,
    #[serde(skip_serializing_if = "Option::is_none")]
    max_age: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    unit: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    axes: Option<Axes>,
    #[serde(skip_serializing_if = "Option::is_none")]
    quaternion: Option<QuaternionOrder>,
    #[serde(skip_serializing_if = "Option::is_none")]
    grasps: Option<GraspSource>,
    #[serde(skip_serializing_if = "Option::is_none")]
    contacts: Option<ContactSource>,
    /// Whether the default entity rules follow the file's own (default true).
    #[serde(skip_serializing_if = "Option::is_none")]
    default_entities: Option<bool>,
    #[serde(skip_serializing_if = "Option::is_none")]
    labels: Option<BTreeMap<String, String>>,
    #[serde(skip_serializing_if = "Option::is_none")]
    bag: Option<BagFile>,
    #[serde(default, rename = "entity", skip_serializing_if = "Vec::is_empty")]
    entities: Vec<EntityRule>,
}

#[derive(Debug, Default, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
struct BagFile {
    #[serde(skip_serializing_if = "Option::is_none")]
    clock_topic: Option<String>,
    #[serde(skip_serializing_if = "Option::is_none")]
    topics: Option<Vec<String>>,
    #[serde(skip_serializing_if = "Option::is_none")]
    objects: Option<ObjectListFields>,
}

/// A mapping file that could not be read: where, which key (the field, a dotted path
/// such as `entity[2].size`), and what is wrong.
pub type MappingError = recording::TextError;

/// How a source name resolved.
#[derive(Debug, Clone, PartialEq)]
pub struct Resolved {
    /// What the entity becomes.
    pub role: Role,
    /// The native name (valid, not yet checked for clashes).
    pub native: String,
    /// Box size in metres, when known (a table's may not be).
    pub size: Option<[f64; 3]>,
    /// Where the pose sits on the box.
    pub origin: Origin,
    /// The rule that matched, for the report: `name "X"`, `glob "*cube*"` or `no rule`.
    pub rule: String,
}

/// Default box size of a hand (the simulator's).
pub const HAND_SIZE: [f64; 3] = [0.12, 0.09, 0.04];
/// Default cube edge: 5 cm.
pub const CUBE_SIZE: [f64; 3] = [0.05, 0.05, 0.05];
/// Default size of an `other` entity.
pub const OTHER_SIZE: [f64; 3] = [0.1, 0.1, 0.1];

/// The default globs by role, in the order they are tried (the first that matches wins).
const DEFAULT_GLOBS: [(Role, &[&str]); 5] = [
    (
        Role::LeftHand,
        &["*controller_l*", "*lefthand*", "*hand_l*", "*left_hand*"],
    ),
    (
        Role::RightHand,
        &["*controller_r*", "*righthand*", "*hand_r*", "*right_hand*"],
    ),
    (Role::Cube, &["*cube*"]),
    (Role::Table, &["*table*"]),
    (Role::Ignore, &["*camera*", "*origin*", "*marker*"]),
];

fn default_rules() -> Vec<EntityRule> {
    DEFAULT_GLOBS
        .iter()
        .flat_map(|&(role, globs)| {
            globs.iter().map(move |pattern| EntityRule {
                glob: Some(pattern.to_string()),
                role: Some(role),
                ..EntityRule::default()
            })
        })
        .collect()
}

fn default_labels() -> BTreeMap<String, String> {
    [
        ("IdleMotion", "Idle"),
        ("Reach", "Reach"),
        ("Take", "Take"),
        ("PutSomethingSomeWhere", "Put"),
        ("PutSomethingSomewhere", "Put"),
        ("Release", "Put"),
        ("Stack", "Stack"),
    ]
    .into_iter()
    .map(|(a, b)| (a.to_string(), b.to_string()))
    .collect()
}

impl Mapping {
    /// A message about the value of `labels.LABEL` in the text of a mapping file (a
    /// label mapped to no activity), placed where that value starts (1-based line and
    /// column; 0 and 0 when the text has no such label): a [`Mapping`] keeps no positions.
    pub fn label_error(text: &str, label: &str, message: String) -> recording::TextError {
        let (line, column) = Mapping::label_position(text, label).unwrap_or((0, 0));
        let field = format!("labels.{label}");
        recording::TextError {
            line,
            column,
            field,
            message,
        }
    }

    /// Where the value of `labels.LABEL` starts in the text of a mapping file (1-based
    /// line and column). `None` when the text has no such label.
    fn label_position(text: &str, label: &str) -> Option<(usize, usize)> {
        #[derive(Deserialize)]
        struct Labels {
            #[serde(default)]
            labels: BTreeMap<String, toml::Spanned<String>>,
        }
        let file: Labels = toml::from_str(text).ok()?;
        Some(position(text, file.labels.get(label)?.span().start))
    }

    /// The defaults for a format: entity kinds from name parts (`Controller_L`,
    /// `LeftHand`, `Hand_L`, `left_hand`: left hand; the same with `R`/`Right`: right hand; `Cube`; `Table`;
    /// `Camera`, `Origin`, `Marker` ignored), 5 cm cubes, the label map. Unity: Unity axes,
    /// `[w, x, y, z]`, grasps from events, an entity missing from a step is missing
    /// (`max_age = 0`). Bags: REP 103 axes, `[x, y, z, w]`, grasps from geometry,
    /// `max_age = 0.2` s, frames on `/tf`. Contacts come from geometry.
    pub fn default_for(format: Format) -> Mapping {
        let (axes, quaternion, grasps, max_age) = match format {
            Format::Unity => (
                Axes::UNITY,
                QuaternionOrder::WFirst,
                GraspSource::Events,
                0.0,
            ),
            Format::Ros1 | Format::Ros2 | Format::Arff => (
                Axes::REP103,
                QuaternionOrder::WLast,
                GraspSource::Geometry,
                0.2,
            ),
        };
        Mapping {
            format,
            max_age,
            unit: 1.0,
            axes,
            quaternion,
            grasps,
            contacts: ContactSource::Geometry,
            entities: default_rules(),
            labels: default_labels(),
            bag: BagMapping::default(),
        }
    }

    /// Reads a mapping file; keys it leaves out take the defaults of `format` (or of the
    /// file's own `format` key). `[[entity]]` rules come before the default rules, unless
    /// `default_entities = false`.
    pub fn from_toml(text: &str, format: Format) -> Result<Mapping, MappingError> {
        let file: MappingFile = toml::from_str(text).map_err(|e| toml_error(text, &e))?;
        let mut m = Mapping::default_for(file.format.unwrap_or(format));
        if let Some(v) = file.max_age {
            if !(v.is_finite() && v >= 0.0) {
                return Err(key_error(
                    text,
                    "max_age",
                    format!("max_age {v} is not a number of seconds >= 0"),
                ));
            }
            m.max_age = v;
        }
        if let Some(v) = file.unit {
            if !(v.is_finite() && v > 0.0) {
                return Err(key_error(
                    text,
                    "unit",
                    format!("unit {v} is not a positive number of metres"),
                ));
            }
            m.unit = v;
        }
        m.axes = file.axes.unwrap_or(m.axes);
        m.quaternion = file.quaternion.unwrap_or(m.quaternion);
        m.grasps = file.grasps.unwrap_or(m.grasps);
        m.contacts = file.contacts.unwrap_or(m.contacts);
        if let Some(labels) = file.labels {
            m.labels = labels;
        }
        if let Some(bag) = file.bag {
            if let Some(t) = bag.clock_topic {
                m.bag.clock_topic = t;
            }
            if let Some(t) = bag.topics {
                m.bag.topics = t;
            }
            m.bag.objects = bag.objects.or(m.bag.objects);
        }
        // Bags: grasps and contacts come from geometry unless the object list names a
        // field for them (and the file does not choose otherwise).
        if let Some(objects) = &m.bag.objects {
            if file.grasps.is_none() && (objects.held.is_some() || objects.grabbed_by.is_some()) {
                m.grasps = GraspSource::Field;
            }
            if file.contacts.is_none() && objects.contacts.is_some() {
                m.contacts = ContactSource::Reported;
            }
        }
        for (i, rule) in file.entities.iter().enumerate() {
            check_rule(text, i, rule)?;
        }
        let mut rules = file.entities;
        if file.default_entities.unwrap_or(true) {
            rules.extend(default_rules());
        }
        m.entities = rules;
        Ok(m)
    }

    /// The mapping as a complete TOML file, ready to edit: reading it back with
    /// [`Mapping::from_toml`] gives this mapping.
    pub fn to_toml(&self) -> String {
        let file = MappingFile {
            format: Some(self.format),
            max_age: Some(self.max_age),
            unit: Some(self.unit),
            axes: Some(self.axes),
            quaternion: Some(self.quaternion),
            grasps: Some(self.grasps),
            contacts: Some(self.contacts),
            default_entities: Some(false),
            labels: Some(self.labels.clone()),
            bag: Some(BagFile {
                clock_topic: Some(self.bag.clock_topic.clone()),
                topics: Some(self.bag.topics.clone()),
                objects: self.bag.objects.clone(),
            }),
            entities: self.entities.clone(),
        };
        let body = toml::to_string(&file).unwrap_or_default();
        format!(
            "# demoplan import mapping (docs/import.md lists every key).\n\
             # Entity rules: exact `name`s win over `glob`s; the first matching glob wins.\n{body}"
        )
    }

    /// What a source name becomes. A `N:` prefix (a tf frame id's) is stripped first;
    /// exact names win over globs and the first matching glob wins; a name no rule
    /// matches is ignored.
    pub fn resolve(&self, source_name: &str) -> Resolved {
        let stripped = strip_prefix(source_name);
        let exact = self.entities.iter().find(|r| {
            r.name
                .as_deref()
                .is_some_and(|n| n == source_name || n == stripped)
        });
        let rule = exact.or_else(|| {
            self.entities.iter().find(|r| {
                r.glob
                    .as_deref()
                    .is_some_and(|g| glob::matches(g, stripped))
            })
        });
        let Some(rule) = rule else {
            return Resolved {
                role: Role::Ignore,
                native: String::new(),
                size: None,
                origin: Origin::Center,
                rule: "no rule".to_string(),
            };
        };
        let role = rule.role.unwrap_or(Role::Ignore);
        let native = rule.rename.clone().unwrap_or_else(|| match role {
            Role::LeftHand => "left_hand".to_string(),
            Role::RightHand => "right_hand".to_string(),
            _ => native_name(stripped, role),
        });
        let size = rule.size.or(match role {
            Role::LeftHand | Role::RightHand => Some(HAND_SIZE),
            Role::Cube => Some(CUBE_SIZE),
            Role::Other => Some(OTHER_SIZE),
            Role::Table | Role::Ignore => None,
        });
        let described = match (&rule.name, &rule.glob) {
            (Some(n), _) => format!("name \"{n}\""),
            (None, Some(g)) => format!("glob \"{g}\""),
            (None, None) => "a rule".to_string(),
        };
        Resolved {
            role,
            native,
            size,
            origin: rule.origin.unwrap_or_default(),
            rule: described,
        }
    }
}

/// Strips a tf-style `N:` prefix (digits and a colon).
pub fn strip_prefix(name: &str) -> &str {
    match name.split_once(':') {
        Some((n, rest)) if !n.is_empty() && n.bytes().all(|b| b.is_ascii_digit()) => rest,
        _ => name,
    }
}

/// A valid native name from a source name: characters other than ASCII letters, digits,
/// `_` and `-` become `_`; a name not starting with a letter gets the role's name in
/// front (`3DPrintedCube_red` becomes `cube_3DPrintedCube_red`); at most 64 bytes.
pub fn native_name(source: &str, role: Role) -> String {
    let mut name: String = source
        .chars()
        .map(|c| {
            if c.is_ascii_alphanumeric() || c == '_' || c == '-' {
                c
            } else {
                '_'
            }
        })
        .collect();
    if !name.starts_with(|c: char| c.is_ascii_alphabetic()) {
        name = format!("{}_{name}", role.name());
    }
    name.truncate(recording::MAX_NAME_LEN);
    name
}

fn check_rule(text: &str, i: usize, rule: &EntityRule) -> Result<(), MappingError> {
    let at = format!("entity[{i}]");
    let fail = |key: &str, message: String| {
        let mut e = key_error(text, "entity", message);
        e.field = format!("{at}{key}");
        e
    };
    match (&rule.name, &rule.glob) {
        (Some(_), Some(_)) => return Err(fail("", "give `name` or `glob`, not both".into())),
        (None, None) => return Err(fail("", "give a `name` or a `glob`".into())),
        _ => {}
    }
    if rule.role.is_none() {
        return Err(fail(
            ".role",
            "missing `role` (left_hand, right_hand, cube, table, other or ignore)".into(),
        ));
    }
    if let Some(s) = rule.size {
        if !s.iter().all(|v| v.is_finite() && *v > 0.0) {
            return Err(fail(
                ".size",
                format!("size {s:?} is not three positive lengths in metres"),
            ));
        }
    }
    if let Some(n) = &rule.rename {
        if !recording::is_valid_name(n) {
            return Err(fail(
                ".as",
                format!(
                    "`{n}` is not a valid entity name (an ASCII letter, then letters, digits, \
                     `_` or `-`)"
                ),
            ));
        }
    }
    Ok(())
}

fn position(text: &str, offset: usize) -> (usize, usize) {
    let before = &text[..offset.min(text.len())];
    let line = before.matches('\n').count().saturating_add(1);
    let line_start = before.rfind('\n').map_or(0, |i| i.saturating_add(1));
    let column = before.len().saturating_sub(line_start).saturating_add(1);
    (line, column)
}

fn toml_error(text: &str, e: &toml::de::Error) -> MappingError {
    let (line, column) = e.span().map_or((0, 0), |s| position(text, s.start));
    let message = e.message().trim().to_string();
    // The key: toml names an unknown key in the message; otherwise the line's key.
    let key = message
        .split('`')
        .nth(1)
        .filter(|_| message.starts_with("unknown field"))
        .map(str::to_string)
        .or_else(|| line_key(text, line))
        .unwrap_or_default();
    MappingError {
        line,
        column,
        field: key,
        message,
    }
}

fn line_key(text: &str, line: usize) -> Option<String> {
    let l = text.lines().nth(line.checked_sub(1)?)?;
    let key = l.split('=').next()?.trim();
    (!key.is_empty() && !key.starts_with('[')).then(|| key.to_string())
}

/// An error about `key` at its first line in `text` (a key set at the top level or in a
/// table: the first `key =` line).
fn key_error(text: &str, key: &str, message: String) -> MappingError {
    let found = text.lines().enumerate().find(|(_, l)| {
        let t = l.trim_start();
        t.strip_prefix(key)
            .is_some_and(|rest| rest.trim_start().starts_with('=') || key == "entity")
            || (key == "entity" && t.starts_with("[[entity]]"))
    });
    let line = found.map_or(0, |(i, _)| i.saturating_add(1));
    MappingError {
        line,
        column: 0,
        field: key.to_string(),
        message,
    }
}

#[cfg(test)]
#[allow(clippy::arithmetic_side_effects, clippy::cast_possible_truncation)] // tests, not readers
mod tests {
    use super::*;

    #[test]
    fn a_bad_label_is_placed_at_its_value() {
        let text = "[labels]\nPour = \"Put\"\nSpin = \"Twirl\"\n";
        let e = Mapping::label_error(text, "Spin", "no such activity".into());
        assert_eq!((e.line, e.column, e.field.as_str()), (3, 8, "labels.Spin"));
        assert_eq!(e.message, "no such activity");
        // A label the text does not have: no place.
        let e = Mapping::label_error(text, "Jump", String::new());
        assert_eq!((e.line, e.column), (0, 0));
    }

    #[test]
    fn default_kinds_from_name_parts() {
        let m = Mapping::default_for(Format::Unity);
        for (name, role, native) in [
            ("VR_Controller_L", Role::LeftHand, "left_hand"),
            ("VR_Controller_R", Role::RightHand, "right_hand"),
            ("LeftHand", Role::LeftHand, "left_hand"),
            ("2:Hand_R", Role::RightHand, "right_hand"),
            ("3DPrintedCube_red", Role::Cube, "cube_3DPrintedCube_red"),
            ("Table_1", Role::Table, "Table_1"),
            ("Main Camera", Role::Ignore, ""),
            ("XR Origin", Role::Ignore, ""),
            ("Marker_3", Role::Ignore, ""),
            ("Lamp", Role::Ignore, ""),
        ] {
            let r = m.resolve(name);
            assert_eq!(r.role, role, "{name}");
            if role != Role::Ignore {
                assert_eq!(r.native, native, "{name}");
            }
        }
        assert_eq!(m.resolve("Cube_a").size, Some(CUBE_SIZE));
    }

    #[test]
    fn exact_names_win_over_globs_and_first_glob_wins() {
        let m = Mapping::from_toml(
            r#"
[[entity]]
glob = "*cube*"
role = "other"
[[entity]]
name = "BigCube"
role = "cube"
size = [0.1, 0.1, 0.1]
as = "big"
"#,
            Format::Unity,
        )
        .unwrap();
        let big = m.resolve("BigCube");
        assert_eq!((big.role, big.native.as_str()), (Role::Cube, "big"));
        assert_eq!(big.size, Some([0.1; 3]));
        // The file's glob comes before the default `*cube*`.
        assert_eq!(m.resolve("Cube_1").role, Role::Other);
    }

    #[test]
    fn to_toml_reads_back_to_the_same_mapping() {
        for format in [Format::Unity, Format::Ros1, Format::Ros2, Format::Arff] {
            let mut m = Mapping::default_for(format);
            m.entities.insert(
                0,
                EntityRule {
                    name: Some("Table_1".into()),
                    role: Some(Role::Table),
                    size: Some([1.2, 0.8, 0.75]),
                    origin: Some(Origin::Bottom),
                    ..Default::default()
                },
            );
            m.bag.objects = Some(ObjectListFields {
                topic: "/objects".into(),
                list: "objects".into(),
                name: "name".into(),
                pose: "pose".into(),
                grabbed_by: Some("grabbed_by".into()),
                ..Default::default()
            });
            let text = m.to_toml();
            assert_eq!(
                Mapping::from_toml(&text, Format::Ros2).unwrap(),
                m,
                "{text}"
            );
        }
    }

    #[test]
    fn unknown_keys_name_line_and_key() {
        let e = Mapping::from_toml("axes = \"unity\"\ncolour = 3\n", Format::Unity).unwrap_err();
        assert_eq!((e.line, e.field.as_str()), (2, "colour"));
        let e = Mapping::from_toml("[bag]\nclock = \"/tf\"\n", Format::Ros1).unwrap_err();
        assert_eq!((e.line, e.field.as_str()), (2, "clock"));
        let e = Mapping::from_toml("axes = [\"x\", \"x\", \"z\"]\n", Format::Ros1).unwrap_err();
        assert_eq!((e.line, e.field.as_str()), (1, "axes"));
        assert!(e.message.contains("signed permutation"), "{}", e.message);
        let e = Mapping::from_toml("[[entity]]\nglob = \"*\"\n", Format::Ros1).unwrap_err();
        assert_eq!((e.line, e.field.as_str()), (1, "entity[0].role"));
    }
}
