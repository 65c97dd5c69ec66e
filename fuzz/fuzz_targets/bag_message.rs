//! The definition parser and the message decoder: a definition text, then a NUL byte,
//! then a message, decoded both as ROS 1 and as CDR.
//!
//! The check is `fuzz_checks::bag_message`, shared with the replay of old crashes
//! (`crates/fuzz-checks/tests/replay.rs`).
#![no_main]

use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| fuzz_checks::bag_message(data));
