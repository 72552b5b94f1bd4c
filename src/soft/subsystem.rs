//! The soft bodies as one of the world's subsystems.

use super::SoftSystem;
use crate::math::saturation::first_at_range_edge;
use crate::math::state_hash::StateHasher;
use crate::math::{Real, Vec3};
use crate::types::{Handle, Metrics, Part, SceneError, Stage, StepContext, Subsystem};

impl<R: Real> Subsystem<R> for SoftSystem<R> {
    fn stage(&self) -> Stage {
        Stage::Soft
    }

    fn part(&self) -> Part {
        Part::Soft
    }

    /// One world substep; the substep index and count place the kinematic attachments
    /// along their path to this tick's goal.
    fn step(&mut self, context: &mut StepContext<'_, R>) {
        SoftSystem::step(
            self,
            context.dt,
            context.gravity,
            context.substep,
            context.substeps,
        );
    }

    fn end_tick(&mut self) {
        SoftSystem::end_tick(self);
    }

    fn hash_state(&self, hasher: &mut StateHasher) {
        SoftSystem::hash_state(self, hasher);
    }

    fn slot_digests(&self) -> Vec<(Handle, u32)> {
        SoftSystem::slot_digests(self)
    }

    /// The first vertex whose position or velocity is at the range's edge.
    fn saturated_object(&self) -> Option<Handle> {
        let v = &self.vertices;
        first_at_range_edge(0..v.position.len(), &[&v.position, &v.velocity])
            .map(|i| Handle::new(i as u32, 0))
    }

    /// Energies (elastic included), momentum and the largest speed, plus the stretch
    /// columns and the vertex count.
    fn add_metrics(&self, gravity: Vec3<R>, metrics: &mut Metrics) {
        let soft = self.metrics(gravity);
        metrics.kinetic_energy += soft.kinetic_energy;
        metrics.potential_energy += soft.potential_energy;
        for (total, part) in metrics.momentum.iter_mut().zip(soft.momentum) {
            *total += part;
        }
        metrics.max_speed = metrics.max_speed.max(soft.max_speed);
        metrics.max_stretch = soft.max_stretch;
        metrics.mean_stretch = soft.mean_stretch;
        metrics.soft_vertices = soft.vertices;
    }

    fn validate(&self) -> Result<(), SceneError> {
        SoftSystem::validate(self)
    }

    fn restore_from(&mut self, restored: Self) {
        SoftSystem::restore_from(self, restored);
    }
}
