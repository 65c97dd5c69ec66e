//! What `demoplan learn` reads, and how it learns it: [`learning_inputs`] expands the
//! paths it is given (folders into the recordings they hold, the simulator's truth files
//! skipped), and [`Batch`] is learning in two phases, the slow one (segmenting) apart
//! from the short one that reads, changes and writes the library, so that a caller can
//! hold the library's lock for the second only (`docs/reliability.md`).

use std::fmt::Write as _;
use std::io::Read;
use std::path::{Path, PathBuf};

use crate::hash::StableHasher;
use crate::library::{Added, Library, RecordingInfo};
use crate::pipeline::Segmented;

/// The paths to learn from, and what was skipped on the way (one note per folder, and
/// one for simulator files given by name), for the caller to show.
#[derive(Debug, Clone, Default, PartialEq, Eq)]
pub struct Inputs {
    /// The files, in the order given; a folder's files sorted by name.
    pub files: Vec<PathBuf>,
    /// What each folder held and what was skipped.
    pub notes: Vec<String>,
}

/// Why the paths name nothing to learn from.
#[derive(Debug, thiserror::Error)]
pub enum InputsError {
    /// A folder could not be listed.
    #[error("cannot read folder {}: {source}", path.display())]
    Folder {
        /// The folder.
        path: PathBuf,
        /// Why.
        source: std::io::Error,
    },
    /// A folder holds no recording.
    #[error("{} holds no recording (native .jsonl, a Unity log, or an ARFF table)", .0.display())]
    EmptyFolder(PathBuf),
    /// Nothing is left once the simulator's files are skipped.
    #[error("no recording to learn from (the simulator's *.truth.jsonl and simulation.json are not recordings)")]
    Nothing,
    /// A file in a folder could not be told apart (it cannot be read).
    #[error(transparent)]
    Open(#[from] import::OpenError),
}

/// A file the simulator writes beside its recordings, which is no recording.
fn simulator_file(name: &str) -> bool {
    name.ends_with(".truth.jsonl") || name == "simulation.json"
}

fn name_of(path: &Path) -> String {
    path.file_name()
        .map(|n| n.to_string_lossy().into_owned())
        .unwrap_or_default()
}

/// Whether a file in a folder is one to learn from: a native `.jsonl`, an ARFF table
/// ([`segment::is_arff_file`]) or a `.json` file that is a Unity log by its content.
fn is_recording(file: &Path) -> Result<bool, InputsError> {
    let name = name_of(file);
    Ok(name.ends_with(".jsonl")
        || segment::is_arff_file(file)
        || (name.ends_with(".json") && import::SourceKind::of(file)? == import::SourceKind::Unity))
}

/// What `learn` reads from `paths`: files as given, and every recording in a folder
/// (native `.jsonl`, Unity logs and ARFF by content), sorted by name. The simulator's
/// ground truth (`*.truth.jsonl`) and its `simulation.json` are skipped, also when given
/// by name (a glob such as `demos/*.jsonl` names the truth files), and the notes say
/// what was skipped. A folder without a recording, or nothing at all to learn from, is
/// an error.
pub fn learning_inputs(paths: &[PathBuf]) -> Result<Inputs, InputsError> {
    let mut inputs = Inputs::default();
    let mut skipped_given = Vec::new();
    for path in paths {
        if !path.is_dir() {
            if simulator_file(&name_of(path)) {
                skipped_given.push(path.display().to_string());
            } else {
                inputs.files.push(path.clone());
            }
            continue;
        }
        let folder_error = |source| InputsError::Folder {
            path: path.clone(),
            source,
        };
        let mut files = Vec::new();
        for entry in std::fs::read_dir(path).map_err(folder_error)? {
            let entry = entry.map_err(folder_error)?;
            if entry.file_type().is_ok_and(|t| t.is_file()) {
                files.push(entry.path());
            }
        }
        files.sort();
        let (mut found, mut truth, mut others) = (0, 0, Vec::new());
        for file in files {
            let name = name_of(&file);
            if simulator_file(&name) {
                truth += 1;
            } else if is_recording(&file)? {
                found += 1;
                inputs.files.push(file);
            } else {
                others.push(name);
            }
        }
        if found == 0 {
            return Err(InputsError::EmptyFolder(path.clone()));
        }
        let mut note = format!("{}: {found} recording(s)", path.display());
        if truth > 0 {
            let _ = write!(
                note,
                "; skipped {truth} file(s) of the simulator (*.truth.jsonl, simulation.json)"
            );
        }
        if !others.is_empty() {
            let _ = write!(note, "; skipped, not recordings: {}", others.join(", "));
        }
        inputs.notes.push(note);
    }
    if !skipped_given.is_empty() {
        inputs.notes.push(format!(
            "skipped {} file(s) of the simulator, not recordings: {}",
            skipped_given.len(),
            skipped_given.join(", ")
        ));
    }
    if inputs.files.is_empty() {
        return Err(InputsError::Nothing);
    }
    Ok(inputs)
}

/// The content hash (16 hex digits) of what `input` reads, in pieces: the hash by which
/// a library knows a recording it has counted.
pub fn content_hash(mut input: impl Read) -> std::io::Result<String> {
    let mut hasher = StableHasher::new();
    let mut buffer = vec![0u8; 1 << 20];
    loop {
        let n = input.read(&mut buffer)?;
        if n == 0 {
            break;
        }
        hasher.write(&buffer[..n]);
    }
    Ok(format!("{:016x}", hasher.finish()))
}

/// One recording of a [`Batch`]: where it came from, its content hash and, unless it
/// was known when the batch was prepared, its segments.
#[derive(Debug)]
struct Prepared {
    path: PathBuf,
    hash: String,
    segmented: Option<Segmented>,
}

/// Recordings prepared for learning (phase one): hashed, and segmented unless the
/// library already counted them (or the batch has the same content twice).
#[derive(Debug, Default)]
pub struct Batch {
    prepared: Vec<Prepared>,
}

impl Batch {
    /// Phase one: each file's hash (`hash`) and, unless `known` (the library as first
    /// read) has it, its segments (`segment`). No library is changed.
    pub fn prepare<E>(
        files: &[PathBuf],
        known: Option<&Library>,
        mut hash: impl FnMut(&Path) -> Result<String, E>,
        mut segment: impl FnMut(&Path) -> Result<Segmented, E>,
    ) -> Result<Batch, E> {
        let mut batch = Batch::default();
        for path in files {
            let hash = hash(path)?;
            let seen = known.is_some_and(|l| l.has_recording(&hash))
                || batch.prepared.iter().any(|p| p.hash == hash);
            let segmented = if seen { None } else { Some(segment(path)?) };
            batch.prepared.push(Prepared {
                path: path.clone(),
                hash,
                segmented,
            });
        }
        Ok(batch)
    }

