//! `demoplan classify`: print the activity tree (the paper's Table 1, or `--tree`), learn
//! one with C4.5 from labelled frames (`--learn FILE... -o TREE`), or classify labelled
//! frames and compare with their labels.
//!
//! Labelled frames are ARFF hand-state tables with an activity attribute, or simulated
//! recordings with their ground truth beside them (`NAME.truth.jsonl`). An ARFF file that
//! is not a hand-state table (any nominal data set) can be learned from on its own, with
//! `--class` naming the class (default: the last attribute).

use std::fmt::Write as _;
use std::path::{Path, PathBuf};

use grounding::HandFacts;
use segment::{ActivityTree, Feature, LabelMap, C45};

use crate::commands::demo_input;
use crate::diagnostic::Failure;
use crate::exit::ExitCode;
use crate::output::write_atomically;

/// The command line of `classify`.
#[derive(Debug)]
pub struct ClassifyArgs {
    pub files: Vec<PathBuf>,
    pub tree: Option<PathBuf>,
    pub learn: bool,
    pub out: Option<PathBuf>,
    pub class: Option<String>,
    pub config: Option<PathBuf>,
    /// A mapping file whose `[labels]` table maps ARFF labels to activities.
    pub mapping: Option<PathBuf>,
}

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
    let mut out = String::new();
    for path in &args.files {
        let cases = labelled(path, &config, &labels)?;
        report(&mut out, path, &tree, &cases);
    }
    print!("{out}");
    Ok(ExitCode::SUCCESS)
}

/// Frames of hands with labels (indices into `labels`, activity names).
struct Labelled {
    frames: Vec<(HandFacts, usize)>,
    labels: Vec<String>,
    hand_state: bool,
    /// Frames left out: their labels are not in the label map.
    left_out: usize,
}

/// The labelled frames of a file. An ARFF table's labels go through the label map;
/// those it does not know are left out and named on standard error, once per file.
fn labelled(
    path: &Path,
    config: &grounding::GroundingConfig,
    map: &LabelMap,
) -> Result<Labelled, Failure> {
    if demo_input::is_arff(path) {
        let frames = demo_input::hand_frames(path)?;
        let mapped = frames.activities(map);
        if let Some(w) = mapped.warning() {
            demo_input::warn(path, &[w]);
        }
        let mut labels: Vec<String> = Vec::new();
        let mut cases = Vec::new();
        for (f, a) in frames.frames.iter().zip(&mapped.activities) {
            let Some(a) = a else { continue };
            let name = a.name();
            let k = match labels.iter().position(|l| l == name) {
                Some(k) => k,
                None => {
                    labels.push(name.to_string());
                    labels.len() - 1
                }
            };
            cases.push((f.hand, k));
        }
        return Ok(Labelled {
            frames: cases,
            labels,
            hand_state: frames.has_hand_state,
            left_out: mapped.left_out(),
        });
    }
    let tree = ActivityTree::table_one();
    let mut grounded: Vec<(u64, Vec<HandFacts>)> = Vec::new();
    let segmented = demo_input::segment_recording(
        path,
        config,
        &tree,
        |_, _| {},
        |g| grounded.push((g.index, g.hands.to_vec())),
    )?;
    let truth = demo_input::read_truth(path, &segmented.header)?;
    let mut labels: Vec<String> = Vec::new();
    let mut frames = Vec::new();
    for (index, hands) in grounded {
        let Some(names) = truth.get(index as usize) else {
            continue;
        };
        for (hand, name) in hands.iter().zip(names) {
            let k = match labels.iter().position(|l| l == name) {
                Some(k) => k,
                None => {
                    labels.push(name.clone());
                    labels.len() - 1
                }
            };
            frames.push((*hand, k));
        }
    }
    Ok(Labelled {
        frames,
        labels,
        hand_state: true,
        left_out: 0,
    })
}

fn report(out: &mut String, path: &Path, tree: &ActivityTree, cases: &Labelled) {
    let (frames, labels) = (&cases.frames, &cases.labels);
    let predicted: Vec<&str> = frames
        .iter()
        .map(|(h, _)| tree.classify(h).name())
        .collect();
    let agree = frames
        .iter()
        .zip(&predicted)
        .filter(|((_, l), p)| labels[*l] == **p)
        .count();
    let left_out = match cases.left_out {
        0 => String::new(),
        n => format!("; {n} left out, their labels not in the label map"),
    };
    let _ = writeln!(
        out,
        "{}: {} labelled hand frames, {} agree with the tree ({:.2}%){left_out}",
        path.display(),
        frames.len(),
        agree,
        100.0 * agree as f64 / frames.len().max(1) as f64
    );
    let columns: Vec<&str> = segment::Activity::ALL.iter().map(|a| a.name()).collect();
    let _ = write!(out, "{:<10}", "label");
    for c in &columns {
        let _ = write!(out, " {c:>7}");
    }
    out.push('\n');
    for (k, label) in labels.iter().enumerate() {
        let _ = write!(out, "{label:<10}");
        for c in &columns {
            let n = frames
                .iter()
                .zip(&predicted)
                .filter(|((_, l), p)| *l == k && *p == c)
                .count();
            let _ = write!(out, " {n:>7}");
        }
        out.push('\n');
    }
}

fn learn(args: &ClassifyArgs) -> Result<ExitCode, Failure> {
    let learner = C45::default();
    // A nominal data set that is not a hand-state table: learn it as it is.
    if let [path] = args.files.as_slice() {
        if demo_input::is_arff(path) {
            let (table, text) = demo_input::arff_table(path)?;
            if !table.is_hand_state() {
                let (data, warnings) = table
                    .dataset(args.class.as_deref())
                    .map_err(|e| demo_input::arff_failure(path, &text, &e))?;
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
    for path in &args.files {
        let l = labelled(path, &config, &map)?;
        hand_state &= l.hand_state;
        for (hand, k) in l.frames {
            let name = &l.labels[k];
            let k = match labels.iter().position(|x| x == name) {
                Some(k) => k,
                None => {
                    labels.push(name.clone());
                    labels.len() - 1
                }
            };
            cases.push((hand, k));
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
