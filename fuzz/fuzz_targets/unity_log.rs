//! The Unity log reader and the import core: any bytes either import into a recording
//! that reads back, or give an input error; never a panic.
#![no_main]

use libfuzzer_sys::fuzz_target;

fuzz_target!(|bytes: &[u8]| {
    let mapping = import::Mapping::default_for(import::Format::Unity);
    let mut source = import::unity::UnityLog::new(|| Ok(bytes));
    if let Ok((out, _, _)) = import::import(&mut source, &mapping, "fuzz", Vec::new()) {
        // What the import writes, the native reader reads.
        assert!(recording::Recording::read(&out[..]).is_ok());
    }
});
