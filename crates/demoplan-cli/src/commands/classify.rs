//! `demoplan classify`: print the activity tree (the paper's Table 1, or `--tree`), learn
//! one with C4.5 from labelled frames (`--learn FILE... -o TREE`), or classify labelled
//! frames and compare with their labels.
//!
//! Labelled frames are ARFF hand-state tables with an activity attribute, or simulated
//! recordings with their ground truth beside them (`NAME.truth.jsonl`). An ARFF file that
//! is not a hand-state table (any nominal data set) can be learned from on its own, with
//! `--class` naming the class (default: the last attribute).

use std::path::Path;

use grounding::HandFacts;
use segment::{Activity, ActivityTree, Confusion, LabelMap, UnknownLabels, C45};

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
        let mut confusion = Confusion::default();
        let l = labelled(path, &config, &labels, &mut |hand, label| {
            confusion.add(label, tree.classify(&hand));
        })?;
        output::print(
            &mut out,
            &confusion.report(&path.display().to_string(), l.left_out),
        )?;
    }
    Ok(ExitCode::SUCCESS)
}

/// What a file's labelled frames are: whether the hands' states say `handOpen`, and
/// the frames left out.
struct Labelled {
    hand_state: bool,
    /// Frames left out: their labels are not in the label map.
    left_out: usize,
}

/// The labelled frames of a file, each given to `each` as it is read, with its label.
/// An ARFF table is read a row at a time and its labels go through the label map; those
/// it does not know are left out and named on standard error, once per file.
fn labelled(
    path: &Path,
    config: &grounding::GroundingConfig,
    map: &LabelMap,
    each: &mut dyn FnMut(HandFacts, Activity),
) -> Result<Labelled, Failure> {
    if demo_input::is_arff(path) {
        let table = demo_input::hand_table(path)?;
        let mut unknown = UnknownLabels::default();
        demo_input::arff_frames(path, &table, |f| {
            if let Some(a) = unknown.activity(map, f) {
                each(f.hand, a);
            }
        })?;
        if let Some(w) = unknown.warning() {
            demo_input::warn(path, &[w]);
        }
        return Ok(Labelled {
            hand_state: table.has_hand_state(),
            left_out: unknown.left_out(),
        });
    }
    let tree = ActivityTree::table_one();
    let mut grounded = learn::HandsGrounded::default();
    let segmented = demo_input::segment_recording(path, None, config, &tree, &mut grounded)?;
    let truth = demo_input::read_truth(path, &segmented.header)?;
    for (hand, activity) in grounded.labelled(&truth) {
        each(hand, activity);
    }
    Ok(Labelled {
        hand_state: true,
        left_out: 0,
    })
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
                return finish(args, &learner.learn_checked(&data));
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
    let mut cases: Vec<(HandFacts, Activity)> = Vec::new();
    let mut hand_state = true;
    // C4.5 needs every case at once: only these (a hand state and a label each) are
    // kept, not the files' rows.
    for path in &args.files {
        let l = labelled(path, &config, &map, &mut |hand, label| {
            cases.push((hand, label))
        })?;
        hand_state &= l.hand_state;
    }
    if cases.is_empty() {
        return Err(Failure::plain(
            ExitCode::INPUT_ERROR,
            "no labelled frames to learn from",
        ));
    }
    finish(
        args,
        &segment::learn_activity_tree(&learner, &cases, hand_state),
    )
}

fn finish(args: &ClassifyArgs, learned: &segment::LearnedTree) -> Result<ExitCode, Failure> {
    print!("{}", learned.report());
    if let Some(out) = &args.out {
        write_atomically(out, &learned.tree.to_json())?;
        println!("Tree written to {}", out.display());
    }
    Ok(ExitCode::SUCCESS)
}
