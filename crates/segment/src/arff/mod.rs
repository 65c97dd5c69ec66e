//! Weka's ARFF: a tolerant reader of tables, and their reading as the symbolic hand-state
//! frames of the activity recognisers this work builds on (attributes such as
//! `Hand {NotMove, Move, ToolUse}`, `ObjectActedOn`, `ObjectInHand`,
//! `HandState {Open, Close}`, `Activity {...}`).
//!
//! Real files are messy; what the reader accepts beyond its header (object names where
//! the header declares only `{None, Something}`, `NONE` in any case, activity labels
//! outside the declared set) it says in [`ArffWarning`]s.

use std::collections::BTreeSet;

use grounding::{Fact, FactSpace, HandFacts, Predicate, State};
use recording::{Entity, EntityId, EntityKind, Header, Vec3};

use crate::c45::{Case, Dataset};
use crate::labels::{LabelMap, UnknownLabel};
use crate::segmenter::{Segment, Segmenter};
use crate::tree::{Activity, ActivityTree};

mod reader;
use crate::tree::{Attribute, Feature};
pub use reader::{is_arff_text, read_arff, WEKA_DUMMY_STRING};

/// The type of an ARFF attribute.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum ArffKind {
    /// `{a, b, c}`: the declared values.
    Nominal(Vec<String>),
    /// `numeric`, `real`, `integer`.
    Numeric,
    /// `string`.
    String,
    /// `date [format]`: the format as written (Java's `SimpleDateFormat`), or Weka's
    /// default `yyyy-MM-dd'T'HH:mm:ss`. Values are kept as text, not parsed.
    Date(String),
}

/// An attribute of an ARFF table.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct ArffAttribute {
    /// Its name.
    pub name: String,
    /// Its type.
    pub kind: ArffKind,
    /// The line it is declared on.
    pub line: usize,
}

/// A data row: its line and one value per attribute (`None` for `?`).
#[derive(Debug, Clone, PartialEq)]
pub struct ArffRow {
    /// 1-based line.
    pub line: usize,
    /// The values as written (unquoted), one per attribute.
    pub values: Vec<Option<String>>,
}

/// A whole ARFF file.
#[derive(Debug, Clone, PartialEq)]
pub struct ArffTable {
    /// `@relation`.
    pub relation: String,
    /// `@attribute`s.
    pub attributes: Vec<ArffAttribute>,
    /// `@data` rows.
    pub rows: Vec<ArffRow>,
}

/// A file that cannot be read: line, column (1-based; 0 when unknown), field, what.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("line {line}, field `{field}`: {message}")]
pub struct ArffError {
    /// 1-based line.
    pub line: usize,
    /// 1-based column.
    pub column: usize,
    /// The attribute (or header keyword) concerned.
    pub field: String,
    /// What is wrong.
    pub message: String,
}

/// Something accepted that the header did not declare.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct ArffWarning {
    /// The first line it happened on.
    pub line: usize,
    /// What was accepted.
    pub message: String,
}

pub(crate) fn error(
    line: usize,
    column: usize,
    field: &str,
    message: impl Into<String>,
) -> ArffError {
    ArffError {
        line,
        column,
        field: field.into(),
        message: message.into(),
    }
}

impl ArffTable {
    /// The position of an attribute, by name ignoring case.
    pub fn attribute(&self, name: &str) -> Option<usize> {
        self.attributes
            .iter()
            .position(|a| a.name.eq_ignore_ascii_case(name))
    }

