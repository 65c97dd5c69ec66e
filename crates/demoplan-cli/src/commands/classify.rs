//! `demoplan classify`: print the activity tree (the paper's Table 1, or `--tree`), learn
//! one with C4.5 from labelled frames (`--learn FILE... -o TREE`), or classify labelled
//! frames and compare with their labels.
//!
//! Labelled frames are ARFF hand-state tables with an activity attribute, or simulated
//! recordings with their ground truth beside them (`NAME.truth.jsonl`). An ARFF file that
//! is not a hand-state table (any nominal data set) can be learned from on its own, with
//! `--class` naming the class (default: the last attribute).

use std::fmt::Write as _;
use std::path::Path;

use grounding::HandFacts;
use segment::{Activity, ActivityTree, Feature, LabelMap, UnknownLabels, C45};

use crate::cli::ClassifyArgs;
use crate::commands::demo_input;
use crate::diagnostic::Failure;
use crate::exit::ExitCode;
use crate::output::{self, write_atomically};

pub fn run(args: ClassifyArgs) -> Result<ExitCode, Failure> {
    if args.learn {
        return learn(&args);
    }
    if args.out.is_some() {
        return Err(Failure::plain(
            ExitCode::USAGE,
            "-o/--out writes a learned tree: use it with --learn",
        ));
    }
    if args.files.is_empty() {
        let tree = match &args.tree {
            Some(path) => demo_input::decision_tree(path)?,
            None => ActivityTree::table_one().tree().clone(),
        };
        print!("{tree}");
        return Ok(ExitCode::SUCCESS);
    }
    let tree = demo_input::activity_tree(args.tree.as_deref())?;
    let config = demo_input::config(args.config.as_deref())?;
    let labels = demo_input::label_map(args.mapping.as_deref())?;
    // Each file is printed as soon as it is classified: its frames are tallied as they
    // are read, not kept.
    let mut out = std::io::stdout().lock();
    for path in &args.files {
        let mut agreement = Agreement::default();
        let l = labelled(path, &config, &labels, &mut |hand, label| {
            agreement.add(label, tree.classify(&hand));
        })?;
        let mut text = String::new();
        report(&mut text, path, &l, &agreement);
        output::print(&mut out, &text)?;
    }
    Ok(ExitCode::SUCCESS)
}

/// What a file's labelled frames are: the labels met (`each` gives indices into them),
/// whether the hands' states say `handOpen`, and the frames left out.
struct Labelled {
    labels: Vec<String>,
    hand_state: bool,
    /// Frames left out: their labels are not in the label map.
    left_out: usize,
}

/// The index of `name` in `labels`, added if it is new.
fn label_index(labels: &mut Vec<String>, name: &str) -> usize {
    match labels.iter().position(|l| l == name) {
        Some(k) => k,
        None => {
            labels.push(name.to_string());
            labels.len() - 1
        }
    }
}

/// The labelled frames of a file, each given to `each` as it is read (with its label's
/// index). An ARFF table is read a row at a time and its labels go through the label
/// map; those it does not know are left out and named on standard error, once per file.
fn labelled(
    path: &Path,
    config: &grounding::GroundingConfig,
    map: &LabelMap,
    each: &mut dyn FnMut(HandFacts, usize),
) -> Result<Labelled, Failure> {
    if demo_input::is_arff(path) {
        let table = demo_input::hand_table(path)?;
        let mut unknown = UnknownLabels::default();
        let mut labels: Vec<String> = Vec::new();
        demo_input::arff_frames(path, &table, |f| {
            if let Some(a) = unknown.activity(map, f) {
                each(f.hand, label_index(&mut labels, a.name()));
            }
        })?;
        if let Some(w) = unknown.warning() {
            demo_input::warn(path, &[w]);
        }
        return Ok(Labelled {
            labels,
            hand_state: table.has_hand_state(),
            left_out: unknown.left_out(),
        });
    }
    let tree = ActivityTree::table_one();
    let mut grounded: Vec<(u64, Vec<HandFacts>)> = Vec::new();
    let mut observer = HandsGrounded(&mut grounded);
    let segmented = demo_input::segment_recording(path, None, config, &tree, &mut observer)?;
    let truth = demo_input::read_truth(path, &segmented.header)?;
    let mut labels: Vec<String> = Vec::new();
    for (index, hands) in grounded {
        let Some(names) = truth.get(index as usize) else {
            continue;
        };
        for (hand, name) in hands.iter().zip(names) {
            each(*hand, label_index(&mut labels, name));
        }
    }
    Ok(Labelled {
        labels,
        hand_state: true,
        left_out: 0,
    })
}

/// Keeps each grounded frame's hand facts.
struct HandsGrounded<'a>(&'a mut Vec<(u64, Vec<HandFacts>)>);

impl learn::Observer for HandsGrounded<'_> {
    fn grounded(&mut self, g: &grounding::GroundedFrame<'_>) {
        self.0.push((g.index, g.hands.to_vec()));
    }
}

