//! Weka's ARFF: a tolerant reader of tables, and their reading as the symbolic hand-state
//! frames of the activity recognisers this work builds on (attributes such as
//! `Hand {NotMove, Move, ToolUse}`, `ObjectActedOn`, `ObjectInHand`,
//! `HandState {Open, Close}`, `Activity {...}`).
//!
//! Real files are messy; what the reader accepts beyond its header (object names where
//! the header declares only `{None, Something}`, `NONE` in any case, activity labels
//! outside the declared set) it says in [`ArffWarning`]s.

// A reader of untrusted input (issue 23): no arithmetic that can wrap or panic, no
// cast that can truncate; each such operation is checked, saturating or proved in range.
#![deny(clippy::arithmetic_side_effects, clippy::cast_possible_truncation)]

use std::borrow::Borrow;
use std::collections::BTreeSet;

use grounding::{Fact, FactSpace, HandFacts, Predicate, State};
use recording::{Entity, EntityId, EntityKind, Header, Vec3};

use crate::c45::{Case, Dataset};
use crate::labels::{LabelMap, UnknownLabel};
use crate::segmenter::{Segment, Segmenter};
use crate::tree::{Activity, ActivityTree};

mod reader;
use crate::tree::{Attribute, Feature};
pub use reader::{is_arff_file, is_arff_text, read_arff, ArffReader, WEKA_DUMMY_STRING};

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

/// A file that cannot be read: line, column (1-based; 0 when unknown), field (the
/// attribute or header keyword concerned), what.
pub type ArffError = recording::TextError;

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
                            attribute.values.len().saturating_sub(1)
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

/// The position of an attribute, by any of `names` ignoring case.
fn find_any(attributes: &[ArffAttribute], names: &[&str]) -> Option<usize> {
    names.iter().find_map(|n| {
        attributes
            .iter()
            .position(|a| a.name.eq_ignore_ascii_case(n))
    })
}

/// `None` or `nil`, in any case: no object.
fn is_none(v: &str) -> bool {
    v.eq_ignore_ascii_case("none") || v.eq_ignore_ascii_case("nil")
}

/// Whether attributes make a hand-state table (a hand's motion, the object acted on, the
/// object in hand).
pub fn is_hand_state(attributes: &[ArffAttribute]) -> bool {
    find_any(attributes, HAND).is_some()
        && find_any(attributes, ACTED_ON).is_some()
        && find_any(attributes, IN_HAND).is_some()
}

impl ArffTable {
    /// Whether the table has the hand-state columns (a hand's motion, the object acted
    /// on, the object in hand).
    pub fn is_hand_state(&self) -> bool {
        is_hand_state(&self.attributes)
    }

    /// Reads the table as frames of one hand. Rows without a time attribute are
    /// `1 / frame_rate` apart.
    pub fn hand_frames(&self, frame_rate: f64) -> Result<HandFrames, ArffError> {
        let table = HandTable::scan(
            &self.relation,
            &self.attributes,
            self.rows.iter().map(Ok),
            frame_rate,
        )?;
        let frames = table
            .frames(self.rows.iter().map(Ok))
            .collect::<Result<Vec<_>, _>>()?;
        Ok(HandFrames {
            header: table.header,
            frames,
            labels: table.labels,
            has_hand_state: table.columns.state.is_some(),
            warnings: table.warnings,
        })
    }
}

/// Where a hand-state table keeps its columns.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
struct HandColumns {
    hand: usize,
    acted: usize,
    held: usize,
    state: Option<usize>,
    activity: Option<usize>,
    /// A numeric time attribute.
    time: Option<usize>,
}

impl HandColumns {
    fn find(attributes: &[ArffAttribute]) -> Result<HandColumns, ArffError> {
        let need = |names: &[&str]| {
            find_any(attributes, names).ok_or_else(|| {
                error(
                    0,
                    0,
                    names[0],
                    format!("not a hand-state table: no attribute `{}`", names[0]),
                )
            })
        };
        Ok(HandColumns {
            hand: need(HAND)?,
            acted: need(ACTED_ON)?,
            held: need(IN_HAND)?,
            state: find_any(attributes, HAND_STATE),
            activity: find_any(attributes, ACTIVITY),
            time: find_any(attributes, TIME).filter(|&t| attributes[t].kind == ArffKind::Numeric),
        })
    }
}

/// What a first pass sees of an object column: the names the header does not declare
/// and the first odd spelling of None.
#[derive(Debug, Default)]
struct ObjectColumn {
    declared: Vec<String>,
    names_met: Vec<String>,
    first_line: usize,
    odd_none: Option<(usize, String)>,
}

