//! Segmentation: each hand on its own, a segment where its tuple (handMove, actedOn is an
//! object, inHand is an object) stays the same; segments shorter than the minimum merge
//! into a neighbour.

use grounding::{GroundedFrame, HandFacts, State};
use recording::EntityId;

use crate::tree::{Activity, ActivityTree};

/// A stretch of one hand's time with one tuple, classified.
#[derive(Debug, Clone, PartialEq)]
pub struct Segment {
    /// The hand.
    pub hand: EntityId,
    /// Time of its first frame (s).
    pub start: f64,
    /// Time of its last frame (s).
    pub end: f64,
    /// Number of frames.
    pub frames: u64,
    /// The activity (the majority of its frames' classes).
    pub activity: Activity,
    /// The tuple: `handMove`.
    pub moving: bool,
    /// The object acted on at the segment's last frame, if any.
    pub acted_on: Option<EntityId>,
    /// The object in hand at the segment's last frame, if any.
    pub in_hand: Option<EntityId>,
    /// Every object the hand held at some frame of the segment, sorted: what it may
    /// have moved (a segment's last frame shows only the object it ends with).
    pub held: Vec<EntityId>,
    /// Every object the hand acted on at some frame of the segment, sorted.
    pub acted: Vec<EntityId>,
    /// The facts at the last frame before the segment (for the first segment: at its
    /// first frame): the state its activity starts from.
    pub start_state: State,
    /// The facts at its last frame.
    pub end_state: State,
}

impl Segment {
    /// Seconds from the first to the last frame.
    pub fn duration(&self) -> f64 {
        self.end - self.start
    }
}

/// Tolerance on durations: timestamps are written to the microsecond.
const EPSILON: f64 = 1e-7;

#[derive(Debug, Clone)]
struct Run {
    tuple: u8,
    start: f64,
    end: f64,
    /// When the next run starts (its duration is `next - start`).
    next: f64,
    frames: u64,
    votes: [u32; 5],
    activity: Activity,
    moving: bool,
    acted_on: Option<EntityId>,
    in_hand: Option<EntityId>,
    held: Vec<EntityId>,
    acted: Vec<EntityId>,
    start_state: State,
    end_state: State,
}

/// Adds `e` to a sorted set of entities.
fn insert_sorted(set: &mut Vec<EntityId>, e: EntityId) {
    if let Err(at) = set.binary_search(&e) {
        set.insert(at, e);
    }
}

impl Run {
    /// Takes in the objects another run held and acted on.
    fn union_objects(&mut self, other: &Run) {
        for &e in &other.held {
            insert_sorted(&mut self.held, e);
        }
        for &e in &other.acted {
            insert_sorted(&mut self.acted, e);
        }
    }

    fn absorb_after(&mut self, later: Run) {
        self.union_objects(&later);
        self.end = later.end;
        self.next = later.next;
        self.frames += later.frames;
        self.end_state = later.end_state;
    }

    /// Joins a later run of the same activity; the joined run has the tuple (and
    /// objects) of the longer part.
    fn join(&mut self, later: Run) {
        if later.next - later.start > self.next - self.start {
            self.tuple = later.tuple;
            self.moving = later.moving;
            self.acted_on = later.acted_on;
            self.in_hand = later.in_hand;
        }
        for (v, w) in self.votes.iter_mut().zip(later.votes) {
            *v += w;
        }
        self.absorb_after(later);
    }

    fn absorb_before(&mut self, earlier: Run) {
        self.union_objects(&earlier);
        self.start = earlier.start;
        self.frames += earlier.frames;
        self.start_state = earlier.start_state;
    }

    fn into_segment(self, hand: EntityId) -> Segment {
        Segment {
            hand,
            start: self.start,
            end: self.end,
            frames: self.frames,
            activity: self.activity,
            moving: self.moving,
            acted_on: self.acted_on,
            in_hand: self.in_hand,
            held: self.held,
            acted: self.acted,
            start_state: self.start_state,
            end_state: self.end_state,
        }
    }
}

