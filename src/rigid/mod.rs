//! Rigid bodies: shapes, mass properties, collision, the contact solver, islands and
//! sleeping.
//!
//! Data flows one way: a scene's [`RigidDesc`] compiles into a [`RigidSystem`] (body
//! storage and persistent contacts); each step runs the stages listed on
//! [`RigidSystem`]; the state is hashed for checksums ([`hashing`]) and reported as
//! [`RigidMetrics`].
//!
//! # Files
//!
//! Description and storage: [`desc`] scene types · [`build`] checks and compilation ·
//! [`bodies`] structure-of-arrays storage · [`system`] the system and its step ·
//! [`commands`] inputs · [`hashing`] canonical state · [`metrics`] reporting.
//!
//! Geometry: [`shape`] shapes · [`convex`] hulls and support mappings · [`mesh`] triangle meshes and
//! heightfields · [`mass`] mass properties · [`transform`] placements ·
//! [`aabb`] bounding boxes · [`manifold`] contact manifolds · [`broadphase`] pairs ·
//! [`narrowphase`] manifolds per shape pair.
//!
//! Joints: [`joints`] kinds, storage, breaking and queries; their rows live in the solver.
//!
//! Game API: [`filter`] collision layers and query filters · `sensors` overlap detection ·
//! [`events`] contact, sensor and joint events · `spawn` templates and spawning by input.
//!
//! Dynamics: [`collide`] stage 1 (with `capped_pairs`, what it keeps past the broadphase's cap) · [`contact`] persistent contacts · [`sleep`] islands,
//! waking and sleeping · [`solve`] stage 3 · [`solver`] the soft-step sequential-impulse
//! solver · [`continuous`] the last stage, fast bodies swept against thin ones · [`material`] friction and restitution mixing · [`gyroscopic`] ω update with
//! gyroscopic torque.
//!
//! Queries: [`query`] rays, shape casts, overlaps and closest points, over a bounding-volume
//! tree kept current by the step.

pub mod aabb;
pub(crate) mod bodies;
pub mod broadphase;
pub(crate) mod build;
mod capped_pairs;
mod collide;
mod commands;
pub(crate) mod contact;
pub(crate) mod continuous;
pub mod convex;
pub mod desc;
pub mod events;
pub mod filter;
pub mod gyroscopic;
mod hashing;
pub mod joints;
pub mod manifold;
pub mod mass;
pub mod material;
pub mod mesh;
mod metrics;
pub mod narrowphase;
mod obstacle;
pub(crate) mod proxies;
pub mod query;
mod recycle;
mod sensors;
pub mod shape;
pub mod shape_serde;
mod sleep;
mod solve;
pub(crate) mod solver;
mod spawn;
mod subsystem;
mod system;
pub mod transform;

pub use aabb::Aabb;
pub use convex::{ConvexHull, HullError};
pub use desc::{BodyDesc, BodyKind, Grid, RigidDesc, SolverSettings};
pub use events::{Event, EventKind};
pub use filter::{CollisionFilter, QueryFilter};
pub use joints::{JointDesc, JointEvent, JointGrid, JointKind, JointsDesc, Limits, Motor, Spring};
pub use manifold::{MAX_MANIFOLD_POINTS, Manifold, ManifoldPoint};
pub use mass::MassProperties;
pub use material::Material;
pub use mesh::{HeightField, MeshError, TriMesh};
pub use metrics::RigidMetrics;
pub use query::{PointProjection, RayHit};
pub use shape::{Part, Shape};
pub use spawn::{BodyTemplate, JointTemplate};
pub use system::RigidSystem;
pub use transform::Transform;
