//! The particle system as one of the world's subsystems.

use super::ParticleSystem;
use crate::math::saturation::first_at_range_edge;
use crate::math::state_hash::StateHasher;
use crate::math::{Real, Vec3};
use crate::types::{Handle, Metrics, Part, SceneError, Stage, StepContext, Subsystem};

impl<R: Real> Subsystem<R> for ParticleSystem<R> {
    fn stage(&self) -> Stage {
        Stage::Particles
    }

    fn part(&self) -> Part {
        Part::Particles
    }

    fn step(&mut self, context: &mut StepContext<'_, R>) {
        ParticleSystem::step(self, context.dt, context.gravity, context.rng);
    }

    fn end_tick(&mut self) {
        ParticleSystem::end_tick(self);
    }

    fn hash_state(&self, hasher: &mut StateHasher) {
        ParticleSystem::hash_state(self, hasher);
    }

    fn slot_digests(&self) -> Vec<(Handle, u32)> {
        ParticleSystem::slot_digests(self)
    }

    /// The first live particle whose position or velocity is at the range's edge.
    fn saturated_object(&self) -> Option<Handle> {
        let (k, a) = (&self.storage.kinematics, &self.storage.attributes);
        first_at_range_edge(
            (0..a.alive.len()).filter(|&i| a.alive[i]),
            &[&k.positions, &k.velocities],
        )
        .map(|i| self.storage.handle(i))
    }

    /// Kinetic and potential energy, momentum and the largest speed, and the live count.
    fn add_metrics(&self, gravity: Vec3<R>, metrics: &mut Metrics) {
        metrics.kinetic_energy += self.kinetic_energy().to_f64();
        metrics.potential_energy += self.potential_energy(gravity).to_f64();
        for (total, part) in metrics.momentum.iter_mut().zip(self.momentum().to_f64()) {
            *total += part;
        }
        metrics.max_speed = metrics.max_speed.max(self.max_speed().to_f64());
        metrics.particles += u64::from(self.live_count());
    }

    fn validate(&self) -> Result<(), SceneError> {
        ParticleSystem::validate(self)
    }

    fn restore_from(&mut self, restored: Self) {
        ParticleSystem::restore_from(self, restored);
    }
}
