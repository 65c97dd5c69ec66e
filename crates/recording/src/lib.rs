//! Recordings of demonstrations: hands and objects tracked over time, and demoplan's
//! native JSON Lines format for them (`docs/recording-format.md`).
//!
//! A [`Recording`] is a [`Header`] (what was recorded: id, participant, task, nominal
//! frame rate, the tracked [`Entity`]s with their [`EntityKind`] and box size) and
//! [`Frame`]s (a time and, per entity, an [`EntityState`]: pose, optional velocity, for
//! hands a grip and the object held; and the [`Contact`]s reported). Entities are indexed
//! by [`EntityId`]. Conventions follow ROS REP 103: metres, seconds, right-handed, z up,
//! quaternions written (x, y, z, w).
//!
//! [`Summary`] gathers what a recording holds (timing, gaps, fields present) a frame at a
//! time and renders it for people.
//!
//! [`Reader`] streams: it reads the header when made and then one frame at a time, so a
//! recording of any length is read in bounded memory. Errors ([`ReadError`]) name the
//! line, the column and the field. [`Writer`] writes the same format and refuses frames
//! the reader would refuse. The crate does no I/O beyond the `BufRead` and `Write` it is
//! given, and never prints.
//!
//! ```
//! use recording::*;
//!
//! let header = Header {
//!     id: "demo".into(),
//!     participant: "p01".into(),
//!     task: "stack cube_b on cube_a".into(),
//!     frame_rate: 90.0,
//!     entities: vec![
//!         Entity { name: "right_hand".into(), kind: EntityKind::Hand,
//!                  size: Vec3::new(0.12, 0.09, 0.04), fixed: None },
//!         Entity { name: "cube_a".into(), kind: EntityKind::Cube,
//!                  size: Vec3::new(0.05, 0.05, 0.05), fixed: None },
//!     ],
//!     meta: Default::default(),
//! };
//! let mut frame = Frame::empty(0.0, 2);
//! frame.states[0] = Some(EntityState {
//!     pose: Pose { position: Vec3::new(0.3, -0.3, 0.8), orientation: Quaternion::IDENTITY },
//!     grip: Some(0.1),
//!     ..Default::default()
//! });
//! let mut writer = Writer::new(Vec::new(), &header)?;
//! writer.write_frame(&frame)?;
//! let bytes = writer.finish()?;
//!
//! let mut reader = Reader::new(&bytes[..])?;
//! assert_eq!(reader.header().entities.len(), 2);
//! let mut read = Frame::default();
//! assert!(reader.read_frame(&mut read)?);
//! assert_eq!(read, frame);
//! assert!(!reader.read_frame(&mut read)?);
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

mod activity;
mod check;
mod error;
mod excerpt;
mod model;
mod parser;
mod reader;
mod summary;
mod writer;

pub use activity::Activity;
pub use check::{check_frame, check_header, is_valid_name, Problem, MAX_ENTITIES, MAX_NAME_LEN};
pub use error::{ErrorKind, ReadError, WriteError};
pub use excerpt::{offending_line, Excerpt};
pub use model::{
    Contact, Entity, EntityId, EntityKind, EntityState, Frame, Header, Pose, Quaternion, Recording,
    Vec3,
};
pub use reader::{Reader, MAX_LINE_BYTES};
pub use summary::{Summary, GAP};
pub use writer::Writer;

/// The `format` field of a recording's header.
pub const FORMAT_NAME: &str = "demoplan-recording";

/// The format version this crate reads and writes.
pub const FORMAT_VERSION: u32 = 1;
