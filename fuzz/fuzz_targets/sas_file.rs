//! The `output.sas` reader on any UTF-8 text; a task that comes out must validate (the
//! reader promises it), write and read back unchanged, and is searched a little.
//!
//! The check is `fuzz_checks::sas_file`, shared with the replay of old crashes
//! (`crates/fuzz-checks/tests/replay.rs`).
#![no_main]

use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| fuzz_checks::sas_file(data));
