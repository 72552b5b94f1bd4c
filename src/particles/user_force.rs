//! User-defined force generators: Rust code registered by name, referred to by scenes.
//!
//! A scene lists `User(name: "wind")` among its forces; the program registers the code with
//! [`ParticleSystem::register_user_force`](super::ParticleSystem::register_user_force) before
//! the first step and checks with
//! [`ParticleSystem::check_user_forces`](super::ParticleSystem::check_user_forces) that every
//! name is registered. A name that is not registered contributes no force.
//!
//! The registry is not simulation state: it is not hashed, not serialised, and a snapshot
//! restored with [`ParticleSystem::restore_from`](super::ParticleSystem::restore_from) keeps
//! the registry of the system it is restored into. Every peer must register the same code
//! under the same names.

use core::fmt;
use std::sync::Arc;

use crate::math::{Real, Vec3};

/// What a user force generator sees: the particle arrays, indexed by slot.
///
/// During an RK4 step, `positions` and `velocities` are those of the current stage, not the
/// stored state. Dead slots have `alive[i] == false`; pinned and dead slots have
/// `inv_masses[i] == 0`, and forces on them are ignored.
#[derive(Clone, Copy, Debug)]
pub struct ParticleView<'a, R: Real> {
    /// x, m.
    pub positions: &'a [Vec3<R>],
    /// v, m/s.
    pub velocities: &'a [Vec3<R>],
    /// 1/m, 1/kg (0 for pinned and dead slots).
    pub inv_masses: &'a [R],
    /// Group of each slot.
    pub groups: &'a [u16],
    /// Whether each slot holds a particle.
    pub alive: &'a [bool],
}

/// A force generator written in Rust.
///
/// `accumulate` must be a deterministic function of its arguments: integer-backed [`Real`]
/// arithmetic only, slots visited in a fixed order, no hash-map iteration, no clocks. It may
/// be called several times per step (four times with RK4).
pub trait ParticleForce<R: Real>: Send + Sync {
    /// Adds the force on each particle, in newtons, to `forces[i]` (same indexing as the
    /// view; `forces.len()` is the slot count).
    fn accumulate(&self, particles: &ParticleView<'_, R>, forces: &mut [Vec3<R>]);
}

/// Registered user forces by name, in registration order.
pub(crate) struct UserForceRegistry<R: Real> {
    entries: Vec<(String, Arc<dyn ParticleForce<R>>)>,
}

impl<R: Real> UserForceRegistry<R> {
    /// Registers `force` under `name`, replacing any generator registered under that name.
    pub fn register(&mut self, name: String, force: Box<dyn ParticleForce<R>>) {
        let force: Arc<dyn ParticleForce<R>> = Arc::from(force);
        match self.entries.iter_mut().find(|(n, _)| *n == name) {
            Some(entry) => entry.1 = force,
            None => self.entries.push((name, force)),
        }
    }

    /// The generator registered under `name`.
    pub fn get(&self, name: &str) -> Option<&dyn ParticleForce<R>> {
        self.entries
            .iter()
            .find(|(n, _)| n == name)
            .map(|(_, force)| force.as_ref())
    }
}

impl<R: Real> Default for UserForceRegistry<R> {
    fn default() -> Self {
        Self {
            entries: Vec::new(),
        }
    }
}

impl<R: Real> Clone for UserForceRegistry<R> {
    /// Shares the registered generators (they are immutable).
    fn clone(&self) -> Self {
        Self {
            entries: self.entries.clone(),
        }
    }
}

impl<R: Real> PartialEq for UserForceRegistry<R> {
    /// Always true: the registry is code, not simulation state, so it does not take part in
    /// comparing two systems.
    fn eq(&self, _other: &Self) -> bool {
        true
    }
}

impl<R: Real> fmt::Debug for UserForceRegistry<R> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_list()
            .entries(self.entries.iter().map(|(name, _)| name))
            .finish()
    }
}
