//! Minimum durations: a change of a fact counts only once it has lasted `min_duration`,
//! and then from the frame where it began (so boundaries are not delayed). Frames are
//! held back until they are older than `min_duration`, when nothing can change them any
//! more.
//!
//! Two kinds of signal: bits (each fact on its own) and categorical values (which object
//! a hand acts on or holds: one value of several, so that a hand never acts on two
//! objects at once). Work per frame is a few word operations while nothing changes, and
//! proportional to the frames a run spans when a change commits.

/// Timestamps are written to the microsecond: a run this much short of the minimum
/// still counts (so 0.12 s - 0.07 s, which is 0.04999... in floating point, is 0.05 s).
const EPSILON: f64 = 1e-7;

/// "No object" for a categorical signal.
pub(crate) const NO_VALUE: u16 = u16::MAX;

/// A frame released by the debouncer: its sequence number, time, bits and values.
pub(crate) struct Released<'a> {
    pub seq: u64,
    pub time: f64,
    pub words: &'a [u64],
    pub values: &'a [u16],
}

#[derive(Debug, Clone)]
pub(crate) struct Debouncer {
    min: f64,
    words: usize,
    values: usize,
    started: bool,
    committed: Vec<u64>,
    pending: Vec<u64>,
    /// Per bit: the sequence number of the frame its pending run began at.
    start: Vec<u64>,
    value_committed: Vec<u16>,
    /// Per value: the pending new value and where its run began, if a run is pending.
    value_pending: Vec<Option<(u16, u64)>>,
    /// Frames held back, a ring indexed by sequence number modulo `cap`.
    cap: usize,
    head: u64,
    next: u64,
    ring_time: Vec<f64>,
    ring_words: Vec<u64>,
    ring_values: Vec<u16>,
}

impl Debouncer {
    pub fn new(min: f64, words: usize, values: usize) -> Debouncer {
        let cap = 64;
        let no_facts = vec![0; words];
        Debouncer {
            min,
            words,
            values,
            started: false,
            committed: no_facts.clone(),
            pending: no_facts,
            start: vec![0; words * 64],
            value_committed: vec![NO_VALUE; values],
            value_pending: vec![None; values],
            cap,
            head: 0,
            next: 0,
            ring_time: vec![0.0; cap],
            ring_words: vec![0; cap * words],
            ring_values: vec![NO_VALUE; cap * values],
        }
    }

    fn slot(&self, seq: u64) -> usize {
        (seq as usize) & (self.cap - 1)
    }

    fn grow(&mut self) {
        let cap = self.cap * 2;
        let mut time = vec![0.0; cap];
        let mut words = vec![0; cap * self.words];
        let mut values = vec![NO_VALUE; cap * self.values];
        for seq in self.head..self.next {
            let (from, to) = (self.slot(seq), (seq as usize) & (cap - 1));
            time[to] = self.ring_time[from];
            words[to * self.words..(to + 1) * self.words]
                .copy_from_slice(&self.ring_words[from * self.words..(from + 1) * self.words]);
            values[to * self.values..(to + 1) * self.values]
                .copy_from_slice(&self.ring_values[from * self.values..(from + 1) * self.values]);
        }
        self.cap = cap;
        self.ring_time = time;
        self.ring_words = words;
        self.ring_values = values;
    }

