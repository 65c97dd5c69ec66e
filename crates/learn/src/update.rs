//! The library as a file, and learning recordings into it while other learners may write
//! it too (`docs/reliability.md`).
//!
//! [`Update::run`] works in two phases, so that concurrent learners of one library lose
//! no counts and wait for each other only briefly: first the slow part, hashing and
//! segmenting the recordings the library does not count yet, without a lock; then,
//! holding the library's [`WriteLock`], reading the library again, adding the recordings
//! and writing it durably by a rename, so that the read and the write see no other writer
//! in between.

use std::path::{Path, PathBuf};
use std::time::Duration;

use crate::{
    content_hash, Batch, Grouping, Library, LibraryError, LockError, OperatorForm, Segmented,
    Waiting, WriteLock, DEFAULT_LAMBDA,
};

/// A library file that could not be read.
#[derive(Debug, thiserror::Error)]
pub enum LibraryFileError {
    /// The file cannot be opened or read.
    #[error("cannot read {}: {source}", path.display())]
    Io {
        path: PathBuf,
        source: std::io::Error,
    },
    /// The file is not UTF-8 text; `byte` is where it stops being.
    #[error("{}: not UTF-8 text (byte {byte})", path.display())]
    NotText { path: PathBuf, byte: usize },
    /// The text is no library this version reads; `text` is the file's, for showing
    /// the error's line.
    #[error("{}: {error}", path.display())]
    Library {
        path: PathBuf,
        text: String,
        error: LibraryError,
    },
}

impl Library {
    /// Reads a library file.
    pub fn read_file(path: &Path) -> Result<Library, LibraryFileError> {
        let bytes = std::fs::read(path).map_err(|source| LibraryFileError::Io {
            path: path.to_path_buf(),
            source,
        })?;
        let text = String::from_utf8(bytes).map_err(|e| LibraryFileError::NotText {
            path: path.to_path_buf(),
            byte: e.utf8_error().valid_up_to(),
        })?;
        Library::from_json(&text).map_err(|error| LibraryFileError::Library {
            path: path.to_path_buf(),
            text,
            error,
        })
    }
}

/// What to learn into: the library to add to (or a new one), the file to write, and the
/// settings of a new library, which an existing one must have.
#[derive(Debug, Clone)]
pub struct Update<'a> {
    /// The library to add to (it may also be `out`); `None`: a new library.
    pub library: Option<&'a Path>,
    /// Where the library is written.
    pub out: &'a Path,
    /// The largest cost of a new library (default [`DEFAULT_LAMBDA`]).
    pub lambda: Option<u32>,
    /// How a new library groups segments into activities (default `settled`).
    pub grouping: Option<Grouping>,
    /// The form of a new library's operators (default specific; `learn --generalise`:
    /// generalised).
    pub form: Option<OperatorForm>,
    /// How long to wait while another learner holds the lock; `None`: as long as it
    /// takes.
    pub lock_timeout: Option<Duration>,
}

