//! The wall-clock timings of a tick's stages ([`Stage`]).
//!
//! Timings are measured only when asked for ([`World::enable_timing`](super::World)), are
//! kept outside the simulated state, and never enter a snapshot or a checksum.

use std::time::{Duration, Instant};

use crate::types::Stage;

/// Accumulated wall-clock time per stage over the ticks run since timing was enabled.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct StageTimings {
    totals: [Duration; Stage::ALL.len()],
    runs: [u64; Stage::ALL.len()],
}

impl StageTimings {
    /// Runs `f`, adding its wall-clock time to `stage`.
    #[inline]
    pub(crate) fn time<T>(&mut self, stage: Stage, f: impl FnOnce() -> T) -> T {
        let start = Instant::now(); // ok-det: timing is reported, never simulated
        let value = f();
        self.totals[stage as usize] += start.elapsed();
        self.runs[stage as usize] += 1;
        value
    }

    /// Total time spent in `stage`.
    pub fn total(&self, stage: Stage) -> Duration {
        self.totals[stage as usize]
    }

    /// How many times `stage` ran.
    pub fn runs(&self, stage: Stage) -> u64 {
        self.runs[stage as usize]
    }

    /// Stages that ran at least once, with their total time and run count.
    pub fn rows(&self) -> impl Iterator<Item = (Stage, Duration, u64)> + '_ {
        Stage::ALL
            .into_iter()
            .filter(|s| self.runs(*s) > 0)
            .map(|s| (s, self.total(s), self.runs(s)))
    }
}
