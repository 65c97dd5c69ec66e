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
use segment::{Activity, ActivityTree, Confusion, LabelMap};

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

/// `--learn` ([`learn::learn_tree`]); the grounding and label map are read only for
/// labelled frames.
fn learn(args: &ClassifyArgs) -> Result<ExitCode, Failure> {
    let frames = || -> Result<_, Failure> {
        let config = demo_input::config(args.config.as_deref())?;
        Ok((config, demo_input::label_map(args.mapping.as_deref())?))
    };
    let class = args.class.as_deref();
    finish(
        args,
        &learn::learn_tree(&args.files, class, frames, &mut demo_input::warn)?,
    )
}

/// Why no tree was learned: a file's failure, a `--class` for hand states (36), no
/// labelled frames (31).
impl From<learn::TreeError> for Failure {
    fn from(e: learn::TreeError) -> Failure {
        match e {
            learn::TreeError::File(e) => demo_input::file_failure(e),
            e @ learn::TreeError::ClassOfHandStates => Failure::plain(ExitCode::USAGE, e),
            e @ learn::TreeError::NoFrames => Failure::plain(ExitCode::INPUT_ERROR, e),
        }
    }
}

fn finish(args: &ClassifyArgs, learned: &segment::LearnedTree) -> Result<ExitCode, Failure> {
    print!("{}", learned.report());
    if let Some(out) = &args.out {
        write_atomically(out, &learned.tree.to_json())?;
        println!("Tree written to {}", out.display());
    }
    Ok(ExitCode::SUCCESS)
}
