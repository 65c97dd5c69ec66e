//! The progress bar of `reproduce` and `study`: the experiment reports cells done, the
//! cell running and the time since the start; this draws them with an estimate of the
//! time left, on standard error and only when it is a terminal.

use std::io::IsTerminal;

use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};

/// A bar, hidden when standard error is not a terminal.
#[derive(Debug)]
pub struct Bar {
    bar: ProgressBar,
}

impl Bar {
    pub fn new() -> Bar {
        let bar = ProgressBar::with_draw_target(
            None,
            if std::io::stderr().is_terminal() {
                ProgressDrawTarget::stderr()
            } else {
                ProgressDrawTarget::hidden()
            },
        );
        let style = ProgressStyle::with_template(
            "[{bar:30}] {pos}/{len} {elapsed_precise} (about {eta} left) {msg}",
        )
        .map(|s| s.progress_chars("#> "))
        .unwrap_or_else(|_| ProgressStyle::default_bar());
        bar.set_style(style);
        Bar { bar }
    }

    /// Shows where the grid is.
    pub fn update(&self, p: experiment::Progress<'_>) {
        self.bar.set_length(p.total as u64);
        self.bar.set_position(p.done as u64);
        self.bar.set_message(p.current.to_string());
    }

    pub fn finish(&self) {
        self.bar.finish_and_clear();
    }
}
