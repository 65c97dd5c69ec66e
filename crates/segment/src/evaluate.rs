//! Measuring segmentation against labelled frames (a simulator's ground truth, an
//! annotated table): frame agreement away from the labels' boundaries, and the
//! sequence of activities.

use recording::EntityId;

use crate::segmenter::Segment;
use crate::tree::Activity;

/// The activity each frame gets from the segments of one hand (`times` in order; a frame
/// belongs to the last segment that starts at or before it).
pub fn frame_activities(segments: &[Segment], hand: EntityId, times: &[f64]) -> Vec<Activity> {
    let mine: Vec<&Segment> = segments.iter().filter(|s| s.hand == hand).collect();
    let mut k = 0;
    times
        .iter()
        .map(|&t| {
            while k + 1 < mine.len() && mine[k + 1].start <= t {
                k += 1;
            }
            mine.get(k).map_or(Activity::Idle, |s| s.activity)
        })
        .collect()
}

/// How many frames agree, of how many counted: frames closer than `ignore` seconds to a
/// boundary of `truth` (a frame whose label differs from the previous one's) are not
/// counted.
pub fn agreement(
    times: &[f64],
    predicted: &[Activity],
    truth: &[Activity],
    ignore: f64,
) -> (usize, usize) {
    let boundaries: Vec<f64> = (1..truth.len())
        .filter(|&i| truth[i] != truth[i - 1])
        .map(|i| times[i])
        .collect();
    let mut b = 0;
    let (mut agree, mut counted) = (0, 0);
    for (i, &t) in times.iter().enumerate() {
        while b < boundaries.len() && boundaries[b] < t - ignore - 1e-7 {
            b += 1;
        }
        if boundaries
            .get(b)
            .is_some_and(|&x| (x - t).abs() <= ignore + 1e-7)
        {
            continue;
        }
        counted += 1;
        agree += usize::from(predicted.get(i) == truth.get(i));
    }
    (agree, counted)
}

/// The sequence of activities of per-frame labels, with runs shorter than `min` (s)
/// merged into a neighbour as the segmenter merges them (joining equal neighbours, else
/// the run before, else the run after) and equal neighbours joined.
pub fn sequence(times: &[f64], labels: &[Activity], min: f64) -> Vec<Activity> {
    // Runs: (activity, start time, duration to the next run's start).
    let mut runs: Vec<(Activity, f64, f64)> = Vec::new();
    for (i, (&t, &a)) in times.iter().zip(labels).enumerate() {
        if i == 0 || labels[i - 1] != a {
            runs.push((a, t, 0.0));
        }
    }
    let period = if times.len() > 1 {
        times[times.len() - 1] - times[times.len() - 2]
    } else {
        0.0
    };
    let end = times.last().copied().unwrap_or(0.0) + period;
    for i in 0..runs.len() {
        let next = runs.get(i + 1).map_or(end, |r| r.1);
        runs[i].2 = next - runs[i].1;
    }
    let mut out: Vec<Activity> = Vec::new();
    let mut pending_short = false;
    for &(a, _, d) in &runs {
        if d < min - 1e-7 {
            pending_short = true;
            if out.is_empty() {
                continue;
            }
            continue;
        }
        if out.last() != Some(&a) {
            out.push(a);
        }
        pending_short = false;
    }
    if out.is_empty() && pending_short {
        // Everything short: the longest run.
        if let Some(r) = runs.iter().max_by(|x, y| x.2.total_cmp(&y.2)) {
            out.push(r.0);
        }
    }
    out
}

/// Whether `ours` is the sequence of the labels when runs of the labels that lie wholly
/// within `ignore` seconds of their boundaries (the frames [`agreement`] does not count)
/// may be left out: a run that short is too brief to demand, so its being found or not
/// is no error. Longer runs must all be there, in order, and nothing else.
pub fn sequence_matches(
    times: &[f64],
    labels: &[Activity],
    ours: &[Activity],
    ignore: f64,
) -> bool {
    // Runs: (activity, whether it may be left out).
    let mut runs: Vec<(Activity, usize, usize)> = Vec::new();
    for (i, &a) in labels.iter().enumerate() {
        match runs.last_mut() {
            Some(r) if r.0 == a => r.2 = i,
            _ => runs.push((a, i, i)),
        }
    }
    let n = runs.len();
    let optional: Vec<bool> = runs
        .iter()
        .enumerate()
        .map(|(k, &(_, first, last))| {
            // Every frame of the run is within `ignore` of its start or of its end.
            let start = (k > 0).then(|| times[first]);
            let end = (k + 1 < n).then(|| times.get(last + 1).copied().unwrap_or(times[last]));
            (first..=last).all(|i| {
                let t = times[i];
                start.is_some_and(|s| t - s <= ignore + 1e-7)
                    || end.is_some_and(|e| e - t <= ignore + 1e-7)
            })
        })
        .collect();
    // reach[j]: the runs so far can make ours[..j] (the last element possibly still open).
    let m = ours.len();
    let mut reach = vec![false; m + 1];
    reach[0] = true;
    for (k, &(a, _, _)) in runs.iter().enumerate() {
        let mut next = vec![false; m + 1];
        for j in 0..=m {
            if !reach[j] {
                continue;
            }
            if optional[k] {
                next[j] = true;
            }
            if j > 0 && ours[j - 1] == a {
                next[j] = true;
            } else if j < m && ours[j] == a {
                next[j + 1] = true;
            }
        }
        reach = next;
    }
    reach[m]
}

/// The sequence of activities of one hand's segments, equal neighbours joined.
pub fn segment_sequence(segments: &[Segment], hand: EntityId) -> Vec<Activity> {
    let mut out: Vec<Activity> = Vec::new();
    for s in segments.iter().filter(|s| s.hand == hand) {
        if out.last() != Some(&s.activity) {
            out.push(s.activity);
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use Activity::*;

    #[test]
    fn boundaries_are_ignored_and_short_runs_do_not_count_in_sequences() {
        let times: Vec<f64> = (0..10).map(|i| i as f64 * 0.1).collect();
        let truth = [
            Idle, Idle, Idle, Reach, Reach, Reach, Take, Idle, Idle, Idle,
        ];
        let pred = [
            Idle, Idle, Reach, Reach, Reach, Idle, Idle, Idle, Idle, Reach,
        ];
        // Boundaries at 0.3, 0.6 and 0.7: frames 2-8 lie within 0.1 s of one.
        assert_eq!(agreement(&times, &pred, &truth, 0.1), (2, 3));
        assert_eq!(sequence(&times, &truth, 0.15), [Idle, Reach, Idle]);
        assert_eq!(sequence(&times, &truth, 0.0), [Idle, Reach, Take, Idle]);
        // Take (one frame) may be found or not; Reach (0.3 s) must be.
        assert!(sequence_matches(&times, &truth, &[Idle, Reach, Idle], 0.1));
        assert!(sequence_matches(
            &times,
            &truth,
            &[Idle, Reach, Take, Idle],
            0.1
        ));
        assert!(!sequence_matches(&times, &truth, &[Idle, Take, Idle], 0.05));
        assert!(sequence_matches(&times, &truth, &[Idle, Reach, Idle], 0.05));
        assert!(!sequence_matches(
            &times,
            &truth,
            &[Idle, Reach, Idle, Reach],
            0.1
        ));
    }
}