/// Why an update wrote nothing. Errors of the segmentation are the caller's.
#[derive(Debug, thiserror::Error)]
pub enum UpdateError {
    /// The library to add to could not be read.
    #[error(transparent)]
    Read(#[from] LibraryFileError),
    /// A recording could not be read for its hash.
    #[error("cannot read {}: {source}", path.display())]
    Hash {
        path: PathBuf,
        source: std::io::Error,
    },
    /// The library's lambda is not the one asked for (`--lambda`): costs of one library
    /// use one.
    #[error(
        "--lambda {asked} differs from the library's lambda {library} ({}); costs of one \
         library use one lambda",
        path.display()
    )]
    Lambda {
        path: PathBuf,
        asked: u32,
        library: u32,
    },
    /// The library groups segments otherwise than asked (`--activities`): one library
    /// counts activities of one kind.
    #[error(
        "--activities {} differs from the library's `{}` activities ({}); one library \
         counts activities of one kind",
        asked.name(), library.name(), path.display()
    )]
    Grouping {
        path: PathBuf,
        asked: Grouping,
        library: Grouping,
    },
    /// The library's operators are of another form than asked (`--generalise`): one
    /// library holds operators of one form.
    #[error(
        "{} operators asked for{}, but the library's are {} ({}); one library holds \
         operators of one form: learn into a new library to change it",
        asked.name(),
        if *asked == OperatorForm::Generalised { " (--generalise)" } else { "" },
        library.name(),
        path.display()
    )]
    Form {
        path: PathBuf,
        asked: OperatorForm,
        library: OperatorForm,
    },
    /// The library's lock was not taken.
    #[error(transparent)]
    Lock(#[from] LockError),
    /// The library could not be written.
    #[error(transparent)]
    Write(#[from] atomic_write::WriteError),
}

/// An update done: the library as written, and a line per recording saying what was
/// counted.
#[derive(Debug)]
pub struct Updated {
    pub library: Library,
    pub log: String,
}

impl Update<'_> {
    /// Reads the library to add to, if any, and checks its settings: the first look of
    /// phase one (which recordings it counts already), and the read under the lock.
    pub fn read(&self) -> Result<Option<Library>, UpdateError> {
        let Some(path) = self.library else {
            return Ok(None);
        };
        let library = Library::read_file(path)?;
        if let Some(asked) = self.lambda.filter(|&l| l != library.lambda) {
            return Err(UpdateError::Lambda {
                path: path.to_path_buf(),
                asked,
                library: library.lambda,
            });
        }
        if let Some(asked) = self.grouping.filter(|&g| g != library.grouping) {
            return Err(UpdateError::Grouping {
                path: path.to_path_buf(),
                asked,
                library: library.grouping,
            });
        }
        if let Some(asked) = self.form.filter(|&f| f != library.form()) {
            return Err(UpdateError::Form {
                path: path.to_path_buf(),
                asked,
                library: library.form(),
            });
        }
        Ok(Some(library))
    }

    /// Learns `files` into the library, in the two phases of the module's doc. `before`
    /// is the first look at the library ([`Update::read`]): the recordings it counts
    /// already are not segmented again. `segment` segments a recording (in phase one,
    /// and in phase two one that vanished from the library meanwhile); `waiting` hears
    /// once that another learner holds the lock.
    pub fn run<E: From<UpdateError>>(
        &self,
        before: Option<Library>,
        files: &[PathBuf],
        mut segment: impl FnMut(&Path) -> Result<Segmented, E>,
        waiting: impl FnOnce(&Waiting),
    ) -> Result<Updated, E> {
        let hash = |path: &Path| {
            std::fs::File::open(path)
                .and_then(content_hash)
                .map_err(|source| {
                    E::from(UpdateError::Hash {
                        path: path.to_path_buf(),
                        source,
                    })
                })
        };
        let batch = Batch::prepare(files, before.as_ref(), hash, &mut segment)?;
        drop(before);
        // The lock and the write go to the library's canonical path: through a symlink
        // or a relative name, one library is one file with one lock.
        let lock =
            WriteLock::acquire(self.out, self.lock_timeout, waiting).map_err(UpdateError::from)?;
        atomic_write::remove_stale_temporaries(lock.target());
        let mut library = match self.read()? {
            Some(library) => library,
            None => Library::with_form(
                self.lambda.unwrap_or(DEFAULT_LAMBDA),
                self.grouping.unwrap_or_default(),
                self.form.unwrap_or_default(),
            ),
        };
        let log = batch.add_to(&mut library, &mut segment)?;
        atomic_write::write_durably(lock.target(), library.to_json()).map_err(UpdateError::from)?;
        drop(lock);
        Ok(Updated { library, log })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_library_with_other_settings_or_no_library_text_is_refused_naming_it() {
        let dir = std::env::temp_dir().join(format!("learn-update-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir_all(&dir).unwrap();
        let path = dir.join("lib.json");
        std::fs::write(&path, Library::with_grouping(100, Grouping::Runs).to_json()).unwrap();
        let update = |lambda, grouping| Update {
            library: Some(&path),
            out: &path,
            lambda,
            grouping,
            form: None,
            lock_timeout: None,
        };
        assert!(update(Some(100), Some(Grouping::Runs))
            .read()
            .unwrap()
            .is_some());
        assert!(matches!(
            update(Some(50), None).read(),
            Err(UpdateError::Lambda {
                asked: 50,
                library: 100,
                ..
            })
        ));
        let grouping = update(None, Some(Grouping::Settled)).read();
        assert!(
            matches!(
                &grouping,
                Err(UpdateError::Grouping {
                    asked: Grouping::Settled,
                    library: Grouping::Runs,
                    ..
                })
            ),
            "{grouping:?}"
        );
        // Each says what was asked, the library's setting, the file and why.
        let said = |e: Result<Option<Library>, UpdateError>| e.err().map(|e| e.to_string());
        assert_eq!(
            said(update(Some(50), None).read()),
            Some(format!(
                "--lambda 50 differs from the library's lambda 100 ({}); costs of one library \
                 use one lambda",
                path.display()
            ))
        );
        assert_eq!(
            said(grouping),
            Some(format!(
                "--activities settled differs from the library's `runs` activities ({}); one \
                 library counts activities of one kind",
                path.display()
            ))
        );
        let generalise = Update {
            form: Some(OperatorForm::Generalised),
            ..update(None, None)
        };
        assert_eq!(
            said(generalise.read()),
            Some(format!(
                "generalised operators asked for (--generalise), but the library's are \
                 specific ({}); one library holds operators of one form: learn into a new \
                 library to change it",
                path.display()
            ))
        );
        let specific = Update {
            form: Some(OperatorForm::Specific),
            ..update(None, None)
        };
        assert!(specific.read().unwrap().is_some());
        std::fs::write(&path, b"{\"format\": \xff}").unwrap();
        assert!(matches!(
            Library::read_file(&path),
            Err(LibraryFileError::NotText { byte: 11, .. })
        ));
        std::fs::write(&path, "{}").unwrap();
        assert!(matches!(
            Library::read_file(&path),
            Err(LibraryFileError::Library { .. })
        ));
        assert!(matches!(
            Library::read_file(&dir.join("missing.json")),
            Err(LibraryFileError::Io { .. })
        ));
        let _ = std::fs::remove_dir_all(&dir);
    }
}
