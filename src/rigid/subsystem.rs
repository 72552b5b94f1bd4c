//! The rigid bodies as one of the world's subsystems.

use super::RigidSystem;
use crate::math::saturation::first_at_range_edge;
use crate::math::state_hash::StateHasher;
use crate::math::{Real, Vec3};
use crate::types::{Handle, Metrics, Part, SceneError, Stage, StepContext, Subsystem};

impl<R: Real> Subsystem<R> for RigidSystem<R> {
    fn stage(&self) -> Stage {
        Stage::Rigid
    }

    fn part(&self) -> Part {
        Part::Rigid
    }

    fn step(&mut self, context: &mut StepContext<'_, R>) {
        RigidSystem::step(self, context.dt, context.gravity);
    }

    /// Clears the force accumulators and puts the tick's events in canonical order.
    fn end_tick(&mut self) {
        RigidSystem::end_tick(self);
        self.sort_events();
    }

    fn hash_state(&self, hasher: &mut StateHasher) {
        RigidSystem::hash_state(self, hasher);
    }

    fn slot_digests(&self) -> Vec<(Handle, u32)> {
        RigidSystem::slot_digests(self)
    }

    /// The first live body whose position or linear or angular velocity is at the range's
    /// edge.
    fn saturated_object(&self) -> Option<Handle> {
        let b = &self.bodies;
        first_at_range_edge(
            (0..b.len()).filter(|&i| b.alive[i]),
            &[&b.position, &b.linear_velocity, &b.angular_velocity],
        )
        .map(|i| b.handle(i))
    }

    /// Energies, momentum and the largest speed, plus the contact, sleep and joint columns.
    fn add_metrics(&self, gravity: Vec3<R>, metrics: &mut Metrics) {
        let rigid = self.metrics(gravity);
        metrics.kinetic_energy += rigid.kinetic_energy;
        metrics.rigid_kinetic_energy = rigid.kinetic_energy;
        metrics.rigid_potential_energy = rigid.potential_energy;
        metrics.rigid_mass = rigid.mass;
        metrics.potential_energy += rigid.potential_energy;
        for (total, part) in metrics.momentum.iter_mut().zip(rigid.momentum) {
            *total += part;
        }
        metrics.max_speed = metrics.max_speed.max(rigid.max_speed);
        metrics.max_penetration = rigid.max_penetration;
        metrics.awake_bodies = rigid.awake_bodies;
        metrics.sleeping_bodies = rigid.sleeping_bodies;
        metrics.joints = rigid.joints;
        metrics.max_joint_error = rigid.max_joint_error;
    }

    fn validate(&self) -> Result<(), SceneError> {
        RigidSystem::validate(self)
    }

    fn restore_from(&mut self, restored: Self) {
        RigidSystem::restore_from(self, restored);
    }
}
