//! Rigid bodies (in progress): shapes, mass properties and the rotational update.
//!
//! What exists: the shapes a body can have ([`Shape`]), their mass properties from density
//! and the standard table of solids with the parallel-axis theorem for compounds
//! ([`MassProperties`]), and the implicit gyroscopic update of the angular velocity
//! ([`gyroscopic`]). Bodies in the world, contacts, the solver, islands and sleeping are
//! not built yet; scenes with a `rigid` section are still refused.
//!
//! # Files
//!
//! [`shape`] shapes · [`mass`] mass properties · [`gyroscopic`] ω update with gyroscopic
//! torque.

pub mod gyroscopic;
pub mod mass;
pub mod shape;

pub use mass::MassProperties;
pub use shape::{Part, Shape};
