//! The recording reader over any bytes: the header, then every frame.
//!
//! The check is `fuzz_checks::recording`, shared with the replay of old crashes
//! (`crates/fuzz-checks/tests/replay.rs`).
#![no_main]

use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| fuzz_checks::recording(data));
