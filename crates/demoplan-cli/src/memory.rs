//! Memory accounting for `--overall-memory-limit`: a global allocator that counts the
//! bytes in use, so the search can stop itself (exit 22) before an allocation fails or
//! the kernel kills the process.

// The only unsafe code of the project: a GlobalAlloc implementation has to be `unsafe`.
// It forwards every call to the system allocator unchanged and only counts sizes.
#![allow(unsafe_code)]

use std::alloc::{GlobalAlloc, Layout, System};
use std::sync::atomic::{AtomicU64, Ordering};

static IN_USE: AtomicU64 = AtomicU64::new(0);
static PEAK: AtomicU64 = AtomicU64::new(0);

/// Counts `size` more bytes in use and raises the peak.
fn grow(size: usize) {
    let now = IN_USE.fetch_add(size as u64, Ordering::Relaxed) + size as u64;
    PEAK.fetch_max(now, Ordering::Relaxed);
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
        IN_USE.fetch_sub(layout.size() as u64, Ordering::Relaxed);
    }

    unsafe fn realloc(&self, ptr: *mut u8, layout: Layout, new_size: usize) -> *mut u8 {
        // SAFETY: forwarded unchanged.
        let p = unsafe { System.realloc(ptr, layout, new_size) };
        if !p.is_null() {
            IN_USE.fetch_sub(layout.size() as u64, Ordering::Relaxed);
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

/// Starts a new peak heap at what is in use now (each run of `reproduce` and `study`
/// reports its own peak).
pub fn reset_peak() {
    PEAK.store(heap_in_use(), Ordering::Relaxed);
}

/// The probe that lets the experiment measure each run's peak heap.
pub fn probe() -> slim::MemoryProbe {
    slim::MemoryProbe {
        reset: reset_peak,
        peak: peak_heap,
    }
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
