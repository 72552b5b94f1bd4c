//! What the world watches around each stage it runs during a tick: the stage's wall-clock
//! time (when timing is on) and whether it saturated, so that a tick's first saturation can
//! be put down to a stage ([`super::health::SaturationSite`]).
//!
//! Both are reporting, outside the simulated state. The saturation counter is read before
//! and after each stage call (two thread-local reads), never inside a stage's loops.

use super::stage::StageTimings;
use crate::math::saturation::saturation_count;
use crate::types::Stage;

/// The watch over one tick's stages.
pub(crate) struct StageWatch {
    /// The world's timings, when enabled; handed back after the tick.
    pub timings: Option<Box<StageTimings>>,
    /// The first stage that saturated during the tick.
    pub first_saturated: Option<Stage>,
}

impl StageWatch {
    /// A watch for a tick, with the world's timings (if enabled).
    pub fn new(timings: Option<Box<StageTimings>>) -> Self {
        Self {
            timings,
            first_saturated: None,
        }
    }

    /// Runs `f` as (part of) `stage`: times it when timing is on, and notes the stage if
    /// it is the tick's first to saturate.
    #[inline]
    pub fn run<T>(&mut self, stage: Stage, f: impl FnOnce() -> T) -> T {
        let before = saturation_count();
        let value = match &mut self.timings {
            Some(t) => t.time(stage, f),
            None => f(),
        };
        if self.first_saturated.is_none() && saturation_count() != before {
            self.first_saturated = Some(stage);
        }
        value
    }
}
