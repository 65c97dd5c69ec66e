//! The operator library: every demonstrated operator with its count and provenance, the
//! recordings it was learned from, costs from counts and display names by rank; stored
//! as versioned JSON.

// A reader of untrusted input (issue 23): no arithmetic that can wrap or panic, no
// cast that can truncate; each such operation is checked, saturating or proved in range.
#![deny(clippy::arithmetic_side_effects, clippy::cast_possible_truncation)]

use std::collections::BTreeMap;

use grounding::{FactSpace, Predicate};
use recording::Header;
use segment::{Activity, Segment};
use serde::{Deserialize, Serialize};

use crate::generalise::{generalise, OperatorForm};
use crate::meaning::Breach;
use crate::mend::{mend, MendCounts};
use crate::operator::{fact_text, lift_all, LiftedFact, Operator, ParamType};
use crate::pipeline::{activities, Grouping};

/// The format name written into every library file.
pub const FORMAT_NAME: &str = "demoplan-library";

/// The newest library format version this build reads and the one it writes.
pub const FORMAT_VERSION: u32 = 1;

/// The paper's lambda: the largest action cost.
pub const DEFAULT_LAMBDA: u32 = 100;

/// A recording the library has learned from. Its content hash keeps it from being
/// counted twice.
#[derive(Debug, Clone, PartialEq, Eq, Default, Serialize, Deserialize)]
pub struct RecordingInfo {
    /// Hash of the recording's bytes, 16 hex digits.
    pub hash: String,
    /// The recording's id (from its header).
    pub id: String,
    /// The participant (from its header).
    pub participant: String,
    /// Where it was read from, as given (informative only).
    #[serde(default)]
    pub source: String,
    /// Its number of frames.
    #[serde(default)]
    pub frames: u64,
    /// Its number of segments (each counted once in the library).
    #[serde(default)]
    pub segments: u64,
    /// Changes seen in it that no hand caused (a cube tipping over, tracker noise): in no
    /// operator's effects (docs/operators.md). Written only when not 0.
    #[serde(default, skip_serializing_if = "is_zero")]
    pub uncaused: u64,
    /// Its activities mended, per breach (docs/operators.md). Written only when any.
    #[serde(default, skip_serializing_if = "BTreeMap::is_empty")]
    pub mended: BTreeMap<Breach, u64>,
    /// Its activities dropped as noise, per breach. Written only when any.
    #[serde(default, skip_serializing_if = "BTreeMap::is_empty")]
    pub dropped: BTreeMap<Breach, u64>,
}

fn is_zero(n: &u64) -> bool {
    *n == 0
}

/// One demonstrated segment behind an operator.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Provenance {
    /// Recording id.
    pub recording: String,
    /// Recording content hash.
    pub hash: String,
    /// Participant.
    pub participant: String,
    /// The hand's entity name.
    pub hand: String,
    /// Start of the segment (s, rounded to the millisecond).
    pub start: f64,
    /// End of the segment (s, rounded to the millisecond).
    pub end: f64,
}

/// An operator with its count and provenance.
#[derive(Debug, Clone, PartialEq)]
pub struct Entry {
    /// The operator, canonical.
    pub operator: Operator,
    /// How many segments demonstrated it.
    pub count: u64,
    /// Which segments, sorted.
    pub provenance: Vec<Provenance>,
}

/// The library. Its content does not depend on the order recordings were added in.
#[derive(Debug, Clone, PartialEq)]
pub struct Library {
    /// The largest cost (`lambda` of the cost formula).
    pub lambda: u32,
    /// How segments become activities; one library counts with one grouping.
    pub grouping: Grouping,
    /// Whether the library shows its operators as demonstrated or generalised.
    form: OperatorForm,
    recordings: BTreeMap<String, RecordingInfo>,
    /// The demonstrated operators: what is counted, merged and stored.
    operators: BTreeMap<Operator, Entry>,
    /// With [`OperatorForm::Generalised`], the generalised operators computed from
    /// `operators` after every change (empty otherwise).
    generalised: BTreeMap<Operator, Entry>,
}