    /// The table as a dataset for C4.5: nominal attributes, the class `class` (default:
    /// the last attribute). Values outside a declared set are accepted as new values
    /// (with a warning); other attribute types are left out (with a warning); rows whose
    /// class is unknown are skipped.
    pub fn dataset(&self, class: Option<&str>) -> Result<(Dataset, Vec<ArffWarning>), ArffError> {
        let c = match class {
            Some(name) => self
                .attribute(name)
                .ok_or_else(|| error(0, 0, name, format!("no attribute `{name}` to learn")))?,
            None => self.attributes.len().saturating_sub(1),
        };
        let mut warnings = Vec::new();
        let mut columns = Vec::new();
        for (i, a) in self.attributes.iter().enumerate() {
            match &a.kind {
                ArffKind::Nominal(values) => columns.push((i, Attribute { name: a.name.clone(), values: values.clone() }, None::<usize>)),
                _ if i == c => {
                    return Err(error(a.line, 0, &a.name, "the class must be a nominal attribute"))
                }
                _ => warnings.push(ArffWarning {
                    line: a.line,
                    message: format!("attribute `{}` is not nominal; C4.5 here learns from nominal attributes only, so it is left out", a.name),
                }),
            }
        }
        let mut cases = Vec::new();
        for row in &self.rows {
            let mut values = Vec::new();
            let mut label = None;
            for (i, attribute, first) in &mut columns {
                let v = match &row.values[*i] {
                    None => None,
                    Some(v) => Some(match attribute.value(v) {
                        Some(x) => x,
                        None => {
                            attribute.values.push(v.clone());
                            if first.is_none() {
                                *first = Some(row.line);
                            }
                            attribute.values.len() - 1
                        }
                    }),
                };
                if *i == c {
                    label = v;
                } else {
                    values.push(v);
                }
            }
            if let Some(class) = label {
                cases.push(Case {
                    values,
                    class,
                    weight: 1.0,
                });
            }
        }
        for (i, attribute, first) in &columns {
            if let (Some(line), ArffKind::Nominal(declared)) = (first, &self.attributes[*i].kind) {
                let extra: Vec<&str> = attribute.values[declared.len()..]
                    .iter()
                    .map(String::as_str)
                    .collect();
                warnings.push(ArffWarning {
                    line: *line,
                    message: format!(
                        "accepted values of `{}` that the header does not declare: {}",
                        attribute.name,
                        extra.join(", ")
                    ),
                });
            }
        }
        let mut class_attribute = None;
        let mut attributes = Vec::new();
        for (i, a, _) in columns {
            if i == c {
                class_attribute = Some(a);
            } else {
                attributes.push(a);
            }
        }
        let class_attribute = class_attribute.unwrap_or_else(|| Attribute::new("class", &[]));
        Ok((
            Dataset {
                attributes,
                class_name: class_attribute.name,
                classes: class_attribute.values,
                cases,
            },
            warnings,
        ))
    }
}

/// One frame of a hand-state table.
#[derive(Debug, Clone, PartialEq)]
pub struct LabelledFrame {
    /// The row's line.
    pub line: usize,
    /// Time (s): the table's time attribute, or the row number over the frame rate.
    pub time: f64,
    /// The hand's state; objects are entities of [`HandFrames::header`].
    pub hand: HandFacts,
    /// The activity label, if the table has one and it is known.
    pub label: Option<String>,
}

/// A hand-state table read as frames of one hand.
#[derive(Debug, Clone, PartialEq)]
pub struct HandFrames {
    /// A header for the frames: the hand (`hand`), then every object named, sorted.
    pub header: Header,
    /// The frames, in order.
    pub frames: Vec<LabelledFrame>,
    /// The activity labels: those declared, then others met, in order of appearance.
    pub labels: Vec<String>,
    /// Whether the table has `HandState` (`handOpen`).
    pub has_hand_state: bool,
    /// What was accepted beyond the header.
    pub warnings: Vec<ArffWarning>,
}

/// Names the hand-state columns go by (compared ignoring case).
const HAND: &[&str] = &["Hand", "HandMove", "HandMotion"];
const ACTED_ON: &[&str] = &["ObjectActedOn", "ActedOn", "ObjectActOn", "ActOn"];
const IN_HAND: &[&str] = &["ObjectInHand", "InHand"];
const HAND_STATE: &[&str] = &["HandState", "HandOpen"];
const ACTIVITY: &[&str] = &["Activity", "Class", "Label"];
const TIME: &[&str] = &["Time", "t", "Timestamp"];

impl ArffTable {
    fn find_any(&self, names: &[&str]) -> Option<usize> {
        names.iter().find_map(|n| self.attribute(n))
    }

    /// Whether the table has the hand-state columns (a hand's motion, the object acted
    /// on, the object in hand).
    pub fn is_hand_state(&self) -> bool {
        self.find_any(HAND).is_some()
            && self.find_any(ACTED_ON).is_some()
            && self.find_any(IN_HAND).is_some()
    }

