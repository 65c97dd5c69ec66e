//! The Unity log reader and the import core: any bytes either import into a recording
//! that reads back, or give an input error; never a panic.
//!
//! The check is `fuzz_checks::unity_log`, shared with the replay of old crashes
//! (`crates/fuzz-checks/tests/replay.rs`).
#![no_main]

use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| fuzz_checks::unity_log(data));
