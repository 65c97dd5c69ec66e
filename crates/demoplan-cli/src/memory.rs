//! Memory accounting for `--overall-memory-limit`: a global allocator that counts the
//! bytes in use, so the search can stop itself (exit 22) before an allocation fails or
//! the kernel kills the process.

// The only unsafe code of the project: a GlobalAlloc implementation has to be `unsafe`.
// It forwards every call to the system allocator unchanged and only counts sizes.
#![allow(unsafe_code)]

use std::alloc::{GlobalAlloc, Layout, System};
use std::sync::atomic::{AtomicU64, Ordering};

static IN_USE: AtomicU64 = AtomicU64::new(0);
/// The most bytes in use since the last [`reset_peak`]: one relaxed `fetch_max` per
/// allocation, so that `reproduce` and `study` report each run's peak heap.
static PEAK: AtomicU64 = AtomicU64::new(0);

fn grew(previous: u64, size: usize) {
    PEAK.fetch_max(previous + size as u64, Ordering::Relaxed);
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
            grew(
                IN_USE.fetch_add(layout.size() as u64, Ordering::Relaxed),
                layout.size(),
            );
        }
        p
    }

    unsafe fn alloc_zeroed(&self, layout: Layout) -> *mut u8 {
        // SAFETY: forwarded unchanged.
        let p = unsafe { System.alloc_zeroed(layout) };
        if !p.is_null() {
            grew(
                IN_USE.fetch_add(layout.size() as u64, Ordering::Relaxed),
                layout.size(),
            );
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
            grew(
                IN_USE.fetch_add(new_size as u64, Ordering::Relaxed),
                new_size,
            );
        }
        p
    }
}

/// Bytes currently allocated on the heap.
pub fn heap_in_use() -> u64 {
    IN_USE.load(Ordering::Relaxed)
}

/// Starts a new peak heap at what is in use now.
pub fn reset_peak() {
    PEAK.store(heap_in_use(), Ordering::Relaxed);
}

/// The peak heap in bytes since the last [`reset_peak`].
pub fn peak_heap() -> u64 {
    PEAK.load(Ordering::Relaxed)
}

/// The probe that lets the experiment measure each run's peak heap.
pub fn probe() -> slim::MemoryProbe {
    slim::MemoryProbe {
        reset: reset_peak,
        peak: peak_heap,
    }
}

/// The process's peak resident set size in KiB (`VmHWM`), where the system reports it.
pub fn peak_rss_kb() -> Option<u64> {
    let status = std::fs::read_to_string("/proc/self/status").ok()?;
    let line = status.lines().find(|l| l.starts_with("VmHWM:"))?;
    line.split_whitespace().nth(1)?.parse().ok()
}
