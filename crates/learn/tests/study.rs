//! Learning from the simulator's demonstrations: learning in any order and incrementally
//! gives the same library, a recording is never counted twice, the file format
//! round-trips, and the library of every simulated study (seeds 1 to 20) is ranked and
//! levelled as Algorithm 1 needs.

#![allow(clippy::unwrap_used, clippy::expect_used)]

use grounding::GroundingConfig;
use learn::{levels, DomainOptions, Grouping, Library, RecordingInfo};
use segment::Activity;
use segment::ActivityTree;

/// A simulated demonstration ready to learn from: what `demoplan learn` gets from a
/// recording file (its hash is that of the JSON Lines text, as for files).
struct Learnable {
    info: RecordingInfo,
    header: recording::Header,
    segmented: learn::Segmented,
}

fn learnable(demo: &simulate::Demonstration) -> Learnable {
    let header = demo.header().clone();
    let frames: Vec<recording::Frame> = demo.frames().map(|(f, _)| f).collect();
    let hash = learn::recording_hash(&header, &frames);
    let segmented = learn::segment_frames(
        &header,
        frames,
        &GroundingConfig::default(),
        &ActivityTree::table_one(),
    );
    Learnable {
        info: RecordingInfo {
            hash,
            id: header.id.clone(),
            participant: header.participant.clone(),
            source: String::new(),
            frames: segmented.frames,
            segments: 0,
            ..Default::default()
        },
        header,
        segmented,
    }
}

fn add(library: &mut Library, l: &Learnable) -> learn::Added {
    library.add_recording(
        l.info.clone(),
        &l.header,
        &l.segmented.space,
        &l.segmented.segments,
    )
}

fn default_recordings() -> Vec<Learnable> {
    simulate::default_study()
        .demonstrations
        .iter()
        .map(learnable)
        .collect()
}

#[test]
fn learning_order_and_batches_do_not_change_the_library() {
    let recordings = default_recordings();
    let mut batch = Library::default();
    for r in &recordings {
        add(&mut batch, r);
    }
    // Reversed and interleaved orders.
    let mut reversed = Library::default();
    for r in recordings.iter().rev() {
        add(&mut reversed, r);
    }
    let mut interleaved = Library::default();
    for r in recordings
        .iter()
        .step_by(2)
        .chain(recordings.iter().skip(1).step_by(2))
    {
        add(&mut interleaved, r);
    }
    assert_eq!(batch.to_json(), reversed.to_json());
    assert_eq!(batch.to_json(), interleaved.to_json());
    // Incremental through the file: learn half, write, read, learn the rest.
    let mut first = Library::default();
    for r in &recordings[..5] {
        add(&mut first, r);
    }
    let mut second = Library::from_json(&first.to_json()).unwrap();
    for r in &recordings[5..] {
        add(&mut second, r);
    }
    assert_eq!(batch.to_json(), second.to_json());
    // Merging two libraries learned apart.
    let mut a = Library::default();
    let mut b = Library::default();
    for (i, r) in recordings.iter().enumerate() {
        add(if i % 3 == 0 { &mut a } else { &mut b }, r);
    }
    a.merge(&b).unwrap();
    assert_eq!(batch.to_json(), a.to_json());
    // A library that groups segments otherwise counts other things: no merging.
    let mut runs = Library::with_grouping(learn::DEFAULT_LAMBDA, Grouping::Runs);
    add(&mut runs, &recordings[0]);
    let error = a.merge(&runs).unwrap_err();
    assert!(error.to_string().contains("`runs` activities"), "{error}");
    assert_eq!(batch.to_json(), a.to_json());
}

#[test]
fn a_recording_is_never_counted_twice() {
    let recordings = default_recordings();
    let mut library = Library::default();
    let added = add(&mut library, &recordings[0]);
    assert!(matches!(added, learn::Added::Counted { segments, .. } if segments > 0));
    let before = library.to_json();
    assert_eq!(
        add(&mut library, &recordings[0]),
        learn::Added::AlreadyCounted
    );
    assert_eq!(library.to_json(), before);
    // Also through a file, and through merging a library that has it.
    let mut read = Library::from_json(&before).unwrap();
    assert_eq!(add(&mut read, &recordings[0]), learn::Added::AlreadyCounted);
    read.merge(&library).unwrap();
    assert_eq!(read.to_json(), before);
}

