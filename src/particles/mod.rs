//! Particles: point masses with emitters, force generators and seven integrators, in
//! deterministic fixed point.
//!
//! A [`ParticleSystem`] is built from a scene's [`ParticlesDesc`] and owned by the world.
//! Storage is structure-of-arrays (one `Vec` per attribute, indexed by slot); every loop runs
//! in ascending slot order with integer-backed [`Real`](crate::math::Real) arithmetic, so
//! every peer computes the same bits.
//!
//! # Tick contract
//!
//! Per tick, the world must:
//!
//! 1. apply the tick's commands ([`ParticleSystem::apply_force`],
//!    [`apply_impulse`](ParticleSystem::apply_impulse),
//!    [`set_velocity`](ParticleSystem::set_velocity), [`spawn`](ParticleSystem::spawn),
//!    [`remove`](ParticleSystem::remove), [`move_pinned`](ParticleSystem::move_pinned),
//!    [`set_emitter`](ParticleSystem::set_emitter)) in its canonical input order;
//! 2. call [`ParticleSystem::step`] once per substep, with the substep length
//!    Δt = 1/(tick rate · substeps), the current world gravity and the world's RNG;
//! 3. call [`ParticleSystem::end_tick`] once.
//!
//! External forces from `apply_force` act in **every substep of the tick** they were applied
//! in and are cleared by `end_tick`. Impulses, velocity changes, spawns, removals and moves
//! take effect at once. Lifetimes are seconds of simulated time, consumed by each step.
//!
//! Before the first step the program registers the scene's user forces
//! ([`ParticleSystem::register_user_force`]) and checks them
//! ([`ParticleSystem::check_user_forces`]). A snapshot is restored with
//! [`ParticleSystem::restore_from`], which keeps the registered user forces.
//!
//! # Files
//!
//! [`desc`] scene types · `build` validation and compilation · `storage` slots and recycling ·
//! [`emitter`] emission and its random draws · `forces` force generators and a(x, v) ·
//! `damping` v ← v·d^Δt · [`user_force`] user generators · [`integrators`] the seven schemes ·
//! `fused_euler` their one-pass semi-implicit Euler for linear fields ·
//! [`collisions`] bouncing off the rigid bodies · [`contact_desc`] and [`contacts`] particle
//! contacts, rods and cables (the mass-aggregate engine) · `implicit_euler` the implicit
//! step · `commands` command methods · `metrics` energies and momenta · `validate` invariants of a decoded state · [`hashing`] canonical hash
//! order.

mod build;
pub(crate) mod collisions;
mod commands;
pub mod contact_desc;
pub mod contacts;
mod damping;
pub mod desc;
pub mod emitter;
pub(crate) mod forces;
mod fused_euler;
mod groups;
pub mod hashing;
mod implicit_euler;
pub mod integrators;
mod metrics;
mod storage;
mod subsystem;
mod system;
mod template;
pub mod user_force;
mod validate;

pub use desc::{
    CollisionDesc, ContactPlaneDesc, ContactsDesc, DEFAULT_CAPACITY, EmitterDesc, ForceDesc,
    Interval, LinkDesc, MAX_CAPACITY, MAX_EMISSION_RATE, ParticleDesc, ParticleTemplate,
    ParticlesDesc, Spread, SpringDesc,
};
pub use integrators::Integrator;
pub use system::{ParticleSystem, StepReport};
pub use user_force::{ParticleForce, ParticleView};
