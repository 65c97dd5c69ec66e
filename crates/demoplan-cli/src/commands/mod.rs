//! One module per subcommand.

pub mod check;
pub mod fmt;
pub mod plan;
pub mod translate;
pub mod validate;
