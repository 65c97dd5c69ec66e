//! Packed states and the state registry.
//!
//! A state assigns each variable a value. [`StatePacker`] stores a state in as few `u64`
//! words as the domains allow: each variable takes `ceil(log2(domain size))` bits (none
//! for a domain of one value), several variables share a word, and no variable is split
//! across two words. [`StateRegistry`] keeps every distinct packed state once, in one
//! arena (`Vec<u64>` of fixed-length slices), and maps packed states to dense
//! [`StateId`]s through a hash table that stores only ids and hashes and compares through
//! the arena.

use std::hash::Hasher;

use hashbrown::HashTable;
use rustc_hash::FxHasher;

use crate::segmented::SegmentedArena;

/// Index of a state in a [`StateRegistry`], in order of registration.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct StateId(pub u32);

impl StateId {
    /// As an index into a vector.
    pub fn index(self) -> usize {
        self.0 as usize
    }
}

/// Where one variable lives in a packed state.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
struct Slot {
    word: u32,
    shift: u32,
    /// `bits` low ones, not shifted.
    mask: u64,
}

/// Packs states (one `u32` value per variable) into `u64` words and back.
///
/// Variables are placed first-fit in decreasing order of width, so the layout depends
/// only on the domain sizes.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct StatePacker {
    slots: Vec<Slot>,
    words: usize,
}

/// Bits needed for values `0..domain_size`.
fn bits_for(domain_size: u32) -> u32 {
    if domain_size <= 1 {
        0
    } else {
        32 - (domain_size - 1).leading_zeros()
    }
}

impl StatePacker {
    /// A packer for variables with these domain sizes. O(n * words).
    pub fn new(domain_sizes: &[u32]) -> StatePacker {
        let mut order: Vec<usize> = (0..domain_sizes.len()).collect();
        // Widest first; ties by index (the sort is stable).
        order.sort_by_key(|&v| std::cmp::Reverse(bits_for(domain_sizes[v])));
        let mut free: Vec<u32> = Vec::new();
        let mut slots = vec![
            Slot {
                word: 0,
                shift: 0,
                mask: 0
            };
            domain_sizes.len()
        ];
        for v in order {
            let bits = bits_for(domain_sizes[v]);
            if bits == 0 {
                continue;
            }
            let word = match free.iter().position(|&f| f >= bits) {
                Some(w) => w,
                None => {
                    free.push(64);
                    free.len() - 1
                }
            };
            let shift = 64 - free[word];
            free[word] -= bits;
            slots[v] = Slot {
                word: word as u32,
                shift,
                mask: (1u64 << bits) - 1,
            };
        }
        // At least one word, so that variables of one value (no bits) read word 0.
        StatePacker {
            slots,
            words: free.len().max(1),
        }
    }

    /// A packer for the variables of `task`.
    pub fn for_task(task: &task::Task) -> StatePacker {
        let sizes: Vec<u32> = task.variables.iter().map(|v| v.domain_size()).collect();
        StatePacker::new(&sizes)
    }

    /// The number of `u64` words of one packed state (at least 1).
    pub fn words_per_state(&self) -> usize {
        self.words
    }

    /// The number of variables.
    pub fn num_variables(&self) -> usize {
        self.slots.len()
    }

    /// Writes the packed form of `state` (one value per variable, each below its domain
    /// size) into `out` (`words_per_state` words).
    #[inline]
    pub fn pack(&self, state: &[u32], out: &mut [u64]) {
        out.fill(0);
        for (slot, &value) in self.slots.iter().zip(state) {
            out[slot.word as usize] |= (u64::from(value) & slot.mask) << slot.shift;
        }
    }

    /// Writes the values of `packed` into `out` (one per variable).
    #[inline]
    pub fn unpack(&self, packed: &[u64], out: &mut [u32]) {
        for (slot, value) in self.slots.iter().zip(out.iter_mut()) {
            *value = ((packed[slot.word as usize] >> slot.shift) & slot.mask) as u32;
        }
    }

    /// The value of variable `var` in `packed`.
    #[inline]
    pub fn get(&self, packed: &[u64], var: usize) -> u32 {
        let slot = self.slots[var];
        ((packed[slot.word as usize] >> slot.shift) & slot.mask) as u32
    }

    /// Sets variable `var` to `value` in `packed`.
    #[inline]
    pub fn set(&self, packed: &mut [u64], var: usize, value: u32) {
        let slot = self.slots[var];
        let word = &mut packed[slot.word as usize];
        *word =
            (*word & !(slot.mask << slot.shift)) | ((u64::from(value) & slot.mask) << slot.shift);
    }

