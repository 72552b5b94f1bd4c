//! Rigid bodies (in progress): shapes, mass properties, the rotational update and the
//! collision building blocks.
//!
//! What exists: the shapes a body can have ([`Shape`]), their mass properties from density
//! and the standard table of solids with the parallel-axis theorem for compounds
//! ([`MassProperties`]), the implicit gyroscopic update of the angular velocity
//! ([`gyroscopic`]), placements ([`Transform`]), bounding boxes ([`Aabb`]) and contact
//! manifolds ([`Manifold`]). Scenes with a `rigid` section are still refused.
//!
//! # Files
//!
//! [`shape`] shapes · [`mass`] mass properties · [`gyroscopic`] ω update with gyroscopic
//! torque · [`transform`] placements · [`aabb`] bounding boxes · [`manifold`] contact
//! manifolds.

pub mod aabb;
pub mod broadphase;
pub mod gyroscopic;
pub mod manifold;
pub mod mass;
pub mod narrowphase;
pub mod shape;
pub mod transform;

pub use aabb::Aabb;
pub use manifold::{MAX_MANIFOLD_POINTS, Manifold, ManifoldPoint};
pub use mass::MassProperties;
pub use shape::{Part, Shape};
pub use transform::Transform;
