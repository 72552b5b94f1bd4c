//! Convex shapes beyond the sphere, box and capsule: the convex hull and its
//! construction, and the support mappings that GJK, EPA and the queries use for every
//! convex shape.
//!
//! # Files
//!
//! [`hull`] the hull's data (vertices, faces, edges) and its checks · `quickhull` the
//! deterministic construction from points · `hull_mass` its volume integrals · [`support`]
//! support points of every convex shape · `gjk` distance and closest points of two cores · `epa`
//! penetration normal and depth of two overlapping cores.

pub(crate) mod epa;
pub(crate) mod gjk;
pub mod hull;
mod hull_mass;
mod quickhull;
pub mod support;

pub use self::hull::{ConvexHull, HullError, HullFace, MAX_HULL_POINTS};
pub use self::support::{Convex, Rounded};