    /// Adds a frame's raw bits and values; releases every frame that is now final.
    pub fn push(
        &mut self,
        time: f64,
        raw: &[u64],
        raw_values: &[u16],
        mut emit: impl FnMut(Released<'_>),
    ) {
        if !self.started {
            self.started = true;
            self.committed.copy_from_slice(raw);
            self.value_committed.copy_from_slice(raw_values);
        }
        if (self.next - self.head) as usize >= self.cap {
            self.grow();
        }
        let seq = self.next;
        self.next += 1;
        let slot = self.slot(seq);
        let (nw, nv) = (self.words, self.values);
        self.ring_time[slot] = time;
        self.ring_words[slot * nw..(slot + 1) * nw].copy_from_slice(&self.committed);
        self.ring_values[slot * nv..(slot + 1) * nv].copy_from_slice(&self.value_committed);

        for (w, &raw_word) in raw.iter().enumerate().take(nw) {
            // Runs that end at this frame (the raw value is back to the committed one)
            // count if they lasted the minimum up to this frame: they become the
            // committed value, for their frames, and what follows starts a new run.
            let mut ended = self.pending[w] & !(raw_word ^ self.committed[w]);
            self.pending[w] &= !ended;
            while ended != 0 {
                let b = ended.trailing_zeros() as usize;
                ended &= ended - 1;
                let from = self.start[w * 64 + b];
                if time - self.ring_time[self.slot(from)] >= self.min - EPSILON {
                    let bit = 1u64 << b;
                    self.committed[w] ^= bit;
                    for q in from..=seq {
                        let s = self.slot(q);
                        self.ring_words[s * nw + w] ^= bit;
                    }
                }
            }
            let diff = raw_word ^ self.committed[w];
            let mut new = diff & !self.pending[w];
            while new != 0 {
                let b = new.trailing_zeros() as usize;
                new &= new - 1;
                self.start[w * 64 + b] = seq;
            }
            self.pending[w] = diff;
            let mut p = diff;
            while p != 0 {
                let b = p.trailing_zeros() as usize;
                p &= p - 1;
                let from = self.start[w * 64 + b];
                if time - self.ring_time[self.slot(from)] >= self.min - EPSILON {
                    let bit = 1u64 << b;
                    self.committed[w] ^= bit;
                    self.pending[w] &= !bit;
                    for q in from..=seq {
                        let s = self.slot(q);
                        self.ring_words[s * nw + w] ^= bit;
                    }
                }
            }
        }
        for (k, &value) in raw_values.iter().enumerate().take(nv) {
            // A pending run that ends here counts if it lasted the minimum.
            if let Some((v, from)) = self.value_pending[k] {
                if v != value {
                    self.value_pending[k] = None;
                    if time - self.ring_time[self.slot(from)] >= self.min - EPSILON {
                        self.value_committed[k] = v;
                        for q in from..seq {
                            let s = self.slot(q);
                            self.ring_values[s * nv + k] = v;
                        }
                        let s = self.slot(seq);
                        self.ring_values[s * nv + k] = v;
                    }
                }
            }
            if value == self.value_committed[k] {
                self.value_pending[k] = None;
                continue;
            }
            let from = match self.value_pending[k] {
                Some((v, from)) if v == value => from,
                _ => {
                    self.value_pending[k] = Some((value, seq));
                    seq
                }
            };
            if time - self.ring_time[self.slot(from)] >= self.min - EPSILON {
                self.value_committed[k] = value;
                self.value_pending[k] = None;
                for q in from..=seq {
                    let s = self.slot(q);
                    self.ring_values[s * nv + k] = value;
                }
            }
        }
        while self.head < self.next
            && time - self.ring_time[self.slot(self.head)] >= self.min - EPSILON
        {
            self.release(&mut emit);
        }
    }

    fn release(&mut self, emit: &mut impl FnMut(Released<'_>)) {
        let seq = self.head;
        self.head += 1;
        let s = self.slot(seq);
        let (nw, nv) = (self.words, self.values);
        emit(Released {
            seq,
            time: self.ring_time[s],
            words: &self.ring_words[s * nw..(s + 1) * nw],
            values: &self.ring_values[s * nv..(s + 1) * nv],
        });
    }

    /// Releases the frames still held back. Changes still pending are shorter than the
    /// minimum, so they are dropped.
    pub fn finish(&mut self, mut emit: impl FnMut(Released<'_>)) {
        while self.head < self.next {
            self.release(&mut emit);
        }
        self.pending.iter_mut().for_each(|p| *p = 0);
        self.value_pending.iter_mut().for_each(|p| *p = None);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Debounces one bit and one value sampled every 0.01 s; returns what was released.
    fn run(min: f64, bits: &[u8], values: &[u16]) -> (Vec<u8>, Vec<u16>) {
        let mut d = Debouncer::new(min, 1, 1);
        let mut out = (Vec::new(), Vec::new());
        let mut collect = |r: Released<'_>| {
            out.0.push(r.words[0] as u8);
            out.1.push(r.values[0]);
        };
        for (i, (&b, &v)) in bits.iter().zip(values).enumerate() {
            d.push(i as f64 * 0.01, &[u64::from(b)], &[v], &mut collect);
        }
        d.finish(&mut collect);
        out
    }

    #[test]
    fn short_runs_are_dropped_and_long_ones_keep_their_start() {
        // A run of 3 frames (0.02 s) is noise; one of 6 (0.05 s) counts from its start.
        let bits = [0, 0, 1, 1, 1, 0, 0, 1, 1, 1, 1, 1, 1, 0, 0];
        let vals = [9, 9, 9, 1, 1, 1, 9, 9, 2, 2, 2, 2, 2, 2, 2];
        let (b, v) = run(0.05, &bits, &vals);
        assert_eq!(b, [0, 0, 0, 0, 0, 0, 0, 1, 1, 1, 1, 1, 1, 1, 1]);
        assert_eq!(v, [9, 9, 9, 9, 9, 9, 9, 9, 2, 2, 2, 2, 2, 2, 2]);
        // No minimum: everything passes.
        let (b, _) = run(0.0, &bits, &vals);
        assert_eq!(b, bits);
    }

    #[test]
    fn the_ring_grows_when_the_minimum_spans_many_frames() {
        let bits: Vec<u8> = (0..500).map(|i| u8::from((i / 150) % 2 == 1)).collect();
        let vals = vec![NO_VALUE; 500];
        let (b, _) = run(1.0, &bits, &vals);
        // The last run (50 frames, 0.5 s) is shorter than the minimum.
        assert_eq!(b[..450], bits[..450]);
        assert!(b[450..].iter().all(|&x| x == 0));
    }
}