/// Per label (index), how many frames the tree classified as each activity.
#[derive(Debug, Default)]
struct Agreement {
    counts: Vec<[u64; Activity::ALL.len()]>,
}

impl Agreement {
    fn add(&mut self, label: usize, predicted: Activity) {
        if self.counts.len() <= label {
            self.counts.resize(label + 1, [0; Activity::ALL.len()]);
        }
        self.counts[label][predicted.index()] += 1;
    }

    fn count(&self, label: usize, predicted: Activity) -> u64 {
        self.counts.get(label).map_or(0, |c| c[predicted.index()])
    }
}

fn report(out: &mut String, path: &Path, cases: &Labelled, agreement: &Agreement) {
    let labels = &cases.labels;
    let frames: u64 = agreement.counts.iter().flatten().sum();
    let agree: u64 = labels
        .iter()
        .enumerate()
        .map(|(k, l)| {
            Activity::ALL
                .iter()
                .filter(|a| a.name() == l)
                .map(|&a| agreement.count(k, a))
                .sum::<u64>()
        })
        .sum();
    let left_out = match cases.left_out {
        0 => String::new(),
        n => format!("; {n} left out, their labels not in the label map"),
    };
    let _ = writeln!(
        out,
        "{}: {} labelled hand frames, {} agree with the tree ({:.2}%){left_out}",
        path.display(),
        frames,
        agree,
        100.0 * agree as f64 / frames.max(1) as f64
    );
    let _ = write!(out, "{:<10}", "label");
    for a in Activity::ALL {
        let _ = write!(out, " {:>7}", a.name());
    }
    out.push('\n');
    for (k, label) in labels.iter().enumerate() {
        let _ = write!(out, "{label:<10}");
        for a in Activity::ALL {
            let _ = write!(out, " {:>7}", agreement.count(k, a));
        }
        out.push('\n');
    }
}

fn learn(args: &ClassifyArgs) -> Result<ExitCode, Failure> {
    let learner = C45::default();
    // A nominal data set that is not a hand-state table: learn it as it is.
    if let [path] = args.files.as_slice() {
        if demo_input::is_arff(path) {
            let hand_state = segment::is_hand_state(demo_input::arff_reader(path)?.attributes());
            if !hand_state {
                let table = demo_input::arff_table(path)?;
                let (data, warnings) = table
                    .dataset(args.class.as_deref())
                    .map_err(|e| demo_input::arff_failure(path, &e))?;
                demo_input::warn(path, &warnings);
                let tree = learner.learn(&data);
                let right = data
                    .cases
                    .iter()
                    .filter(|c| tree.classify(&c.values) == c.class)
                    .count();
                return finish(args, &tree, right, data.cases.len());
            }
        }
    }
    if args.class.is_some() {
        return Err(Failure::plain(
            ExitCode::USAGE,
            "--class is for an ARFF data set that is not a hand-state table; hand-state frames are learned by their activity",
        ));
    }
    let config = demo_input::config(args.config.as_deref())?;
    let map = demo_input::label_map(args.mapping.as_deref())?;
    let mut labels: Vec<String> = Vec::new();
    let mut cases: Vec<(HandFacts, usize)> = Vec::new();
    let mut hand_state = true;
    // C4.5 needs every case at once: only these (a hand state and a label index each)
    // are kept, not the files' rows.
    for path in &args.files {
        let mut file_cases = Vec::new();
        let l = labelled(path, &config, &map, &mut |hand, k| {
            file_cases.push((hand, k))
        })?;
        hand_state &= l.hand_state;
        for (hand, k) in file_cases {
            cases.push((hand, label_index(&mut labels, &l.labels[k])));
        }
    }
    if cases.is_empty() {
        return Err(Failure::plain(
            ExitCode::INPUT_ERROR,
            "no labelled frames to learn from",
        ));
    }
    let mut features = vec![Feature::HandMove, Feature::ActedOn, Feature::InHand];
    if hand_state {
        features.push(Feature::HandOpen);
    }
    let data = segment::dataset(&features, &labels, cases.into_iter());
    let tree = learner.learn(&data);
    let right = data
        .cases
        .iter()
        .filter(|c| tree.classify(&c.values) == c.class)
        .count();
    finish(args, &tree, right, data.cases.len())
}

fn finish(
    args: &ClassifyArgs,
    tree: &segment::DecisionTree,
    right: usize,
    total: usize,
) -> Result<ExitCode, Failure> {
    print!("{tree}");
    println!(
        "\nCorrectly classified training cases: {right} of {total} ({:.2}%)",
        100.0 * right as f64 / total.max(1) as f64
    );
    if let Some(out) = &args.out {
        write_atomically(out, &tree.to_json())?;
        println!("Tree written to {}", out.display());
    }
    Ok(ExitCode::SUCCESS)
}
