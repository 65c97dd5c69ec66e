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
use segment::{Activity, ActivityTree, Confusion, LabelMap, C45};

use crate::cli::ClassifyArgs;
use crate::commands::demo_input;
use crate::diagnostic::Failure;
use crate::output::{self, write_atomically};
use slim::ExitCode;

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

/// [`learn::labelled_frames`], with what the ARFF reader accepted said on standard
/// error.
fn labelled(
    path: &Path,
    config: &grounding::GroundingConfig,
    map: &LabelMap,
    each: &mut dyn FnMut(HandFacts, Activity),
) -> Result<learn::Labelled, Failure> {
    learn::labelled_frames(path, config, map, each, &mut |w| demo_input::warn(path, w))
        .map_err(demo_input::file_failure)
}

fn learn(args: &ClassifyArgs) -> Result<ExitCode, Failure> {
    let learner = C45::default();
    // A nominal data set that is not a hand-state table: learn it as it is.
    if let [path] = args.files.as_slice() {
        if segment::is_arff_file(path) {
            let reader = learn::arff_reader(path).map_err(demo_input::file_failure)?;
            if !segment::is_hand_state(reader.attributes()) {
                let arff = |e| demo_input::arff_failure(path, &e);
                let table = reader.into_table().map_err(arff)?;
                let (data, warnings) = table.dataset(args.class.as_deref()).map_err(arff)?;
                warnings.iter().for_each(|w| demo_input::warn(path, w));
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
