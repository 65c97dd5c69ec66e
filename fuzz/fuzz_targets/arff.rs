//! The ARFF reader (Weka's grammar: commas and/or whitespace, quotes with escapes,
//! comments, sparse rows) and content detection; a table that reads is turned into a
//! dataset, and a hand-state table into frames, their activities by the default label
//! map, a dataset over them, and segments with the hand's own facts as states.
#![no_main]

use libfuzzer_sys::fuzz_target;

fuzz_target!(|text: &str| {
    let _ = segment::is_arff_text(text);
    let Ok(table) = segment::read_arff(text) else {
        return;
    };
    let _ = table.dataset(None);
    if let Ok(frames) = table.hand_frames(30.0) {
        let map = segment::LabelMap::default();
        let activities = frames.activities(&map);
        let _ = activities.warning();
        let _ = frames.dataset(&map);
        let _ = frames.segments(&segment::ActivityTree::table_one(), 0.1);
    }
});