    /// The word, the bits to clear and the bits to set that write `value` into `var`.
    pub(crate) fn write_mask(&self, var: usize, value: u32) -> (u32, u64, u64) {
        let slot = self.slots[var];
        (
            slot.word,
            slot.mask << slot.shift,
            (u64::from(value) & slot.mask) << slot.shift,
        )
    }
}

fn hash_words(words: &[u64]) -> u64 {
    let mut hasher = FxHasher::default();
    for &w in words {
        hasher.write_u64(w);
    }
    hasher.finish()
}

/// Every state seen so far, stored once, with dense ids.
///
/// Insertion and lookup are expected O(words per state).
#[derive(Debug, Clone)]
pub struct StateRegistry {
    words: usize,
    arena: SegmentedArena,
    len: u32,
    table: HashTable<StateId>,
}

impl StateRegistry {
    /// An empty registry for packed states of `words_per_state` words.
    pub fn new(words_per_state: usize) -> StateRegistry {
        StateRegistry {
            words: words_per_state,
            arena: SegmentedArena::new(words_per_state),
            len: 0,
            table: HashTable::new(),
        }
    }

    /// The number of registered states.
    pub fn len(&self) -> usize {
        self.len as usize
    }

    /// True if no state is registered.
    pub fn is_empty(&self) -> bool {
        self.len == 0
    }

    /// The packed state with this id.
    #[inline]
    pub fn get(&self, id: StateId) -> &[u64] {
        self.arena.get(id.index())
    }

    /// The id of `packed`, registering it if it is new; the flag tells whether it was.
    /// `None` once `u32::MAX` states are registered.
    #[inline]
    pub fn insert(&mut self, packed: &[u64]) -> Option<(StateId, bool)> {
        debug_assert_eq!(packed.len(), self.words);
        let hash = hash_words(packed);
        let arena = &self.arena;
        let found = self.table.find(hash, |&id| arena.get(id.index()) == packed);
        if let Some(&id) = found {
            return Some((id, false));
        }
        if self.len == u32::MAX {
            return None;
        }
        let id = StateId(self.len);
        self.len += 1;
        self.arena.push(packed);
        let arena = &self.arena;
        self.table
            .insert_unique(hash, id, |&other| hash_words(arena.get(other.index())));
        Some((id, true))
    }

    /// The id of `packed` if it is registered.
    pub fn find(&self, packed: &[u64]) -> Option<StateId> {
        self.table
            .find(hash_words(packed), |&id| {
                self.arena.get(id.index()) == packed
            })
            .copied()
    }

    /// Bytes held by the arena and the table (capacity, not length).
    pub fn memory_bytes(&self) -> usize {
        self.arena.memory_bytes() + self.table.allocation_size()
    }

