//! Tasks for tests, shared by the integration tests and the crate's unit tests
//! (`src/lib.rs` includes this file under `cfg(test)`): random valid tasks for property
//! tests, and `op`, an operator written briefly. They live in `task::testing` (feature
//! `testing`), shared with translate's tests.

#![allow(unused_imports)] // each test binary uses its part

pub use task::testing::{op, optimal_cost, task, tasks};
