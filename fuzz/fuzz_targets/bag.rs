//! The ROS bag readers (ROS 1 records and chunks, MCAP through the `mcap` crate): a bag
//! in memory is listed and every message decoded; every field path of the first
//! messages is looked up. Seeds: the committed fixtures, one file per container and
//! compression.
//!
//! The check is `fuzz_checks::bag`, shared with the replay of old crashes
//! (`crates/fuzz-checks/tests/replay.rs`).
#![no_main]

use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| fuzz_checks::bag(data));
