//! A progress bar on standard error, for long runs watched from a terminal.

use std::io::{IsTerminal, Write};

/// Runs longer than this many ticks get a progress bar.
const MIN_TICKS: u64 = 2000;

/// Width of the bar in characters.
const WIDTH: u64 = 40;

/// A one-line progress bar, redrawn when the percentage changes. Shown only when standard
/// error is a terminal and the work is long; otherwise every call does nothing.
#[derive(Debug)]
pub struct Progress {
    total: u64,
    /// What is counted, for the line: `tick`, `run`.
    unit: &'static str,
    shown_percent: Option<u64>,
    enabled: bool,
}

impl Progress {
    /// A bar for a run of `total` ticks.
    pub fn new(total: u64) -> Self {
        Self {
            total,
            unit: "tick",
            shown_percent: None,
            enabled: total > MIN_TICKS && std::io::stderr().is_terminal(),
        }
    }

    /// A bar for a benchmark of `total` runs, each of which may take seconds.
    pub fn runs(total: usize) -> Self {
        Self {
            total: total as u64,
            unit: "run",
            shown_percent: None,
            enabled: total > 0 && std::io::stderr().is_terminal(),
        }
    }

    /// Shows that `done` of the ticks have run.
    pub fn update(&mut self, done: u64) {
        if !self.enabled {
            return;
        }
        let percent = done.saturating_mul(100) / self.total;
        if self.shown_percent == Some(percent) {
            return;
        }
        self.shown_percent = Some(percent);
        let filled = (percent * WIDTH / 100) as usize;
        let bar = format!(
            "{}{}",
            "#".repeat(filled),
            "-".repeat(WIDTH as usize - filled)
        );
        let total = self.total;
        let _ = write!(
            std::io::stderr().lock(),
            "\r[{bar}] {percent:3}% {} {done}/{total}",
            self.unit
        );
    }

    /// Erases the bar.
    pub fn finish(&mut self) {
        if self.enabled && self.shown_percent.is_some() {
            let _ = write!(std::io::stderr().lock(), "\r\x1b[2K");
        }
    }
}
