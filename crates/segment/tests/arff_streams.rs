//! ARFF tables stream: reading a hand-state table row by row ([`ArffReader`], then
//! [`HandTable`]'s two passes) takes the same peak heap for a table ten times longer,
//! and far less than the table's text. The table is generated while it is read, so the
//! test's own input takes no heap; the heap is counted by this test binary's allocator.
//!
//! This binary holds one test only: the allocator counts every thread's allocations,
//! and another test running beside it would be counted too.

// A counting allocator has to implement `GlobalAlloc`, which is `unsafe`. It forwards
// every call to the system allocator unchanged and only counts sizes.
#![allow(unsafe_code, clippy::unwrap_used, clippy::expect_used)]

use std::alloc::{GlobalAlloc, Layout, System};
use std::io::{BufReader, Read};
use std::sync::atomic::{AtomicU64, Ordering};

use segment::{Activity, ActivityTree, ArffReader, HandTable, LabelMap, UnknownLabels};

static IN_USE: AtomicU64 = AtomicU64::new(0);
static PEAK: AtomicU64 = AtomicU64::new(0);

struct Counting;

// SAFETY: every method forwards to `System` with the caller's arguments and returns its
// result; the counters have no influence on the memory handed out.
unsafe impl GlobalAlloc for Counting {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        // SAFETY: forwarded unchanged.
        let p = unsafe { System.alloc(layout) };
        if !p.is_null() {
            let now = IN_USE.fetch_add(layout.size() as u64, Ordering::Relaxed);
            PEAK.fetch_max(now + layout.size() as u64, Ordering::Relaxed);
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
            let now = IN_USE.fetch_add(new_size as u64, Ordering::Relaxed);
            PEAK.fetch_max(now + new_size as u64, Ordering::Relaxed);
        }
        p
    }
}

#[global_allocator]
static ALLOCATOR: Counting = Counting;

/// The recognisers' labels, one block of rows each, in this order: every table has the
/// same five segments whatever its length, so only the rows' count grows.
const BLOCKS: [(&str, &str, &str, &str, &str); 5] = [
    ("NotMove", "None", "None", "Open", "IdleMotion"),
    ("Move", "cube_a", "None", "Open", "Reach"),
    ("NotMove", "cube_a", "cube_a", "Close", "Take_1"),
    ("Move", "cube_b", "cube_a", "Close", "PutSomethingSomeWhere"),
    ("NotMove", "None", "None", "Open", "Wave"),
];

const HEADER: &str = "% a recogniser's hand states\n@relation hands\n\
@attribute Hand {NotMove, Move, ToolUse}\n\
@attribute ObjectActedOn {None, Something}\n\
@attribute ObjectInHand {None, Something}\n\
@attribute HandState {Open, Close}\n\
@attribute Activity {IdleMotion, Reach, Take, PutSomethingSomeWhere}\n\
@data\n";

/// A hand-state table of `rows` rows, written as it is read: tab-separated rows with
/// object names the header does not declare, a comment now and then.
struct GeneratedTable {
    rows: usize,
    next: usize,
    pending: Vec<u8>,
    at: usize,
}

impl GeneratedTable {
    fn new(rows: usize) -> GeneratedTable {
        GeneratedTable {
            rows,
            next: 0,
            pending: HEADER.as_bytes().to_vec(),
            at: 0,
        }
    }

    /// The length of the table's text.
    fn text_len(rows: usize) -> usize {
        let mut table = GeneratedTable::new(rows);
        let mut sink = Vec::new();
        table.read_to_end(&mut sink).unwrap();
        sink.len()
    }
}

impl Read for GeneratedTable {
    fn read(&mut self, buf: &mut [u8]) -> std::io::Result<usize> {
        while self.at == self.pending.len() {
            if self.next == self.rows {
                return Ok(0);
            }
            self.pending.clear();
            self.at = 0;
            let (hand, acted, held, state, label) = BLOCKS[self.next * BLOCKS.len() / self.rows];
            if self.next % 1000 == 999 {
                self.pending.extend_from_slice(b"% a comment line\n");
            }
            let row = format!("{hand}\t{acted},\t{held}\t{state}\t'{label}'\n");
            self.pending.extend_from_slice(row.as_bytes());
            self.next += 1;
        }
        let n = buf.len().min(self.pending.len() - self.at);
        buf[..n].copy_from_slice(&self.pending[self.at..self.at + n]);
        self.at += n;
        Ok(n)
    }
}

/// What a streamed read of a table finds, and its peak heap above what was in use
/// before it.
struct Streamed {
    peak_heap: u64,
    frames: u64,
    activities: Vec<Activity>,
    objects: Vec<String>,
    left_out: usize,
}

fn stream(rows: usize) -> Streamed {
    let base = IN_USE.load(Ordering::Relaxed);
    PEAK.store(base, Ordering::Relaxed);
    // The first pass: the scene and the labels.
    let reader = ArffReader::new(BufReader::new(GeneratedTable::new(rows))).unwrap();
    let (relation, attributes) = (reader.relation().to_string(), reader.attributes().to_vec());
    let table = HandTable::scan(&relation, &attributes, reader, 30.0).unwrap();
    // The second pass: the frames, segmented, and their labels through the label map.
    let map = LabelMap::default();
    let mut unknown = UnknownLabels::default();
    let reader = ArffReader::new(BufReader::new(GeneratedTable::new(rows))).unwrap();
    let frames = table.frames(reader).inspect(|frame| {
        if let Ok(frame) = frame {
            unknown.activity(&map, frame);
        }
    });
    let segmented = table
        .segments(frames, &ActivityTree::table_one(), 0.25)
        .unwrap();
    let peak_heap = PEAK.load(Ordering::Relaxed).saturating_sub(base);
    Streamed {
        peak_heap,
        frames: segmented.frames,
        activities: segmented.segments.iter().map(|s| s.activity).collect(),
        objects: table
            .header
            .entities
            .iter()
            .map(|e| e.name.clone())
            .collect(),
        left_out: unknown.left_out(),
    }
}

#[test]
fn a_hand_state_table_streams_in_a_peak_heap_that_does_not_grow_with_its_rows() {
    let short = stream(20_000);
    let long = stream(200_000);
    for (s, rows) in [(&short, 20_000), (&long, 200_000)] {
        // Every row was read, as the frames of the same demonstration.
        assert_eq!(s.frames, rows);
        // One segment per block, each block's hand state a different tuple.
        assert_eq!(s.activities.len(), BLOCKS.len(), "{:?}", s.activities);
        assert_eq!(s.objects, ["hand", "cube_a", "cube_b"]);
        // `Wave` is no activity of the label map: its block is left out.
        assert_eq!(s.left_out, rows as usize / 5);
    }
    assert_eq!(short.activities, long.activities);
    assert!(
        long.peak_heap as f64 <= short.peak_heap as f64 * 1.1,
        "the peak heap grew with the table: {} bytes for 20,000 rows, {} for 200,000",
        short.peak_heap,
        long.peak_heap
    );
    // And it is nothing like the table: the long one's text is megabytes.
    let text = GeneratedTable::text_len(200_000);
    assert!(text > 5_000_000, "{text}");
    assert!(
        (long.peak_heap as usize) < text / 50,
        "peak heap {} bytes for a text of {text}",
        long.peak_heap
    );
}
