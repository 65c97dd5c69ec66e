//! The findings text is written from results alone: a committed results file (a
//! reduced `reproduce` grid: priorities 1 and 3, goals 1 to 3, 5 s limit) gives the
//! same text on every machine.

#![allow(clippy::unwrap_used, clippy::expect_used)] // tests fail loudly by design

use std::path::Path;

use experiment::{findings, parse_records, ratio, LevelChoice, Planner, RunRecord};
use report::Measure;

fn fixture() -> Vec<RunRecord> {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/fixtures/reduced-reproduce.jsonl");
    let text = std::fs::read_to_string(&path).unwrap();
    parse_records(&text, &path).unwrap()
}

#[test]
fn findings_of_a_fixed_results_file() {
    let notes = findings(&fixture());
    insta::assert_snapshot!(notes.join("\n\n"));
}

#[test]
fn findings_state_the_ratios_the_records_give() {
    let records = fixture();
    let notes = findings(&records).join("\n");
    let pick = |planner: Planner, level: LevelChoice| {
        records
            .iter()
            .find(|r| r.planner == planner && r.level == level && r.conditions.height == 4)
            .unwrap()
    };
    for planner in Planner::DEMOPLAN {
        let full = pick(planner, LevelChoice::Prio(3));
        for (den, name) in [
            (pick(planner, LevelChoice::Prio(1)), "ratio_p1"),
            (pick(planner, LevelChoice::Algorithm1), "ratio_alg1"),
        ] {
            for (measure, words) in [
                (Measure::Search, "search time"),
                (Measure::Total, "total time"),
            ] {
                let r = ratio(full, den, measure).map_or("none".to_string(), |r| r.to_string());
                let text = format!("{r} by {words}");
                assert!(
                    notes.contains(&format!("{name} = {text}")) || notes.contains(&text),
                    "{name} {text}\n{notes}"
                );
            }
        }
    }
    // The iPDB run of the largest domain hit the limit in its hill climbing: by total
    // time its ratios are lower bounds, by search time there is none (the search never
    // began).
    assert!(pick(Planner::Ipdb, LevelChoice::Prio(3)).hit_limit());
    assert!(
        notes.contains("ratio_p1 = none by search time, >= 3.42x by total time"),
        "{notes}"
    );
}

#[test]
fn no_records_no_findings() {
    assert!(findings(&[]).is_empty());
}
