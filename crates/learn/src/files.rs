//! Demonstration files by path: ARFF hand-state tables read in two passes, a row at a
//! time (the first pass finds the objects and labels, the second gives the frames), any
//! recording (native, or a Unity log or bag imported with its format's default mapping)
//! segmented, and the labelled frames that C4.5 learns from and `classify` checks.
//! Errors say which file, and keep the reader's line, column and field.

use std::fs::File;
use std::io::BufReader;
use std::path::{Path, PathBuf};

use grounding::{GroundingConfig, HandFacts};
use segment::{
    Activity, ActivityTree, ArffError, ArffReader, ArffWarning, HandTable, LabelMap, UnknownLabels,
};

use crate::{segment_reader, HandsGrounded, Observer, Segmented};

/// Frame rate assumed for ARFF tables without a time attribute.
pub const ARFF_FRAME_RATE: f64 = 30.0;

/// A demonstration file that could not be read, by what went wrong where.
#[derive(Debug, thiserror::Error)]
pub enum FileError {
    /// The file cannot be opened or read (missing, no permission).
    #[error("cannot read {}: {source}", path.display())]
    Read {
        path: PathBuf,
        source: std::io::Error,
    },
    /// A malformed ARFF table: where, in [`ArffError`]'s line, column and field.
    #[error("{}: {error}", path.display())]
    Arff { path: PathBuf, error: ArffError },
    /// A recording that could not be opened ([`import::open_recording`]).
    #[error("{error}")]
    Open {
        path: PathBuf,
        error: import::OpenError,
    },
    /// A malformed recording.
    #[error("{}: {error}", path.display())]
    Recording {
        path: PathBuf,
        error: recording::ReadError,
    },
    /// The ground truth beside a simulated recording, missing (line 0) or malformed.
    #[error("{}", truth_message(truth, recording, *line, message))]
    Truth {
        truth: PathBuf,
        recording: PathBuf,
        /// 1-based line of the truth file; 0 when it could not be read at all.
        line: u64,
        message: String,
    },
}

/// A missing truth file names the recording it belongs to; a malformed one its line.
fn truth_message(truth: &Path, recording: &Path, line: u64, message: &str) -> String {
    match line {
        0 => format!(
            "cannot read {} (the ground truth of {}, needed for its labels): {message}",
            truth.display(),
            recording.display()
        ),
        _ => format!("{}:{line}: {message}", truth.display()),
    }
}

fn arff_error(path: &Path) -> impl Fn(ArffError) -> FileError + '_ {
    move |error| FileError::Arff {
        path: path.to_path_buf(),
        error,
    }
}

/// An ARFF file opened for reading a row at a time: its header read and checked.
pub fn arff_reader(path: &Path) -> Result<ArffReader<BufReader<File>>, FileError> {
    let file = File::open(path).map_err(|source| FileError::Read {
        path: path.to_path_buf(),
        source,
    })?;
    ArffReader::new(BufReader::new(file)).map_err(arff_error(path))
}

/// An ARFF file that is a nominal data set, not a hand-state table
/// ([`segment::is_hand_state`]), read whole for C4.5 with `class` as its class (default:
/// the last attribute); `warn` sees what the reader accepted. `None` for a hand-state
/// table: its frames are learned by their activity.
pub fn nominal_dataset(
    path: &Path,
    class: Option<&str>,
    warn: &mut dyn FnMut(&ArffWarning),
) -> Result<Option<segment::Dataset>, FileError> {
    let reader = arff_reader(path)?;
    if segment::is_hand_state(reader.attributes()) {
        return Ok(None);
    }
    let table = reader.into_table().map_err(arff_error(path))?;
    let (data, warnings) = table.dataset(class).map_err(arff_error(path))?;
    warnings.iter().for_each(warn);
    Ok(Some(data))
}

/// The first pass over an ARFF hand-state table: its objects and labels, and the warnings
/// about what the reader accepted (`table.warnings`).
pub fn hand_table(path: &Path) -> Result<HandTable, FileError> {
    let reader = arff_reader(path)?;
    let (relation, attributes) = (reader.relation().to_string(), reader.attributes().to_vec());
    HandTable::scan(&relation, &attributes, reader, ARFF_FRAME_RATE).map_err(arff_error(path))
}