    /// Reads the table as frames of one hand. Rows without a time attribute are
    /// `1 / frame_rate` apart.
    pub fn hand_frames(&self, frame_rate: f64) -> Result<HandFrames, ArffError> {
        let need = |names: &[&str]| {
            self.find_any(names).ok_or_else(|| {
                error(
                    0,
                    0,
                    names[0],
                    format!("not a hand-state table: no attribute `{}`", names[0]),
                )
            })
        };
        let hand = need(HAND)?;
        let acted = need(ACTED_ON)?;
        let held = need(IN_HAND)?;
        let state = self.find_any(HAND_STATE);
        let activity = self.find_any(ACTIVITY);
        let time = self
            .find_any(TIME)
            .filter(|&t| self.attributes[t].kind == ArffKind::Numeric);
        let mut warnings = Vec::new();
        // Objects: every value of the object columns that is not None.
        let mut objects = BTreeSet::new();
        let is_none = |v: &str| v.eq_ignore_ascii_case("none") || v.eq_ignore_ascii_case("nil");
        for col in [acted, held] {
            let declared = match &self.attributes[col].kind {
                ArffKind::Nominal(v) => v.clone(),
                _ => Vec::new(),
            };
            let only_placeholder = !declared.is_empty()
                && declared
                    .iter()
                    .all(|v| is_none(v) || v.eq_ignore_ascii_case("something"));
            let mut names_met: Vec<&str> = Vec::new();
            let mut first_line = 0;
            let mut odd_none: Option<(usize, &str)> = None;
            for row in &self.rows {
                let Some(v) = row.values[col].as_deref() else {
                    continue;
                };
                if is_none(v) {
                    if !declared.iter().any(|d| d == v) && odd_none.is_none() {
                        odd_none = Some((row.line, v));
                    }
                    continue;
                }
                objects.insert(v.to_string());
                if !declared.iter().any(|d| d == v) && !names_met.contains(&v) {
                    if names_met.is_empty() {
                        first_line = row.line;
                    }
                    names_met.push(v);
                }
            }
            let name = &self.attributes[col].name;
            if !names_met.is_empty() {
                let why = if only_placeholder {
                    "the header declares only {None, Something}"
                } else {
                    "the header does not declare them"
                };
                warnings.push(ArffWarning {
                    line: first_line,
                    message: format!(
                        "`{name}`: accepted object names ({}) where {why}",
                        names_met.join(", ")
                    ),
                });
            }
            if let Some((line, v)) = odd_none {
                warnings.push(ArffWarning {
                    line,
                    message: format!("`{name}`: read `{v}` as None"),
                });
            }
        }
        let objects: Vec<String> = objects.into_iter().collect();
        let mut entities = vec![Entity {
            name: "hand".into(),
            kind: EntityKind::Hand,
            size: Vec3::new(0.12, 0.09, 0.04),
            fixed: None,
        }];
        entities.extend(objects.iter().map(|o| Entity {
            name: o.clone(),
            kind: EntityKind::Other,
            size: Vec3::new(0.05, 0.05, 0.05),
            fixed: None,
        }));
        let object_id = |v: Option<&str>| -> Option<EntityId> {
            let v = v?;
            if is_none(v) {
                return None;
            }
            objects
                .binary_search_by(|o| o.as_str().cmp(v))
                .ok()
                .map(|i| EntityId(i as u32 + 1))
        };
        let mut labels: Vec<String> = match activity.map(|a| &self.attributes[a].kind) {
            Some(ArffKind::Nominal(v)) => v.clone(),
            _ => Vec::new(),
        };
        let declared_labels = labels.len();
        let mut first_extra = 0;
        let mut frames = Vec::with_capacity(self.rows.len());
        for (n, row) in self.rows.iter().enumerate() {
            let field = |c: usize| self.attributes[c].name.as_str();
            let moving = match row.values[hand].as_deref() {
                Some(v) if v.eq_ignore_ascii_case("move") || v.eq_ignore_ascii_case("tooluse") => {
                    true
                }
                Some(v) if v.eq_ignore_ascii_case("notmove") => false,
                Some(v) => {
                    return Err(error(
                        row.line,
                        0,
                        field(hand),
                        format!("`{v}` is not a hand motion (NotMove, Move, ToolUse)"),
                    ))
                }
                None => {
                    return Err(error(
                        row.line,
                        0,
                        field(hand),
                        "the hand's motion is unknown (`?`)",
                    ))
                }
            };
            let open = match state.and_then(|s| row.values[s].as_deref()) {
                None => None,
                Some(v) if v.eq_ignore_ascii_case("open") => Some(true),
                Some(v) if v.eq_ignore_ascii_case("close") || v.eq_ignore_ascii_case("closed") => {
                    Some(false)
                }
                Some(v) => {
                    let s = state.map_or("HandState", field);
                    return Err(error(
                        row.line,
                        0,
                        s,
                        format!("`{v}` is not a hand state (Open, Close)"),
                    ));
                }
            };
            let label = activity.and_then(|a| row.values[a].clone());
            if let Some(l) = &label {
                if !labels.contains(l) {
                    if labels.len() == declared_labels {
                        first_extra = row.line;
                    }
                    labels.push(l.clone());
                }
            }
            let t = match time.and_then(|t| row.values[t].as_deref()) {
                Some(v) => v.parse::<f64>().unwrap_or(0.0),
                None => n as f64 / frame_rate,
            };
            if let Some(previous) = frames.last().map(|f: &LabelledFrame| f.time) {
                if t <= previous {
                    let tf = time.map_or("Time", field);
                    return Err(error(
                        row.line,
                        0,
                        tf,
                        format!("time {t} is not after the previous row's {previous}"),
                    ));
                }
            }
            frames.push(LabelledFrame {
                line: row.line,
                time: t,
                hand: HandFacts {
                    moving,
                    open,
                    acted_on: object_id(row.values[acted].as_deref()),
                    in_hand: object_id(row.values[held].as_deref()),
                },
                label,
            });
        }
        if labels.len() > declared_labels {
            let name = activity.map_or("Activity", |a| self.attributes[a].name.as_str());
            warnings.push(ArffWarning {
                line: first_extra,
                message: format!(
                    "`{name}`: accepted labels the header does not declare: {}",
                    labels[declared_labels..].join(", ")
                ),
            });
        }
        warnings.sort_by_key(|w| w.line);
        Ok(HandFrames {
            header: Header {
                id: self.relation.clone(),
                participant: String::new(),
                task: String::new(),
                frame_rate,
                entities,
                meta: Default::default(),
            },
            frames,
            labels,
            has_hand_state: state.is_some(),
            warnings,
        })
    }
}

