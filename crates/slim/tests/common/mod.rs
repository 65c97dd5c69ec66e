//! What the slim crate's test binaries share.

#![allow(clippy::unwrap_used, dead_code)] // each test binary uses a part

use learn::Library;

/// The widening library: its priority-1 domain cannot reach the paper's goals, its
/// priority 2 can (`tests/fixtures/widening-library.json`).
pub fn widening_library() -> Library {
    let text = std::fs::read_to_string(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/tests/fixtures/widening-library.json"
    ))
    .unwrap();
    Library::from_json(&text).unwrap()
}