/// An operator with what its rank gives it: name, rank within its type, and cost.
#[derive(Debug, Clone, Copy)]
pub struct Ranked<'a> {
    /// The library entry.
    pub entry: &'a Entry,
    /// 1 for the most frequent operator of its type.
    pub rank: usize,
    /// The paper's cost, from count and type count.
    pub cost: u32,
}

impl Ranked<'_> {
    /// The display name: `put` for rank 1, `put2` for rank 2, ...
    pub fn name(&self) -> String {
        display_name(self.entry.operator.activity, self.rank)
    }

    /// The operator.
    pub fn operator(&self) -> &Operator {
        &self.entry.operator
    }

    /// Its count.
    pub fn count(&self) -> u64 {
        self.entry.count
    }
}

/// `put` for rank 1, `put2` for rank 2, ...
pub fn display_name(activity: Activity, rank: usize) -> String {
    let base = activity.operator_name();
    if rank <= 1 {
        base.to_string()
    } else {
        format!("{base}{rank}")
    }
}

/// The paper's cost, `ceil(lambda * (1 - count / type_count))`, in integers. A type with
/// no segments has no operators; its cost is defined as `lambda`.
pub fn cost(lambda: u32, count: u64, type_count: u64) -> u32 {
    if type_count == 0 {
        return lambda;
    }
    let count = count.min(type_count);
    // u32 times u64 fits u128, and the quotient is at most `lambda`.
    let numerator = u128::from(lambda).saturating_mul(u128::from(type_count.saturating_sub(count)));
    u32::try_from(numerator.div_ceil(u128::from(type_count))).unwrap_or(lambda)
}

/// What adding a recording did.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Added {
    /// Its segments were counted: how many, and how many operators were new.
    Counted {
        /// Segments counted.
        segments: u64,
        /// Operators not in the library before.
        new_operators: usize,
    },
    /// A recording with the same content hash was counted before: nothing changed.
    AlreadyCounted,
}

impl Default for Library {
    fn default() -> Library {
        Library::new(DEFAULT_LAMBDA)
    }
}

impl Library {
    /// An empty library with the default grouping ([`Grouping::Settled`]).
    pub fn new(lambda: u32) -> Library {
        Library::with_grouping(lambda, Grouping::default())
    }

    /// An empty library that groups segments into activities as `grouping` says.
    pub fn with_grouping(lambda: u32, grouping: Grouping) -> Library {
        Library::with_form(lambda, grouping, OperatorForm::default())
    }

    /// An empty library that groups segments as `grouping` says and shows its operators
    /// in `form`: with [`OperatorForm::Generalised`], [`entries`](Self::entries),
    /// [`ranked`](Self::ranked), names, costs and domains are those of the generalised
    /// operators ([`generalise`]), computed from the demonstrated ones, which the
    /// library keeps ([`specific_entries`](Self::specific_entries)) so that learning
    /// stays incremental and independent of order.
    pub fn with_form(lambda: u32, grouping: Grouping, form: OperatorForm) -> Library {
        Library {
            lambda,
            grouping,
            form,
            recordings: BTreeMap::new(),
            operators: BTreeMap::new(),
            generalised: BTreeMap::new(),
        }
    }

    /// The form the library shows its operators in.
    pub fn form(&self) -> OperatorForm {
        self.form
    }

    /// The operators the library shows: demonstrated or generalised.
    fn shown(&self) -> &BTreeMap<Operator, Entry> {
        match self.form {
            OperatorForm::Specific => &self.operators,
            OperatorForm::Generalised => &self.generalised,
        }
    }

    /// Recomputes the generalised operators from the demonstrated ones: a generalised
    /// operator's count is the sum of its members', its provenance their union.
    fn refresh(&mut self) {
        if self.form != OperatorForm::Generalised {
            return;
        }
        let entries: Vec<&Entry> = self.operators.values().collect();
        let operators: Vec<Operator> = entries.iter().map(|e| e.operator.clone()).collect();
        self.generalised = generalise(&operators)
            .into_iter()
            .map(|(operator, members)| {
                let mut count = 0u64;
                let mut provenance = Vec::new();
                for m in members {
                    if let Some(e) = entries.get(m) {
                        count = count.saturating_add(e.count);
                        provenance.extend(e.provenance.iter().cloned());
                    }
                }
                sort_provenance(&mut provenance);
                let entry = Entry {
                    operator: operator.clone(),
                    count,
                    provenance,
                };
                (operator, entry)
            })
            .collect();
    }

