//! A monotone priority queue over `u64` keys: a bucket per key for small keys, a radix
//! heap for the others.
//!
//! Valid when every pushed key is at least the last popped key, which holds for
//! Dijkstra-like explorations with non-negative costs. Pairs of equal keys come out last
//! in, first out (a stack per key, as Fast Downward's bucket queue hands them out; LM-cut's
//! ties depend on it). Keys below [`SMALL_KEYS`] go to a bucket of their own (push and pop
//! O(1), plus a cursor that moves over the keys once per exploration), the others to a
//! radix heap (push O(1), pop amortised O(log C) for keys spread over a range C). Nothing
//! is allocated once the buckets have grown.

/// Keys below this have a bucket each: every h^max of a unit-cost task, and most of
/// those of tasks with small costs.
const SMALL_KEYS: usize = 1024;

/// A priority queue of `(key, value)` pairs with monotone keys.
#[derive(Debug, Clone)]
pub(crate) struct RadixHeap {
    /// `small[k]`: the values of key `k < SMALL_KEYS`, the last pushed on top.
    small: Vec<Vec<u32>>,
    /// No small key below `cursor` is queued.
    cursor: usize,
    small_len: usize,
    /// Bucket `i > 0` holds keys whose highest bit differing from `last` is bit `i - 1`;
    /// bucket 0 holds keys equal to `last`. Only keys of at least `SMALL_KEYS`.
    buckets: Vec<Vec<(u64, u32)>>,
    last: u64,
    len: usize,
}

impl RadixHeap {
    pub(crate) fn new() -> RadixHeap {
        RadixHeap {
            small: (0..SMALL_KEYS).map(|_| Vec::new()).collect(),
            cursor: SMALL_KEYS,
            small_len: 0,
            buckets: (0..65).map(|_| Vec::new()).collect(),
            last: 0,
            len: 0,
        }
    }

    pub(crate) fn clear(&mut self) {
        if self.small_len > 0 {
            for b in &mut self.small[self.cursor..] {
                b.clear();
            }
            self.small_len = 0;
        }
        self.cursor = SMALL_KEYS;
        if self.len > 0 {
            for b in &mut self.buckets {
                b.clear();
            }
            self.len = 0;
        }
        self.last = 0;
    }

    #[inline]
    fn bucket(&self, key: u64) -> usize {
        (64 - (key ^ self.last).leading_zeros()) as usize
    }

    /// Adds a pair; `key` must not be below the last popped key.
    #[inline]
    pub(crate) fn push(&mut self, key: u64, value: u32) {
        if key < SMALL_KEYS as u64 {
            let k = key as usize;
            // Below the cursor only before the first pop since the queue was cleared:
            // later keys are at least the last popped one, where the cursor stands.
            self.cursor = self.cursor.min(k);
            self.small[k].push(value);
            self.small_len += 1;
        } else {
            debug_assert!(key >= self.last, "radix heap keys must be monotone");
            let b = self.bucket(key);
            self.buckets[b].push((key, value));
            self.len += 1;
        }
    }

    /// Removes a pair with the smallest key; of those, the last pushed.
    #[inline]
    pub(crate) fn pop(&mut self) -> Option<(u64, u32)> {
        if self.small_len > 0 {
            while self.small[self.cursor].is_empty() {
                self.cursor += 1;
            }
            self.small_len -= 1;
            return self.small[self.cursor]
                .pop()
                .map(|v| (self.cursor as u64, v));
        }
        self.pop_large()
    }

    fn pop_large(&mut self) -> Option<(u64, u32)> {
        if self.len == 0 {
            return None;
        }
        if self.buckets[0].is_empty() {
            let i = self.buckets.iter().position(|b| !b.is_empty())?;
            let min = self.buckets[i].iter().map(|&(k, _)| k).min()?;
            self.last = min;
            let items = std::mem::take(&mut self.buckets[i]);
            for &(k, v) in &items {
                let b = self.bucket(k);
                self.buckets[b].push((k, v));
            }
            // Give the emptied bucket its allocation back.
            let mut items = items;
            items.clear();
            self.buckets[i] = items;
        }
        self.len -= 1;
        self.buckets[0].pop()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn pops_in_key_order_with_monotone_pushes() {
        let mut h = RadixHeap::new();
        for (k, v) in [(5, 0), (3, 1), (9, 2), (3, 3), (1 << 40, 4), (7, 5)] {
            h.push(k, v);
        }
        let mut keys = Vec::new();
        let mut pushed_more = false;
        while let Some((k, _)) = h.pop() {
            keys.push(k);
            if k == 5 && !pushed_more {
                pushed_more = true;
                h.push(6, 9);
                h.push(5, 10);
            }
        }
        assert_eq!(keys, [3, 3, 5, 5, 6, 7, 9, 1 << 40]);
        h.clear();
        assert_eq!(h.pop(), None);
    }

    /// LM-cut's first-round supporters are the preconditions popped last among equal
    /// costs, so the order of ties is behaviour: last in, first out, for small keys (a
    /// bucket each) and large ones (the radix part) alike.
    #[test]
    fn equal_keys_come_out_last_in_first_out() {
        let mut h = RadixHeap::new();
        let big = SMALL_KEYS as u64 + 5;
        for (k, v) in [(7, 0), (big, 1), (7, 2), (2, 3), (big, 4), (7, 5), (big, 6)] {
            h.push(k, v);
        }
        let mut popped = Vec::new();
        while let Some(pair) = h.pop() {
            popped.push(pair);
            if pair == (7, 5) {
                h.push(7, 7);
            }
        }
        assert_eq!(
            popped,
            [
                (2, 3),
                (7, 5),
                (7, 7),
                (7, 2),
                (7, 0),
                (big, 6),
                (big, 4),
                (big, 1)
            ]
        );
    }

    /// After `clear` the first keys may lie anywhere, below the last popped one too.
    #[test]
    fn clear_forgets_the_last_key() {
        let mut h = RadixHeap::new();
        h.push(40, 0);
        h.push(30, 1);
        assert_eq!(h.pop(), Some((30, 1)));
        h.clear();
        h.push(9, 2);
        h.push(3, 3);
        assert_eq!(h.pop(), Some((3, 3)));
        assert_eq!(h.pop(), Some((9, 2)));
        assert_eq!(h.pop(), None);
    }
}