/// An ARFF hand-state table segmented, in two passes: its hand's own facts are the
/// states (it has no geometry to ground). `warn` hears what the first pass accepted
/// before the second begins.
pub fn segment_arff(
    path: &Path,
    tree: &ActivityTree,
    min_duration: f64,
    warn: &mut dyn FnMut(&ArffWarning),
) -> Result<Segmented, FileError> {
    let table = hand_table(path)?;
    table.warnings.iter().for_each(&mut *warn);
    let segmented = table
        .segments(table.frames(arff_reader(path)?), tree, min_duration)
        .map_err(arff_error(path))?;
    Ok(Segmented::from_table(table.header, segmented))
}

/// Opens a recording of any source kind, a Unity log or bag imported with its format's
/// default mapping, and segments it; `observer` sees every frame.
pub fn segment_path(
    path: &Path,
    config: &GroundingConfig,
    tree: &ActivityTree,
    observer: &mut dyn Observer,
) -> Result<Segmented, FileError> {
    let open_error = |error| FileError::Open {
        path: path.to_path_buf(),
        error,
    };
    let kind = import::SourceKind::of(path).map_err(open_error)?;
    let mapping = kind.format().map(import::Mapping::default_for);
    let mut reader = import::open_recording(path, kind, mapping.as_ref()).map_err(open_error)?;
    segment_reader(&mut reader, config, tree, observer).map_err(|error| FileError::Recording {
        path: path.to_path_buf(),
        error,
    })
}

/// The ground truth of a simulated recording ([`simulate::truth_path`]): per frame and
/// hand, the activity.
pub fn read_truth(
    recording: &Path,
    header: &recording::Header,
) -> Result<Vec<Vec<Activity>>, FileError> {
    let truth = simulate::truth_path(recording);
    let failed = |line: u64, message: String| FileError::Truth {
        truth: truth.clone(),
        recording: recording.to_path_buf(),
        line,
        message,
    };
    let file = File::open(&truth).map_err(|e| failed(0, e.to_string()))?;
    let (_, frames) = simulate::read_truth(BufReader::new(file), header)
        .map_err(|e| failed(e.line, e.message))?;
    Ok(frames
        .iter()
        .map(|f| f.hands.iter().map(|h| h.activity).collect())
        .collect())
}

/// What a file's labelled frames were.
#[derive(Debug, Clone, Default, PartialEq, Eq)]
pub struct Labelled {
    /// Whether the hands' states say `handOpen` (a recording's do; an ARFF table's when
    /// it has the attribute).
    pub hand_state: bool,
    /// Frames left out: their labels are not in the label map.
    pub left_out: usize,
}

/// The labelled frames of a file, each given to `each` with its label as it is read: an
/// ARFF table ([`segment::is_arff_file`]) a row at a time, its labels through `map`
/// (frames of labels it does not know are left out and counted); a simulated recording
/// grounded with `config`, its labels from the ground truth beside it. `warn` hears what
/// an ARFF reader accepted after the first pass, and the labels left out at the end.
pub fn labelled_frames(
    path: &Path,
    config: &GroundingConfig,
    map: &LabelMap,
    each: &mut dyn FnMut(HandFacts, Activity),
    warn: &mut dyn FnMut(&ArffWarning),
) -> Result<Labelled, FileError> {
    if segment::is_arff_file(path) {
        let table = hand_table(path)?;
        table.warnings.iter().for_each(&mut *warn);
        let mut unknown = UnknownLabels::default();
        for frame in table.frames(arff_reader(path)?) {
            let frame = frame.map_err(arff_error(path))?;
            if let Some(a) = unknown.activity(map, &frame) {
                each(frame.hand, a);
            }
        }
        if let Some(w) = unknown.warning() {
            warn(&w);
        }
        return Ok(Labelled {
            hand_state: table.has_hand_state(),
            left_out: unknown.left_out(),
        });
    }
    let tree = ActivityTree::table_one();
    let mut grounded = HandsGrounded::default();
    let segmented = segment_path(path, config, &tree, &mut grounded)?;
    let truth = read_truth(path, &segmented.header)?;
    for (hand, activity) in grounded.labelled(&truth) {
        each(hand, activity);
    }
    Ok(Labelled {
        hand_state: true,
        left_out: 0,
    })
}

