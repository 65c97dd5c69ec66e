//! How learning fares on two-handed demonstrations: an evaluation for tuning the
//! learning of operators from recordings that look like real ones (issue 39).
//!
//! For each seed it simulates a study in the simulator's `two-handed` style (both hands at
//! once, recordings cut mid-motion, poses and grips only: see `docs/recording-format.md`),
//! learns its library through the whole pipeline (frames, grounding, segmentation,
//! activities, operators; `learn::add_frames`), and prints
//!
//! - the number of activities and of distinct operators, and operators per type;
//! - the agreement of the (mended) activity classes with the simulator's ground truth:
//!   for each activity, the class of the truth activity of its hand that overlaps it
//!   longest (`learn::truth_activities`: the noise-free hand facts through the same
//!   segmenter and grouping), and the confusions, class -> truth; activities mended and
//!   dropped (`learn::mend`);
//! - the number of learned Idle operators whose add effects hold `inHand`, `onTop` or
//!   `inTouch` (an Idle that grasps or stacks: a change some other activity caused or
//!   should have been classified as).
//!
//! ```text
//! cargo run --release -p learn --example two_handed -- [--seeds 1-5] [--style two-handed]
//!     [--participants 3] [--per-participant 4] [--activities settled|runs]
//! ```

use std::collections::BTreeMap;

use grounding::{GroundingConfig, Predicate};
use learn::{Grouping, Library};
use segment::{Activity, ActivityTree};
use simulate::{SimParams, Style};

struct Options {
    seeds: Vec<u64>,
    style: Style,
    participants: u32,
    per_participant: u32,
    grouping: Grouping,
}

fn parse() -> Result<Options, String> {
    let mut o = Options {
        seeds: (1..=5).collect(),
        style: Style::TwoHanded,
        participants: 3,
        per_participant: 4,
        grouping: Grouping::Settled,
    };
    let mut args = std::env::args().skip(1);
    while let Some(flag) = args.next() {
        let value = args.next().ok_or(format!("{flag}: give a value"))?;
        let number = |v: &str| v.parse::<u32>().map_err(|e| format!("{flag} {v}: {e}"));
        match flag.as_str() {
            "--seeds" => o.seeds = seeds(&value)?,
            "--style" => {
                o.style = Style::from_name(&value)
                    .ok_or(format!("--style {value}: none of {}", Style::names()))?
            }
            "--participants" => o.participants = number(&value)?,
            "--per-participant" => o.per_participant = number(&value)?,
            "--activities" => {
                o.grouping =
                    Grouping::from_name(&value).ok_or(format!("--activities {value}: unknown"))?
            }
            _ => return Err(format!("unknown option {flag}")),
        }
    }
    Ok(o)
}

/// `1-5` or `1,4,9`.
fn seeds(text: &str) -> Result<Vec<u64>, String> {
    let mut out = Vec::new();
    for part in text.split(',') {
        let n = |s: &str| {
            s.trim()
                .parse::<u64>()
                .map_err(|e| format!("--seeds {s}: {e}"))
        };
        match part.split_once('-') {
            Some((a, b)) => out.extend(n(a)?..=n(b)?),
            None => out.push(n(part)?),
        }
    }
    Ok(out)
}

/// What one seed's study gave.
#[derive(Default)]
struct Measured {
    activities: usize,
    agree: usize,
    /// (class, truth's majority) -> activities.
    confusion: BTreeMap<(Activity, Activity), usize>,
    operators: usize,
    per_type: BTreeMap<Activity, usize>,
    idle_changes: usize,
    mended: usize,
    dropped: usize,
}

