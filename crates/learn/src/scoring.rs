//! Scoring activities against labelled frames (a simulator's ground truth): the truth's
//! own activities, grouped as the learned ones are, and for each learned activity the
//! class of the truth activity it overlaps most.

use grounding::{HandFacts, State};
use recording::EntityId;
use segment::{Activity, ActivityTree, Segment, Segmenter};

use crate::pipeline::{activities, Grouping};

/// The truth's activities: the truth's per-frame hand facts (`frames`: a time and one
/// [`HandFacts`] per hand of `hands`, noise-free) segmented and classified as the learned
/// ones are (the same tree and minimum duration), grouped as `grouping` says. Their
/// states are empty: only classes and spans are compared.
pub fn truth_activities(
    hands: &[EntityId],
    frames: impl IntoIterator<Item = (f64, Vec<HandFacts>)>,
    tree: &ActivityTree,
    min_duration: f64,
    grouping: Grouping,
) -> Vec<Segment> {
    let mut segmenter = Segmenter::new(hands, tree.clone(), min_duration);
    let empty = State::default();
    for (time, facts) in frames {
        segmenter.push(time, &facts, &empty);
    }
    activities(&segmenter.finish(), grouping)
}

/// For each activity, the class of the truth activity of the same hand that overlaps it
/// longest (`None` when none does).
pub fn truth_classes(learned: &[Segment], truth: &[Segment]) -> Vec<Option<Activity>> {
    learned
        .iter()
        .map(|a| {
            let overlap = |t: &Segment| a.end.min(t.end) - a.start.max(t.start);
            truth
                .iter()
                .filter(|t| t.hand == a.hand && overlap(t) >= 0.0)
                .max_by(|x, y| overlap(x).total_cmp(&overlap(y)))
                .map(|t| t.activity)
        })
        .collect()
}

/// The simulator's truth as the hand facts [`truth_activities`] takes: per frame its time
/// and each hand's noise-free `handMove`, `actedOn` and `inHand`.
pub fn truth_hand_facts(
    truth: &[simulate::TruthFrame],
) -> impl Iterator<Item = (f64, Vec<HandFacts>)> + '_ {
    truth.iter().map(|t| {
        let facts = (t.hands.iter())
            .map(|h| HandFacts {
                moving: h.moving,
                open: None,
                acted_on: h.acted_on,
                in_hand: h.in_hand,
            })
            .collect();
        (t.time, facts)
    })
}
