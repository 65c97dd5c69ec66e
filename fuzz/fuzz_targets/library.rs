//! The operator library's JSON reader; a library that reads must write and read back
//! as an equal library, and write the same text again.
#![no_main]

use libfuzzer_sys::fuzz_target;

fuzz_target!(|text: &str| {
    let Ok(library) = learn::Library::from_json(text) else {
        return;
    };
    let written = library.to_json();
    match learn::Library::from_json(&written) {
        Ok(again) => {
            assert_eq!(again, library, "from_json(to_json(library)) != library");
            assert_eq!(again.to_json(), written, "to_json is not stable");
        }
        Err(e) => panic!("a written library does not read back: {e}\n{written}"),
    }
});
