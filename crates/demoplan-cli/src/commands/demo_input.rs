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

/// An input error (exit 31) at `line` (1-based; 0: none known) and `column` (1-based;
/// 0: the whole line) of `text`, naming `field`.
pub fn text_failure(
    path: &Path,
    text: &str,
    code: &'static str,
    line: usize,
    column: usize,
    field: &str,
    message: &str,
) -> Failure {
    let label = if field.is_empty() {
        "here".to_string()
    } else {
        format!("field `{field}`")
    };
    let Some(start) = line_start(text, line) else {
        let what = if field.is_empty() {
            String::new()
        } else {
            format!(", field `{field}`")
        };
        return Failure::plain(
            ExitCode::INPUT_ERROR,
            format!("{}{what}: {message}", path.display()),
        );
    };
    let rest = &text[start..];
    let line_text = rest.split('\n').next().unwrap_or("").trim_end_matches('\r');
    let (offset, width) = if column == 0 {
        let indent = line_text.len() - line_text.trim_start().len();
        (indent, line_text.trim().len())
    } else {
        let at = (column - 1).min(line_text.len());
        let token = line_text[at..]
            .find(|c: char| c.is_whitespace() || c == ',')
            .unwrap_or(line_text.len() - at);
        (at, token.max(1).min(line_text.len().saturating_sub(at)))
    };
    let diagnostic = SourceDiagnostic {
        code: code.to_string(),
        message: message.to_string(),
        help: None,
        label,
        span: (start + offset, width).into(),
        source: NamedSource::new(path.display().to_string(), text.to_string()),
    };
    Failure {
        code: ExitCode::INPUT_ERROR,
        text: render(&diagnostic),
    }
}

fn line_start(text: &str, line: usize) -> Option<usize> {
    if line == 0 {
        return None;
    }
    let mut start = 0;
    for _ in 1..line {
        start += text[start..].find('\n')? + 1;
    }
    (start <= text.len()).then_some(start)
}

/// The grounding configuration: the file's, or the defaults.
pub fn config(path: Option<&Path>) -> Result<GroundingConfig, Failure> {
    let Some(path) = path else {
        return Ok(GroundingConfig::default());
    };
    let text = input::read_text(path)?;
    GroundingConfig::from_toml(&text).map_err(|e| {
        text_failure(
            path,
            &text,
            "grounding::config",
            e.line,
            e.column,
            &e.field,
            &e.message,
        )
    })
}

/// A decision tree file.
pub fn decision_tree(path: &Path) -> Result<DecisionTree, Failure> {
    let text = input::read_text(path)?;
    DecisionTree::from_json(&text).map_err(|e| tree_failure(path, &text, &e))
}

/// The activity tree: the file's, or the paper's Table 1.
pub fn activity_tree(path: Option<&Path>) -> Result<ActivityTree, Failure> {
    let Some(path) = path else {
        return Ok(ActivityTree::table_one());
    };
    ActivityTree::new(decision_tree(path)?).map_err(|e| {
        let text = std::fs::read_to_string(path).unwrap_or_default();
        tree_failure(path, &text, &e)
    })
}

/// The failure for an error in the tree file at `path`, shown on its line of `text`.
fn tree_failure(path: &Path, text: &str, e: &segment::TreeError) -> Failure {
    text_failure(
        path,
        text,
        "segment::tree",
        e.line,
        e.column,
        &e.field,
        &e.message,
    )
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
        let (line, column) = import::Mapping::label_position(&text, &e.label).unwrap_or((0, 0));
        text_failure(
            path,
            &text,
            "import::mapping",
            line,
            column,
            &format!("labels.{}", e.label),
            &e.to_string(),
        )
    })
}

/// The failure for an ARFF error, shown on its line of the file. The file is read again
/// for that: tables are read a row at a time and no text is kept. A file that cannot be
/// read again (or is not UTF-8 text) gets the message without its line shown.
pub fn arff_failure(path: &Path, e: &segment::ArffError) -> Failure {
    match std::fs::read_to_string(path) {
        Ok(text) => text_failure(
            path,
            &text,
            "segment::arff",
            e.line,
            e.column,
            &e.field,
            &e.message,
        ),
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

/// The failure for a demonstration file that could not be read ([`learn::FileError`]).
pub fn file_failure(e: learn::FileError) -> Failure {
    use learn::FileError as E;
    match e {
        E::Read { path, source } => Failure::plain(
            ExitCode::USAGE,
            format!("cannot read {}: {source}", path.display()),
        ),
        E::Arff { path, error } => arff_failure(&path, &error),
        E::Open { path, error } => recording_input::open_failure(&path, error),
        E::Recording { path, error } => recording_input::recording_failure(&path, &error),
        E::Truth {
            truth,
            recording,
            line: 0,
            message,
        } => Failure::plain(
            ExitCode::USAGE,
            format!(
                "cannot read {} (the ground truth of {}, needed for its labels): {message}",
                truth.display(),
                recording.display()
            ),
        ),
        E::Truth {
            truth,
            line,
            message,
            ..
        } => Failure::plain(
            ExitCode::INPUT_ERROR,
            format!("{}:{line}: {message}", truth.display()),
        ),
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
