//! Static level geometry: triangle meshes ([`TriMesh`]) and heightfields ([`HeightField`],
//! collided as the mesh of its grid).
//!
//! A mesh is source data (vertices and triangles, or a grid of heights) and tables
//! derived from it when it is made: unit face normals, the active edges and corners that
//! may push a body along something other than a face normal (`edges.rs`), and a
//! bounding-volume tree over the triangles (`bvh.rs`). Scenes, replays and snapshots
//! carry the source data only, and reading it back derives the same tables, so a mesh
//! costs nothing in a checksum and a replay is self-contained.
//!
//! Meshes belong to static or kinematic bodies; the narrowphase collides every other
//! shape with the triangles under its bounding box (`narrowphase/triangle.rs`).

mod bvh;
mod closest;
mod edges;
mod error;
mod heightfield;
mod obj;
mod trimesh;

pub(crate) use self::closest::{TriangleFeature, closest_point};
pub(crate) use self::edges::{EDGE_ACTIVE, VERTEX_ACTIVE};
pub use self::error::MeshError;
pub use self::heightfield::HeightField;
pub use self::obj::{read_obj, read_obj_file};
pub use self::trimesh::TriMesh;

/// The most triangles a mesh or a heightfield may have: 2²² = 4 194 304. Contacts name a
/// triangle by a 32-bit index, and a mesh this size already takes a few hundred MB with
/// its tables.
pub const MAX_MESH_TRIANGLES: usize = 1 << 22;

/// The most vertices a mesh may have: 2²² = 4 194 304.
pub const MAX_MESH_VERTICES: usize = 1 << 22;

/// The longest a triangle's edge may be along any axis, m: products of two edge lengths
/// must stay far inside the scalar's range (10⁸ m² against 2·10⁹ for I32F32).
pub const MAX_EDGE_LENGTH: i32 = 10_000;
