//! The search-string parser (`astar(lmcut())`, aliases) on arbitrary UTF-8.
#![no_main]

use libfuzzer_sys::fuzz_target;

fuzz_target!(|text: &str| {
    let _ = search::parse_search(text);
});