    /// The bytes the lookup table's next growth will allocate, once it is within a
    /// sixteenth of its capacity (else 0). A table grows by doubling, allocating the new
    /// one while the old is alive: a single step of tens of megabytes on a large search,
    /// which a memory check made only after it would see too late.
    pub fn imminent_growth_bytes(&self) -> usize {
        let capacity = self.table.capacity();
        let left = capacity.saturating_sub(self.table.len());
        if capacity > 0 && left <= capacity / 16 {
            self.table.allocation_size().saturating_mul(2)
        } else {
            0
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The growth is announced before the table doubles (so that the search can stop
    /// first), with about the size of the new table, and not otherwise.
    #[test]
    fn the_state_table_announces_its_doubling_before_it_happens() {
        let mut registry = StateRegistry::new(1);
        let mut announced = 0;
        let mut doublings = 0;
        for i in 0..100_000u64 {
            let (before, growth) = (registry.memory_bytes(), registry.imminent_growth_bytes());
            if growth > 0 {
                announced += 1;
            }
            let capacity = registry.table.capacity();
            registry.insert(&[i]);
            if registry.table.capacity() > capacity && capacity >= 1024 {
                doublings += 1;
                // The step just taken was announced, at twice the old table.
                assert!(growth > 0, "state {i}: the doubling came unannounced");
                assert!(registry.memory_bytes() - before <= growth, "state {i}");
            }
        }
        assert!(doublings >= 5);
        // Announced only near a doubling: a sixteenth of the states at most, roughly.
        assert!(announced < 100_000 / 8, "{announced}");
    }

    #[test]
    fn bits() {
        assert_eq!(bits_for(1), 0);
        assert_eq!(bits_for(2), 1);
        assert_eq!(bits_for(3), 2);
        assert_eq!(bits_for(4), 2);
        assert_eq!(bits_for(5), 3);
        assert_eq!(bits_for(1 << 20), 20);
        assert_eq!(bits_for((1 << 20) + 1), 21);
        assert_eq!(bits_for(u32::MAX), 32);
    }

    #[test]
    fn packing_round_trip_with_odd_domains() {
        let sizes = [
            3, 5, 1, 7, 2, 100_000, 33, 1, 4, 9, 17, 65, 129, 3, 3, 3, 5, 1_000_003, 2, 2,
        ];
        let packer = StatePacker::new(&sizes);
        let total_bits: u32 = sizes.iter().map(|&s| bits_for(s)).sum();
        assert!(packer.words_per_state() >= total_bits.div_ceil(64) as usize);
        assert!(packer.words_per_state() <= sizes.len());
        let mut seed = 12345u64;
        let mut packed = vec![0u64; packer.words_per_state()];
        let mut back = vec![0u32; sizes.len()];
        for _ in 0..1000 {
            let state: Vec<u32> = sizes
                .iter()
                .map(|&s| {
                    seed = seed
                        .wrapping_mul(6364136223846793005)
                        .wrapping_add(1442695040888963407);
                    ((seed >> 33) % u64::from(s)) as u32
                })
                .collect();
            packer.pack(&state, &mut packed);
            packer.unpack(&packed, &mut back);
            assert_eq!(state, back);
            for (v, &value) in state.iter().enumerate() {
                assert_eq!(packer.get(&packed, v), value);
            }
            // Setting one variable leaves the others alone.
            let v = (seed % sizes.len() as u64) as usize;
            let new_value = (sizes[v] - 1).min(state[v] + 1);
            packer.set(&mut packed, v, new_value);
            packer.unpack(&packed, &mut back);
            let mut expected = state.clone();
            expected[v] = new_value;
            assert_eq!(back, expected);
        }
    }

    #[test]
    fn max_domain_and_many_binaries() {
        let mut sizes = vec![u32::MAX, u32::MAX];
        sizes.extend(std::iter::repeat_n(2, 130));
        let packer = StatePacker::new(&sizes);
        // Two 32-bit variables fill one word; 130 binary variables need three more.
        assert_eq!(packer.words_per_state(), 4);
        let state: Vec<u32> = (0..sizes.len())
            .map(|i| {
                if i < 2 {
                    u32::MAX - 1 - i as u32
                } else {
                    (i % 2) as u32
                }
            })
            .collect();
        let mut packed = vec![0; 4];
        packer.pack(&state, &mut packed);
        let mut back = vec![0; sizes.len()];
        packer.unpack(&packed, &mut back);
        assert_eq!(back, state);
    }

    #[test]
    fn trivial_domains() {
        let packer = StatePacker::new(&[1, 1]);
        assert_eq!(packer.words_per_state(), 1);
        let mut packed = [7];
        packer.pack(&[0, 0], &mut packed);
        assert_eq!(packed, [0]);
        let mut back = [5, 5];
        packer.unpack(&packed, &mut back);
        assert_eq!(back, [0, 0]);
        assert_eq!(StatePacker::new(&[]).words_per_state(), 1);
        // A registry of empty states holds one state.
        let mut registry = StateRegistry::new(0);
        assert_eq!(registry.insert(&[]), Some((StateId(0), true)));
        assert_eq!(registry.insert(&[]), Some((StateId(0), false)));
        assert_eq!(registry.len(), 1);
    }

    #[test]
    fn registry_deduplicates() {
        let mut registry = StateRegistry::new(2);
        assert!(registry.is_empty());
        let mut ids = Vec::new();
        for i in 0..10_000u64 {
            let (id, new) = registry.insert(&[i, i * 7]).unwrap();
            assert!(new);
            assert_eq!(id, StateId(i as u32));
            ids.push(id);
        }
        for i in (0..10_000u64).rev() {
            let (id, new) = registry.insert(&[i, i * 7]).unwrap();
            assert!(!new);
            assert_eq!(id, ids[i as usize]);
            assert_eq!(registry.get(id), &[i, i * 7]);
            assert_eq!(registry.find(&[i, i * 7]), Some(id));
        }
        assert_eq!(registry.find(&[1, 1]), None);
        assert_eq!(registry.len(), 10_000);
        assert!(registry.memory_bytes() >= 10_000 * 16);
    }
}
