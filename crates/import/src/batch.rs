//! Importing several sources into one folder (`demoplan import`): every source's kind and
//! output file are planned before anything is written, so that two sources with one
//! output name are refused with nothing written; then each source is opened for its two
//! passes, counting the bytes it reads (for a progress bar).

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicU64, Ordering};
use std::sync::Arc;

use crate::{CountingReader, Format, ImportError, Mapping, OpenError, Source, SourceKind};

/// One source of an import, and where its recording goes.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Planned {
    pub source: PathBuf,
    pub kind: SourceKind,
    /// The recording's id: the source's file stem.
    pub stem: String,
    /// `DIR/STEM.jsonl`.
    pub out: PathBuf,
}

/// Why an import was refused before it wrote anything.
#[derive(Debug, thiserror::Error)]
pub enum PlanError {
    /// A source that could not be told apart ([`SourceKind::of`]).
    #[error("{error}")]
    Open { path: PathBuf, error: OpenError },
    /// A native recording, which needs no import.
    #[error(
        "{}: not a source import reads (a Unity playback log: a JSON object with \
         `playbackTimestepMilliseconds` and `log`; a ROS 1 bag, an MCAP file or a ROS 2 \
         bag folder)",
        .0.display()
    )]
    Native(PathBuf),
    /// Two sources whose recordings would have one name.
    #[error(
        "{} and {} would both be written to {}: import them into different folders \
         (nothing was written)",
        first.display(), second.display(), out.display()
    )]
    Clash {
        first: PathBuf,
        second: PathBuf,
        out: PathBuf,
    },
}

/// Plans the import of `sources` into the folder `dir`, in order, each to
/// `DIR/STEM.jsonl`.
pub fn plan_import(sources: &[PathBuf], dir: &Path) -> Result<Vec<Planned>, PlanError> {
    let mut outputs: BTreeMap<PathBuf, &PathBuf> = BTreeMap::new();
    let mut plan = Vec::new();
    for source in sources {
        let kind = SourceKind::of(source).map_err(|error| PlanError::Open {
            path: source.clone(),
            error,
        })?;
        if kind == SourceKind::Native {
            return Err(PlanError::Native(source.clone()));
        }
        let stem = source
            .file_stem()
            .map(|s| s.to_string_lossy().into_owned())
            .unwrap_or_default();
        let out = dir.join(format!("{stem}.jsonl"));
        if let Some(first) = outputs.insert(out.clone(), source) {
            return Err(PlanError::Clash {
                first: first.clone(),
                second: source.clone(),
                out,
            });
        }
        plan.push(Planned {
            source: source.clone(),
            kind,
            stem,
            out,
        });
    }
    Ok(plan)
}

/// The formats of the planned sources, each once, by name (a mapping per format).
pub fn formats(plan: &[Planned]) -> Vec<Format> {
    let mut formats: Vec<Format> = plan.iter().map(Planned::format).collect();
    formats.sort_by_key(|f| f.name());
    formats.dedup();
    formats
}

/// The closing words of `demoplan import`: each mapping used (by format name), in the
/// mapping file's own syntax, for the user to save, edit and pass back with `--mapping`.
pub fn mappings_used(mappings: &BTreeMap<&'static str, Mapping>) -> String {
    let mut text = String::new();
    for (format, mapping) in mappings {
        let which = if mappings.len() > 1 {
            format!(" for {format} sources")
        } else {
            String::new()
        };
        text.push_str(&format!(
            "\nmapping used{which} (save it, edit it and pass it with --mapping):\n\n"
        ));
        text.push_str(&mapping.to_toml());
    }
    text
}

/// Why a planned source's recording was not written.
#[derive(Debug, thiserror::Error)]
pub enum BatchError {
    /// The source could not be opened or imported.
    #[error(transparent)]
    Import(ImportError),
    /// The recording could not be written (nothing of it was).
    #[error(transparent)]
    Write(atomic_write::WriteError),
}

impl Planned {
    /// Imports the source into its recording, `out`, written whole or not at all, and
    /// returns what `demoplan import` says of it ([`Planned::imported`]). Every byte
    /// read is counted in `bytes_read` ([`Planned::open`]); `opened` is told the count
    /// once the source is open, before its passes.
    pub fn import_file(
        &self,
        mapping: &Mapping,
        bytes_read: Arc<AtomicU64>,
        opened: impl FnOnce(u64),
    ) -> Result<String, BatchError> {
        let mut source = self
            .open(mapping, bytes_read.clone())
            .map_err(BatchError::Import)?;
        opened(bytes_read.load(Ordering::Relaxed));
        let (mut failure, mut said) = (None, String::new());
        let written = atomic_write::write_atomically_with(&self.out, |w| {
            match crate::import(source.as_mut(), mapping, &self.stem, w) {
                Ok((_, header, report)) => {
                    said = self.imported(&header, &report);
                    Ok(())
                }
                Err(e) => {
                    failure = Some(e);
                    Err(std::io::Error::other("import failed"))
                }
            }
        });
        match failure {
            Some(e) => Err(BatchError::Import(e)),
            None => written.map(|()| said).map_err(BatchError::Write),
        }
    }

    /// The bytes one pass over the source reads: a bag folder's are its MCAP files' (the
    /// bag knows them), a file's its own; 0 when that cannot be known.
    pub fn size(&self) -> u64 {
        let bag = match self.kind {
            SourceKind::Bag(_) => crate::ros::bag_size(&self.source).ok(),
            _ => None,
        };
        bag.unwrap_or_else(|| std::fs::metadata(&self.source).map_or(0, |m| m.len()))
    }