    /// Phase two: adds every recording to `library` (the library as read again for the
    /// write). A recording known in phase one but gone from the library now (it was
    /// replaced meanwhile) is segmented here with `segment`. Returns a line per
    /// recording saying what was counted.
    pub fn add_to<E>(
        self,
        library: &mut Library,
        mut segment: impl FnMut(&Path) -> Result<Segmented, E>,
    ) -> Result<String, E> {
        let mut log = String::new();
        for input in self.prepared {
            let path = &input.path;
            let counted = if library.has_recording(&input.hash) {
                Added::AlreadyCounted
            } else {
                let segmented = match input.segmented {
                    Some(s) => s,
                    None => segment(path)?,
                };
                let info = RecordingInfo {
                    hash: input.hash,
                    id: segmented.header.id.clone(),
                    participant: segmented.header.participant.clone(),
                    source: path.display().to_string(),
                    frames: segmented.frames,
                    segments: 0,
                    ..Default::default()
                };
                library.add_recording(
                    info,
                    &segmented.header,
                    &segmented.space,
                    &segmented.segments,
                )
            };
            let _ = match counted {
                Added::Counted {
                    segments,
                    new_operators,
                } => writeln!(
                    log,
                    "{}: {segments} activities, {new_operators} new operator(s)",
                    path.display()
                ),
                Added::AlreadyCounted => writeln!(
                    log,
                    "{}: already in the library (same content), not counted again",
                    path.display()
                ),
            };
        }
        Ok(log)
    }
}
