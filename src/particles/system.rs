//! The particle system: its state, the step, the end of a tick, and read access.

use serde::{Deserialize, Serialize};

use super::contacts::ParticleContacts;
use super::desc::CollisionDesc;
use super::emitter::Emitter;
use super::forces::{ForceField, ForceGenerator, ForceSet};
use super::integrators::{self, Integrator, Scratch, StepContext};
use super::storage::ParticleStorage;
use super::template::SpawnTemplate;
use super::user_force::{ParticleForce, UserForceRegistry};
use crate::math::rng::Pcg32;
use crate::math::{Fx, Real, Vec3};
use crate::types::Handle;
use crate::types::SceneError;

/// A deterministic particle system: point masses in structure-of-arrays storage, emitters,
/// force generators and one of seven integrators.
///
/// Build it with [`ParticleSystem::from_desc`]; see the [module documentation](super) for the
/// order in which the world must call [`step`](Self::step), [`end_tick`](Self::end_tick)
/// and the command methods.
///
/// `Clone`, `PartialEq` and serde cover the complete simulation state. The registered user
/// forces and the integrators' scratch arrays are not state: they are not serialised or
/// compared, a clone shares the user forces, and
/// [`restore_from`](Self::restore_from) keeps them.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(bound = "")]
pub struct ParticleSystem<R: Real = Fx> {
    pub(super) integrator: Integrator,
    pub(super) storage: ParticleStorage<R>,
    pub(super) templates: Vec<SpawnTemplate<R>>,
    pub(super) emitters: Vec<Emitter<R>>,
    pub(super) forces: ForceSet<R>,
    /// The groups that collide with the rigid bodies, ascending by group.
    pub(super) collisions: Vec<CollisionDesc<R>>,
    /// Particle contacts, planes, rods and cables, when the scene has them.
    pub(super) contacts: Option<ParticleContacts<R>>,
    /// Whether `storage.kinematics.accelerations` holds a(x, v) of the current state, so
    /// that velocity Verlet can reuse it.
    pub(super) accelerations_current: bool,
    /// The world gravity the last step ran with, m/s².
    pub(super) last_gravity: Vec3<R>,
    /// Whether a command applied an external force this tick.
    pub(super) external_forces_pending: bool,
    #[serde(skip)]
    pub(super) user_forces: UserForceRegistry<R>,
    #[serde(skip)]
    pub(super) scratch: Scratch<R>,
}

/// What happened during one step, besides the state change.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct StepReport {
    /// Particles created by emitters.
    pub emitted: u32,
    /// Particles emitters owed but could not create because the system was full.
    pub dropped: u32,
    /// Particles whose lifetime ran out.
    pub expired: u32,
}

impl<R: Real> ParticleSystem<R> {
    /// Advances the system by one step of `dt` seconds under the world gravity `gravity`
    /// (m/s²), drawing emitter randomness from `rng`. In order:
    ///
    /// 1. age: every mortal particle loses `dt` of lifetime; those left with `dt/2` or less
    ///    die (so a lifetime of L seconds lasts round(L/dt) steps);
    /// 2. emit: emitters in scene order (see [`emitter`](super::emitter) for the draws);
    /// 3. integrate: forces are accumulated and every movable particle advanced with the
    ///    system's [`Integrator`] (the tick's external forces act in every step);
    /// 4. damp: v ← v · d^dt for each damping generator.
    pub fn step(&mut self, dt: R, gravity: Vec3<R>, rng: &mut Pcg32) -> StepReport {
        let mut report = StepReport {
            expired: self.storage.age(dt),
            ..StepReport::default()
        };
        for emitter in &mut self.emitters {
            let emission = emitter.emit(dt, &mut self.storage, rng);
            report.emitted += emission.emitted;
            report.dropped += emission.dropped;
        }
        if gravity != self.last_gravity {
            // A jump in the forcing: Störmer–Verlet restarts from (x, v).
            self.storage.kinematics.has_previous_position.fill(false);
            self.accelerations_current = false;
            self.last_gravity = gravity;
        }
        if report.expired > 0 || report.emitted > 0 {
            self.accelerations_current = false;
        }

        if let Some(contacts) = &mut self.contacts {
            contacts.remember(&self.storage.kinematics.velocities);
        }
        let field = ForceField::new(
            &self.forces,
            &self.user_forces,
            &self.storage.attributes,
            gravity,
        );
        integrators::advance(
            self.integrator,
            dt,
            StepContext {
                kinematics: &mut self.storage.kinematics,
                attributes: &self.storage.attributes,
                field: &field,
                scratch: &mut self.scratch,
                accelerations_current: &mut self.accelerations_current,
            },
        );
        for damping in &mut self.forces.dampings {
            damping.apply(dt, &mut self.storage.kinematics, &self.storage.attributes);
        }
        if let Some(contacts) = &mut self.contacts
            && contacts.resolve(dt, &mut self.storage.kinematics, &self.storage.attributes)
        {
            self.accelerations_current = false;
        }
        report
    }