#[test]
fn the_file_round_trips_and_counts_add_up() {
    let recordings = default_recordings();
    let mut library = Library::default();
    for r in &recordings {
        add(&mut library, r);
    }
    let text = library.to_json();
    let read = Library::from_json(&text).unwrap();
    assert_eq!(read, library);
    assert_eq!(read.to_json(), text);
    // Every activity (once mended) is one operator occurrence; type counts are sums of
    // counts.
    let activities: u64 = recordings
        .iter()
        .map(|r| {
            let grouped = learn::activities(&r.segmented.segments, library.grouping);
            learn::mend(&grouped, library.grouping, &r.segmented.space)
                .0
                .len() as u64
        })
        .sum();
    assert_eq!(library.segments(), activities);
    let by_type: u64 = Activity::OPERATOR_ORDER
        .iter()
        .map(|&a| library.type_count(a))
        .sum();
    assert_eq!(by_type, activities);
    // Provenance: one entry per counted activity.
    for e in library.entries() {
        assert_eq!(e.provenance.len() as u64, e.count);
    }
}

/// The library of a simulated study of the paper's shape (3 participants x 4).
fn study_library(seed: u64) -> Library {
    let study = simulate::study(&simulate::SimParams::default(), seed, 3, 4).unwrap();
    let mut library = Library::default();
    for demo in &study.demonstrations {
        add(&mut library, &learnable(demo));
    }
    library
}

/// Issue 39: the mended rules of Table 1 read as effects (docs/operators.md) hold for
/// every operator: no Idle adds `inHand`, `onTop` or `inTouch`, no Reach adds `inHand`,
/// no Stack ends holding the cube it held.
fn assert_operators_mean_their_class(library: &Library, what: &str) {
    use grounding::Predicate::{InHand, InTouch, OnTop};
    for e in library.entries() {
        let op = &e.operator;
        let text = op.canonical_text();
        let adds = |p| op.add.iter().any(|f| f.predicate == p);
        match op.activity {
            Activity::Idle => {
                assert!(
                    !adds(InHand) && !adds(OnTop) && !adds(InTouch),
                    "{what}: {text}"
                );
            }
            Activity::Reach => assert!(!adds(InHand), "{what}: {text}"),
            Activity::Stack => {
                let kept = (op.pre_positive.iter())
                    .filter(|f| f.predicate == InHand)
                    .any(|f| !op.delete.contains(f));
                assert!(!kept, "{what}: {text}");
            }
            _ => {}
        }
    }
}

/// What holds of the library of every study, whatever its size (the sizes over 100 seeds
/// are the calibration script's: `cargo run --release -p learn --example calibrate`):
/// every type of Table 1 is demonstrated, the levels of Algorithm 1 are nested and grow,
/// priority 1 holds the most frequent operators of each type (ties included), the last
/// level holds every operator that changes something, and within a type an operator seen
/// more often never costs more.
#[test]
fn every_studys_library_has_nested_levels_ranked_by_count() {
    for seed in 1..=20 {
        let library = study_library(seed);
        assert_operators_mean_their_class(&library, &format!("seed {seed}"));
        let sizes: Vec<usize> = levels(&library, DomainOptions::default())
            .iter()
            .map(|l| l.operators.len())
            .collect();
        let all_levels = levels(&library, DomainOptions::default());
        for a in Activity::OPERATOR_ORDER {
            let ranked = library.ranked_type(a);
            assert!(!ranked.is_empty(), "seed {seed}: no {a} operator");
            assert_eq!(
                ranked.iter().map(|r| r.count()).sum::<u64>(),
                library.type_count(a),
                "seed {seed}: {a}"
            );
            for w in ranked.windows(2) {
                assert!(w[0].count() >= w[1].count(), "seed {seed}: {a} not ranked");
                assert!(w[0].cost <= w[1].cost, "seed {seed}: {a} costs");
            }
            // Priority 1: every operator with effects of the highest count of its type.
            let with_effects: Vec<_> = ranked
                .iter()
                .filter(|r| r.operator().has_effects())
                .collect();
            if let Some(top) = with_effects.first() {
                let mut first: Vec<String> = all_levels[0]
                    .operators
                    .iter()
                    .filter(|r| r.entry.operator.activity == a)
                    .map(|r| r.name())
                    .collect();
                let mut expected: Vec<String> = with_effects
                    .iter()
                    .filter(|r| r.count() == top.count())
                    .map(|r| r.name())
                    .collect();
                first.sort();
                expected.sort();
                assert_eq!(first, expected, "seed {seed}: priority 1 of {a}");
            }
        }
        assert!(
            sizes.windows(2).all(|w| w[0] < w[1]),
            "seed {seed}: levels {sizes:?}"
        );
        for w in all_levels.windows(2) {
            for op in &w[0].operators {
                assert!(
                    w[1].operators.iter().any(|o| o.name() == op.name()),
                    "seed {seed}: {} left level {}",
                    op.name(),
                    w[1].prio
                );
            }
        }
        let changing = library
            .entries()
            .filter(|e| e.operator.has_effects())
            .count();
        assert_eq!(sizes.last().copied(), Some(changing), "seed {seed}");
    }
}

