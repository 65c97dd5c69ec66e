//! What every reader must do on any input, written once as functions of bytes: the
//! cargo-fuzz targets in `fuzz/` call them (one target per function, same name), and
//! `tests/replay.rs` runs every input that ever crashed a target
//! (`fuzz/regressions/TARGET/`) through them as an ordinary test. A panic is a finding:
//! the readers must refuse bad input with an error, and the assertions here state the
//! properties of what they accept (round trips, valid tasks, plans that replay).
//!
//! ```
//! // Any bytes: an error or a recording, never a panic.
//! fuzz_checks::recording(b"{\"format\":\"demoplan-recording\"");
//! fuzz_checks::check("search_string", b"astar(lmcut())");
//! ```

use std::sync::OnceLock;
use std::time::{Duration, Instant};

use search::{Outcome, SearchLimits};

/// A target's check: any bytes in, a panic for a finding.
pub type Check = fn(&[u8]);

/// Every target, by name (the names of `fuzz/fuzz_targets/*.rs` and of the folders of
/// `fuzz/corpus` and `fuzz/regressions`), with its check.
pub const TARGETS: &[(&str, Check)] = &[
    ("pddl_translate", pddl_translate),
    ("search_string", search_string),
    ("sas_file", sas_file),
    ("recording", recording),
    ("arff", arff),
    ("library", library),
    ("unity_log", unity_log),
    ("import_mapping", import_mapping),
    ("bag", bag),
    ("bag_message", bag_message),
    ("bag_import", bag_import),
];

/// Runs the check of target `name` on `data`. Panics for a name that is no target.
pub fn check(name: &str, data: &[u8]) {
    match TARGETS.iter().find(|(n, _)| *n == name) {
        Some((_, check)) => check(data),
        None => panic!("no fuzz target is called {name}"),
    }
}

/// How long each search may run. Short: the point is to reach the search code with odd
/// tasks, not to solve them.
const SEARCH_TIME: Duration = Duration::from_millis(5);

/// How many bytes of its own structures a search may use.
const SEARCH_BYTES: u64 = 32 << 20;

/// Notes how far an input got, on standard error, when `FUZZ_TRACE` is set: run a
/// target with `-runs=0` over its corpus to see how many inputs reach each stage.
pub fn trace(stage: &str) {
    static ON: OnceLock<bool> = OnceLock::new();
    if *ON.get_or_init(|| std::env::var_os("FUZZ_TRACE").is_some()) {
        eprintln!("FUZZ_TRACE {stage}");
    }
}

/// Searches `task` with `astar(blind())` and `astar(lmcut())` for a few milliseconds
/// each. Panics (a finding) if a search fails on a task that validates, if a plan does
/// not replay to a goal or its cost is not the sum of its operators' costs, or if both
/// searches finish with different verdicts or plan costs (both are optimal).
pub fn search_a_little(task: &task::Task) {
    let valid = task.validate().is_ok();
    let mut costs = Vec::new();
    for config in ["astar(blind())", "astar(lmcut())"] {
        let Ok(config) = search::parse_search(config) else {
            panic!("the fixed search string {config} does not parse");
        };
        let limits = SearchLimits {
            deadline: Some(Instant::now() + SEARCH_TIME),
            memory_limit_bytes: Some(SEARCH_BYTES),
            memory_usage: None,
            cancel: None,
        };
        let result = match search::search(task, &config, &limits, None) {
            Ok(result) => result,
            Err(e) => {
                assert!(!valid, "search failed on a valid task: {e}");
                trace("search refused the task");
                return;
            }
        };
        match result.outcome {
            Outcome::Solved(plan) => {
                let end = match search::replay(task, &plan.operators) {
                    Ok(end) => end,
                    Err(e) => panic!("a plan found by search does not replay: {e}"),
                };
                assert!(task.is_goal(&end), "a plan found by search misses the goal");
                let cost: u64 = plan
                    .operators
                    .iter()
                    .map(|&op| task.cost(&task.operators[op.index()]))
                    .sum();
                assert_eq!(cost, plan.cost, "a plan's cost is not its operators' sum");
                costs.push(Some(plan.cost));
            }
            Outcome::Unsolvable => costs.push(None),
            Outcome::TimeLimit | Outcome::MemoryLimit | Outcome::Cancelled => {
                trace("search stopped at a limit");
                return;
            }
        }
    }
    trace(if costs[0].is_some() {
        "search solved"
    } else {
        "search proved unsolvable"
    });
    if let [a, b] = costs[..] {
        assert_eq!(a, b, "blind and lmcut disagree (cost, or solvable or not)");
    }
}

