//! The command methods the world calls while applying a tick's inputs.
//!
//! Each returns whether its target existed: `false` for a stale handle, a group with no live
//! particle, a template or emitter index out of range, or a full system. A target that
//! exists but cannot be affected (a pinned particle pushed by a force) still returns `true`.
//! Every change that alters forces or velocities marks the stored accelerations (velocity
//! Verlet) stale, and a velocity change or a new external force restarts Störmer–Verlet from
//! (x, v).

use super::storage::NewParticle;
use super::system::ParticleSystem;
use crate::math::{Real, Vec3};
use crate::types::Handle;
use crate::types::{Command, Target};

impl<R: Real> ParticleSystem<R> {
    /// Applies a world command aimed at particles; false when its target does not exist
    /// or the command is not about particles (gravity and payloads belong to the world).
    pub fn apply_command(&mut self, command: &Command<R>) -> bool {
        match *command {
            Command::ApplyForce { target, force, .. } => self.apply_force(target, force),
            Command::ApplyImpulse {
                target, impulse, ..
            } => self.apply_impulse(target, impulse),
            Command::SetVelocity { target, velocity } => self.set_velocity(target, velocity),
            Command::Spawn {
                template,
                position,
                velocity,
            } => self.spawn(template, position, velocity).is_some(),
            Command::Remove { target } => self.remove(target),
            Command::MoveKinematic { target, position } => self.move_pinned(target, position),
            Command::SetEmitter { emitter, on } => self.set_emitter(emitter, on),
            Command::SetGravity { .. }
            | Command::Payload(_)
            | Command::SetMotor { .. }
            | Command::SpawnBody { .. }
            | Command::SpawnJoint { .. }
            | Command::MoveCharacter { .. }
            | Command::DisturbWater { .. } => false,
        }
    }

    /// Adds `force` (N) to the external force of each targeted particle. External forces act
    /// in every step of the current tick and are cleared by [`Self::end_tick`]; several
    /// commands in one tick add up. Störmer–Verlet restarts from (x, v) at both ends of the
    /// tick, so the particle receives the impulse F·(tick length).
    pub fn apply_force(&mut self, target: Target, force: Vec3<R>) -> bool {
        let matched = self.for_each_target(target, |system, i| {
            system.storage.attributes.external_forces[i] += force;
            system.storage.kinematics.has_previous_position[i] = false;
        });
        if matched {
            self.external_forces_pending = true;
        }
        matched
    }

    /// Changes the velocity of each targeted movable particle by Δv = J / m, with the
    /// impulse J in N·s (computed as J · (1/m)).
    pub fn apply_impulse(&mut self, target: Target, impulse: Vec3<R>) -> bool {
        self.for_each_target(target, |system, i| {
            let inv_mass = system.storage.attributes.inv_masses[i];
            if inv_mass != R::ZERO {
                let velocity = system.storage.kinematics.velocities[i] + impulse * inv_mass;
                system.change_velocity(i, velocity);
            }
        })
    }

    /// Sets the velocity (m/s) of each targeted movable particle; pinned ones stay at rest.
    pub fn set_velocity(&mut self, target: Target, velocity: Vec3<R>) -> bool {
        self.for_each_target(target, |system, i| {
            if system.storage.attributes.is_movable(i) {
                system.change_velocity(i, velocity);
            }
        })
    }

    /// Creates a particle from template number `template` at `position` (m) with `velocity`
    /// (m/s), in the lowest free slot. `None` when there is no such template or the system
    /// is full.
    pub fn spawn(&mut self, template: u32, position: Vec3<R>, velocity: Vec3<R>) -> Option<Handle> {
        let template = *self.templates.get(template as usize)?;
        let handle = self.storage.allocate(NewParticle {
            position,
            velocity,
            mass: template.mass,
            inv_mass: template.inv_mass,
            group: template.group,
            lifetime: template.lifetime,
        })?;
        self.accelerations_current = false;
        Some(handle)
    }

    /// Kills each targeted particle; its slot becomes free for reuse.
    pub fn remove(&mut self, target: Target) -> bool {
        self.for_each_target(target, |system, i| system.storage.kill(i))
    }

    /// Moves each targeted pinned particle to `position` (m). Returns false when no pinned
    /// particle matched; movable particles are not moved (forces move them).
    pub fn move_pinned(&mut self, target: Target, position: Vec3<R>) -> bool {
        let mut moved = false;
        for i in self.storage.candidate_slots(target) {
            if self.storage.matches(i, target) && self.storage.attributes.is_pinned(i) {
                self.storage.kinematics.positions[i] = position;
                self.storage.kinematics.previous_positions[i] = position;
                moved = true;
            }
        }
        if moved {
            self.accelerations_current = false;
        }
        moved
    }

    /// Switches emitter number `emitter` on or off; false when there is no such emitter.
    pub fn set_emitter(&mut self, emitter: u32, on: bool) -> bool {
        match self.emitters.get_mut(emitter as usize) {
            Some(e) => {
                e.on = on;
                true
            }
            None => false,
        }
    }

    /// Calls `action` for each live particle of `target`, in ascending slot order; true when
    /// there was at least one. Marks the stored accelerations stale when there was.
    fn for_each_target(
        &mut self,
        target: Target,
        mut action: impl FnMut(&mut Self, usize),
    ) -> bool {
        let mut matched = false;
        for i in self.storage.candidate_slots(target) {
            if self.storage.matches(i, target) {
                action(self, i);
                matched = true;
            }
        }
        if matched {
            self.accelerations_current = false;
        }
        matched
    }

    /// Sets the velocity of slot `i`; Störmer–Verlet restarts from (x, v).
    fn change_velocity(&mut self, i: usize, velocity: Vec3<R>) {
        self.storage.kinematics.velocities[i] = velocity;
        self.storage.kinematics.has_previous_position[i] = false;
    }
}