#[derive(Debug, Clone)]
struct HandSegmenter {
    hand: EntityId,
    current: Option<Run>,
    kept: Option<Run>,
    shorts: Vec<Run>,
}

/// Cuts each hand's frames into segments and classifies them, frame by frame: memory
/// and work per frame do not grow with the recording (segments are kept as they end).
///
/// Merging: neighbouring segments shorter than the minimum that have the same activity
/// join first (the activity's tuple changed within, as when a hand stops while still
/// acting on a cube and then acts on nothing: Idle both); if together they last the
/// minimum, they stand as one segment. A segment still shorter than the minimum joins
/// its neighbours when the segments before and after it have the same tuple (all three
/// become one); otherwise the one after it if it has that one's activity and not the
/// one before's, else the one before it (or, at the start of the recording, the one
/// after). A merged segment keeps the tuple and activity of the long segment it joined.
#[derive(Debug, Clone)]
pub struct Segmenter {
    tree: ActivityTree,
    min: f64,
    hands: Vec<HandSegmenter>,
    last_state: State,
    last_time: f64,
    period: f64,
    started: bool,
    done: Vec<Segment>,
}

impl Segmenter {
    /// A segmenter for these hands (in the order frames give them), classifying with
    /// `tree`; segments shorter than `min_duration` (s) merge into a neighbour.
    pub fn new(hands: &[EntityId], tree: ActivityTree, min_duration: f64) -> Segmenter {
        Segmenter {
            tree,
            min: min_duration,
            hands: hands
                .iter()
                .map(|&hand| HandSegmenter {
                    hand,
                    current: None,
                    kept: None,
                    shorts: Vec::new(),
                })
                .collect(),
            last_state: State::default(),
            last_time: 0.0,
            period: 0.0,
            started: false,
            done: Vec::new(),
        }
    }

    /// Adds a grounded frame.
    pub fn push_grounded(&mut self, frame: &GroundedFrame<'_>) {
        self.push(frame.time, frame.hands, frame.state);
    }

    /// Adds a frame: its time, per hand its facts, and the state (empty when there is no
    /// environment, as for ARFF tables).
    pub fn push(&mut self, time: f64, hands: &[HandFacts], state: &State) {
        if self.started {
            self.period = time - self.last_time;
        }
        for (h, facts) in self.hands.iter_mut().zip(hands) {
            let tuple = u8::from(facts.moving)
                | u8::from(facts.acted_on.is_some()) << 1
                | u8::from(facts.in_hand.is_some()) << 2;
            let activity = self.tree.classify(facts);
            match &mut h.current {
                Some(run) if run.tuple == tuple => {
                    run.end = time;
                    run.frames += 1;
                    run.votes[activity.index()] += 1;
                    if let Some(e) = facts.acted_on {
                        run.acted_on = Some(e);
                        insert_sorted(&mut run.acted, e);
                    }
                    if let Some(e) = facts.in_hand {
                        run.in_hand = Some(e);
                        insert_sorted(&mut run.held, e);
                    }
                }
                _ => {
                    let start_state = if self.started {
                        self.last_state.clone()
                    } else {
                        state.clone()
                    };
                    if let Some(mut run) = h.current.take() {
                        run.next = time;
                        run.end_state = self.last_state.clone();
                        accept(h, run, self.min, &mut self.done);
                    }
                    let mut votes = [0; 5];
                    votes[activity.index()] = 1;
                    h.current = Some(Run {
                        tuple,
                        start: time,
                        end: time,
                        next: time,
                        frames: 1,
                        votes,
                        activity,
                        moving: facts.moving,
                        acted_on: facts.acted_on,
                        in_hand: facts.in_hand,
                        held: facts.in_hand.into_iter().collect(),
                        acted: facts.acted_on.into_iter().collect(),
                        start_state,
                        end_state: State::default(),
                    });
                }
            }
        }
        self.last_state.copy_from(state);
        self.last_time = time;
        self.started = true;
    }

