//! Import of real recordings into demoplan's native model (`docs/import.md`).
//!
//! A [`Mapping`] (TOML, or [`Mapping::default_for`] a [`Format`]) says which source names
//! are hands, cubes and tables, the source's axes and quaternion order, and where grasps
//! and contacts come from. A [`Source`] replays a file as [`Event`]s; [`import`] makes two
//! passes over it ([`Importer::survey`] plans the [`recording::Header`],
//! [`Importer::assemble`] yields the [`recording::Frame`]s) and writes a native recording
//! through [`recording::Writer`], in REP 103 conventions, with a per-file [`Report`].
//!
//! # How a source plugs in
//!
//! A source implements [`Source`]: `pass` reads the file from its start and sends, in time
//! order, one [`Event::Observe`] per entity observation (source name, pose in the source's
//! own axes and quaternion order, optionally velocity, grip, held object, "grabbed by",
//! contacts) and one [`Event::Frame`] per frame tick (a Unity step, a message of a bag's
//! clock topic). Times are seconds on the source's clock. `pass` is called twice, so the
//! source must be re-readable (it reopens its file); memory stays bounded by one step or
//! message. When the [`Sink`] returns a [`Problem`], the source stops and returns
//! [`ImportError::Input`] with its [`Location`] (step, line and column; or topic and
//! message index). Conversion of axes and units, names, tables, grasps from geometry,
//! `max_age` and gaps are the core's job, not the source's. [`unity::UnityLog`] is the
//! reference source.
//!
//! ```
//! use import::{import, unity::UnityLog, Format, Mapping};
//!
//! let log = br#"{"playbackTimestepMilliseconds": 20, "log": [
//!   {"time": 0, "logStep": [
//!     {"name": "VR_Controller_R", "position": [0.3, 1.0, 0.2], "orientation": [1, 0, 0, 0],
//!      "velocity": [0, 0, 0], "events": []},
//!     {"name": "Cube_red", "position": [0.0, 0.8, 0.4], "orientation": [1, 0, 0, 0],
//!      "velocity": [0, 0, 0], "events": []}]},
//!   {"time": 50, "logStep": [
//!     {"name": "VR_Controller_R", "position": [0.1, 0.9, 0.4], "orientation": [1, 0, 0, 0],
//!      "velocity": [0, 0, 0], "events": [{"name": "OnGrabPressReplay", "property": "Cube_red,7"}]},
//!     {"name": "Cube_red", "position": [0.0, 0.8, 0.4], "orientation": [1, 0, 0, 0],
//!      "velocity": [0, 0, 0], "events": []}]}
//! ]}"#;
//! let mut source = UnityLog::new(|| Ok(&log[..]));
//! let (bytes, header, report) =
//!     import(&mut source, &Mapping::default_for(Format::Unity), "demo", Vec::new())?;
//! assert_eq!(header.entities.len(), 3); // right_hand, Cube_red and the inferred table
//! assert_eq!(report.grasps, 1);
//! let recording = recording::Recording::read(&bytes[..])?;
//! let cube = recording.header.find("Cube_red").unwrap();
//! // Unity (0, 0.8, 0.4) is REP 103 (0.4, 0, 0.8).
//! assert_eq!(recording.frames[0].state(cube).unwrap().pose.position.to_array(), [0.4, 0.0, 0.8]);
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

mod assemble;
mod axes;
mod batch;
mod error;
mod glob;
mod mapping;
mod open;
pub mod ros;
/// Counts the bytes a reader reads, for progress (bags use it too).
pub use bags::CountingReader;
pub mod unity;

pub use assemble::{
    import, Event, Gap, Held, IgnoredEntity, Importer, MappedEntity, Observation, Report, Sink,
    Source, SOURCE_PASSES,
};
pub use axes::{Axes, QuaternionOrder, SignedAxis};
pub use batch::{formats, mappings_used, plan_import, BatchError, PlanError, Planned};
pub use error::{ImportError, InputError, Location, Problem};
pub use mapping::{
    native_name, strip_prefix, BagMapping, ContactSource, EntityRule, Format, GraspSource, Mapping,
    MappingError, ObjectListFields, Origin, Resolved, Role, CUBE_SIZE, HAND_SIZE, OTHER_SIZE,
};
pub use open::{open_recording, recording_id, OpenError, RecordingReader, SourceKind};
