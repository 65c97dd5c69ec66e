//! The ARFF reader (Weka's grammar: commas and/or whitespace, quotes with escapes,
//! comments, sparse rows) and content detection; a table that reads is turned into a
//! dataset, and a hand-state table into frames, their activities by the default label
//! map, a dataset over them, and segments with the hand's own facts as states; and the
//! same read a row at a time (`ArffReader`, `HandTable`).
//!
//! The check is `fuzz_checks::arff`, shared with the replay of old crashes
//! (`crates/fuzz-checks/tests/replay.rs`).
#![no_main]

use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| fuzz_checks::arff(data));
