//! Shared by `segment`, `classify`, `timeline` and `learn`: reading grounding
//! configurations, trees and label maps, and segmenting recordings and ARFF tables
//! ([`learn`]'s files), with their errors rendered with file, line and field (exit 31).

use std::path::{Path, PathBuf};

use grounding::GroundingConfig;
use learn::Segmented;
use miette::NamedSource;
use segment::{ActivityTree, DecisionTree, LabelMap};

use crate::cli::SegmentationArgs;
use crate::diagnostic::{render, Failure, SourceDiagnostic};
use crate::input;
use crate::recording_input;
use slim::ExitCode;

/// An input error (exit 31) in `text`, the file at `path`, shown on its line with the
/// span [`recording::TextError::span`] underlines; without a line, one line naming the
/// file and the field.
pub fn text_failure(path: &Path, text: &str, code: &str, e: &recording::TextError) -> Failure {
    let field = (!e.field.is_empty()).then(|| format!("field `{}`", e.field));
    let Some(span) = e.span(text) else {
        let what = field.map_or(String::new(), |f| format!(", {f}"));
        let message = format!("{}{what}: {}", path.display(), e.message);
        return Failure::plain(ExitCode::INPUT_ERROR, message);
    };
    let diagnostic = SourceDiagnostic {
        code: code.to_string(),
        message: e.message.clone(),
        help: None,
        label: field.unwrap_or_else(|| "here".to_string()),
        span: span.into(),
        source: NamedSource::new(path.display().to_string(), text.to_string()),
    };
    Failure {
        code: ExitCode::INPUT_ERROR,
        text: render(&diagnostic),
    }
}

/// The grounding configuration: the file's, or the defaults.
pub fn config(path: Option<&Path>) -> Result<GroundingConfig, Failure> {
    let Some(path) = path else {
        return Ok(GroundingConfig::default());
    };
    let text = input::read_text(path)?;
    GroundingConfig::from_toml(&text)
        .map_err(|e| text_failure(path, &text, "grounding::config", &e))
}

/// A decision tree file.
pub fn decision_tree(path: &Path) -> Result<DecisionTree, Failure> {
    let text = input::read_text(path)?;
    DecisionTree::from_json(&text).map_err(|e| text_failure(path, &text, "segment::tree", &e))
}

/// The activity tree: the file's, or the paper's Table 1.
pub fn activity_tree(path: Option<&Path>) -> Result<ActivityTree, Failure> {
    let Some(path) = path else {
        return Ok(ActivityTree::table_one());
    };
    ActivityTree::new(decision_tree(path)?).map_err(|e| {
        let text = std::fs::read_to_string(path).unwrap_or_default();
        text_failure(path, &text, "segment::tree", &e)
    })
}

/// The label map: the defaults, with the `[labels]` table of the mapping file on top
/// (`LABEL = "Activity"`). The mapping file is the import crate's, the one every command
/// takes with `--mapping` (`docs/import.md`): a malformed file or an unknown key is an
/// input error naming its line and key, as is an activity that does not exist.
pub fn label_map(path: Option<&Path>) -> Result<LabelMap, Failure> {
    let Some(path) = path else {
        return Ok(LabelMap::default());
    };
    let mapping = recording_input::mapping(Some(path), import::Format::Arff)?;
    LabelMap::with_overrides(
        mapping
            .labels
            .iter()
            .map(|(label, activity)| (label.as_str(), activity.as_str())),
    )
    .map_err(|e| {
        // The mapping keeps no positions: find the label's value in the file again.
        let text = std::fs::read_to_string(path).unwrap_or_default();
        let e = import::Mapping::label_error(&text, &e.label, e.to_string());
        text_failure(path, &text, "import::mapping", &e)
    })
}