/// The PDDL front end and translator: the input is a domain and a problem, split at the
/// first NUL byte (or in the middle when there is none); both are parsed, checked and
/// translated, and a task that comes out is searched for a few milliseconds. What the
/// canonical writer prints of the domain and problem must parse and print the same again.
pub fn pddl_translate(data: &[u8]) {
    let Ok(text) = std::str::from_utf8(data) else {
        return;
    };
    let (domain_text, problem_text) = match text.split_once('\0') {
        Some(pair) => pair,
        None => {
            let mut mid = text.len() / 2;
            while !text.is_char_boundary(mid) {
                mid -= 1;
            }
            text.split_at(mid)
        }
    };
    let domain = pddl::parse_domain(domain_text);
    let problem = pddl::parse_problem(problem_text);
    let (Ok(domain), Ok(problem)) = (domain, problem) else {
        trace("not parsed");
        return;
    };
    // The canonical writer's text must parse, and write the same text again.
    let written = domain.to_string();
    match pddl::parse_domain(&written) {
        Ok(again) => assert_eq!(
            again.to_string(),
            written,
            "domain: write(parse(write(d))) != write(d)"
        ),
        Err(e) => panic!("a written domain does not parse: {e}\n{written}"),
    }
    let written = problem.to_string();
    match pddl::parse_problem(&written) {
        Ok(again) => assert_eq!(
            again.to_string(),
            written,
            "problem: write(parse(write(p))) != write(p)"
        ),
        Err(e) => panic!("a written problem does not parse: {e}\n{written}"),
    }
    if pddl::check_problem(&domain, &problem).is_err() {
        trace("parsed, not checked");
        return;
    }
    let translation = translate::translate(&domain, &problem);
    if let Ok(translate::Translation::Unsolvable { .. }) = translation {
        trace("translated: unsolvable");
    }
    if translation.is_err() {
        trace("checked, translation refused");
    }
    if let Ok(translate::Translation::Task(translated)) = translation {
        assert!(
            translated.task.validate().is_ok(),
            "translation gave an invalid task"
        );
        search_a_little(&translated.task);
    }
}

/// The search-string parser (`astar(lmcut())`) on any UTF-8 text.
pub fn search_string(data: &[u8]) {
    if let Ok(text) = std::str::from_utf8(data) {
        let _ = search::parse_search(text);
    }
}

