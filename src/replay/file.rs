//! A replay in memory: the scene, the inputs fed to it and the checkpoints recorded.

use core::num::NonZeroU32;

use super::format::Checkpoint;
use crate::math::Fx;
use crate::scene::Scene;
use crate::world::TickInput;

/// A recorded run, ready to verify, re-record or write.
///
/// Built by a [`Recorder`](super::Recorder) or read from a file
/// ([`Replay::read`]); its invariants are those of the file format (see
/// [`format`](super::format)): the scene's script is empty, the inputs are canonical and
/// below `ticks`, and the checkpoints sit at tick 0, at every multiple of
/// `checksum_every` and at `ticks`.
#[derive(Clone, Debug, PartialEq)]
pub struct Replay {
    pub(super) state_version: u32,
    pub(super) scene: Scene<Fx>,
    pub(super) inputs: Vec<TickInput<Fx>>,
    pub(super) ticks: u64,
    pub(super) checksum_every: NonZeroU32,
    pub(super) checkpoints: Vec<Checkpoint>,
}

impl Replay {
    /// The engine state version the replay was recorded with.
    pub fn state_version(&self) -> u32 {
        self.state_version
    }

    /// The scene, with an empty script (its inputs are in [`Replay::inputs`]).
    pub fn scene(&self) -> &Scene<Fx> {
        &self.scene
    }

    /// The non-empty inputs, in ascending tick order.
    pub fn inputs(&self) -> &[TickInput<Fx>] {
        &self.inputs
    }

    /// Ticks simulated.
    pub fn ticks(&self) -> u64 {
        self.ticks
    }

    /// Interval between checkpoints, in ticks.
    pub fn checksum_every(&self) -> NonZeroU32 {
        self.checksum_every
    }

    /// The recorded checkpoints, in ascending tick order; the last is at [`Replay::ticks`].
    pub fn checkpoints(&self) -> &[Checkpoint] {
        &self.checkpoints
    }

    /// The world checksum after the last tick.
    pub fn final_checksum(&self) -> u64 {
        self.checkpoints.last().map_or(0, |c| c.total)
    }

    /// How many checkpoints a run of `ticks` ticks has with one every `every` ticks: tick 0,
    /// every multiple of `every`, and `ticks` itself.
    pub fn checkpoint_count(ticks: u64, every: NonZeroU32) -> u64 {
        let every = u64::from(every.get());
        ticks / every + 1 + u64::from(!ticks.is_multiple_of(every))
    }

    /// The tick of checkpoint number `index` in such a run.
    pub fn checkpoint_tick(index: u64, ticks: u64, every: NonZeroU32) -> u64 {
        index.saturating_mul(u64::from(every.get())).min(ticks)
    }
}
