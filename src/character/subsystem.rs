//! The characters as one of the world's subsystems.

use super::surroundings::NoSurroundings;
use super::system::CharacterSystem;
use crate::math::saturation::at_range_edge;
use crate::math::state_hash::StateHasher;
use crate::math::{Real, Vec3};
use crate::types::{Handle, Metrics, Part, SceneError, Stage, StepContext, Subsystem};

impl<R: Real> Subsystem<R> for CharacterSystem<R> {
    fn stage(&self) -> Stage {
        Stage::Characters
    }

    fn part(&self) -> Part {
        Part::Characters
    }

    /// Moves the characters by one substep in a world without bodies. The world steps
    /// them once per tick with the bodies in view instead
    /// (`world/character_coupling.rs`).
    fn step(&mut self, context: &mut StepContext<'_, R>) {
        self.step_tick(context.dt, context.gravity, &mut NoSurroundings);
    }

    fn hash_state(&self, hasher: &mut StateHasher) {
        CharacterSystem::hash_state(self, hasher);
    }

    fn slot_digests(&self) -> Vec<(Handle, u32)> {
        CharacterSystem::slot_digests(self)
    }

    /// Characters are kinematic: they add no energy, momentum or column to the metrics
    /// (their poses are in `fixstep run --bodies`).
    fn add_metrics(&self, _gravity: Vec3<R>, _metrics: &mut Metrics) {}

    /// The first character whose position or velocity is at the range's edge.
    fn saturated_object(&self) -> Option<Handle> {
        self.characters
            .iter()
            .position(|c| at_range_edge(c.position) || at_range_edge(c.velocity))
            .map(Self::handle)
    }

    fn validate(&self) -> Result<(), SceneError> {
        CharacterSystem::validate(self)
    }

    fn restore_from(&mut self, restored: Self) {
        *self = restored;
    }
}
