//! A fixed-timestep accumulator for game loops.
//!
//! The simulation always advances in whole ticks of `1 / tick_rate` seconds; the game
//! feeds the accumulator its variable frame time and gets back how many ticks to run, plus
//! the fraction of a tick left over for interpolating the rendered state between the last
//! two ticks (`alpha`, in [0, 1)). Frame time is measured by the game and never enters the
//! simulation: only the tick count does, so every peer still runs the same ticks.

use core::time::Duration;

/// Converts variable frame times into a whole number of fixed ticks.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct FixedTimestep {
    tick_nanos: u64,
    accumulated_nanos: u64,
    max_ticks_per_frame: u32,
}

impl FixedTimestep {
    /// An accumulator for `tick_rate` ticks per second (at least 1) that runs at most
    /// `max_ticks_per_frame` ticks per frame, dropping the excess after a long stall
    /// (the usual guard against the "spiral of death").
    pub fn new(tick_rate: u32, max_ticks_per_frame: u32) -> Self {
        Self {
            tick_nanos: 1_000_000_000 / u64::from(tick_rate.max(1)),
            accumulated_nanos: 0,
            max_ticks_per_frame: max_ticks_per_frame.max(1),
        }
    }

    /// Adds a frame's elapsed time and returns how many ticks to simulate now.
    pub fn advance(&mut self, frame_time: Duration) -> u32 {
        let frame_nanos = u64::try_from(frame_time.as_nanos()).unwrap_or(u64::MAX);
        self.accumulated_nanos = self.accumulated_nanos.saturating_add(frame_nanos);
        let due = self.accumulated_nanos / self.tick_nanos;
        let ticks = due.min(u64::from(self.max_ticks_per_frame));
        self.accumulated_nanos = if due > ticks {
            self.accumulated_nanos % self.tick_nanos
        } else {
            self.accumulated_nanos - ticks * self.tick_nanos
        };
        ticks as u32
    }

    /// How far the current time is between the last tick and the next, in [0, 1).
    /// Render `previous.lerp(current, alpha)`.
    pub fn alpha(&self) -> f64 // ok-det: render alpha, never simulated
    {
        self.accumulated_nanos as f64 / self.tick_nanos as f64 // ok-det: render alpha
    }

    /// Length of one tick.
    pub fn tick_duration(&self) -> Duration {
        Duration::from_nanos(self.tick_nanos)
    }
}
