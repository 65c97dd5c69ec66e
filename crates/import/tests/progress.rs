//! The byte counter a caller watches for progress: after an import it has counted the
//! bytes of every pass over the source, for ROS 1 bags, a ROS 2 folder and a Unity log.

#![allow(clippy::unwrap_used, clippy::expect_used)] // tests fail loudly by design

use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicU64, Ordering};
use std::sync::Arc;

use import::ros::{bag_size, RosBag};
use import::unity::UnityLog;
use import::{import, CountingReader, Format, Mapping, SOURCE_PASSES};

fn bag_fixtures() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../bags/tests/fixtures")
}

/// The sum of the sizes of a folder's `.mcap` files.
fn mcap_bytes(folder: &Path) -> u64 {
    std::fs::read_dir(folder)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|x| x == "mcap"))
        .map(|p| std::fs::metadata(p).unwrap().len())
        .sum()
}

/// Imports `path` watching the counter: (bytes after opening, bytes at the end).
fn counted_bag_import(path: &Path, format: Format) -> (u64, u64) {
    let mapping = Mapping::default_for(format);
    let counter = Arc::new(AtomicU64::new(0));
    let mut bag = RosBag::open_counting(path, &mapping, Some(counter.clone())).unwrap();
    let opened = counter.load(Ordering::Relaxed);
    import(&mut bag, &mapping, "counted", Vec::new()).unwrap();
    (opened, counter.load(Ordering::Relaxed))
}

#[test]
fn a_ros2_folder_counts_its_mcap_files_once_per_pass() {
    for stem in ["p01-d01", "p01-d02"] {
        let folder = bag_fixtures().join(format!("{stem}-ros2"));
        let size = mcap_bytes(&folder);
        let (opened, end) = counted_bag_import(&folder, Format::Ros2);
        assert_eq!(bag_size(&folder).unwrap(), size, "{stem}");
        // Listing the topics reads the files through once, then each pass of the import
        // reads them through again: a caller's bar ends at `opened + passes * size`.
        assert_eq!(opened, size, "{stem}");
        assert_eq!(end, opened + SOURCE_PASSES * size, "{stem}");
    }
}

#[test]
fn a_ros1_bag_counts_its_index_then_a_full_pass() {
    for name in ["p01-d01.bz2.bag", "p01-d01.lz4.bag", "p01-d02.lz4.bag"] {
        let path = bag_fixtures().join(name);
        let size = std::fs::metadata(&path).unwrap().len();
        let (opened, end) = counted_bag_import(&path, Format::Ros1);
        assert_eq!(bag_size(&path).unwrap(), size, "{name}");
        // Opening reads the header and the index only (through a buffer, so a little more
        // than the index); each pass reads the whole file and the index again.
        assert!(opened > 0 && opened < size, "{name}: {opened} of {size}");
        assert!(end >= opened + SOURCE_PASSES * size, "{name}: {end}");
        assert!(
            end <= opened + SOURCE_PASSES * (size + opened),
            "{name}: {end}"
        );
    }
}

#[test]
fn a_unity_log_read_through_a_counting_reader_counts_both_passes() {
    let path = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../demoplan-cli/tests/fixtures/unity/p01-d01.json");
    let size = std::fs::metadata(&path).unwrap().len();
    let counter = Arc::new(AtomicU64::new(0));
    let mut log = UnityLog::new(|| {
        Ok(CountingReader::new(
            std::fs::File::open(&path)?,
            counter.clone(),
        ))
    });
    let mapping = Mapping::default_for(Format::Unity);
    import(&mut log, &mapping, "counted", Vec::new()).unwrap();
    assert_eq!(counter.load(Ordering::Relaxed), SOURCE_PASSES * size);
}
