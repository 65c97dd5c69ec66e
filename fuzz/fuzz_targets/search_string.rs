//! The search-string parser (`astar(lmcut())`, aliases) on any UTF-8 text.
//!
//! The check is `fuzz_checks::search_string`, shared with the replay of old crashes
//! (`crates/fuzz-checks/tests/replay.rs`).
#![no_main]

use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| fuzz_checks::search_string(data));
