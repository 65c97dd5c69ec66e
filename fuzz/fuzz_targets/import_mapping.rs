//! The mapping file reader: any text is a mapping or an error with a line; a mapping
//! read prints as TOML that reads back to the same mapping.
#![no_main]

use libfuzzer_sys::fuzz_target;

fuzz_target!(|text: &str| {
    let Ok(mapping) = import::Mapping::from_toml(text, import::Format::Unity) else {
        return;
    };
    let printed = mapping.to_toml();
    let again = import::Mapping::from_toml(&printed, import::Format::Ros1);
    assert_eq!(again.as_ref(), Ok(&mapping), "{printed}");
    let _ = mapping.resolve(text);
});
