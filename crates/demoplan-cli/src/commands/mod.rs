//! One module per subcommand.

pub mod check;
pub mod classify;
pub mod demo_input;
pub mod execute;
pub mod fmt;
pub mod import;
pub mod inspect;
pub mod library;
pub mod plan;
pub mod reproduce;
pub mod segment;
pub mod simulate;
pub mod solve;
pub mod study;
pub mod timeline;
pub mod translate;
pub mod validate;