    /// Counts the operators of a recording's activities (its segments, consecutive ones of
    /// the same class per hand merged: see [`activities`]), unless a recording with the
    /// same hash was counted before.
    pub fn add_recording(
        &mut self,
        info: RecordingInfo,
        header: &Header,
        space: &FactSpace,
        segments: &[Segment],
    ) -> Added {
        if self.recordings.contains_key(&info.hash) {
            return Added::AlreadyCounted;
        }
        let mut new_operators = 0usize;
        let grouped = activities(segments, self.grouping);
        let (activities, mending) = mend(&grouped, self.grouping, space);
        let (operators, uncaused) = lift_all(&activities, space, header);
        for (s, operator) in activities.iter().zip(operators) {
            let provenance = Provenance {
                recording: info.id.clone(),
                hash: info.hash.clone(),
                participant: info.participant.clone(),
                hand: header
                    .entities
                    .get(s.hand.index())
                    .map(|e| e.name.clone())
                    .unwrap_or_default(),
                start: millis(s.start),
                end: millis(s.end),
            };
            if self.count_operator(operator, 1, vec![provenance]) {
                new_operators = new_operators.saturating_add(1);
            }
        }
        self.refresh();
        let segments_counted = activities.len() as u64;
        self.recordings.insert(
            info.hash.clone(),
            RecordingInfo {
                segments: segments_counted,
                uncaused,
                mended: mending.mended,
                dropped: mending.dropped,
                ..info
            },
        );
        Added::Counted {
            segments: segments_counted,
            new_operators,
        }
    }

    /// Adds every recording and count of another library (recordings this one has are
    /// skipped). Libraries that group segments differently count different things and
    /// are not merged; nor are libraries of different operator forms.
    pub fn merge(&mut self, other: &Library) -> Result<(), LibraryError> {
        if other.form != self.form {
            return Err(LibraryError {
                line: 0,
                column: 0,
                field: "operator_form".to_string(),
                message: format!(
                    "cannot merge a library of {} operators into one of {} operators",
                    other.form.name(),
                    self.form.name()
                ),
            });
        }
        if other.grouping != self.grouping {
            return Err(LibraryError {
                line: 0,
                column: 0,
                field: "activities".to_string(),
                message: format!(
                    "cannot merge a library of `{}` activities into one of `{}` activities",
                    other.grouping.name(),
                    self.grouping.name()
                ),
            });
        }
        let fresh: Vec<&String> = other
            .recordings
            .keys()
            .filter(|h| !self.recordings.contains_key(*h))
            .collect();
        for hash in &fresh {
            if let Some(info) = other.recordings.get(*hash) {
                self.recordings.insert((*hash).clone(), info.clone());
            }
        }
        for e in other.operators.values() {
            let mine: Vec<Provenance> = e
                .provenance
                .iter()
                .filter(|p| fresh.contains(&&p.hash))
                .cloned()
                .collect();
            if mine.is_empty() {
                continue;
            }
            self.count_operator(e.operator.clone(), mine.len() as u64, mine);
        }
        self.refresh();
        Ok(())
    }

    /// Adds `count` occurrences of an operator without provenance (for tests of what
    /// is computed from counts).
    #[cfg(test)]
    pub(crate) fn insert_counted(&mut self, operator: Operator, count: u64) {
        self.count_operator(operator, count, Vec::new());
        self.refresh();
    }

    /// Counts `count` more demonstrations of `operator`, by the segments of
    /// `provenance`; true if the library did not have the operator yet.
    fn count_operator(
        &mut self,
        operator: Operator,
        count: u64,
        provenance: Vec<Provenance>,
    ) -> bool {
        let mut new = false;
        let entry = self.operators.entry(operator.clone()).or_insert_with(|| {
            new = true;
            Entry {
                operator,
                count: 0,
                provenance: Vec::new(),
            }
        });
        entry.count = entry.count.saturating_add(count);
        entry.provenance.extend(provenance);
        sort_provenance(&mut entry.provenance);
        new
    }

