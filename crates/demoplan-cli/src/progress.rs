//! The progress bars, on standard error and only when it is a terminal: `reproduce` and
//! `study` show cells done, failed and to go, the cell running and the time since the
//! start with the time left (`experiment::Progress::time_left`) ([`Bar`]); `import` shows bytes read with the rate and the
//! time left ([`BytesBar`]).

use std::io::IsTerminal;
use std::sync::atomic::{AtomicBool, AtomicU64, Ordering};
use std::sync::Arc;
use std::time::Duration;

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
        let style = ProgressStyle::with_template("[{bar:30}] {pos}/{len} {elapsed_precise} {msg}")
            .map(|s| s.progress_chars("#> "))
            .unwrap_or_else(|_| ProgressStyle::default_bar());
        bar.set_style(style);
        Bar { bar }
    }

    /// Shows where the grid is: cells done, failed and left, the time left.
    pub fn update(&self, p: experiment::Progress<'_>) {
        self.bar.set_length(p.total as u64);
        self.bar.set_position(p.done as u64);
        let left = p
            .time_left()
            .map_or("?".into(), |t| format!("{:.0} s", t.as_secs_f64()));
        self.bar.set_message(format!(
            "{} failed, {} to go (about {left} left) {}",
            p.failed,
            p.remaining(),
            p.current
        ));
    }

    pub fn finish(&self) {
        self.bar.finish_and_clear();
    }
}

/// Bytes read of a long import (every pass over the source), from a counter the reader
/// advances: the readers (in library crates) only add to the counter, and a thread of
/// this bar's redraws from it every 100 ms. Hidden, with no thread, when standard error
/// is not a terminal or `shown` is false.
#[derive(Debug)]
pub struct BytesBar {
    bar: ProgressBar,
    bytes_read: Arc<AtomicU64>,
    stop: Arc<AtomicBool>,
    ticker: Option<std::thread::JoinHandle<()>>,
}

impl BytesBar {
    pub fn new(what: &str, total: u64, shown: bool) -> BytesBar {
        let shown = shown && std::io::stderr().is_terminal();
        let target = if shown {
            ProgressDrawTarget::stderr()
        } else {
            ProgressDrawTarget::hidden()
        };
        let bar = ProgressBar::with_draw_target(Some(total), target);
        let style = ProgressStyle::with_template(
            "{msg} [{bar:30}] {bytes}/{total_bytes} {binary_bytes_per_sec} (about {eta} left)",
        )
        .map(|s| s.progress_chars("#> "))
        .unwrap_or_else(|_| ProgressStyle::default_bar());
        bar.set_style(style);
        bar.set_message(what.to_string());
        let bytes_read = Arc::new(AtomicU64::new(0));
        let stop = Arc::new(AtomicBool::new(false));
        let ticker = shown.then(|| {
            let (bar, bytes_read, stop) = (bar.clone(), bytes_read.clone(), stop.clone());
            std::thread::spawn(move || {
                while !stop.load(Ordering::Relaxed) {
                    refresh(&bar, &bytes_read);
                    std::thread::sleep(Duration::from_millis(100));
                }
            })
        });
        BytesBar {
            bar,
            bytes_read,
            stop,
            ticker,
        }
    }

    /// The counter the reader advances.
    pub fn counter(&self) -> Arc<AtomicU64> {
        self.bytes_read.clone()
    }

    /// The total, once it is better known (a bag's topic listing is read before it).
    pub fn set_total(&self, total: u64) {
        self.bar.set_length(total);
    }

    /// Stops the redrawing and clears the bar.
    pub fn finish(mut self) {
        self.stop_ticker();
        self.bar.finish_and_clear();
    }

    fn stop_ticker(&mut self) {
        self.stop.store(true, Ordering::Relaxed);
        if let Some(ticker) = self.ticker.take() {
            let _ = ticker.join();
        }
    }
}

impl Drop for BytesBar {
    /// An import that fails leaves no thread drawing behind it.
    fn drop(&mut self) {
        self.stop_ticker();
        self.bar.finish_and_clear();
    }
}

fn refresh(bar: &ProgressBar, bytes_read: &AtomicU64) {
    let read = bytes_read.load(Ordering::Relaxed);
    // A ROS 1 bag's index is read again at each pass: the total grows rather than overflow.
    if read > bar.length().unwrap_or(0) {
        bar.set_length(read);
    }
    bar.set_position(read);
}
