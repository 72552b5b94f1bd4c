//! The contract between the world and each of its subsystems.
//!
//! The world keeps its subsystems in [`Stage`] order and drives them only through
//! [`Subsystem`]: per tick, [`begin_tick`](Subsystem::begin_tick), then
//! [`step`](Subsystem::step) once per substep, then (after every stage has run)
//! [`end_tick`](Subsystem::end_tick); and, between ticks, hashing, digests, metrics,
//! validation and restoring. A subsystem absent from the scene is simply not in the list.

use super::{Handle, Metrics, Part, SceneError, Stage};
use crate::math::rng::Pcg32;
use crate::math::state_hash::StateHasher;
use crate::math::{Real, Vec3};

/// What a subsystem needs to advance one substep (after Box2D's `b2StepContext`).
#[derive(Debug)]
pub struct StepContext<'a, R: Real> {
    /// Length of the substep, 1 / (tick_rate · substeps) s.
    pub dt: R,
    /// Gravitational acceleration, m/s².
    pub gravity: Vec3<R>,
    /// The world's seeded generator; the subsystems draw from it in stage order.
    pub rng: &'a mut Pcg32,
    /// This substep's index within the tick, `0..substeps`.
    pub substep: u32,
    /// Substeps per tick.
    pub substeps: u32,
}

/// A simulated subsystem of the world: particles, rigid bodies, soft bodies or fluid.
///
/// Every method must be deterministic and must touch only the subsystem's own state (and,
/// in [`step`](Subsystem::step), the generator it is handed), so that the world's result
/// depends only on the stage order.
pub trait Subsystem<R: Real> {
    /// The stage that steps this subsystem (its place in the tick and in timing tables).
    fn stage(&self) -> Stage;

    /// The part of the world checksum this subsystem's state forms.
    fn part(&self) -> Part;

    /// Called once per tick, before the first substep.
    fn begin_tick(&mut self) {}

    /// Advances one substep of `context.dt` seconds.
    fn step(&mut self, context: &mut StepContext<'_, R>);

    /// Called once per tick after every stage has stepped: clears per-tick accumulators.
    fn end_tick(&mut self) {}

    /// Hashes the canonical state, the subsystem's sub-checksum.
    fn hash_state(&self, hasher: &mut StateHasher);

    /// One 32-bit digest per object slot, in ascending slot index, with the slot's handle.
    fn slot_digests(&self) -> Vec<(Handle, u32)>;

    /// Adds this subsystem's reporting figures to `metrics` (energies and momentum summed,
    /// speeds maximised, its own columns set); `gravity` (m/s²) gives potential energy.
    fn add_metrics(&self, gravity: Vec3<R>, metrics: &mut Metrics);

    /// The handle of the first object (lowest slot) whose position or velocity holds a
    /// value at the edge of the numeric range
    /// ([`at_range_edge`](crate::math::saturation::at_range_edge)), if any: where a
    /// tick's saturation is reported ([`crate::world::health::SaturationSite`]). Called
    /// only after a tick that saturated.
    fn saturated_object(&self) -> Option<Handle>;

    /// Checks the invariants the subsystem relies on, for a state from outside (a
    /// snapshot); the error names the offending field.
    fn validate(&self) -> Result<(), SceneError>;

    /// Takes `restored`'s simulated state (a snapshot's), keeping what is not state: this
    /// system's registered user forces, scratch memory and warnings.
    fn restore_from(&mut self, restored: Self)
    where
        Self: Sized;
}
