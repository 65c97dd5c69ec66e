//! Checking an activity tree against labelled hand frames, and learning one from them
//! (what `demoplan classify` does): a [`Confusion`] table of labels against the tree's
//! activities, and [`learn_activity_tree`], C4.5 over the hand's features.
//!
//! ```
//! use grounding::HandFacts;
//! use segment::{Activity, ActivityTree, Confusion};
//!
//! let tree = ActivityTree::table_one();
//! let mut confusion = Confusion::default();
//! let idle = HandFacts { moving: false, open: None, acted_on: None, in_hand: None };
//! confusion.add(Activity::Idle, tree.classify(&idle));
//! confusion.add(Activity::Reach, tree.classify(&idle));
//! assert_eq!((confusion.frames(), confusion.agreeing()), (2, 1));
//! ```

use std::fmt::Write as _;

use grounding::HandFacts;

use crate::arff::dataset;
use crate::c45::{Dataset, C45};
use crate::tree::{Activity, DecisionTree, Feature};

/// Per label, how many frames a tree classified as each activity. Labels are kept in the
/// order they were first met, which is the order of the table's rows.
#[derive(Debug, Clone, Default, PartialEq, Eq)]
pub struct Confusion {
    labels: Vec<Activity>,
    /// `counts[label][predicted]`, both by [`Activity::index`].
    counts: [[u64; Activity::ALL.len()]; Activity::ALL.len()],
}

impl Confusion {
    /// One frame labelled `label` that the tree classified as `predicted`.
    pub fn add(&mut self, label: Activity, predicted: Activity) {
        if !self.labels.contains(&label) {
            self.labels.push(label);
        }
        self.counts[label.index()][predicted.index()] += 1;
    }

    /// The labels met, in the order first met.
    pub fn labels(&self) -> &[Activity] {
        &self.labels
    }

    /// Frames labelled `label` that the tree classified as `predicted`.
    pub fn count(&self, label: Activity, predicted: Activity) -> u64 {
        self.counts[label.index()][predicted.index()]
    }

    /// Every frame counted.
    pub fn frames(&self) -> u64 {
        self.counts.iter().flatten().sum()
    }

    /// Frames whose label is the tree's activity.
    pub fn agreeing(&self) -> u64 {
        Activity::ALL.iter().map(|&a| self.count(a, a)).sum()
    }

    /// The report of labelled frames from `source`: a line with the counts (and the
    /// `left_out` frames whose labels the label map did not know), then a row per label
    /// with its frames per activity the tree gave them.
    pub fn report(&self, source: &str, left_out: usize) -> String {
        let (frames, agree) = (self.frames(), self.agreeing());
        let left_out = match left_out {
            0 => String::new(),
            n => format!("; {n} left out, their labels not in the label map"),
        };
        let mut out = format!(
            "{source}: {frames} labelled hand frames, {agree} agree with the tree ({:.2}%){left_out}\n",
            100.0 * agree as f64 / frames.max(1) as f64
        );
        let _ = write!(out, "{:<10}", "label");
        for a in Activity::ALL {
            let _ = write!(out, " {:>7}", a.name());
        }
        out.push('\n');
        for &label in &self.labels {
            let _ = write!(out, "{:<10}", label.name());
            for a in Activity::ALL {
                let _ = write!(out, " {:>7}", self.count(label, a));
            }
            out.push('\n');
        }
        out
    }
}

/// A tree learned by C4.5, with how many of its training cases it classifies right.
#[derive(Debug, Clone, PartialEq)]
pub struct LearnedTree {
    /// The tree.
    pub tree: DecisionTree,
    /// Training cases the tree classifies as labelled.
    pub correct: usize,
    /// Training cases.
    pub cases: usize,
}