fn measure(o: &Options, seed: u64) -> Result<Measured, String> {
    let params: SimParams = o.style.params();
    let study = simulate::study(&params, seed, o.participants, o.per_participant)
        .map_err(|e| e.to_string())?;
    let config = GroundingConfig::default();
    let tree = ActivityTree::table_one();
    let mut library = Library::with_grouping(learn::DEFAULT_LAMBDA, o.grouping);
    let mut m = Measured::default();
    for demo in &study.demonstrations {
        let (frames, truth): (Vec<_>, Vec<_>) = demo.frames().unzip();
        let segmented = learn::segment_frames(demo.header(), frames.clone(), &config, &tree);
        let grouped = learn::activities(&segmented.segments, o.grouping);
        let (mended, counts) = learn::mend(&grouped, o.grouping, &segmented.space);
        m.dropped += counts.dropped_total() as usize;
        m.mended += counts.mended_total() as usize;
        let truth_frames = learn::truth_hand_facts(&truth);
        let hands = segmented.space.hands().to_vec();
        let truth_activities =
            learn::truth_activities(&hands, truth_frames, &tree, config.min_duration, o.grouping);
        let classes = learn::truth_classes(&mended, &truth_activities);
        for (a, truth) in mended.iter().zip(classes) {
            let truth = truth.unwrap_or(Activity::Idle);
            m.activities += 1;
            m.agree += usize::from(truth == a.activity);
            *m.confusion.entry((a.activity, truth)).or_default() += 1;
        }
        learn::add_frames(&mut library, demo.header(), frames, &config, &tree, "");
    }
    for entry in library.entries() {
        let op = &entry.operator;
        m.operators += 1;
        *m.per_type.entry(op.activity).or_default() += 1;
        let changes = op.add.iter().any(|f| {
            matches!(
                f.predicate,
                Predicate::InHand | Predicate::OnTop | Predicate::InTouch
            )
        });
        if op.activity == Activity::Idle && changes {
            m.idle_changes += 1;
        }
    }
    Ok(m)
}

fn main() {
    let o = match parse() {
        Ok(o) => o,
        Err(e) => {
            eprintln!("two_handed: {e}");
            std::process::exit(2);
        }
    };
    println!(
        "style {}, {} x {} demonstrations, activities {}",
        o.style,
        o.participants,
        o.per_participant,
        o.grouping.name()
    );
    let types = Activity::OPERATOR_ORDER;
    let type_names: Vec<String> = types.iter().map(|t| format!("{t:?}")).collect();
    println!(
        "{:>5} {:>10} {:>7} {:>7} {:>9} {:>9}  {}  {:>11}",
        "seed",
        "activities",
        "mended",
        "dropped",
        "agree",
        "operators",
        type_names
            .iter()
            .map(|n| format!("{n:>6}"))
            .collect::<String>(),
        "idle+change"
    );
    let mut total = Measured::default();
    for &seed in &o.seeds {
        let m = match measure(&o, seed) {
            Ok(m) => m,
            Err(e) => {
                eprintln!("seed {seed}: {e}");
                std::process::exit(1);
            }
        };
        println!(
            "{seed:>5} {:>10} {:>7} {:>7} {:>8.1}% {:>9}  {}  {:>11}",
            m.activities,
            m.mended,
            m.dropped,
            100.0 * m.agree as f64 / m.activities.max(1) as f64,
            m.operators,
            types
                .iter()
                .map(|t| format!("{:>6}", m.per_type.get(t).copied().unwrap_or(0)))
                .collect::<String>(),
            m.idle_changes
        );
        total.activities += m.activities;
        total.mended += m.mended;
        total.dropped += m.dropped;
        total.agree += m.agree;
        total.operators += m.operators;
        total.idle_changes += m.idle_changes;
        for (k, v) in m.confusion {
            *total.confusion.entry(k).or_default() += v;
        }
        for (k, v) in m.per_type {
            *total.per_type.entry(k).or_default() += v;
        }
    }
    let n = o.seeds.len().max(1) as f64;
    println!(
        "{:>5} {:>10.1} {:>7.1} {:>7.1} {:>8.1}% {:>9.1}  {}  {:>11.1}",
        "mean",
        total.activities as f64 / n,
        total.mended as f64 / n,
        total.dropped as f64 / n,
        100.0 * total.agree as f64 / total.activities.max(1) as f64,
        total.operators as f64 / n,
        types
            .iter()
            .map(|t| format!(
                "{:>6.1}",
                total.per_type.get(t).copied().unwrap_or(0) as f64 / n
            ))
            .collect::<String>(),
        total.idle_changes as f64 / n
    );
    println!("class -> truth (activities over all seeds):");
    for ((class, truth), count) in &total.confusion {
        let mark = if class == truth { "" } else { "  (disagree)" };
        println!("  {class:?} -> {truth:?}: {count}{mark}");
    }
}