    /// The recordings learned from, by hash.
    pub fn recordings(&self) -> impl Iterator<Item = &RecordingInfo> {
        self.recordings.values()
    }

    /// Activities mended and dropped over every recording ([`crate::mend`]).
    pub fn mend_counts(&self) -> MendCounts {
        let mut counts = MendCounts::default();
        for r in self.recordings.values() {
            counts.add(&MendCounts {
                mended: r.mended.clone(),
                dropped: r.dropped.clone(),
            });
        }
        counts
    }

    /// Changes that no hand caused, over every recording ([`crate::cause`]).
    pub fn uncaused(&self) -> u64 {
        (self.recordings.values()).fold(0u64, |sum, r| sum.saturating_add(r.uncaused))
    }

    /// Whether a recording with this hash was counted.
    pub fn has_recording(&self, hash: &str) -> bool {
        self.recordings.contains_key(hash)
    }

    /// Every entry the library shows (generalised ones in a generalised library), in
    /// canonical order.
    pub fn entries(&self) -> impl Iterator<Item = &Entry> {
        self.shown().values()
    }

    /// Every demonstrated operator, in canonical order: the same as
    /// [`entries`](Self::entries) in a library of specific operators.
    pub fn specific_entries(&self) -> impl Iterator<Item = &Entry> {
        self.operators.values()
    }

    /// Number of distinct operators shown.
    pub fn len(&self) -> usize {
        self.shown().len()
    }

    /// Whether the library has no operator.
    pub fn is_empty(&self) -> bool {
        self.operators.is_empty()
    }

    /// Number of segments of a type: the sum of its operators' counts (the same in
    /// either form).
    pub fn type_count(&self, activity: Activity) -> u64 {
        self.operators
            .values()
            .filter(|e| e.operator.activity == activity)
            .fold(0u64, |sum, e| sum.saturating_add(e.count))
    }

    /// Number of segments of all types. Saturating: the counts of a library read are
    /// checked to add up without overflow (`from_json`), so only a library grown past
    /// 2^64 - 1 segments in memory would saturate.
    pub fn segments(&self) -> u64 {
        self.operators
            .values()
            .fold(0u64, |sum, e| sum.saturating_add(e.count))
    }