impl LearnedTree {
    /// The tree's lines, then Weka's line on the training cases.
    pub fn report(&self) -> String {
        format!(
            "{}\nCorrectly classified training cases: {} of {} ({:.2}%)\n",
            self.tree,
            self.correct,
            self.cases,
            100.0 * self.correct as f64 / self.cases.max(1) as f64
        )
    }
}

impl C45 {
    /// [`C45::learn`], and the learned tree checked on the data it was learned from.
    pub fn learn_checked(&self, data: &Dataset) -> LearnedTree {
        let tree = self.learn(data);
        let correct = data
            .cases
            .iter()
            .filter(|c| tree.classify(&c.values) == c.class)
            .count();
        LearnedTree {
            tree,
            correct,
            cases: data.cases.len(),
        }
    }
}

/// An activity tree learned by C4.5 from labelled hand frames, over `handMove`,
/// `actedOn`, `inHand` and, when `hand_open` (the frames' states say it), `handOpen`.
/// The classes are the labels in the order first met.
pub fn learn_activity_tree(
    learner: &C45,
    cases: &[(HandFacts, Activity)],
    hand_open: bool,
) -> LearnedTree {
    let mut features = vec![Feature::HandMove, Feature::ActedOn, Feature::InHand];
    if hand_open {
        features.push(Feature::HandOpen);
    }
    let mut classes: Vec<Activity> = Vec::new();
    for &(_, label) in cases {
        if !classes.contains(&label) {
            classes.push(label);
        }
    }
    let names: Vec<String> = classes.iter().map(|a| a.name().to_string()).collect();
    let indexed = cases.iter().map(|&(hand, label)| {
        let class = classes.iter().position(|&c| c == label).unwrap_or(0);
        (hand, class)
    });
    learner.learn_checked(&dataset(&features, &names, indexed))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::tree::ActivityTree;
    use grounding::HandFacts;
    use recording::EntityId;

    fn hand(moving: bool, acted_on: bool, in_hand: bool) -> HandFacts {
        HandFacts {
            moving,
            open: None,
            acted_on: acted_on.then_some(EntityId(1)),
            in_hand: in_hand.then_some(EntityId(2)),
        }
    }

    #[test]
    fn the_report_counts_agreement_and_lists_labels_in_the_order_met() {
        let tree = ActivityTree::table_one();
        let mut c = Confusion::default();
        c.add(Activity::Reach, tree.classify(&hand(true, true, false)));
        c.add(Activity::Reach, tree.classify(&hand(false, false, false)));
        c.add(Activity::Idle, tree.classify(&hand(false, false, false)));
        assert_eq!(c.labels(), [Activity::Reach, Activity::Idle]);
        assert_eq!(c.count(Activity::Reach, Activity::Idle), 1);
        let report = c.report("a.arff", 4);
        let lines: Vec<&str> = report.lines().collect();
        assert_eq!(
            lines[0],
            "a.arff: 3 labelled hand frames, 2 agree with the tree (66.67%); 4 left out, \
             their labels not in the label map"
        );
        assert!(lines[1].starts_with("label"));
        assert!(lines[2].starts_with("Reach"), "{report}");
        assert!(lines[3].starts_with("Idle"), "{report}");
        assert_eq!(lines.len(), 4);
    }

    #[test]
    fn a_tree_learned_from_table_one_frames_classifies_them_all_right() {
        let table = ActivityTree::table_one();
        let mut cases = Vec::new();
        for _ in 0..5 {
            for facts in [
                hand(true, true, false),
                hand(true, false, true),
                hand(false, false, true),
                hand(false, false, false),
                hand(true, false, false),
            ] {
                cases.push((facts, table.classify(&facts)));
            }
        }
        let learned = learn_activity_tree(&C45::default(), &cases, false);
        assert_eq!((learned.correct, learned.cases), (25, 25));
        assert_eq!(learned.tree.classes[0], "Reach");
        assert!(learned
            .report()
            .ends_with("Correctly classified training cases: 25 of 25 (100.00%)\n"));
    }
}
