//! A segmented recording as a timeline (`demoplan timeline`): per hand its speed, its
//! distance to every object and its grip, with the grounding thresholds, and its
//! segments (and the simulator's truth) as bands coloured by activity, so that a person
//! can see why a segment was cut where it was. The drawing is `report`'s.

use grounding::{Grounder, GroundingConfig, HandSignals};
use recording::Frame;
use report::{Band, BandRow, Color, Panel, Series, Threshold, Timeline, Track};
use segment::Activity;

use crate::pipeline::{Observer, Segmented};

/// The signals of every frame, per hand, as the grounder saw them: an [`Observer`] of
/// the pipeline.
#[derive(Debug, Default, Clone)]
pub struct Signals {
    times: Vec<f64>,
    /// Per frame, the grounder's signals of each hand.
    hands: Vec<Vec<HandSignals>>,
}

impl Observer for Signals {
    fn frame(&mut self, frame: &Frame, grounder: &Grounder) {
        self.times.push(frame.time);
        self.hands.push(grounder.signals().to_vec());
    }
}

/// The colour of an activity's bands.
pub fn activity_color(a: Activity) -> Color {
    match a {
        Activity::Stack => Color(214, 39, 40),
        Activity::Idle => Color(217, 217, 217),
        Activity::Reach => Color(31, 119, 180),
        Activity::Put => Color(44, 160, 44),
        Activity::Take => Color(255, 127, 14),
    }
}

/// Distance lines, by object: Tableau's colours without grey and olive.
const OBJECT_COLORS: [Color; 8] = {
    let t = report::palette::TABLEAU10;
    [t[0], t[1], t[2], t[3], t[4], t[5], t[6], t[9]]
};
const INK: Color = Color(34, 34, 34);
/// The speed panel's top is the fastest frame's speed, within these bounds (m/s).
const SPEED_SCALE: (f32, f32) = (0.3, 3.0);

/// The timeline of a segmented recording whose frames `signals` saw; `truth` (per frame,
/// per hand, the activity) adds a band row of the simulator's truth per hand.
/// `source` names where the recording came from, in the title.
pub fn timeline(
    s: &Segmented,
    signals: &Signals,
    truth: Option<&[Vec<Activity>]>,
    config: &GroundingConfig,
    source: &str,
) -> Timeline {
    let start = signals.times.first().copied().unwrap_or(0.0);
    let end = signals.times.last().copied().unwrap_or(1.0);
    let max_speed = signals
        .hands
        .iter()
        .flatten()
        .map(|h| h.speed)
        .fold(SPEED_SCALE.0, f32::max)
        .min(SPEED_SCALE.1);
    let series = |hand: usize,
                  name: &str,
                  color: Color,
                  value: &dyn Fn(&HandSignals) -> Option<f32>| Series {
        name: name.to_string(),
        color,
        points: signals
            .times
            .iter()
            .zip(&signals.hands)
            .map(|(&t, hands)| {
                let v = hands.get(hand).and_then(value).map_or(f64::NAN, f64::from);
                (t, v)
            })
            .collect(),
    };
    let threshold = |value: f64, name: &str| Threshold {
        value,
        name: name.to_string(),
    };
    let objects = s.space.objects();
    let tracks = s
        .space
        .hands()
        .iter()
        .enumerate()
        .map(|(hi, &hand)| {
            let distances = objects
                .iter()
                .enumerate()
                .map(|(k, &obj)| {
                    let color = OBJECT_COLORS[k % OBJECT_COLORS.len()];
                    series(hi, &s.header.entity(obj).name, color, &|h| {
                        h.distances.get(k).copied()
                    })
                })
                .collect();
            let panel = |label: &str, max: f64, thresholds: &[(f64, &str)], series| Panel {
                label: label.to_string(),
                max,
                thresholds: thresholds
                    .iter()
                    .map(|&(v, name)| threshold(v, name))
                    .collect(),
                series,
            };
            let (acted_on, graspable) = (config.acted_on.distance, config.graspable.distance);
            let (closed, open) = (config.hand_open.close_above, config.hand_open.open_below);
            let panels = vec![
                panel(
                    "speed (m/s)",
                    f64::from(max_speed),
                    &[(config.hand_move.speed, "handMove")],
                    vec![series(hi, "speed", INK, &|h| Some(h.speed))],
                ),
                panel(
                    "distance (m)",
                    0.4,
                    &[(acted_on, "actedOn"), (graspable, "graspable")],
                    distances,
                ),
                panel(
                    "grip",
                    1.0,
                    &[(closed, "closed"), (open, "open")],
                    vec![series(hi, "grip", INK, &|h| h.grip)],
                ),
            ];
            let mut bands = vec![BandRow {
                label: "segments".into(),
                bands: s
                    .segments
                    .iter()
                    .filter(|g| g.hand == hand)
                    .map(|g| Band {
                        start: g.start,
                        end: g.end,
                        color: activity_color(g.activity),
                    })
                    .collect(),
                boundaries: true,
            }];
            if let Some(truth) = truth {
                bands.push(BandRow {
                    label: "ground truth".into(),
                    bands: truth_bands(&signals.times, truth, hi),
                    boundaries: false,
                });
            }
            Track {
                name: s.header.entity(hand).name.clone(),
                panels,
                bands,
            }
        })
        .collect();
    Timeline {
        title: format!(
            "{} ({source}, {} frames, {:.2} s)",
            s.header.id, s.frames, s.duration
        ),
        start,
        end,
        tracks,
        legend: Activity::ALL
            .iter()
            .map(|&a| (a.name().to_string(), activity_color(a)))
            .collect(),
    }
}

/// The runs of one truth label of hand `hand` as bands (frames without a label for the
/// hand are Idle).
fn truth_bands(times: &[f64], truth: &[Vec<Activity>], hand: usize) -> Vec<Band> {
    let mut bands: Vec<(f64, f64, Activity)> = Vec::new();
    for (&t, activities) in times.iter().zip(truth) {
        let activity = activities.get(hand).copied().unwrap_or(Activity::Idle);
        match bands.last_mut() {
            Some(last) if last.2 == activity => last.1 = t,
            Some(last) => {
                last.1 = t;
                bands.push((t, t, activity));
            }
            None => bands.push((t, t, activity)),
        }
    }
    bands
        .into_iter()
        .map(|(start, end, activity)| Band {
            start,
            end,
            color: activity_color(activity),
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn truth_runs_become_bands_that_meet() {
        let times = [0.0, 0.1, 0.2, 0.3];
        let truth: Vec<Vec<Activity>> = vec![
            vec![Activity::Reach],
            vec![Activity::Reach],
            vec![Activity::Take],
            // A frame without the hand: Idle.
            vec![],
        ];
        let bands = truth_bands(&times, &truth, 0);
        let spans: Vec<(f64, f64)> = bands.iter().map(|b| (b.start, b.end)).collect();
        assert_eq!(spans, [(0.0, 0.2), (0.2, 0.3), (0.3, 0.3)]);
        assert_eq!(bands[0].color, activity_color(Activity::Reach));
        assert_eq!(bands[1].color, activity_color(Activity::Take));
        assert_eq!(bands[2].color, activity_color(Activity::Idle));
    }
}
