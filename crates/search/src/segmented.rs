//! Growable arrays in fixed-size segments.
//!
//! A `Vec` doubles its capacity when full, so a search holding millions of states keeps
//! up to twice the memory it uses, and briefly three times while it copies. Segments of
//! a fixed size grow one at a time: at most one segment is partly empty and nothing is
//! ever copied. Indexing costs a shift and a mask.

/// Elements per segment: 2^16.
const SEGMENT_BITS: u32 = 16;
const SEGMENT_LEN: usize = 1 << SEGMENT_BITS;
const MASK: usize = SEGMENT_LEN - 1;

/// A vector of `T` stored in segments of 2^16 elements.
#[derive(Debug, Clone, Default)]
pub(crate) struct SegmentedVec<T> {
    segments: Vec<Vec<T>>,
    len: usize,
}

impl<T: Copy> SegmentedVec<T> {
    pub(crate) fn new() -> SegmentedVec<T> {
        SegmentedVec {
            segments: Vec::new(),
            len: 0,
        }
    }

    #[inline]
    pub(crate) fn push(&mut self, value: T) {
        if self.len & MASK == 0 {
            self.segments.push(Vec::with_capacity(SEGMENT_LEN));
        }
        if let Some(last) = self.segments.last_mut() {
            last.push(value);
        }
        self.len += 1;
    }

    #[inline]
    pub(crate) fn get(&self, index: usize) -> &T {
        &self.segments[index >> SEGMENT_BITS][index & MASK]
    }

    #[inline]
    pub(crate) fn get_mut(&mut self, index: usize) -> &mut T {
        &mut self.segments[index >> SEGMENT_BITS][index & MASK]
    }

    pub(crate) fn len(&self) -> usize {
        self.len
    }

    /// Bytes allocated for elements.
    pub(crate) fn memory_bytes(&self) -> usize {
        self.segments.len() * SEGMENT_LEN * std::mem::size_of::<T>()
    }
}

/// Fixed-length records of `u64` words (packed states) in segments of 2^16 records.
#[derive(Debug, Clone)]
pub(crate) struct SegmentedArena {
    words: usize,
    segments: Vec<Vec<u64>>,
    len: usize,
}

impl SegmentedArena {
    pub(crate) fn new(words: usize) -> SegmentedArena {
        SegmentedArena {
            words,
            segments: Vec::new(),
            len: 0,
        }
    }

    #[inline]
    pub(crate) fn push(&mut self, record: &[u64]) {
        if self.len & MASK == 0 {
            self.segments
                .push(Vec::with_capacity(SEGMENT_LEN * self.words));
        }
        if let Some(last) = self.segments.last_mut() {
            last.extend_from_slice(record);
        }
        self.len += 1;
    }

    #[inline]
    pub(crate) fn get(&self, index: usize) -> &[u64] {
        let start = (index & MASK) * self.words;
        &self.segments[index >> SEGMENT_BITS][start..start + self.words]
    }

    /// Bytes allocated for records.
    pub(crate) fn memory_bytes(&self) -> usize {
        self.segments.len() * SEGMENT_LEN * self.words * 8
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn segments_hold_values_across_boundaries() {
        let mut v = SegmentedVec::new();
        for i in 0..(3 * SEGMENT_LEN + 5) as u32 {
            v.push(i);
        }
        assert_eq!(v.len(), 3 * SEGMENT_LEN + 5);
        assert_eq!(*v.get(SEGMENT_LEN), SEGMENT_LEN as u32);
        *v.get_mut(2 * SEGMENT_LEN + 1) = 7;
        assert_eq!(*v.get(2 * SEGMENT_LEN + 1), 7);
        assert_eq!(v.memory_bytes(), 4 * SEGMENT_LEN * 4);

        let mut a = SegmentedArena::new(3);
        for i in 0..(SEGMENT_LEN + 2) as u64 {
            a.push(&[i, i + 1, i + 2]);
        }
        assert_eq!(
            a.get(SEGMENT_LEN + 1),
            &[
                SEGMENT_LEN as u64 + 1,
                SEGMENT_LEN as u64 + 2,
                SEGMENT_LEN as u64 + 3
            ]
        );
    }
}