/// The `output.sas` reader on any UTF-8 text; a task that comes out must validate (the
/// reader promises it), write and read back unchanged, and is searched a little.
pub fn sas_file(data: &[u8]) {
    let Ok(text) = std::str::from_utf8(data) else {
        return;
    };
    let Ok(task) = task::sas_file::read(text) else {
        trace("not read");
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
    search_a_little(&task);
}

/// The recording reader over any bytes: the header, then every frame.
pub fn recording(data: &[u8]) {
    let Ok(mut reader) = recording::Reader::new(data) else {
        return;
    };
    let mut frame = recording::Frame::default();
    while let Ok(true) = reader.read_frame(&mut frame) {}
}

/// The ARFF reader (Weka's grammar: commas and/or whitespace, quotes with escapes,
/// comments, sparse rows) and content detection; a table that reads is turned into a
/// dataset, and a hand-state table into frames, their activities by the default label
/// map, a dataset over them, and segments with the hand's own facts as states; and the
/// same read a row at a time (`ArffReader`, `HandTable`).
pub fn arff(data: &[u8]) {
    let Ok(text) = std::str::from_utf8(data) else {
        return;
    };
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
}

/// The operator library's JSON reader; a library that reads must write and read back
/// as an equal library, and write the same text again.
pub fn library(data: &[u8]) {
    let Ok(text) = std::str::from_utf8(data) else {
        return;
    };
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
}

/// The Unity log reader and the import core: any bytes either import into a recording
/// that reads back, or give an input error; never a panic.
pub fn unity_log(data: &[u8]) {
    let mapping = import::Mapping::default_for(import::Format::Unity);
    let mut source = import::unity::UnityLog::new(|| Ok(data));
    if let Ok((out, _, _)) = import::import(&mut source, &mapping, "fuzz", Vec::new()) {
        // What the import writes, the native reader reads.
        if let Err(e) = recording::Recording::read(&out[..]) {
            panic!("an imported Unity log does not read back: {e}");
        }
    }
}

/// The mapping file reader: any text is a mapping or an error with a line; a mapping
/// read prints as TOML that reads back to the same mapping.
pub fn import_mapping(data: &[u8]) {
    let Ok(text) = std::str::from_utf8(data) else {
        return;
    };
    let Ok(mapping) = import::Mapping::from_toml(text, import::Format::Unity) else {
        return;
    };
    let printed = mapping.to_toml();
    let again = import::Mapping::from_toml(&printed, import::Format::Ros1);
    assert_eq!(again.as_ref(), Ok(&mapping), "{printed}");
    let _ = mapping.resolve(text);
}

/// The ROS bag readers (ROS 1 records and chunks, MCAP through the `mcap` crate): a bag
/// in memory is listed and every message decoded; every field path of the first
/// messages is looked up. Seeds: the committed fixtures, one file per container and
/// compression.
pub fn bag(data: &[u8]) {
    let Ok(bag) = bags::from_bytes(std::path::Path::new("fuzz.bag"), data.to_vec()) else {
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
}

/// The definition parser and the message decoder: a definition text, then a NUL byte,
/// then a message, decoded both as ROS 1 and as CDR.
pub fn bag_message(data: &[u8]) {
    let Some(split) = data.iter().position(|&b| b == 0) else {
        return;
    };
    let Ok(definition) = std::str::from_utf8(&data[..split]) else {
        return;
    };
    let Ok(schema) = bags::Schema::parse("fuzz/Message", definition) else {
        return;
    };
    let message = &data[split + 1..];
    for encoding in [bags::Encoding::Ros1, bags::Encoding::Cdr] {
        if let Ok(value) = bags::decode(&schema, encoding, message) {
            let _ = value.lookup("a[].b");
        }
    }
}

/// The ROS import (ROS 1 bags and MCAP files): a bag in memory is checked against the
/// default mapping of its format and imported (tf composed to its root at every tick,
/// poses to observations); what the import writes, the native reader reads.
pub fn bag_import(data: &[u8]) {
    let Ok(bag) = bags::from_bytes(std::path::Path::new("fuzz.bag"), data.to_vec()) else {
        return;
    };
    let format = match bag.format() {
        bags::Format::Ros1 => import::Format::Ros1,
        bags::Format::Mcap | bags::Format::Ros2Folder => import::Format::Ros2,
    };
    let mapping = import::Mapping::default_for(format);
    let Ok(mut source) = import::ros::RosBag::from_bag(bag, &mapping) else {
        return;
    };
    if let Ok((out, _, _)) = import::import(&mut source, &mapping, "fuzz", Vec::new()) {
        if let Err(e) = recording::Recording::read(&out[..]) {
            panic!("an imported bag does not read back: {e}");
        }
    }
}