    /// What `demoplan import` says of the source once imported: `SOURCE -> OUT`, then the
    /// import's report ([`crate::Report::render`]) indented.
    pub fn imported(&self, header: &recording::Header, report: &crate::Report) -> String {
        let mut text = format!("{} -> {}\n", self.source.display(), self.out.display());
        for line in report.render(header).lines() {
            text.push_str(&format!("  {line}\n"));
        }
        text
    }

    /// The format whose mapping the source is imported with.
    pub fn format(&self) -> Format {
        self.kind.format().unwrap_or(Format::Unity)
    }

    /// Opens the source for its passes; every byte it reads, opening included (a bag's
    /// index or topics), is counted in `bytes_read`.
    pub fn open(
        &self,
        mapping: &Mapping,
        bytes_read: Arc<AtomicU64>,
    ) -> Result<Box<dyn Source>, ImportError> {
        match self.kind {
            SourceKind::Bag(_) => Ok(Box::new(crate::ros::RosBag::open_counting(
                &self.source,
                mapping,
                Some(bytes_read),
            )?)),
            _ => {
                let path = self.source.clone();
                Ok(Box::new(crate::unity::UnityLog::new(move || {
                    let file = std::fs::File::open(&path)?;
                    Ok(CountingReader::new(file, bytes_read.clone()))
                })))
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn scratch(name: &str) -> PathBuf {
        let dir = std::env::temp_dir().join(format!("import-batch-{}-{name}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir_all(dir.join("a")).unwrap();
        std::fs::create_dir_all(dir.join("b")).unwrap();
        dir
    }

    const UNITY: &str = r#"{"playbackTimestepMilliseconds": 10, "log": []}"#;

    #[test]
    fn a_source_is_imported_into_its_file_whole_or_not_at_all() {
        let dir = scratch("import-file");
        let bag =
            Path::new(env!("CARGO_MANIFEST_DIR")).join("../bags/tests/fixtures/p01-d01.lz4.bag");
        let plan = plan_import(std::slice::from_ref(&bag), &dir.join("a")).unwrap();
        let mapping = Mapping::default_for(plan[0].format());
        let counter = Arc::new(AtomicU64::new(0));
        let mut at_open = 0;
        let said = plan[0]
            .import_file(&mapping, counter.clone(), |n| at_open = n)
            .unwrap();
        assert!(
            said.starts_with(&format!("{} -> ", bag.display())),
            "{said}"
        );
        let written = std::fs::read_to_string(dir.join("a/p01-d01.lz4.jsonl")).unwrap();
        let frames = recording::Reader::new(written.as_bytes()).unwrap();
        assert!(frames.map(Result::unwrap).count() > 0);
        let size = plan[0].size();
        assert!(at_open > 0);
        // Each pass reads the whole bag (and a ROS 1 bag's index again: tests/progress.rs).
        assert!(counter.load(Ordering::Relaxed) >= at_open + crate::SOURCE_PASSES * size);

        // A log whose entry is not one: an import error, and no file.
        let bad = dir.join("b/bad.json");
        std::fs::write(&bad, r#"{"playbackTimestepMilliseconds": 10, "log": [7]}"#).unwrap();
        let plan = plan_import(&[bad], &dir.join("b")).unwrap();
        let mapping = Mapping::default_for(plan[0].format());
        let e = plan[0].import_file(&mapping, counter, |_| ()).unwrap_err();
        assert!(matches!(e, BatchError::Import(_)), "{e}");
        assert!(!dir.join("b/bad.jsonl").exists());
    }

    #[test]
    fn the_mappings_used_are_named_by_format_only_when_there_are_several() {
        let unity = Mapping::default_for(Format::Unity);
        let one = mappings_used(&BTreeMap::from([("unity", unity.clone())]));
        assert!(one.starts_with("\nmapping used (save it"), "{one}");
        assert!(one.ends_with(&unity.to_toml()), "{one}");
        let bag = Mapping::default_for(Format::Ros1);
        let two = mappings_used(&BTreeMap::from([("ros1", bag), ("unity", unity)]));
        assert!(two.contains("mapping used for ros1 sources"), "{two}");
        assert!(two.contains("mapping used for unity sources"), "{two}");
    }

    #[test]
    fn sources_are_planned_to_their_stems_and_a_clash_is_refused() {
        let dir = scratch("plan");
        let (a, b) = (dir.join("a/take.json"), dir.join("b/take.json"));
        std::fs::write(&a, UNITY).unwrap();
        std::fs::write(&b, UNITY).unwrap();
        let out = dir.join("out");
        let plan = plan_import(std::slice::from_ref(&a), &out).unwrap();
        assert_eq!(plan.len(), 1);
        assert_eq!(plan[0].kind, SourceKind::Unity);
        assert_eq!(
            (plan[0].stem.as_str(), &plan[0].out),
            ("take", &out.join("take.jsonl"))
        );
        assert_eq!(formats(&plan), vec![Format::Unity]);
        match plan_import(&[a.clone(), b.clone()], &out) {
            Err(PlanError::Clash { first, second, .. }) => assert_eq!((first, second), (a, b)),
            other => panic!("expected a clash, got {other:?}"),
        }
        let native = dir.join("a/rec.jsonl");
        std::fs::write(&native, "{\"format\":\"demoplan-recording\"}\n").unwrap();
        assert!(matches!(
            plan_import(&[native], &out),
            Err(PlanError::Native(_))
        ));
        let _ = std::fs::remove_dir_all(&dir);
    }
}