/// The activities of a table's labels, by a [`LabelMap`].
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct FrameActivities {
    /// Per frame, the activity of its label; `None` without a label or when the map
    /// does not know it.
    pub activities: Vec<Option<Activity>>,
    /// The labels the map does not know, in order of first appearance, with counts.
    pub unknown: Vec<UnknownLabel>,
}

impl FrameActivities {
    /// Frames whose label the map does not know.
    pub fn left_out(&self) -> usize {
        self.unknown.iter().map(|u| u.frames).sum()
    }

    /// One warning naming every unknown label with its count, if there is one.
    pub fn warning(&self) -> Option<ArffWarning> {
        let first = self.unknown.first()?;
        let list: Vec<String> = self
            .unknown
            .iter()
            .map(|u| {
                let s = if u.frames == 1 { "" } else { "s" };
                format!("{} ({} frame{s})", u.label, u.frames)
            })
            .collect();
        Some(ArffWarning {
            line: first.line,
            message: format!(
                "labels the label map does not know, left out: {}",
                list.join(", ")
            ),
        })
    }
}

impl HandFrames {
    /// The activity of each frame's label by `map`, and the labels it does not know.
    pub fn activities(&self, map: &LabelMap) -> FrameActivities {
        let mut unknown: Vec<UnknownLabel> = Vec::new();
        let activities = self
            .frames
            .iter()
            .map(|f| {
                let label = f.label.as_deref()?;
                let activity = map.activity(label);
                if activity.is_none() {
                    match unknown.iter_mut().find(|u| u.label == label) {
                        Some(u) => u.frames += 1,
                        None => unknown.push(UnknownLabel {
                            label: label.to_string(),
                            frames: 1,
                            line: f.line,
                        }),
                    }
                }
                activity
            })
            .collect();
        FrameActivities {
            activities,
            unknown,
        }
    }

