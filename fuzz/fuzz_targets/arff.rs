//! The ARFF reader (Weka's grammar: commas and/or whitespace, quotes with escapes,
//! comments, sparse rows) and content detection; a table that reads is turned into a
//! dataset, and a hand-state table into frames, their activities by the default label
//! map, a dataset over them, and segments with the hand's own facts as states; and the
//! same read a row at a time (`ArffReader`, `HandTable`).
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
    // The same table read as the CLI reads it: a row at a time, in two passes.
    let Ok(reader) = segment::ArffReader::new(text.as_bytes()) else {
        return;
    };
    let (relation, attributes) = (reader.relation().to_string(), reader.attributes().to_vec());
    if let Ok(hands) = segment::HandTable::scan(&relation, &attributes, reader, 30.0) {
        if let Ok(rows) = segment::ArffReader::new(text.as_bytes()) {
            let _ = hands.segments(hands.frames(rows), &segment::ActivityTree::table_one(), 0.1);
        }
    }
});
