//! The label map: which activity an ARFF table's label stands for.
//!
//! The activity recognisers this work builds on label frames with their own names
//! (`IdleMotion`, `PutSomethingSomeWhere`, often with an instance suffix: `Reach_2`).
//! A [`LabelMap`] turns them into the paper's [`Activity`]s; labels it does not know
//! are left out of comparisons and reported with their counts.

use std::collections::BTreeMap;

use crate::tree::Activity;

/// The documented defaults: each activity's own name, and the recognisers' names.
const DEFAULTS: &[(&str, Activity)] = &[
    ("Idle", Activity::Idle),
    ("IdleMotion", Activity::Idle),
    ("Reach", Activity::Reach),
    ("Take", Activity::Take),
    ("Put", Activity::Put),
    ("PutSomethingSomeWhere", Activity::Put),
    ("PutSomethingSomewhere", Activity::Put),
    ("Release", Activity::Put),
    ("Stack", Activity::Stack),
];

/// From labels to activities. Labels match exactly (case matters, as in ARFF's nominal
/// values); a label with an instance suffix, `Name_<digits>`, that does not match
/// itself matches by its name.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct LabelMap {
    labels: BTreeMap<String, Activity>,
}

/// An override naming an activity that does not exist.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[error("label `{label}`: unknown activity `{activity}` (Idle, Reach, Take, Put or Stack)")]
pub struct LabelMapError {
    /// The label being mapped.
    pub label: String,
    /// The activity name given for it.
    pub activity: String,
}

impl Default for LabelMap {
    /// The defaults: `Idle`, `Reach`, `Take`, `Put` and `Stack` to themselves;
    /// `IdleMotion` to Idle; `PutSomethingSomeWhere`, `PutSomethingSomewhere` and
    /// `Release` to Put.
    fn default() -> LabelMap {
        LabelMap {
            labels: DEFAULTS.iter().map(|&(l, a)| (l.to_string(), a)).collect(),
        }
    }
}

impl LabelMap {
    /// The defaults with `overrides` (label, activity name) on top, later pairs winning
    /// over earlier ones. Activity names are the paper's, in any case.
    pub fn with_overrides<'a>(
        overrides: impl IntoIterator<Item = (&'a str, &'a str)>,
    ) -> Result<LabelMap, LabelMapError> {
        let mut map = LabelMap::default();
        for (label, activity) in overrides {
            map.set(label, activity)?;
        }
        Ok(map)
    }

    /// Maps `label` to the activity named `activity`.
    pub fn set(&mut self, label: &str, activity: &str) -> Result<(), LabelMapError> {
        let a = Activity::from_name(activity).ok_or_else(|| LabelMapError {
            label: label.to_string(),
            activity: activity.to_string(),
        })?;
        self.labels.insert(label.to_string(), a);
        Ok(())
    }

    /// The activity of a label, if the map knows it or the name before its instance
    /// suffix.
    pub fn activity(&self, label: &str) -> Option<Activity> {
        if let Some(&a) = self.labels.get(label) {
            return Some(a);
        }
        let (name, suffix) = label.rsplit_once('_')?;
        if suffix.is_empty() || !suffix.bytes().all(|b| b.is_ascii_digit()) {
            return None;
        }
        self.labels.get(name).copied()
    }

    /// Every label the map knows and its activity, sorted by label.
    pub fn entries(&self) -> impl Iterator<Item = (&str, Activity)> {
        self.labels.iter().map(|(l, &a)| (l.as_str(), a))
    }
}

/// A label the map does not know: how many frames carry it and where it first occurs.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct UnknownLabel {
    /// The label as written.
    pub label: String,
    /// Frames that carry it.
    pub frames: usize,
    /// The first line it is on.
    pub line: usize,
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn defaults_suffixes_and_overrides() {
        let map = LabelMap::default();
        assert_eq!(map.activity("IdleMotion"), Some(Activity::Idle));
        assert_eq!(map.activity("PutSomethingSomeWhere"), Some(Activity::Put));
        assert_eq!(map.activity("PutSomethingSomewhere"), Some(Activity::Put));
        assert_eq!(map.activity("Release_12"), Some(Activity::Put));
        assert_eq!(map.activity("Reach_"), None);
        assert_eq!(map.activity("Reach_2b"), None);
        assert_eq!(map.activity("reach"), None);
        assert_eq!(map.activity("Pour"), None);
        let map = LabelMap::with_overrides([("Pour", "put"), ("Release", "Idle")]).unwrap();
        assert_eq!(map.activity("Pour_3"), Some(Activity::Put));
        assert_eq!(map.activity("Release"), Some(Activity::Idle));
        let e = LabelMap::with_overrides([("Pour", "Spill")]).unwrap_err();
        assert_eq!(
            e.to_string(),
            "label `Pour`: unknown activity `Spill` (Idle, Reach, Take, Put or Stack)"
        );
    }
}