/// A hand-state table after a first pass over its rows: the scene (the hand and every
/// object named), the labels and the warnings, all of which a frame needs before it can
/// be read (an object's entity is its place among all the table's object names). A
/// second pass, [`HandTable::frames`], reads the rows as frames one at a time, so that a
/// table of any length is read in memory bounded by its longest line and the number of
/// distinct names in it: read the file twice with an [`ArffReader`].
#[derive(Debug, Clone, PartialEq)]
pub struct HandTable {
    /// A header for the frames: the hand (`hand`), then every object named, sorted.
    pub header: Header,
    /// The activity labels: those declared, then others met, in order of appearance.
    pub labels: Vec<String>,
    /// What was accepted beyond the header.
    pub warnings: Vec<ArffWarning>,
    attributes: Vec<ArffAttribute>,
    columns: HandColumns,
    /// The object names, sorted: entity `i + 1` is `objects[i]`.
    objects: Vec<String>,
}

impl HandTable {
    /// The first pass: reads `rows` of a table with these attributes for its objects
    /// and labels. Rows without a time attribute are `1 / frame_rate` apart.
    pub fn scan<R: Borrow<ArffRow>>(
        relation: &str,
        attributes: &[ArffAttribute],
        rows: impl IntoIterator<Item = Result<R, ArffError>>,
        frame_rate: f64,
    ) -> Result<HandTable, ArffError> {
        let columns = match HandColumns::find(attributes) {
            Ok(columns) => columns,
            Err(e) => {
                // A row that does not read says more than a missing column, and is what
                // `read_arff` then `hand_frames` say first.
                for row in rows {
                    row?;
                }
                return Err(e);
            }
        };
        let mut object_columns = [columns.acted, columns.held].map(|c| ObjectColumn {
            declared: match &attributes[c].kind {
                ArffKind::Nominal(v) => v.clone(),
                _ => Vec::new(),
            },
            ..ObjectColumn::default()
        });
        let mut objects = BTreeSet::new();
        let mut labels: Vec<String> = match columns.activity.map(|a| &attributes[a].kind) {
            Some(ArffKind::Nominal(v)) => v.clone(),
            _ => Vec::new(),
        };
        let declared_labels = labels.len();
        let mut first_extra = 0;
        for row in rows {
            let row = row?;
            let row = row.borrow();
            for (seen, col) in object_columns.iter_mut().zip([columns.acted, columns.held]) {
                let Some(v) = row.values[col].as_deref() else {
                    continue;
                };
                let declared = seen.declared.iter().any(|d| d == v);
                if is_none(v) {
                    if !declared && seen.odd_none.is_none() {
                        seen.odd_none = Some((row.line, v.to_string()));
                    }
                    continue;
                }
                if !objects.contains(v) {
                    objects.insert(v.to_string());
                }
                if !declared && !seen.names_met.iter().any(|n| n == v) {
                    if seen.names_met.is_empty() {
                        seen.first_line = row.line;
                    }
                    seen.names_met.push(v.to_string());
                }
            }
            if let Some(l) = columns.activity.and_then(|a| row.values[a].as_deref()) {
                if !labels.iter().any(|x| x == l) {
                    if labels.len() == declared_labels {
                        first_extra = row.line;
                    }
                    labels.push(l.to_string());
                }
            }
        }
        let mut warnings = Vec::new();
        for (seen, col) in object_columns.iter().zip([columns.acted, columns.held]) {
            let name = &attributes[col].name;
            if !seen.names_met.is_empty() {
                let only_placeholder = !seen.declared.is_empty()
                    && seen
                        .declared
                        .iter()
                        .all(|v| is_none(v) || v.eq_ignore_ascii_case("something"));
                let why = if only_placeholder {
                    "the header declares only {None, Something}"
                } else {
                    "the header does not declare them"
                };
                warnings.push(ArffWarning {
                    line: seen.first_line,
                    message: format!(
                        "`{name}`: accepted object names ({}) where {why}",
                        seen.names_met.join(", ")
                    ),
                });
            }
            if let Some((line, v)) = &seen.odd_none {
                warnings.push(ArffWarning {
                    line: *line,
                    message: format!("`{name}`: read `{v}` as None"),
                });
            }
        }
        if labels.len() > declared_labels {
            let name = columns
                .activity
                .map_or("Activity", |a| attributes[a].name.as_str());
            warnings.push(ArffWarning {
                line: first_extra,
                message: format!(
                    "`{name}`: accepted labels the header does not declare: {}",
                    labels[declared_labels..].join(", ")
                ),
            });
        }
        warnings.sort_by_key(|w| w.line);
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
        Ok(HandTable {
            header: Header {
                id: relation.to_string(),
                participant: String::new(),
                task: String::new(),
                frame_rate,
                entities,
                meta: Default::default(),
            },
            labels,
            warnings,
            attributes: attributes.to_vec(),
            columns,
            objects,
        })
    }