    /// Ends the recording and returns every segment, sorted by start, then hand.
    pub fn finish(mut self) -> Vec<Segment> {
        for h in &mut self.hands {
            if let Some(mut run) = h.current.take() {
                run.next = run.end + self.period;
                run.end_state = self.last_state.clone();
                accept(h, run, self.min, &mut self.done);
            }
            let shorts = std::mem::take(&mut h.shorts);
            match h.kept.take() {
                Some(mut kept) => {
                    for s in shorts {
                        kept.absorb_after(s);
                    }
                    self.done.push(kept.into_segment(h.hand));
                }
                None => {
                    // Nothing long: the whole recording is one segment, classified as its
                    // longest part.
                    let mut iter = shorts.into_iter();
                    if let Some(mut all) = iter.next() {
                        let mut longest = (all.next - all.start, all.activity, all.tuple);
                        for s in iter {
                            if s.next - s.start > longest.0 {
                                longest = (s.next - s.start, s.activity, s.tuple);
                            }
                            all.absorb_after(s);
                        }
                        all.activity = longest.1;
                        all.tuple = longest.2;
                        self.done.push(all.into_segment(h.hand));
                    }
                }
            }
        }
        self.done
            .sort_by(|a, b| a.start.total_cmp(&b.start).then(a.hand.cmp(&b.hand)));
        self.done
    }
}

fn classify(run: &mut Run) {
    let mut best = 0;
    for (i, &v) in run.votes.iter().enumerate() {
        if v > run.votes[best] {
            best = i;
        }
    }
    run.activity = Activity::ALL[best];
}

/// Takes a closed run: keeps it, or holds it back while it is short.
///
/// A short run of the same activity as the short run just before it joins that one
/// first: an activity whose tuple changes within (Idle while still acting on the cube,
/// then Idle acting on nothing) is one stretch of that activity, and it stands as a
/// segment once the stretch lasts the minimum.
fn accept(h: &mut HandSegmenter, mut run: Run, min: f64, done: &mut Vec<Segment>) {
    classify(&mut run);
    let long = |r: &Run| r.next - r.start >= min - EPSILON;
    if !long(&run) {
        match h.shorts.last_mut() {
            Some(last) if last.activity == run.activity => {
                last.join(run);
                if long(last) {
                    if let Some(joined) = h.shorts.pop() {
                        keep(h, joined, done);
                    }
                }
            }
            _ => h.shorts.push(run),
        }
        return;
    }
    keep(h, run, done);
}

