//! The fluid as one of the world's subsystems.

use super::FluidSystem;
use crate::math::saturation::first_at_range_edge;
use crate::math::state_hash::StateHasher;
use crate::math::{Real, Vec3};
use crate::types::{Handle, Metrics, Part, SceneError, Stage, StepContext, Subsystem};

impl<R: Real> Subsystem<R> for FluidSystem<R> {
    fn stage(&self) -> Stage {
        Stage::Fluid
    }

    fn part(&self) -> Part {
        Part::Fluid
    }

    /// One world substep, itself split into the fluid's own substeps.
    fn step(&mut self, context: &mut StepContext<'_, R>) {
        FluidSystem::step(self, context.dt, context.gravity);
    }

    fn hash_state(&self, hasher: &mut StateHasher) {
        FluidSystem::hash_state(self, hasher);
    }

    fn slot_digests(&self) -> Vec<(Handle, u32)> {
        FluidSystem::slot_digests(self)
    }

    /// The first fluid particle whose position or velocity is at the range's edge.
    fn saturated_object(&self) -> Option<Handle> {
        first_at_range_edge(
            0..self.positions.len(),
            &[&self.positions, &self.velocities],
        )
        .map(|i| Handle::new(i as u32, 0))
    }

    /// Energies, momentum and the largest speed, the fluid particles added to the particle
    /// count, and the density, front and substep columns.
    fn add_metrics(&self, gravity: Vec3<R>, metrics: &mut Metrics) {
        let fluid = self.metrics(gravity);
        metrics.kinetic_energy += fluid.kinetic_energy;
        metrics.potential_energy += fluid.potential_energy;
        for (total, part) in metrics.momentum.iter_mut().zip(fluid.momentum) {
            *total += part;
        }
        metrics.max_speed = metrics.max_speed.max(fluid.max_speed);
        metrics.particles += fluid.particles;
        metrics.density_error_avg = fluid.density_error_avg;
        metrics.density_error_max = fluid.density_error_max;
        metrics.front_x = fluid.front_x;
        metrics.fluid_substeps = fluid.substeps;
    }

    fn validate(&self) -> Result<(), SceneError> {
        FluidSystem::validate(self)
    }

    fn restore_from(&mut self, restored: Self) {
        FluidSystem::restore_from(self, restored);
    }
}
