//! Shared by `segment`, `classify` and `timeline`: reading grounding configurations,
//! trees and ARFF tables (errors with file, line and field, exit 31), and running
//! grounding and segmentation over a recording.

use std::fs::File;
use std::io::BufReader;
use std::path::{Path, PathBuf};

use grounding::GroundingConfig;
use learn::Segmented;
use miette::NamedSource;
use recording::{Activity, Header};
use segment::{ActivityTree, ArffReader, DecisionTree, HandTable, LabelMap, LabelledFrame};

use crate::diagnostic::{render, Failure, SourceDiagnostic};
use crate::exit::ExitCode;
use crate::input;
use crate::recording_input;

/// Frame rate assumed for ARFF tables without a time attribute.
pub const ARFF_FRAME_RATE: f64 = 30.0;

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
        code,
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

/// Whether a path names an ARFF table ([`segment::is_arff_file`]: by extension or content).
pub fn is_arff(path: &Path) -> bool {
    segment::is_arff_file(path)
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

/// An ARFF file opened for reading a row at a time: its header read and checked.
pub fn arff_reader(path: &Path) -> Result<ArffReader<BufReader<File>>, Failure> {
    let file = File::open(path).map_err(|e| {
        Failure::plain(
            ExitCode::USAGE,
            format!("cannot read {}: {e}", path.display()),
        )
    })?;
    ArffReader::new(BufReader::new(file)).map_err(|e| arff_failure(path, &e))
}

/// A whole ARFF table in memory, for what needs every row at once (C4.5 on a data set
/// that is not a hand-state table).
pub fn arff_table(path: &Path) -> Result<segment::ArffTable, Failure> {
    arff_reader(path)?
        .into_table()
        .map_err(|e| arff_failure(path, &e))
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

/// An ARFF hand-state table after its first pass (objects, labels); its warnings are
/// printed on standard error. [`arff_frames`] is the second pass.
pub fn hand_table(path: &Path) -> Result<HandTable, Failure> {
    let reader = arff_reader(path)?;
    let (relation, attributes) = (reader.relation().to_string(), reader.attributes().to_vec());
    let table = HandTable::scan(&relation, &attributes, reader, ARFF_FRAME_RATE)
        .map_err(|e| arff_failure(path, &e))?;
    warn(path, &table.warnings);
    Ok(table)
}

/// The second pass over a hand-state table: `each` sees every frame, in order.
pub fn arff_frames(
    path: &Path,
    table: &HandTable,
    mut each: impl FnMut(&LabelledFrame),
) -> Result<(), Failure> {
    for frame in table.frames(arff_reader(path)?) {
        each(&frame.map_err(|e| arff_failure(path, &e))?);
    }
    Ok(())
}

/// An ARFF hand-state table segmented: its hand's own facts are the states (it has no
/// geometry, so no grounding). The file is read twice, a row at a time.
pub fn segment_arff(
    path: &Path,
    tree: &ActivityTree,
    min_duration: f64,
) -> Result<Segmented, Failure> {
    let table = hand_table(path)?;
    let segmented = table
        .segments(table.frames(arff_reader(path)?), tree, min_duration)
        .map_err(|e| arff_failure(path, &e))?;
    Ok(Segmented::from_table(table.header, segmented))
}

/// Prints warnings about what an ARFF reader accepted.
pub fn warn(path: &Path, warnings: &[segment::ArffWarning]) {
    for w in warnings {
        eprintln!("warning: {}:{}: {}", path.display(), w.line, w.message);
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

/// A recording or an ARFF hand-state table (by [`is_arff`]) segmented; a table's states
/// hold the hand's own facts only (it has no geometry to ground).
pub fn segment_file(
    path: &Path,
    mapping: Option<&Path>,
    config: &GroundingConfig,
    tree: &ActivityTree,
) -> Result<Segmented, Failure> {
    if is_arff(path) {
        segment_arff(path, tree, config.min_duration)
    } else {
        segment_recording(path, mapping, config, tree, &mut ())
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

/// The ground truth beside a simulated recording (`NAME.truth.jsonl` for `NAME.jsonl`).
pub fn truth_path(recording: &Path) -> PathBuf {
    let name = recording
        .file_name()
        .map(|n| n.to_string_lossy().into_owned())
        .unwrap_or_default();
    let stem = name.strip_suffix(".jsonl").unwrap_or(&name);
    recording.with_file_name(format!("{stem}.truth.jsonl"))
}

/// Reads the ground truth of a recording: per frame and hand, the activity.
pub fn read_truth(recording: &Path, header: &Header) -> Result<Vec<Vec<Activity>>, Failure> {
    let path = truth_path(recording);
    let file = std::fs::File::open(&path).map_err(|e| {
        Failure::plain(
            ExitCode::USAGE,
            format!(
                "cannot read {} (the ground truth of {}, needed for its labels): {e}",
                path.display(),
                recording.display()
            ),
        )
    })?;
    let (_, frames) = simulate::read_truth(std::io::BufReader::new(file), header).map_err(|e| {
        Failure::plain(
            ExitCode::INPUT_ERROR,
            format!("{}:{}: {}", path.display(), e.line, e.message),
        )
    })?;
    Ok(frames
        .iter()
        .map(|f| f.hands.iter().map(|h| h.activity).collect())
        .collect())
}
