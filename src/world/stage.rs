//! The named stages of a tick, and their wall-clock timings.
//!
//! Timings are measured only when asked for ([`World::enable_timing`](super::World)), are
//! kept outside the simulated state, and never enter a snapshot or a checksum.

use std::time::{Duration, Instant};

/// The stages of [`World::step`](super::World::step), in the order they run.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub enum Stage {
    /// Apply the tick's commands: players in ascending index, commands in order.
    ApplyInputs,
    /// Particles: emit, age, accumulate forces, integrate (once per substep).
    Particles,
    /// Rigid bodies: collide, wake, solve, sleep (once per substep).
    Rigid,
    /// Soft bodies: XPBD substeps and spring-mass integration (once per substep).
    Soft,
    /// Fluid: emit, neighbours, density, pressure solve, advect (once per substep).
    Fluid,
    /// Advance the tick counter and clear per-tick accumulators.
    EndTick,
}

impl Stage {
    /// Every stage, in execution order.
    pub const ALL: [Stage; 6] = [
        Stage::ApplyInputs,
        Stage::Particles,
        Stage::Rigid,
        Stage::Soft,
        Stage::Fluid,
        Stage::EndTick,
    ];

    /// The stage's name as printed in timing tables.
    pub const fn name(self) -> &'static str {
        match self {
            Stage::ApplyInputs => "apply_inputs",
            Stage::Particles => "particles",
            Stage::Rigid => "rigid",
            Stage::Soft => "soft",
            Stage::Fluid => "fluid",
            Stage::EndTick => "end_tick",
        }
    }
}

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