    /// The operators of one type, most frequent first (ties by canonical form), with
    /// rank and cost.
    pub fn ranked_type(&self, activity: Activity) -> Vec<Ranked<'_>> {
        self.ranked_in(self.shown(), activity)
    }

    fn ranked_in<'a>(
        &self,
        operators: &'a BTreeMap<Operator, Entry>,
        activity: Activity,
    ) -> Vec<Ranked<'a>> {
        let type_count = self.type_count(activity);
        let mut entries: Vec<&Entry> = operators
            .values()
            .filter(|e| e.operator.activity == activity)
            .collect();
        // `operators` iterates in canonical order, and the sort is stable.
        entries.sort_by_key(|e| std::cmp::Reverse(e.count));
        entries
            .into_iter()
            .enumerate()
            .map(|(i, entry)| Ranked {
                entry,
                rank: i.saturating_add(1),
                cost: cost(self.lambda, entry.count, type_count),
            })
            .collect()
    }

    /// Every operator ranked, types in [`Activity::OPERATOR_ORDER`].
    pub fn ranked(&self) -> Vec<Ranked<'_>> {
        Activity::OPERATOR_ORDER
            .iter()
            .flat_map(|&a| self.ranked_type(a))
            .collect()
    }

    /// The library as JSON (deterministic: the same library gives the same bytes).
    pub fn to_json(&self) -> String {
        let records = |operators: &BTreeMap<Operator, Entry>| -> Vec<OperatorRecord> {
            Activity::OPERATOR_ORDER
                .iter()
                .flat_map(|&a| self.ranked_in(operators, a))
                .map(|r| OperatorRecord::of(&r))
                .collect()
        };
        let generalised = self.form == OperatorForm::Generalised;
        let file = LibraryFile {
            format: FORMAT_NAME.to_string(),
            version: FORMAT_VERSION,
            lambda: self.lambda,
            activities: self.grouping.name().to_string(),
            type_counts: Activity::OPERATOR_ORDER
                .iter()
                .map(|&a| (a.name().to_string(), self.type_count(a)))
                .collect(),
            recordings: self.recordings.values().cloned().collect(),
            operator_form: generalised.then(|| self.form.name().to_string()),
            operators: records(self.shown()),
            specific_operators: generalised.then(|| records(&self.operators)),
        };
        let mut text = serde_json::to_string_pretty(&file).unwrap_or_default();
        text.push('\n');
        text
    }

    /// Reads a library. Ids, names, costs and type counts in the file are derived data
    /// and are recomputed; operators that are equal once read (e.g. after editing by
    /// hand) are merged.
    pub fn from_json(text: &str) -> Result<Library, LibraryError> {
        let value: serde_json::Value = serde_json::from_str(text).map_err(|e| LibraryError {
            line: e.line(),
            column: e.column(),
            field: String::new(),
            message: format!("not a valid JSON document: {e}"),
        })?;
        let format = value.get("format").and_then(|v| v.as_str());
        if format != Some(FORMAT_NAME) {
            return Err(LibraryError::at(
                text,
                "\"format\"",
                "format",
                format!(
                    "not a demoplan library: `format` is {}, expected \"{FORMAT_NAME}\"",
                    format.map_or("missing".to_string(), |f| format!("\"{f}\""))
                ),
            ));
        }
        match value.get("version").and_then(|v| v.as_u64()) {
            Some(v) if v == u64::from(FORMAT_VERSION) => {}
            Some(v) if v > u64::from(FORMAT_VERSION) => {
                return Err(LibraryError::at(
                    text,
                    "\"version\"",
                    "version",
                    format!(
                        "library format version {v} is newer than this demoplan reads \
                         (up to {FORMAT_VERSION}); use a newer demoplan"
                    ),
                ))
            }
            other => {
                return Err(LibraryError::at(
                    text,
                    "\"version\"",
                    "version",
                    format!(
                        "unknown library format version {}; this demoplan reads version \
                         {FORMAT_VERSION}",
                        other.map_or("(missing)".to_string(), |v| v.to_string())
                    ),
                ))
            }
        }
        let file: LibraryFile = serde_json::from_str(text).map_err(|e| LibraryError {
            line: e.line(),
            column: e.column(),
            field: String::new(),
            message: e.to_string(),
        })?;
        let grouping = Grouping::from_name(&file.activities).ok_or_else(|| {
            LibraryError::at(
                text,
                "\"activities\"",
                "activities",
                format!(
                    "unknown activity grouping \"{}\" (known: {})",
                    file.activities,
                    Grouping::ALL
                        .map(|g| format!("\"{}\"", g.name()))
                        .join(", ")
                ),
            )
        })?;
        let form = match &file.operator_form {
            None => OperatorForm::Specific,
            Some(name) => OperatorForm::from_name(name).ok_or_else(|| {
                LibraryError::at(
                    text,
                    "\"operator_form\"",
                    "operator_form",
                    format!(
                        "unknown operator form \"{name}\" (known: {})",
                        OperatorForm::ALL
                            .map(|f| format!("\"{}\"", f.name()))
                            .join(", ")
                    ),
                )
            })?,
        };
        // A generalised library counts its demonstrated operators; the ones it shows
        // are computed from them.
        let counted = match (form, file.specific_operators) {
            (OperatorForm::Specific, None) => file.operators,
            (OperatorForm::Generalised, Some(specific)) => specific,
            (OperatorForm::Specific, Some(_)) => {
                return Err(LibraryError::at(
                    text,
                    "\"specific_operators\"",
                    "specific_operators",
                    "`specific_operators` belongs to a library of generalised operators, and \
                     this one has no `\"operator_form\": \"generalised\"`"
                        .to_string(),
                ))
            }
            (OperatorForm::Generalised, None) => {
                return Err(LibraryError::at(
                    text,
                    "\"operator_form\"",
                    "specific_operators",
                    "a library of generalised operators lists the demonstrated ones in \
                     `specific_operators`, and this one has none"
                        .to_string(),
                ))
            }
        };
        let mut library = Library::with_form(file.lambda, grouping, form);
        for r in file.recordings {
            if library.recordings.contains_key(&r.hash) {
                return Err(LibraryError::at(
                    text,
                    &format!("\"{}\"", r.hash),
                    "recordings",
                    format!("recording hash {} is listed twice", r.hash),
                ));
            }
            library.recordings.insert(r.hash.clone(), r);
        }
        let mut total: u64 = 0;
        for (i, record) in counted.into_iter().enumerate() {
            let operator = record.operator(text, i)?;
            // Every sum of counts (per type, per library) is at most this total.
            total = match total.checked_add(record.count) {
                Some(total) => total,
                None => {
                    return Err(LibraryError::at(
                        text,
                        &format!("\"{}\"", record.id),
                        "count",
                        format!(
                            "operator {} ({}): the operators' counts add up to more than {} \
                             (a count this large is no count of demonstrations)",
                            i.saturating_add(1),
                            record.name,
                            u64::MAX
                        ),
                    ))
                }
            };
            if record.count == 0 {
                return Err(LibraryError::at(
                    text,
                    &format!("\"{}\"", record.id),
                    "count",
                    format!(
                        "operator {} ({}) has count 0",
                        i.saturating_add(1),
                        record.name
                    ),
                ));
            }
            for p in &record.provenance {
                if !library.recordings.contains_key(&p.hash) {
                    return Err(LibraryError::at(
                        text,
                        &format!("\"{}\"", p.hash),
                        "provenance",
                        format!(
                            "operator {} ({}) names recording hash {}, which `recordings` \
                             does not list",
                            i.saturating_add(1),
                            record.name,
                            p.hash
                        ),
                    ));
                }
            }
            // Below `total`, checked above: no overflow.
            library.count_operator(operator, record.count, record.provenance);
        }
        library.refresh();
        Ok(library)
    }
}

