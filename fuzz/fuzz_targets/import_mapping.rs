//! The mapping file reader: any text is a mapping or an error with a line; a mapping
//! read prints as TOML that reads back to the same mapping.
//!
//! The check is `fuzz_checks::import_mapping`, shared with the replay of old crashes
//! (`crates/fuzz-checks/tests/replay.rs`).
#![no_main]

use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| fuzz_checks::import_mapping(data));
