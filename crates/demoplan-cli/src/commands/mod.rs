//! One module per subcommand.

pub mod check;
pub mod fmt;
pub mod inspect;
pub mod plan;
pub mod simulate;
pub mod translate;
pub mod validate;
