//! Soft bodies: XPBD cloth, rope and jelly, and spring-mass networks.
//!
//! Data flows one way: a scene's [`SoftDesc`] compiles into a [`SoftSystem`] (vertices
//! and constraint rows, structure-of-arrays); each step advances the XPBD bodies together
//! ([`xpbd`]) and each spring-mass body with its particle integrator ([`spring_mass`]);
//! the state is hashed for checksums ([`hashing`]) and reported as [`SoftMetrics`].
//!
//! Both kinds of body live in one system and one stage ([`Stage::Soft`]), after the rigid
//! bodies: they share the vertex store, the static colliders and the metrics. A
//! spring-mass network is not built on the particle system; it reuses its integration
//! schemes and damped-spring force on the soft vertices.
//!
//! # Files
//!
//! [`desc`] scene types · `topology` the cloth, rope and lattice builders · `build` checks
//! and compilation · `system` storage and the step · `constraints` the XPBD rows
//! (distance, bending, volume, attachment) · [`xpbd`] the substep loop ·
//! [`spring_mass`] Hooke springs and the stability bound · `spring_mass_implicit` their implicit Euler step · `collide` static colliders
//! with friction · `body_coupling` contacts with and ties to rigid bodies, two-way, seen
//! through the traits of `rigid_bodies` · `commands` inputs · [`hashing`] canonical state · `metrics` reporting.
//!
//! [`Stage::Soft`]: crate::types::Stage::Soft

pub(crate) mod body_coupling;
mod build;
mod collide;
mod commands;
mod constraints;
pub mod desc;
pub mod hashing;
mod metrics;
pub(crate) mod rigid_bodies;
pub mod spring_mass;
mod spring_mass_implicit;
mod subsystem;
mod system;
mod topology;
pub mod xpbd;

pub use desc::{
    AttachmentDesc, BodyAttachmentDesc, BodyContactsDesc, ColliderDesc, MAX_SOLVER_STEPS,
    MAX_VERTICES, SoftBodyDesc, SoftDesc, SoftModel, SoftShape, XpbdSettings,
};
pub use metrics::SoftMetrics;
pub use system::SoftSystem;
