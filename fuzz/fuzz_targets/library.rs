//! The operator library's JSON reader; a library that reads must write and read back
//! as an equal library, and write the same text again.
//!
//! The check is `fuzz_checks::library`, shared with the replay of old crashes
//! (`crates/fuzz-checks/tests/replay.rs`).
#![no_main]

use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| fuzz_checks::library(data));