fn millis(t: f64) -> f64 {
    (t * 1000.0).round() / 1000.0
}

fn sort_provenance(p: &mut [Provenance]) {
    p.sort_by(|a, b| {
        (&a.recording, &a.hash, &a.hand)
            .cmp(&(&b.recording, &b.hash, &b.hand))
            .then(a.start.total_cmp(&b.start))
            .then(a.end.total_cmp(&b.end))
    });
}

/// A library file that cannot be read: where (1-based line and column; 0 when unknown),
/// which field, and what is wrong.
pub type LibraryError = recording::TextError;

fn runs_grouping() -> String {
    Grouping::Runs.name().to_string()
}

#[derive(Debug, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
struct LibraryFile {
    format: String,
    version: u32,
    lambda: u32,
    /// How segments were grouped into activities ([`Grouping::name`]). Files written
    /// before the field existed counted runs of one class.
    #[serde(default = "runs_grouping")]
    activities: String,
    /// `generalised` in a library of generalised operators ([`OperatorForm::name`]);
    /// absent (files before it existed, and libraries of specific operators): specific.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    operator_form: Option<String>,
    /// Derived (sums of counts); written for readers, ignored when read.
    #[serde(default)]
    type_counts: BTreeMap<String, u64>,
    recordings: Vec<RecordingInfo>,
    /// The operators shown: in a generalised library, derived from
    /// `specific_operators` and ignored when read.
    operators: Vec<OperatorRecord>,
    /// In a generalised library: the demonstrated operators, what is counted.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    specific_operators: Option<Vec<OperatorRecord>>,
}

#[derive(Debug, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
struct OperatorRecord {
    /// Derived from the canonical form; ignored when read.
    #[serde(default)]
    id: String,
    /// Derived from the rank; ignored when read.
    #[serde(default)]
    name: String,
    #[serde(rename = "type")]
    activity: String,
    count: u64,
    /// Derived from counts; ignored when read.
    #[serde(default)]
    cost: u32,
    parameters: Vec<String>,
    precondition: Vec<String>,
    negative_precondition: Vec<String>,
    add: Vec<String>,
    delete: Vec<String>,
    #[serde(default)]
    provenance: Vec<Provenance>,
}