#[test]
fn settling_idles_end_the_activity_before_them() {
    let recordings = default_recordings();
    let mut settled = 0;
    let mut runs = 0;
    for r in &recordings {
        let by_runs = learn::activities(&r.segmented.segments, Grouping::Runs);
        let by_settling = learn::activities(&r.segmented.segments, Grouping::Settled);
        // Every settled activity is a run, or a run and the Idle run after it: it ends
        // where some run ends and never starts with an Idle after another activity.
        for a in &by_settling {
            assert!(by_runs.iter().any(|b| b.hand == a.hand && b.end == a.end));
            assert!(by_runs
                .iter()
                .any(|b| b.hand == a.hand && b.start == a.start));
        }
        for w in by_settling.windows(2) {
            if w[0].hand == w[1].hand {
                assert!(
                    w[1].activity != segment::Activity::Idle,
                    "an Idle after {:?} at {} was not taken in",
                    w[0].activity,
                    w[1].start
                );
            }
        }
        settled += by_settling.len();
        runs += by_runs.len();
    }
    assert!(settled < runs, "{settled} settled activities, {runs} runs");
}

#[test]
fn a_library_records_its_grouping_and_old_files_counted_runs() {
    let recordings = default_recordings();
    let mut library = Library::with_grouping(learn::DEFAULT_LAMBDA, Grouping::Runs);
    add(&mut library, &recordings[0]);
    let text = library.to_json();
    assert!(text.contains("\"activities\": \"runs\""), "{text}");
    assert_eq!(Library::from_json(&text).unwrap().grouping, Grouping::Runs);
    // Written before the field existed: runs.
    let old = text.replace("  \"activities\": \"runs\",\n", "");
    assert_ne!(old, text);
    assert_eq!(Library::from_json(&old).unwrap(), library);
    let unknown = text.replace("\"activities\": \"runs\"", "\"activities\": \"phases\"");
    let error = Library::from_json(&unknown).unwrap_err();
    assert!(error.line > 0, "{error}");
    assert!(
        error
            .to_string()
            .contains("unknown activity grouping \"phases\""),
        "{error}"
    );
}

/// Issue 23: counts read from a library are summed with overflow checks. Two
/// operators whose counts add up past `u64::MAX` are an error naming the second one's
/// line, not a wrapped (or, in a debug build, panicking) sum; counts that fit read.
#[test]
fn counts_that_overflow_when_summed_are_an_error() {
    let mut library = Library::default();
    add(&mut library, &default_recordings()[0]);
    let text = library.to_json();
    let mut value: serde_json::Value = serde_json::from_str(&text).unwrap();
    let operators = value["operators"].as_array_mut().unwrap();
    assert!(operators.len() >= 2);
    // The other operators keep their counts; the first takes what is left up to
    // u64::MAX - 1 and the second 1, so the counts add up to exactly u64::MAX.
    let rest: u64 = operators[2..]
        .iter()
        .map(|o| o["count"].as_u64().unwrap())
        .sum();
    operators[0]["count"] = serde_json::json!(u64::MAX - 1 - rest);
    operators[1]["count"] = serde_json::json!(1);
    let fits = serde_json::to_string_pretty(&value).unwrap();
    let read = Library::from_json(&fits).unwrap();
    assert_eq!(read.segments(), u64::MAX);
    // One more for the second, moved to the end: the running sum is u64::MAX - 1 before
    // it and passes u64::MAX at it, so the error names its line.
    value["operators"][1]["count"] = serde_json::json!(2);
    let operators = value["operators"].as_array_mut().unwrap();
    let second = operators.remove(1);
    operators.push(second);
    let over = serde_json::to_string_pretty(&value).unwrap();
    let e = Library::from_json(&over).unwrap_err();
    assert_eq!(e.field, "count");
    assert!(
        e.message
            .contains("counts add up to more than 18446744073709551615"),
        "{e:?}"
    );
    let last = value["operators"].as_array().unwrap().len() - 1;
    let id = value["operators"][last]["id"].as_str().unwrap();
    let line = over.lines().position(|l| l.contains(id)).unwrap() + 1;
    assert_eq!(e.line, line);
}