    /// Ends the tick: clears the external forces that commands applied for it (particles
    /// that had one restart Störmer–Verlet from (x, v)). Call once per tick, after the
    /// tick's steps.
    pub fn end_tick(&mut self) {
        if self.external_forces_pending {
            let attributes = &mut self.storage.attributes;
            let kinematics = &mut self.storage.kinematics;
            for (force, has_previous) in attributes
                .external_forces
                .iter_mut()
                .zip(&mut kinematics.has_previous_position)
            {
                if *force != Vec3::ZERO {
                    *force = Vec3::ZERO;
                    *has_previous = false;
                }
            }
            self.external_forces_pending = false;
            self.accelerations_current = false;
        }
    }

    /// Registers a user force generator under `name`, replacing any registered under that
    /// name. Scenes refer to it with `User(name: "...")`. Not part of the state: register the
    /// same code on every peer before the first step.
    pub fn register_user_force(
        &mut self,
        name: impl Into<String>,
        force: Box<dyn ParticleForce<R>>,
    ) {
        self.user_forces.register(name.into(), force);
    }

    /// Names of the scene's user forces that are not registered, in scene order.
    pub fn missing_user_forces(&self) -> Vec<String> {
        self.user_forces_in_scene()
            .filter(|(name, _)| self.user_forces.get(name).is_none())
            .map(|(name, _)| name.to_owned())
            .collect()
    }

    /// Fails, naming the scene field (`forces[i].name`), when a user force of the scene is
    /// not registered. Call after registering and before the first step; an unregistered
    /// user force would contribute no force at all.
    pub fn check_user_forces(&self) -> Result<(), SceneError> {
        match self
            .user_forces_in_scene()
            .find(|(name, _)| self.user_forces.get(name).is_none())
        {
            Some((name, scene_index)) => Err(SceneError::new(
                format!("forces[{scene_index}].name"),
                format!("no user force is registered as `{name}`"),
            )),
            None => Ok(()),
        }
    }

    /// Replaces the simulation state with `other`'s (a snapshot), keeping this system's
    /// registered user forces and scratch memory.
    pub fn restore_from(&mut self, other: Self) {
        let user_forces = core::mem::take(&mut self.user_forces);
        let scratch = core::mem::take(&mut self.scratch);
        *self = other;
        self.user_forces = user_forces;
        self.scratch = scratch;
    }

    /// The integration scheme.
    pub fn integrator(&self) -> Integrator {
        self.integrator
    }

    /// The most particles alive at once.
    pub fn capacity(&self) -> u32 {
        self.storage.capacity()
    }

    /// Slots allocated so far, alive or dead (the length of the slot arrays).
    pub fn slot_count(&self) -> usize {
        self.storage.slot_count()
    }

    /// Particles alive.
    pub fn live_count(&self) -> u32 {
        self.storage.live_count()
    }