impl OperatorRecord {
    /// The record of a ranked operator.
    fn of(r: &Ranked<'_>) -> OperatorRecord {
        let op = r.operator();
        let names = op.param_names();
        let facts = |fs: &[LiftedFact]| fs.iter().map(|f| fact_text(f, &names)).collect();
        OperatorRecord {
            id: op.id(),
            name: r.name(),
            activity: op.activity.name().to_string(),
            count: r.count(),
            cost: r.cost,
            parameters: names
                .iter()
                .zip(&op.params)
                .map(|(n, t)| format!("{n} - {}", t.name()))
                .collect(),
            precondition: facts(&op.pre_positive),
            negative_precondition: facts(&op.pre_negative),
            add: facts(&op.add),
            delete: facts(&op.delete),
            provenance: r.entry.provenance.clone(),
        }
    }

    /// The operator this record describes; errors point at the offending string.
    fn operator(&self, text: &str, index: usize) -> Result<Operator, LibraryError> {
        let which = || {
            if self.name.is_empty() {
                format!("operator {}", index.saturating_add(1))
            } else {
                format!("operator {} ({})", index.saturating_add(1), self.name)
            }
        };
        let activity = Activity::from_name(&self.activity).ok_or_else(|| {
            LibraryError::at(
                text,
                &format!("\"{}\"", self.activity),
                "type",
                format!(
                    "{}: unknown activity type `{}` (expected Reach, Take, Put, Stack or Idle)",
                    which(),
                    self.activity
                ),
            )
        })?;
        let mut names = Vec::new();
        let mut params = Vec::new();
        for p in &self.parameters {
            let bad = |why: &str| {
                LibraryError::at(
                    text,
                    &format!("\"{p}\""),
                    "parameters",
                    format!(
                        "{}: parameter `{p}` {why} (expected `?name - type`, type hand, cube, \
                         table or thing)",
                        which()
                    ),
                )
            };
            let (name, ty) = p.split_once(" - ").ok_or_else(|| bad("has no type"))?;
            let name = name.trim();
            if !name.starts_with('?') || name.len() < 2 {
                return Err(bad("is not a variable"));
            }
            let ty = ParamType::from_name(ty.trim()).ok_or_else(|| bad("has an unknown type"))?;
            if names.iter().any(|n| n == name) {
                return Err(bad("is declared twice"));
            }
            names.push(name.to_string());
            params.push(ty);
        }
        if params.len() > 64 {
            return Err(LibraryError::at(
                text,
                &format!("\"{}\"", self.parameters[64]),
                "parameters",
                format!("{}: more than 64 parameters", which()),
            ));
        }
        let facts = |field: &str, list: &[String]| -> Result<Vec<LiftedFact>, LibraryError> {
            list.iter()
                .map(|s| {
                    parse_fact(s, &names, &params).map_err(|why| {
                        LibraryError::at(
                            text,
                            &format!("\"{s}\""),
                            field,
                            format!("{}: {field} `{s}`: {why}", which()),
                        )
                    })
                })
                .collect()
        };
        let sorted = |field: &str, list: &[String]| {
            facts(field, list).map(|mut v| {
                v.sort_unstable();
                v.dedup();
                v
            })
        };
        Ok(Operator::new(
            activity,
            params.clone(),
            sorted("precondition", &self.precondition)?,
            sorted("negative_precondition", &self.negative_precondition)?,
            sorted("add", &self.add)?,
            sorted("delete", &self.delete)?,
        ))
    }
}