    /// Whether the table has `HandState` (`handOpen`).
    pub fn has_hand_state(&self) -> bool {
        self.columns.state.is_some()
    }

    /// The second pass: the same rows as [`HandTable::scan`] read, as frames, one at a
    /// time. A row that is not a hand state (an unknown motion or hand state, time not
    /// after the previous row's) ends it with an error at its line.
    pub fn frames<R, I>(&self, rows: I) -> HandTableFrames<'_, I::IntoIter>
    where
        R: Borrow<ArffRow>,
        I: IntoIterator<Item = Result<R, ArffError>>,
    {
        HandTableFrames {
            table: self,
            rows: rows.into_iter(),
            n: 0,
            previous: None,
            done: false,
        }
    }

    /// The fact space of the table's scene: one hand and the objects it names.
    pub fn fact_space(&self) -> FactSpace {
        FactSpace::new(&self.header)
    }

    /// Segments the table's frames (the second pass, [`HandTable::frames`]) with `tree`
    /// and the minimum duration (s): [`HandFrames::segments`] for a table read row by
    /// row. The first error ends it.
    pub fn segments(
        &self,
        frames: impl IntoIterator<Item = Result<LabelledFrame, ArffError>>,
        tree: &ActivityTree,
        min_duration: f64,
    ) -> Result<TableSegments, ArffError> {
        let space = self.fact_space();
        let mut segmenter = Segmenter::new(&[HAND_ID], tree.clone(), min_duration);
        let (mut count, mut first, mut last) = (0u64, None, 0.0);
        for frame in frames {
            let frame = frame?;
            count = count.saturating_add(1);
            first.get_or_insert(frame.time);
            last = frame.time;
            segmenter.push(frame.time, &[frame.hand], &hand_state(&space, &frame));
        }
        Ok(TableSegments {
            space,
            segments: segmenter.finish(),
            frames: count,
            duration: last - first.unwrap_or(last),
        })
    }

    fn object_id(&self, v: Option<&str>) -> Option<EntityId> {
        let v = v?;
        if is_none(v) {
            return None;
        }
        self.objects
            .binary_search_by(|o| o.as_str().cmp(v))
            .ok()
            // Entity 0 is the hand; the objects follow it.
            .and_then(|i| u32::try_from(i).ok()?.checked_add(1))
            .map(EntityId)
    }

    /// Row `n` (0-based) as a frame; `previous` is the time of the frame before.
    fn frame(
        &self,
        row: &ArffRow,
        n: usize,
        previous: Option<f64>,
    ) -> Result<LabelledFrame, ArffError> {
        let c = &self.columns;
        let field = |c: usize| self.attributes[c].name.as_str();
        let moving = match row.values[c.hand].as_deref() {
            Some(v) if v.eq_ignore_ascii_case("move") || v.eq_ignore_ascii_case("tooluse") => true,
            Some(v) if v.eq_ignore_ascii_case("notmove") => false,
            Some(v) => {
                return Err(error(
                    row.line,
                    0,
                    field(c.hand),
                    format!("`{v}` is not a hand motion (NotMove, Move, ToolUse)"),
                ))
            }
            None => {
                return Err(error(
                    row.line,
                    0,
                    field(c.hand),
                    "the hand's motion is unknown (`?`)",
                ))
            }
        };
        let open = match c.state.and_then(|s| row.values[s].as_deref()) {
            None => None,
            Some(v) if v.eq_ignore_ascii_case("open") => Some(true),
            Some(v) if v.eq_ignore_ascii_case("close") || v.eq_ignore_ascii_case("closed") => {
                Some(false)
            }
            Some(v) => {
                let s = c.state.map_or("HandState", field);
                return Err(error(
                    row.line,
                    0,
                    s,
                    format!("`{v}` is not a hand state (Open, Close)"),
                ));
            }
        };
        let t = match c.time.and_then(|t| row.values[t].as_deref()) {
            Some(v) => v.parse::<f64>().unwrap_or(0.0),
            None => n as f64 / self.header.frame_rate,
        };
        if let Some(previous) = previous {
            if t <= previous {
                let tf = c.time.map_or("Time", field);
                return Err(error(
                    row.line,
                    0,
                    tf,
                    format!("time {t} is not after the previous row's {previous}"),
                ));
            }
        }
        Ok(LabelledFrame {
            line: row.line,
            time: t,
            hand: HandFacts {
                moving,
                open,
                acted_on: self.object_id(row.values[c.acted].as_deref()),
                in_hand: self.object_id(row.values[c.held].as_deref()),
            },
            label: c.activity.and_then(|a| row.values[a].clone()),
        })
    }
}

