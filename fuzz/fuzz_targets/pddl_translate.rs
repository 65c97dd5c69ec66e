//! The PDDL front end and translator: the input is a domain and a problem, split at the
//! first NUL byte (or in the middle when there is none); both are parsed, checked and
//! translated, and a task that comes out is searched for a few milliseconds. What the
//! canonical writer prints of the domain and problem must parse and print the same again.
#![no_main]

use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
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
        demoplan_fuzz::trace("not parsed");
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
        demoplan_fuzz::trace("parsed, not checked");
        return;
    }
    let translation = translate::translate(&domain, &problem);
    if let Ok(translate::Translation::Unsolvable { .. }) = translation {
        demoplan_fuzz::trace("translated: unsolvable");
    }
    if translation.is_err() {
        demoplan_fuzz::trace("checked, translation refused");
    }
    if let Ok(translate::Translation::Task(translated)) = translation {
        assert!(
            translated.task.validate().is_ok(),
            "translation gave an invalid task"
        );
        demoplan_fuzz::search_a_little(&translated.task);
    }
});