/// The failure for an ARFF error, shown on its line of the file. The file is read again
/// for that: tables are read a row at a time and no text is kept. A file that cannot be
/// read again (or is not UTF-8 text) gets the message without its line shown.
fn arff_failure(path: &Path, e: &segment::ArffError) -> Failure {
    match std::fs::read_to_string(path) {
        Ok(text) => text_failure(path, &text, "segment::arff", e),
        Err(_) => Failure::plain(
            ExitCode::INPUT_ERROR,
            format!(
                "{}:{}: field `{}`: {}",
                path.display(),
                e.line,
                e.field,
                e.message
            ),
        ),
    }
}

/// Prints a warning about what an ARFF reader accepted.
pub fn warn(path: &Path, warning: &segment::ArffWarning) {
    eprintln!(
        "warning: {}:{}: {}",
        path.display(),
        warning.line,
        warning.message
    );
}

/// The failure for a demonstration file that could not be read ([`learn::FileError`]):
/// a file that cannot be read, or a missing ground truth, is a command line error (36).
pub fn file_failure(e: learn::FileError) -> Failure {
    use learn::FileError as E;
    match e {
        E::Arff { path, error } => arff_failure(&path, &error),
        E::Open { path, error } => recording_input::open_failure(&path, error),
        E::Recording { path, error } => recording_input::recording_failure(&path, &error),
        e @ E::Truth { line: 1.., .. } => Failure::plain(ExitCode::INPUT_ERROR, e),
        e @ (E::Read { .. } | E::Truth { .. }) => Failure::plain(ExitCode::USAGE, e),
    }
}

/// What `learn` reads from its arguments ([`learn::learning_inputs`]: folders expanded,
/// the simulator's files skipped); what was skipped is said on standard error. No
/// recording at all is a command line error (36).
pub fn recordings(paths: &[PathBuf]) -> Result<Vec<PathBuf>, Failure> {
    let inputs = learn::learning_inputs(paths).map_err(|e| match e {
        learn::InputsError::Open(e) => recording_input::open_failure(&PathBuf::new(), e),
        e => Failure::plain(ExitCode::USAGE, e.to_string()),
    })?;
    for note in &inputs.notes {
        eprintln!("{note}");
    }
    Ok(inputs.files)
}

/// What [`SegmentationArgs`] name, read: how every recording of a command is segmented.
#[derive(Debug)]
pub struct Segmentation<'a> {
    pub config: GroundingConfig,
    pub tree: ActivityTree,
    /// The `--mapping` file, for Unity logs and bags among the inputs.
    pub mapping: Option<&'a Path>,
}

/// Reads the grounding configuration and the activity tree the options name.
pub fn segmentation(args: &SegmentationArgs) -> Result<Segmentation<'_>, Failure> {
    Ok(Segmentation {
        config: config(args.config.as_deref())?,
        tree: activity_tree(args.tree.as_deref())?,
        mapping: args.import.mapping.as_deref(),
    })
}

/// A recording or an ARFF hand-state table ([`segment::is_arff_file`]) segmented; a table's states
/// hold the hand's own facts only (it has no geometry to ground).
pub fn segment_file(path: &Path, with: &Segmentation) -> Result<Segmented, Failure> {
    if segment::is_arff_file(path) {
        learn::segment_arff(path, &with.tree, with.config.min_duration, &mut |w| {
            warn(path, w)
        })
        .map_err(file_failure)
    } else {
        segment_recording(path, with.mapping, &with.config, &with.tree, &mut ())
    }
}

/// Reads a recording (native, or a Unity log or bag imported with `mapping`), grounds
/// it and segments it (`learn::segment_reader`); `observer` sees every frame.
pub fn segment_recording(
    path: &Path,
    mapping: Option<&Path>,
    config: &GroundingConfig,
    tree: &ActivityTree,
    observer: &mut dyn learn::Observer,
) -> Result<Segmented, Failure> {
    let mut reader = recording_input::open(path, mapping)?;
    learn::segment_reader(&mut reader, config, tree, observer)
        .map_err(|e| recording_input::recording_failure(path, &e))
}