    /// The labelled frames as a dataset for C4.5 over the hand features (`handMove`,
    /// `actedOn`, `inHand`, and `handOpen` when the table has it), class `Activity`:
    /// the activities of their labels by `map`, in order of first appearance. Frames
    /// whose label the map does not know are left out.
    pub fn dataset(&self, map: &LabelMap) -> Dataset {
        let mut features = vec![Feature::HandMove, Feature::ActedOn, Feature::InHand];
        if self.has_hand_state {
            features.push(Feature::HandOpen);
        }
        let activities = self.activities(map).activities;
        let mut classes: Vec<Activity> = Vec::new();
        for a in activities.iter().flatten() {
            if !classes.contains(a) {
                classes.push(*a);
            }
        }
        let names: Vec<String> = classes.iter().map(|a| a.name().to_string()).collect();
        dataset(
            &features,
            &names,
            self.frames.iter().zip(&activities).filter_map(|(f, a)| {
                let a = (*a)?;
                Some((f.hand, classes.iter().position(|&c| c == a)?))
            }),
        )
    }

    /// The fact space of the table's scene: one hand and the objects it names.
    pub fn fact_space(&self) -> FactSpace {
        FactSpace::new(&self.header)
    }

    /// The state of one frame: its hand's own facts, which are all a hand-state table
    /// has. `handMove`; `handOpen` when the table says so (a table without `HandState`
    /// never has it); `actedOn` and `inHand` of the objects named. No `graspable`,
    /// `inTouch` or `onTop`: the table has no geometry.
    pub fn state(&self, space: &FactSpace, frame: &LabelledFrame) -> State {
        let mut state = space.empty_state();
        let hand = HAND_ID;
        let hand_facts = &frame.hand;
        let mut add = |fact: Fact| {
            if let Some(id) = space.id(&fact) {
                state.insert(id);
            }
        };
        if hand_facts.moving {
            add(Fact::unary(Predicate::HandMove, hand));
        }
        if hand_facts.open == Some(true) {
            add(Fact::unary(Predicate::HandOpen, hand));
        }
        if let Some(o) = hand_facts.acted_on {
            add(Fact::binary(Predicate::ActedOn, hand, o));
        }
        if let Some(o) = hand_facts.in_hand {
            add(Fact::binary(Predicate::InHand, hand, o));
        }
        state
    }

    /// Segments the table's hand with `tree` and the minimum duration (s), each
    /// segment with its start and end [`HandFrames::state`]; returns the fact space the
    /// states belong to, for learning operators from them.
    pub fn segments(&self, tree: &ActivityTree, min_duration: f64) -> (FactSpace, Vec<Segment>) {
        let space = self.fact_space();
        let mut segmenter = Segmenter::new(&[HAND_ID], tree.clone(), min_duration);
        for f in &self.frames {
            let state = self.state(&space, f);
            segmenter.push(f.time, &[f.hand], &state);
        }
        (space, segmenter.finish())
    }

    /// Seconds from the first frame to the last.
    pub fn duration(&self) -> f64 {
        match (self.frames.first(), self.frames.last()) {
            (Some(a), Some(b)) => b.time - a.time,
            _ => 0.0,
        }
    }
}

/// The one hand of a hand-state table: the first entity of [`HandFrames::header`].
const HAND_ID: EntityId = EntityId(0);

/// A dataset over hand features from `(hand, class index)` pairs.
pub fn dataset(
    features: &[Feature],
    classes: &[String],
    cases: impl Iterator<Item = (HandFacts, usize)>,
) -> Dataset {
    Dataset {
        attributes: features.iter().map(|f| f.attribute()).collect(),
        class_name: "Activity".into(),
        classes: classes.to_vec(),
        cases: cases
            .map(|(hand, class)| Case {
                values: features
                    .iter()
                    .map(|f| f.of(&hand).map(usize::from))
                    .collect(),
                class,
                weight: 1.0,
            })
            .collect(),
    }
}
