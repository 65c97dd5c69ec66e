//! Grounding: from tracked poses to the paper's symbolic state variables (its Table 2),
//! frame by frame.
//!
//! For a recording's scene a [`FactSpace`] numbers every [`Fact`] it can have, in sort
//! order: `handMove(h)`, `handOpen(h)`, `actedOn(h, c)`, `graspable(h, c)`,
//! `inHand(h, c)`, `inTouch(a, b)`, `onTop(a, b)` over its hands, objects and things. A
//! [`State`] is a bit set over that space, so that states compare, differ and restrict
//! to a set of objects in a few word operations, and list their facts sorted.
//!
//! A [`Grounder`] turns [`recording::Frame`]s into [`GroundedFrame`]s: a state and, per
//! hand, its [`HandFacts`] (the tuple the paper segments and classifies by). Every
//! threshold has hysteresis, and a change counts only once it has lasted
//! [`GroundingConfig::min_duration`] (dated from where it began), so tracker noise makes
//! no flicker. The thresholds are a [`GroundingConfig`], the paper's by default, read
//! from TOML (`docs/grounding.md`).
//!
//! ```
//! use grounding::{GroundingConfig, Grounder};
//!
//! let text = std::fs::read_to_string(concat!(
//!     env!("CARGO_MANIFEST_DIR"),
//!     "/../../docs/examples/two-cubes.jsonl"
//! ))?;
//! let recording = recording::Recording::read(text.as_bytes())?;
//! let config = GroundingConfig::from_toml("min_duration = 0.0")?;
//! let mut grounder = Grounder::new(&recording.header, &config);
//! let mut held = Vec::new();
//! let mut collect = |g: &grounding::GroundedFrame<'_>| held.push(g.hands[0].in_hand);
//! for frame in &recording.frames {
//!     grounder.push(frame, &mut collect);
//! }
//! grounder.finish(&mut collect);
//! let cube_a = recording.header.find("cube_a");
//! assert_eq!(held, [None, None, cube_a, cube_a, cube_a, None, None]);
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```
//!
//! The crate does no I/O and never prints.

mod config;
mod debounce;
mod fact;
mod ground;

pub use config::{
    ActedOnConfig, ConfigError, GraspableConfig, GroundingConfig, HandMoveConfig, HandOpenConfig,
    InHandConfig, InHandSource, InTouchConfig, VelocitySource,
};
pub use fact::{Fact, FactDisplay, FactId, FactSpace, Predicate, State};
pub use ground::{GroundedFrame, Grounder, HandFacts, HandSignals};
