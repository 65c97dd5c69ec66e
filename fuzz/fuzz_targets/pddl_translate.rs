//! The PDDL front end and translator: the input is a domain and a problem, split at the
//! first NUL byte (or in the middle when there is none); both are parsed, checked and
//! translated, and a task that comes out is searched for a few milliseconds. What the
//! canonical writer prints of the domain and problem must parse and print the same again.
//!
//! The check is `fuzz_checks::pddl_translate`, shared with the replay of old crashes
//! (`crates/fuzz-checks/tests/replay.rs`).
#![no_main]

use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| fuzz_checks::pddl_translate(data));