/// Why [`learn_tree`] learned no tree (besides a file it could not read).
#[derive(Debug, thiserror::Error)]
pub enum TreeError {
    /// A file could not be read.
    #[error(transparent)]
    File(#[from] FileError),
    /// A class was named for hand-state frames, which are learned by their activity.
    #[error(
        "--class is for an ARFF data set that is not a hand-state table; hand-state frames \
         are learned by their activity"
    )]
    ClassOfHandStates,
    /// The files hold no labelled frame.
    #[error("no labelled frames to learn from")]
    NoFrames,
}

/// A decision tree learned with C4.5 from `files`, as `classify --learn` learns it: a
/// lone ARFF file that is a nominal data set ([`nominal_dataset`]) as it is, with
/// `class` as its class; otherwise the labelled frames of every file
/// ([`labelled_frames`], grounded and labelled with what `frames` reads, only then),
/// their hand states against their activities. Only the cases are kept (C4.5 needs them
/// all at once), not the files' rows. `warn` hears what an ARFF reader accepted.
pub fn learn_tree<E: From<TreeError>>(
    files: &[PathBuf],
    class: Option<&str>,
    frames: impl FnOnce() -> Result<(GroundingConfig, LabelMap), E>,
    warn: &mut dyn FnMut(&Path, &ArffWarning),
) -> Result<segment::LearnedTree, E> {
    let learner = segment::C45::default();
    if let [path] = files {
        if segment::is_arff_file(path) {
            let nominal = nominal_dataset(path, class, &mut |w| warn(path, w));
            if let Some(data) = nominal.map_err(TreeError::from)? {
                return Ok(learner.learn_checked(&data));
            }
        }
    }
    if class.is_some() {
        return Err(TreeError::ClassOfHandStates.into());
    }
    let (config, map) = frames()?;
    let mut cases: Vec<(HandFacts, Activity)> = Vec::new();
    let mut hand_state = true;
    for path in files {
        let mut each = |hand, label| cases.push((hand, label));
        let labelled = labelled_frames(path, &config, &map, &mut each, &mut |w| warn(path, w));
        hand_state &= labelled.map_err(TreeError::from)?.hand_state;
    }
    if cases.is_empty() {
        return Err(TreeError::NoFrames.into());
    }
    Ok(segment::learn_activity_tree(&learner, &cases, hand_state))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_simulated_recordings_labels_come_from_the_truth_beside_it() {
        let dir = std::env::temp_dir().join(format!("learn-files-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir_all(&dir).unwrap();
        let study = simulate::study(&simulate::SimParams::default(), 7, 1, 1).unwrap();
        let demo = &study.demonstrations[0];
        let path = dir.join(demo.recording_name());
        let mut truth = Vec::new();
        let file = File::create(&path).unwrap();
        let written = demo
            .write(std::io::BufWriter::new(file), &mut truth)
            .unwrap();
        let (config, map) = (GroundingConfig::default(), LabelMap::default());
        let mut labels = 0u64;
        let missing = labelled_frames(&path, &config, &map, &mut |_, _| labels += 1, &mut |_| {});
        match missing {
            Err(FileError::Truth {
                truth,
                recording,
                line: 0,
                ..
            }) => assert_eq!(
                (truth, recording),
                (simulate::truth_path(&path), path.clone())
            ),
            other => panic!("expected the missing truth, got {other:?}"),
        }
        std::fs::write(simulate::truth_path(&path), &truth).unwrap();
        let labelled =
            labelled_frames(&path, &config, &map, &mut |_, _| labels += 1, &mut |_| {}).unwrap();
        assert_eq!(
            labelled,
            Labelled {
                hand_state: true,
                left_out: 0
            }
        );
        // A label per hand of every grounded frame, and no more.
        let hands = demo
            .header()
            .entities
            .iter()
            .filter(|e| e.kind == recording::EntityKind::Hand)
            .count() as u64;
        assert!(
            labels > 0 && labels <= written.frames * hands,
            "{labels} labels"
        );
        let _ = std::fs::remove_dir_all(&dir);
    }
}