    /// Handles of the live particles, in ascending slot order.
    pub fn handles(&self) -> impl Iterator<Item = Handle> + '_ {
        (0..self.slot_count())
            .filter(|&i| self.storage.attributes.alive[i])
            .map(|i| self.storage.handle(i))
    }

    /// Whether `handle` refers to a live particle.
    pub fn is_alive(&self, handle: Handle) -> bool {
        self.storage.attributes.resolve(handle).is_some()
    }

    /// Position of a live particle, m.
    pub fn position(&self, handle: Handle) -> Option<Vec3<R>> {
        self.slot(handle)
            .map(|i| self.storage.kinematics.positions[i])
    }

    /// Velocity of a live particle, m/s.
    pub fn velocity(&self, handle: Handle) -> Option<Vec3<R>> {
        self.slot(handle)
            .map(|i| self.storage.kinematics.velocities[i])
    }

    /// Mass of a live particle, kg (0 when pinned).
    pub fn mass(&self, handle: Handle) -> Option<R> {
        self.slot(handle).map(|i| self.storage.attributes.masses[i])
    }

    /// Group of a live particle.
    pub fn group(&self, handle: Handle) -> Option<u16> {
        self.slot(handle).map(|i| self.storage.attributes.groups[i])
    }

    /// Seconds a live particle has left (0 when immortal).
    pub fn remaining_lifetime(&self, handle: Handle) -> Option<R> {
        self.slot(handle)
            .map(|i| self.storage.attributes.lifetimes[i])
    }

    /// Positions of every slot, m; dead slots hold stale values (see [`Self::alive`]).
    pub fn positions(&self) -> &[Vec3<R>] {
        &self.storage.kinematics.positions
    }

    /// Velocities of every slot, m/s; dead slots hold stale values.
    pub fn velocities(&self) -> &[Vec3<R>] {
        &self.storage.kinematics.velocities
    }

    /// Whether each slot holds a live particle.
    pub fn alive(&self) -> &[bool] {
        &self.storage.attributes.alive
    }

    /// The two ends of every spring, in scene order, m: (anchor or first particle, second
    /// particle); springs to a dead particle are left out. For drawing.
    pub fn spring_ends(&self) -> impl Iterator<Item = (Vec3<R>, Vec3<R>)> + '_ {
        self.forces
            .generators
            .iter()
            .filter_map(|generator| match generator {
                ForceGenerator::AnchoredSpring {
                    particle, anchor, ..
                } => Some((*anchor, self.position(*particle)?)),
                ForceGenerator::Spring { first, second, .. } => {
                    Some((self.position(*first)?, self.position(*second)?))
                }
                _ => None,
            })
    }

    /// The two ends of every rod and cable whose particles are alive, in scene order, m,
    /// with `true` for a rod. For drawing.
    pub fn link_ends(&self) -> impl Iterator<Item = (Vec3<R>, Vec3<R>, bool)> + '_ {
        self.contacts.iter().flat_map(|contacts| {
            contacts.link_ends(&self.storage.kinematics.positions, &self.storage.attributes)
        })
    }

    /// Number of emitters.
    pub fn emitter_count(&self) -> usize {
        self.emitters.len()
    }

    /// Whether emitter `index` is switched on.
    pub fn emitter_is_on(&self, index: usize) -> Option<bool> {
        self.emitters.get(index).map(|e| e.on)
    }

    /// The slot of a live particle.
    fn slot(&self, handle: Handle) -> Option<usize> {
        self.storage.attributes.resolve(handle)
    }

    /// (name, index in the scene's force list) of each user force, in scene order.
    fn user_forces_in_scene(&self) -> impl Iterator<Item = (&str, u32)> + '_ {
        self.forces
            .generators
            .iter()
            .filter_map(|generator| match generator {
                ForceGenerator::User { name, scene_index } => Some((name.as_str(), *scene_index)),
                _ => None,
            })
    }
}
