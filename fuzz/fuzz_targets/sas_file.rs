//! The `output.sas` reader on arbitrary text; a task that comes out must validate (the
//! reader promises it), write and read back unchanged, and is searched a little.
#![no_main]

use libfuzzer_sys::fuzz_target;

fuzz_target!(|text: &str| {
    let Ok(task) = task::sas_file::read(text) else {
        demoplan_fuzz::trace("not read");
        return;
    };
    if let Err(e) = task.validate() {
        panic!("sas_file::read returned an invalid task: {e}");
    }
    let written = task::sas_file::write(&task);
    match task::sas_file::read(&written) {
        Ok(again) => assert_eq!(again, task, "read(write(task)) != task"),
        Err(e) => panic!("a written task does not read back: {e}"),
    }
    demoplan_fuzz::search_a_little(&task);
});