/// The frames of a [`HandTable`], one per row: see [`HandTable::frames`].
#[derive(Debug)]
pub struct HandTableFrames<'a, I> {
    table: &'a HandTable,
    rows: I,
    n: usize,
    previous: Option<f64>,
    done: bool,
}

impl<R: Borrow<ArffRow>, I: Iterator<Item = Result<R, ArffError>>> Iterator
    for HandTableFrames<'_, I>
{
    type Item = Result<LabelledFrame, ArffError>;

    fn next(&mut self) -> Option<Self::Item> {
        if self.done {
            return None;
        }
        let frame = match self.rows.next()? {
            Ok(row) => self.table.frame(row.borrow(), self.n, self.previous),
            Err(e) => Err(e),
        };
        match &frame {
            Ok(f) => {
                self.n = self.n.saturating_add(1);
                self.previous = Some(f.time);
            }
            Err(_) => self.done = true,
        }
        Some(frame)
    }
}

/// A hand-state table segmented: [`HandTable::segments`].
#[derive(Debug, Clone)]
pub struct TableSegments {
    /// The fact space the segments' states belong to.
    pub space: FactSpace,
    /// The segments, sorted by start.
    pub segments: Vec<Segment>,
    /// The number of frames (rows).
    pub frames: u64,
    /// Seconds from the first frame to the last.
    pub duration: f64,
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
        left_out(&self.unknown)
    }

    /// One warning naming every unknown label with its count, if there is one.
    pub fn warning(&self) -> Option<ArffWarning> {
        unknown_warning(&self.unknown)
    }
}

/// The labels a [`LabelMap`] does not know, counted frame by frame: what
/// [`FrameActivities`] says of a whole table, for frames read one at a time.
#[derive(Debug, Clone, Default, PartialEq, Eq)]
pub struct UnknownLabels {
    /// The labels the map does not know, in order of first appearance, with counts.
    pub labels: Vec<UnknownLabel>,
}

impl UnknownLabels {
    /// The activity of a frame's label by `map`; `None` without a label, or when the
    /// map does not know it (then it is counted).
    pub fn activity(&mut self, map: &LabelMap, frame: &LabelledFrame) -> Option<Activity> {
        let label = frame.label.as_deref()?;
        let activity = map.activity(label);
        if activity.is_none() {
            match self.labels.iter_mut().find(|u| u.label == label) {
                Some(u) => u.frames = u.frames.saturating_add(1),
                None => self.labels.push(UnknownLabel {
                    label: label.to_string(),
                    frames: 1,
                    line: frame.line,
                }),
            }
        }
        activity
    }

    /// Frames whose label the map does not know.
    pub fn left_out(&self) -> usize {
        left_out(&self.labels)
    }

    /// One warning naming every unknown label with its count, if there is one.
    pub fn warning(&self) -> Option<ArffWarning> {
        unknown_warning(&self.labels)
    }
}

fn left_out(unknown: &[UnknownLabel]) -> usize {
    unknown.iter().map(|u| u.frames).sum()
}

fn unknown_warning(unknown: &[UnknownLabel]) -> Option<ArffWarning> {
    let first = unknown.first()?;
    let list: Vec<String> = unknown
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

impl HandFrames {
    /// The activity of each frame's label by `map`, and the labels it does not know.
    pub fn activities(&self, map: &LabelMap) -> FrameActivities {
        let mut unknown = UnknownLabels::default();
        let activities = self
            .frames
            .iter()
            .map(|f| unknown.activity(map, f))
            .collect();
        FrameActivities {
            activities,
            unknown: unknown.labels,
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
        hand_state(space, frame)
    }

    /// Segments the table's hand with `tree` and the minimum duration (s), each
    /// segment with its start and end [`HandFrames::state`]; returns the fact space the
    /// states belong to, for learning operators from them.
    pub fn segments(&self, tree: &ActivityTree, min_duration: f64) -> (FactSpace, Vec<Segment>) {
        let space = self.fact_space();
        let mut segmenter = Segmenter::new(&[HAND_ID], tree.clone(), min_duration);
        for f in &self.frames {
            segmenter.push(f.time, &[f.hand], &hand_state(&space, f));
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

/// The state of one frame of a hand-state table: [`HandFrames::state`].
fn hand_state(space: &FactSpace, frame: &LabelledFrame) -> State {
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
