//! The recording reader over arbitrary bytes: the header, then every frame.
#![no_main]

use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    let Ok(mut reader) = recording::Reader::new(data) else {
        return;
    };
    let mut frame = recording::Frame::default();
    while let Ok(true) = reader.read_frame(&mut frame) {}
});
