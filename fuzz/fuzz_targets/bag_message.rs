//! The definition parser and the message decoder: a definition text, then a NUL byte, then
//! a message, decoded both as ROS 1 and as CDR.
#![no_main]

use libfuzzer_sys::fuzz_target;

fuzz_target!(|bytes: &[u8]| {
    let Some(split) = bytes.iter().position(|&b| b == 0) else {
        return;
    };
    let Ok(definition) = std::str::from_utf8(&bytes[..split]) else {
        return;
    };
    let Ok(schema) = bags::Schema::parse("fuzz/Message", definition) else {
        return;
    };
    let data = &bytes[split + 1..];
    for encoding in [bags::Encoding::Ros1, bags::Encoding::Cdr] {
        if let Ok(value) = bags::decode(&schema, encoding, data) {
            let _ = value.lookup("a[].b");
        }
    }
});
