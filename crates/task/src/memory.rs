//! Memory accounting for the memory limits ([`crate::Limits::memory_usage`]): an
//! allocator that counts the bytes in use and their peak, so a run can stop itself
//! before an allocation fails or the kernel kills the process. A library cannot install
//! a global allocator: the program does (`#[global_allocator]`, the command line crate
//! for the binary and the Python extension); until it does, every reading is 0.

// The only unsafe code of the project: a GlobalAlloc implementation has to be `unsafe`.
// It forwards every call to the system allocator unchanged and only counts sizes.
#![allow(unsafe_code)]

use std::alloc::{GlobalAlloc, Layout, System};
use std::sync::atomic::{AtomicU64, Ordering};

static IN_USE: AtomicU64 = AtomicU64::new(0);
static PEAK: AtomicU64 = AtomicU64::new(0);

/// The bytes an allocation of `size` takes from the system allocator: glibc's malloc
/// adds an 8-byte header, rounds up to 16 bytes and hands out at least 32. Counting what
/// was asked for alone undercounts small allocations by up to 60% (a 20-byte ground
/// action binding takes a 32-byte chunk), which let a grounding of millions of them
/// exceed its memory limit in resident memory while the count stayed under it.
const fn charged(size: usize) -> u64 {
    let chunk = size.saturating_add(8 + 15) & !15;
    (if chunk < 32 { 32 } else { chunk }) as u64
}

/// Counts an allocation of `size` bytes more in use and raises the peak.
fn grow(size: usize) {
    let bytes = charged(size);
    let now = IN_USE.fetch_add(bytes, Ordering::Relaxed) + bytes;
    PEAK.fetch_max(now, Ordering::Relaxed);
}

/// Counts an allocation of `size` bytes freed.
fn shrink(size: usize) {
    IN_USE.fetch_sub(charged(size), Ordering::Relaxed);
}

/// The system allocator, counting bytes in use.
#[derive(Debug)]
pub struct CountingAllocator;

// SAFETY: every method forwards to `System` with the caller's arguments and returns its
// result; the counter is a side effect with no influence on the memory handed out.
unsafe impl GlobalAlloc for CountingAllocator {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        // SAFETY: forwarded unchanged.
        let p = unsafe { System.alloc(layout) };
        if !p.is_null() {
            grow(layout.size());
        }
        p
    }

    unsafe fn alloc_zeroed(&self, layout: Layout) -> *mut u8 {
        // SAFETY: forwarded unchanged.
        let p = unsafe { System.alloc_zeroed(layout) };
        if !p.is_null() {
            grow(layout.size());
        }
        p
    }

    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        // SAFETY: forwarded unchanged.
        unsafe { System.dealloc(ptr, layout) };
        shrink(layout.size());
    }

    unsafe fn realloc(&self, ptr: *mut u8, layout: Layout, new_size: usize) -> *mut u8 {
        // SAFETY: forwarded unchanged.
        let p = unsafe { System.realloc(ptr, layout, new_size) };
        if !p.is_null() {
            shrink(layout.size());
            grow(new_size);
        }
        p
    }
}

/// The most bytes allocated on the heap at any time since the start, or since the last
/// [`reset_peak`].
pub fn peak_heap() -> u64 {
    PEAK.load(Ordering::Relaxed)
}

/// Starts a new peak heap at what is in use now (each run of an experiment reports its
/// own peak).
pub fn reset_peak() {
    PEAK.store(heap_in_use(), Ordering::Relaxed);
}

/// Bytes currently allocated on the heap.
pub fn heap_in_use() -> u64 {
    IN_USE.load(Ordering::Relaxed)
}

/// The process's peak resident set size in KiB (`VmHWM`), where the system reports it.
pub fn peak_rss_kb() -> Option<u64> {
    let status = std::fs::read_to_string("/proc/self/status").ok()?;
    let line = status.lines().find(|l| l.starts_with("VmHWM:"))?;
    line.split_whitespace().nth(1)?.parse().ok()
}

#[cfg(test)]
mod tests {
    #[test]
    fn allocations_are_charged_as_glibc_chunks() {
        use super::charged;
        assert_eq!(charged(0), 32);
        assert_eq!(charged(20), 32);
        assert_eq!(charged(24), 32);
        assert_eq!(charged(25), 48);
        assert_eq!(charged(1000), 1008);
        assert_eq!(charged(usize::MAX), (usize::MAX & !15) as u64);
    }
}
