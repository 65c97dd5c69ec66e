//! The ROS bag readers (ROS 1 records and chunks, MCAP through the `mcap` crate): a bag in
//! memory is listed and every message decoded; every field path of the first messages is
//! looked up. Seeds: the committed fixtures, one file per container and compression.
#![no_main]

use libfuzzer_sys::fuzz_target;

fuzz_target!(|bytes: &[u8]| {
    let Ok(bag) = bags::from_bytes(std::path::Path::new("fuzz.bag"), bytes.to_vec()) else {
        return;
    };
    let _ = bag.topics();
    let Ok(messages) = bag.messages(|_| true) else {
        return;
    };
    for message in messages.take(64) {
        let Ok(message) = message else { return };
        let _ = message.value.lookup("transforms[].transform.translation.x");
        let _ = message.value.lookup("header.stamp");
    }
});
