//! The ROS import (ROS 1 bags and MCAP files): a bag in memory is checked against the
//! default mapping of its format and imported (tf composed to its root at every tick,
//! poses to observations); what the import writes, the native reader reads.
//!
//! The check is `fuzz_checks::bag_import`, shared with the replay of old crashes
//! (`crates/fuzz-checks/tests/replay.rs`).
#![no_main]

use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| fuzz_checks::bag_import(data));
