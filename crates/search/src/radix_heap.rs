//! A monotone priority queue over `u64` keys (a radix heap).
//!
//! Valid when every pushed key is at least the last popped key, which holds for
//! Dijkstra-like explorations with non-negative costs. Push is O(1); pop is amortised
//! O(log C) for keys spread over a range C, and nothing is allocated once the buckets
//! have grown.

/// A radix heap of `(key, value)` pairs.
#[derive(Debug, Clone)]
pub(crate) struct RadixHeap {
    /// Bucket `i > 0` holds keys whose highest bit differing from `last` is bit `i - 1`;
    /// bucket 0 holds keys equal to `last`.
    buckets: Vec<Vec<(u64, u32)>>,
    last: u64,
    len: usize,
}

impl RadixHeap {
    pub(crate) fn new() -> RadixHeap {
        RadixHeap {
            buckets: (0..65).map(|_| Vec::new()).collect(),
            last: 0,
            len: 0,
        }
    }

    pub(crate) fn clear(&mut self) {
        for b in &mut self.buckets {
            b.clear();
        }
        self.last = 0;
        self.len = 0;
    }

    #[inline]
    fn bucket(&self, key: u64) -> usize {
        (64 - (key ^ self.last).leading_zeros()) as usize
    }

    /// Adds a pair; `key` must not be below the last popped key.
    #[inline]
    pub(crate) fn push(&mut self, key: u64, value: u32) {
        debug_assert!(key >= self.last, "radix heap keys must be monotone");
        let b = self.bucket(key);
        self.buckets[b].push((key, value));
        self.len += 1;
    }

    /// Removes a pair with the smallest key.
    pub(crate) fn pop(&mut self) -> Option<(u64, u32)> {
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
}
