//! Opening a recording of any format by its content: a native recording is read as it
//! is; a Unity log or a ROS bag (ROS 1, MCAP, a ROS 2 bag folder) is imported into memory
//! with a [`Mapping`] first. This is the one way the command line, and the bindings, open
//! what a user calls "a recording".
//!
//! ```
//! use import::{open_recording, SourceKind};
//!
//! let dir = std::env::temp_dir().join(format!("import-open-doc-{}", std::process::id()));
//! std::fs::create_dir_all(&dir)?;
//! let path = dir.join("demo.jsonl");
//! std::fs::write(
//!     &path,
//!     concat!(
//!         r#"{"format":"demoplan-recording","version":1,"id":"demo","participant":"p","#,
//!         r#""task":"t","frame_rate":90,"#,
//!         r#""entities":[{"name":"h","kind":"hand","size":[0.1,0.1,0.1]}]}"#,
//!         "\n"
//!     ),
//! )?;
//! let kind = SourceKind::of(&path)?;
//! assert_eq!(kind, SourceKind::Native);
//! let reader = open_recording(&path, kind, None)?;
//! assert_eq!(reader.header().id, "demo");
//! # std::fs::remove_dir_all(&dir)?;
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

use std::fs::File;
use std::io::{BufRead, BufReader, Read};
use std::path::{Path, PathBuf};

use crate::{import, ros, unity, Format, ImportError, Mapping};

/// Read buffer for native recordings: large, so that reading is not a system call per
/// frame.
const BUFFER: usize = 1 << 20;

/// How much of a file's start tells its format.
const SNIFF_BYTES: u64 = 4096;

/// A recording being read, whatever its source format.
pub type RecordingReader = recording::Reader<Box<dyn BufRead>>;

/// What a path holds, told by its content (never by its name alone).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum SourceKind {
    /// A native recording (JSON Lines).
    Native,
    /// A Unity VR playback log.
    Unity,
    /// A ROS bag: a ROS 1 bag, an MCAP file or a ROS 2 bag folder.
    Bag(Format),
}

/// Why a recording could not be opened.
#[derive(Debug, thiserror::Error)]
pub enum OpenError {
    /// The path is a folder that is not a ROS 2 bag.
    #[error("{} is a folder, not a recording (a ROS 2 bag folder has a metadata.yaml)", .0.display())]
    Folder(PathBuf),
    /// The file cannot be read (missing, no permission).
    #[error("cannot read {}: {source}", path.display())]
    Read {
        /// The file.
        path: PathBuf,
        /// Why.
        source: std::io::Error,
    },
    /// Importing a Unity log or a bag failed.
    #[error(transparent)]
    Import(ImportError),
    /// The native recording (as given, or as imported) is malformed.
    #[error(transparent)]
    Recording(recording::ReadError),
}

impl SourceKind {
    /// Tells a bag, a Unity log and a native recording apart by the start of the file
    /// (a native recording's header names its format on the first line; anything that is
    /// neither a bag nor a Unity log is taken for a native recording, whose reader then
    /// says what is wrong with it).
    pub fn of(path: &Path) -> Result<SourceKind, OpenError> {
        if path.is_dir() {
            return ros::bag_format(path, &[])
                .map(SourceKind::Bag)
                .ok_or_else(|| OpenError::Folder(path.to_path_buf()));
        }
        let mut start = Vec::with_capacity(SNIFF_BYTES as usize);
        File::open(path)
            .and_then(|f| f.take(SNIFF_BYTES).read_to_end(&mut start))
            .map_err(|source| OpenError::Read {
                path: path.to_path_buf(),
                source,
            })?;
        if let Some(format) = ros::bag_format(path, &start) {
            return Ok(SourceKind::Bag(format));
        }
        let native = String::from_utf8_lossy(&start).contains(recording::FORMAT_NAME);
        Ok(if !native && unity::looks_like_unity_log(&start) {
            SourceKind::Unity
        } else {
            SourceKind::Native
        })
    }

    /// The import format of a source that needs a mapping; `None` for a native recording.
    pub fn format(self) -> Option<Format> {
        match self {
            SourceKind::Native => None,
            SourceKind::Unity => Some(Format::Unity),
            SourceKind::Bag(format) => Some(format),
        }
    }
}

/// The id an imported recording gets: the source's file name without its extension.
pub fn recording_id(path: &Path) -> String {
    path.file_stem()
        .map(|s| s.to_string_lossy().into_owned())
        .unwrap_or_else(|| "imported".to_string())
}

