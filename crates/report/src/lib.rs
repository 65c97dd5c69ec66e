//! Figures and the report page of `demoplan reproduce`.
//!
//! The reproduce command runs the paper's grid (every priority domain, five goals, two
//! heuristics) and hands the results to this crate as an [`Experiment`]. The crate draws
//! the paper's figures and writes the report page; it does no I/O: figures come back as
//! SVG text and PNG bytes, the page as a string.
//!
//! - [`search_time_figure`]: Figures 5 and 6, search time per goal on a log axis, one
//!   line per domain; runs at the time limit are open markers at the limit.
//! - [`operators_figure`]: Figure 3, operators per type and priority level.
//! - [`goal_figure`] and [`goals_figure`]: Figure 4, the towers to build.
//! - [`timeline_figure`]: signals over time in panels with thresholds, and bands (a
//!   segmented recording, drawn by `demoplan timeline`).
//! - [`report_html`]: one self-contained page with the paper's Tables 3 and 4
//!   ([`search_time_table`], also as Markdown), the figures, the notes and every file.
//!
//! Figures use a small drawing model ([`Figure`], [`Shape`]) rendered to SVG; their
//! PNGs are that SVG rendered by resvg with one embedded font (DejaVu Sans Mono) and no
//! system fonts, and encoded by the `png` crate, so the same input gives the same bytes
//! on any machine.
//!
//! ```
//! use report::{goal_figure, Goal};
//! let goal = Goal { number: 1, tower: vec!["cube_1".into(), "cube_2".into()] };
//! let figure = goal_figure(&goal, 6);
//! assert!(figure.svg().contains("Goal 1"));
//! let png = figure.png()?;
//! assert!(png.starts_with(b"\x89PNG\r\n\x1a\n"));
//! # Ok::<(), report::RenderError>(())
//! ```

// The tests' shared helpers name this crate `report`, as the integration tests do.
#[cfg(test)]
extern crate self as report;
#[cfg(test)]
#[path = "../tests/common/mod.rs"]
mod test_common;

mod draw;
mod html;
mod model;
pub mod palette;
pub mod paper;
mod planner;
mod plots;
mod render;
mod timeline;

pub use draw::{pt, text_width, Anchor, Color, Figure, Point, Shape, Stroke, Text};
pub use html::{
    html_escape, report_html, search_time_table, time_table, Table, PAPER_IPDB, PAPER_LMCUT,
    PAPER_OPERATORS, PAPER_TITLE, RATIO_ROW,
};
pub use model::{
    domain_label, format_limit, format_seconds, ratio, ratio_by, slimming_ratio, slimming_ratio_by,
    time_cell, time_cell_by, Bound, Experiment, Goal, Level, Measure, Outcome, Ratio, Run,
};
pub use planner::Planner;
pub use plots::{
    decade_label, goal_figure, goals_figure, operators_figure, scaling_figure, search_time_figure,
    time_figure, LogScale, ScalingPanel, ScalingPoint, ScalingSeries,
};
pub use render::RenderError;
pub use timeline::{
    timeline_figure, Band, BandRow, Panel, Series, Threshold, Timeline, Track, MAX_POINTS,
};