/// Takes a long run: the short runs held back before it join the kept run before them,
/// or all three become one when the kept run has the same tuple; short runs that end the
/// wait with the new run's activity (and not the kept run's) join the new run instead.
fn keep(h: &mut HandSegmenter, mut run: Run, done: &mut Vec<Segment>) {
    let mut shorts = std::mem::take(&mut h.shorts);
    match h.kept.take() {
        Some(mut kept) if kept.tuple == run.tuple => {
            for s in shorts {
                kept.absorb_after(s);
            }
            kept.absorb_after(run);
            h.kept = Some(kept);
        }
        Some(mut kept) => {
            if kept.activity != run.activity {
                while shorts.last().is_some_and(|s| s.activity == run.activity) {
                    if let Some(s) = shorts.pop() {
                        run.absorb_before(s);
                    }
                }
            }
            for s in shorts {
                kept.absorb_after(s);
            }
            done.push(kept.into_segment(h.hand));
            h.kept = Some(run);
        }
        None => {
            for s in shorts.into_iter().rev() {
                run.absorb_before(s);
            }
            h.kept = Some(run);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn facts(moving: bool, acted: bool, held: bool) -> HandFacts {
        HandFacts {
            moving,
            open: None,
            acted_on: acted.then_some(EntityId(2)),
            in_hand: held.then_some(EntityId(3)),
        }
    }

    /// Runs of (frames, tuple) at 0.01 s per frame, one hand.
    fn segment(runs: &[(usize, (bool, bool, bool))]) -> Vec<(Activity, f64, f64)> {
        let mut s = Segmenter::new(&[EntityId(0)], ActivityTree::table_one(), 0.05);
        let mut t = 0.0;
        for &(n, (m, a, h)) in runs {
            for _ in 0..n {
                s.push(t, &[facts(m, a, h)], &State::default());
                t += 0.01;
            }
        }
        s.finish()
            .into_iter()
            .map(|g| {
                (
                    g.activity,
                    (g.start * 100.0).round(),
                    (g.end * 100.0).round(),
                )
            })
            .collect()
    }

    const IDLE: (bool, bool, bool) = (false, false, false);
    const REACH: (bool, bool, bool) = (true, true, false);
    const TAKE: (bool, bool, bool) = (false, false, true);
    const PUT: (bool, bool, bool) = (true, false, true);

    #[test]
    fn a_segment_per_tuple() {
        let got = segment(&[(10, IDLE), (10, REACH), (10, TAKE), (10, PUT)]);
        use Activity::*;
        assert_eq!(
            got,
            [
                (Idle, 0.0, 9.0),
                (Reach, 10.0, 19.0),
                (Take, 20.0, 29.0),
                (Put, 30.0, 39.0)
            ]
        );
    }

    #[test]
    fn short_segments_merge_into_a_neighbour() {
        use Activity::*;
        // Between equal neighbours: all three join.
        let got = segment(&[(10, PUT), (2, TAKE), (10, PUT)]);
        assert_eq!(got, [(Put, 0.0, 21.0)]);
        // Between different ones: into the one before.
        let got = segment(&[(10, REACH), (3, IDLE), (10, TAKE)]);
        assert_eq!(got, [(Reach, 0.0, 12.0), (Take, 13.0, 22.0)]);
        // At the start: into the one after.
        let got = segment(&[(2, REACH), (10, TAKE)]);
        assert_eq!(got, [(Take, 0.0, 11.0)]);
    }

    #[test]
    fn short_segments_of_one_activity_stand_together() {
        use Activity::*;
        // Two tuples of Idle (still while acting on the cube, then acting on nothing),
        // each shorter than the minimum but together longer: one Idle segment.
        const STILL_ACTING: (bool, bool, bool) = (false, true, false);
        let got = segment(&[(10, REACH), (3, STILL_ACTING), (3, IDLE), (10, TAKE)]);
        assert_eq!(
            got,
            [(Reach, 0.0, 9.0), (Idle, 10.0, 15.0), (Take, 16.0, 25.0)]
        );
        // Together still too short: into the one before, as a single short would.
        let got = segment(&[(10, REACH), (2, STILL_ACTING), (2, IDLE), (10, TAKE)]);
        assert_eq!(got, [(Reach, 0.0, 13.0), (Take, 14.0, 23.0)]);
        // A short run of the next segment's activity (and not the last one's) joins the
        // next segment.
        let got = segment(&[(10, REACH), (3, STILL_ACTING), (10, IDLE)]);
        assert_eq!(got, [(Reach, 0.0, 9.0), (Idle, 10.0, 22.0)]);
    }

    #[test]
    fn segments_keep_the_states_around_them() {
        let mut s = Segmenter::new(&[EntityId(0)], ActivityTree::table_one(), 0.0);
        let state = |w: u64| State::from_words(vec![w]);
        for (i, (f, w)) in [(IDLE, 1), (IDLE, 2), (REACH, 3), (REACH, 4)]
            .iter()
            .enumerate()
        {
            s.push(i as f64, &[facts(f.0, f.1, f.2)], &state(*w));
        }
        let got = s.finish();
        assert_eq!(got.len(), 2);
        assert_eq!(
            (&got[0].start_state, &got[0].end_state),
            (&state(1), &state(2))
        );
        assert_eq!(
            (&got[1].start_state, &got[1].end_state),
            (&state(2), &state(4))
        );
        assert_eq!(got[1].acted_on, Some(EntityId(2)));
    }
}
