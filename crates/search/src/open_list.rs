//! The A* open list: buckets keyed by (f, h), lowest f first, then lowest h, first in
//! first out within a bucket.

use std::collections::{BTreeMap, VecDeque};

use crate::state::StateId;

/// Buckets of state ids keyed by `(f, h)`.
///
/// Costs are arbitrary `u64`s, so the buckets live in an ordered map; A* keeps only a few
/// (f, h) pairs alive at a time, which keeps each push and pop a handful of comparisons.
/// Emptied buckets are kept for reuse, so steady-state operation does not allocate.
#[derive(Debug, Default)]
pub(crate) struct OpenList {
    buckets: BTreeMap<(u64, u64), VecDeque<StateId>>,
    spare: Vec<VecDeque<StateId>>,
}

impl OpenList {
    pub(crate) fn new() -> OpenList {
        OpenList::default()
    }

    #[inline]
    pub(crate) fn push(&mut self, f: u64, h: u64, id: StateId) {
        match self.buckets.get_mut(&(f, h)) {
            Some(bucket) => bucket.push_back(id),
            None => {
                let mut bucket = self.spare.pop().unwrap_or_default();
                bucket.push_back(id);
                self.buckets.insert((f, h), bucket);
            }
        }
    }

    /// The first entry of the lowest (f, h) bucket, with its key.
    #[inline]
    pub(crate) fn pop(&mut self) -> Option<(u64, u64, StateId)> {
        let mut entry = self.buckets.first_entry()?;
        let key = *entry.key();
        let id = entry.get_mut().pop_front();
        if entry.get().is_empty() {
            self.spare.push(entry.remove());
        }
        Some((key.0, key.1, id?))
    }

    /// A rough count of the bytes held.
    pub(crate) fn memory_bytes(&self) -> usize {
        let live: usize = self.buckets.values().map(|b| b.capacity() * 4 + 64).sum();
        let spare: usize = self.spare.iter().map(|b| b.capacity() * 4 + 24).sum();
        live + spare
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn orders_by_f_then_h_then_fifo() {
        let mut open = OpenList::new();
        open.push(5, 2, StateId(0));
        open.push(5, 1, StateId(1));
        open.push(4, 4, StateId(2));
        open.push(5, 1, StateId(3));
        open.push(6, 0, StateId(4));
        assert_eq!(open.pop(), Some((4, 4, StateId(2))));
        assert_eq!(open.pop(), Some((5, 1, StateId(1))));
        open.push(5, 1, StateId(5));
        assert_eq!(open.pop(), Some((5, 1, StateId(3))));
        assert_eq!(open.pop(), Some((5, 1, StateId(5))));
        assert_eq!(open.pop(), Some((5, 2, StateId(0))));
        assert_eq!(open.pop(), Some((6, 0, StateId(4))));
        assert_eq!(open.pop(), None);
        assert!(open.memory_bytes() > 0);
    }
}
