//! The ARFF reader; a table that reads is turned into hand frames and datasets.
#![no_main]

use libfuzzer_sys::fuzz_target;

fuzz_target!(|text: &str| {
    let Ok(table) = segment::read_arff(text) else {
        return;
    };
    let _ = table.dataset(None);
    if let Ok(frames) = table.hand_frames(30.0) {
        let _ = frames.dataset();
    }
});