/// Opens the recording at `path`, of `kind` ([`SourceKind::of`]), and reads its header.
/// A Unity log or a bag is imported into memory first with `mapping` (`None`: the
/// format's defaults, [`Mapping::default_for`]); a native recording ignores it.
pub fn open_recording(
    path: &Path,
    kind: SourceKind,
    mapping: Option<&Mapping>,
) -> Result<RecordingReader, OpenError> {
    let input: Box<dyn BufRead> = match kind.format() {
        None => {
            let file = File::open(path).map_err(|source| OpenError::Read {
                path: path.to_path_buf(),
                source,
            })?;
            Box::new(BufReader::with_capacity(BUFFER, file))
        }
        Some(format) => {
            let defaults;
            let mapping = match mapping {
                Some(m) => m,
                None => {
                    defaults = Mapping::default_for(format);
                    &defaults
                }
            };
            let id = recording_id(path);
            let imported = match kind {
                SourceKind::Bag(_) => ros::RosBag::open(path, mapping)
                    .and_then(|mut bag| import(&mut bag, mapping, &id, Vec::new())),
                _ => import(&mut unity::log_file(path), mapping, &id, Vec::new()),
            };
            let (bytes, _, _) = imported.map_err(OpenError::Import)?;
            Box::new(std::io::Cursor::new(bytes))
        }
    };
    recording::Reader::new(input).map_err(OpenError::Recording)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn scratch(name: &str) -> PathBuf {
        let dir = std::env::temp_dir().join(format!("import-open-{}-{name}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir_all(&dir).unwrap();
        dir
    }

    const UNITY_LOG: &str = r#"{"playbackTimestepMilliseconds": 20, "log": [
      {"time": 0, "logStep": [
        {"name": "VR_Controller_R", "position": [0.3, 1.0, 0.2], "orientation": [1, 0, 0, 0],
         "velocity": [0, 0, 0], "events": []},
        {"name": "Cube_red", "position": [0.0, 0.8, 0.4], "orientation": [1, 0, 0, 0],
         "velocity": [0, 0, 0], "events": []}]},
      {"time": 20, "logStep": [
        {"name": "VR_Controller_R", "position": [0.3, 1.0, 0.2], "orientation": [1, 0, 0, 0],
         "velocity": [0, 0, 0], "events": []},
        {"name": "Cube_red", "position": [0.0, 0.8, 0.4], "orientation": [1, 0, 0, 0],
         "velocity": [0, 0, 0], "events": []}]}
    ]}"#;

    #[test]
    fn a_unity_log_is_told_by_its_content_and_imported_with_its_name_as_id() {
        let dir = scratch("unity");
        // Named .jsonl on purpose: the content decides, not the name.
        let path = dir.join("session-3.jsonl");
        std::fs::write(&path, UNITY_LOG).unwrap();
        let kind = SourceKind::of(&path).unwrap();
        assert_eq!(kind, SourceKind::Unity);
        assert_eq!(kind.format(), Some(Format::Unity));
        let mut reader = open_recording(&path, kind, None).unwrap();
        assert_eq!(reader.header().id, "session-3");
        assert!(reader.header().find("Cube_red").is_some());
        let mut frame = recording::Frame::default();
        let mut frames = 0;
        while reader.read_frame(&mut frame).unwrap() {
            frames += 1;
        }
        assert_eq!(frames, 2);
        std::fs::remove_dir_all(&dir).unwrap();
    }

    #[test]
    fn a_folder_that_is_no_bag_and_a_missing_file_are_errors_naming_the_path() {
        let dir = scratch("errors");
        let e = SourceKind::of(&dir).unwrap_err();
        assert!(matches!(e, OpenError::Folder(_)), "{e:?}");
        assert!(e.to_string().contains("is a folder, not a recording"));
        let missing = dir.join("missing.jsonl");
        let e = SourceKind::of(&missing).unwrap_err();
        assert!(matches!(e, OpenError::Read { .. }), "{e:?}");
        assert!(e.to_string().contains("missing.jsonl"), "{e}");
        std::fs::remove_dir_all(&dir).unwrap();
    }

    #[test]
    fn a_malformed_native_recording_is_a_recording_error_with_its_line() {
        let dir = scratch("native");
        let path = dir.join("bad.jsonl");
        std::fs::write(&path, "{\"format\":\"demoplan-recording\",\"version\":9}\n").unwrap();
        let kind = SourceKind::of(&path).unwrap();
        assert_eq!(kind, SourceKind::Native);
        match open_recording(&path, kind, None) {
            Err(OpenError::Recording(e)) => assert_eq!(e.line, 1),
            Err(other) => panic!("expected a recording error, got {other:?}"),
            Ok(_) => panic!("a recording of version 9 was opened"),
        }
        std::fs::remove_dir_all(&dir).unwrap();
    }
}