/// `inHand(?h, ?c1)` over the named parameters.
fn parse_fact(s: &str, names: &[String], params: &[ParamType]) -> Result<LiftedFact, String> {
    let s = s.trim();
    let (name, rest) = s.split_once('(').ok_or("expected `predicate(?a, ?b)`")?;
    let args = rest.strip_suffix(')').ok_or("expected `)` at the end")?;
    let predicate = Predicate::ALL
        .into_iter()
        .find(|p| p.name().eq_ignore_ascii_case(name.trim()))
        .ok_or_else(|| {
            format!(
                "unknown predicate `{}` (expected one of {})",
                name.trim(),
                Predicate::ALL.map(|p| p.name()).join(", ")
            )
        })?;
    let args: Vec<&str> = args.split(',').map(str::trim).collect();
    if args.len() != predicate.arity() {
        return Err(format!(
            "{} takes {} argument(s), not {}",
            predicate.name(),
            predicate.arity(),
            args.len()
        ));
    }
    let mut idx = [0u8; 2];
    for (k, a) in args.iter().enumerate() {
        let i = names
            .iter()
            .position(|n| n == a)
            .ok_or_else(|| format!("`{a}` is not a parameter"))?;
        idx[k] = u8::try_from(i).map_err(|_| format!("`{a}` is parameter {i}, past the 256th"))?;
    }
    if predicate.arity() == 1 {
        idx[1] = idx[0];
    }
    // Argument types: the hand slot takes a hand, other slots things.
    let hand_slots: &[usize] = match predicate {
        Predicate::HandMove | Predicate::HandOpen => &[0],
        Predicate::ActedOn | Predicate::Graspable | Predicate::InHand => &[0],
        Predicate::InTouch | Predicate::OnTop => &[],
    };
    for k in 0..predicate.arity() {
        let is_hand = params[idx[k] as usize] == ParamType::Hand;
        if hand_slots.contains(&k) != is_hand {
            return Err(format!(
                "argument {} of {} must be {}",
                k.saturating_add(1),
                predicate.name(),
                if hand_slots.contains(&k) {
                    "a hand"
                } else {
                    "a thing (cube, table or thing), not a hand"
                }
            ));
        }
    }
    Ok(LiftedFact::new(predicate, idx[0], idx[1]))
}

#[cfg(test)]
#[allow(clippy::arithmetic_side_effects, clippy::cast_possible_truncation)] // tests, not readers
mod tests {
    use super::*;

    #[test]
    fn cost_formula_at_its_edges() {
        // The only operator of its type costs nothing.
        assert_eq!(cost(100, 7, 7), 0);
        // Rounding up: 1 - 1/3 = 0.666..., times 100 is 66.6..., so 67.
        assert_eq!(cost(100, 1, 3), 67);
        assert_eq!(cost(100, 2, 3), 34);
        // Exact: 1 - 1/4 = 0.75.
        assert_eq!(cost(100, 1, 4), 75);
        // Seen once among many: close to lambda but below it.
        assert_eq!(cost(100, 1, 1000), 100);
        assert_eq!(cost(100, 1, 1001), 100);
        assert_eq!(cost(100, 999, 1000), 1);
        // Another lambda.
        assert_eq!(cost(10, 1, 3), 7);
        // No overflow with huge counts.
        assert_eq!(cost(u32::MAX, 1, u64::MAX), u32::MAX);
    }

    #[test]
    fn display_names_follow_figure_two() {
        assert_eq!(display_name(Activity::Put, 1), "put");
        assert_eq!(display_name(Activity::Put, 2), "put2");
        assert_eq!(display_name(Activity::Reach, 11), "reach11");
    }

    #[test]
    fn facts_parse_with_types_checked() {
        let names = vec!["?h".to_string(), "?c1".to_string(), "?t".to_string()];
        let params = vec![ParamType::Hand, ParamType::Cube, ParamType::Table];
        assert_eq!(
            parse_fact("inHand(?h, ?c1)", &names, &params),
            Ok(LiftedFact::new(Predicate::InHand, 0, 1))
        );
        assert_eq!(
            parse_fact("INTOUCH(?t, ?c1)", &names, &params),
            Ok(LiftedFact::new(Predicate::InTouch, 1, 2))
        );
        assert!(parse_fact("inHand(?c1, ?h)", &names, &params)
            .is_err_and(|e| e.contains("must be a hand")));
        assert!(parse_fact("onTop(?c1)", &names, &params).is_err_and(|e| e.contains("takes 2")));
        assert!(parse_fact("under(?c1, ?t)", &names, &params)
            .is_err_and(|e| e.contains("unknown predicate")));
        assert!(parse_fact("onTop(?c1, ?c9)", &names, &params)
            .is_err_and(|e| e.contains("not a parameter")));
    }
}
