//! [`MeshError`]: why vertices and triangles, or a height grid, make no mesh.

use super::{MAX_EDGE_LENGTH, MAX_MESH_TRIANGLES, MAX_MESH_VERTICES};
use crate::rigid::build::MAX_MAGNITUDE;

/// Why a triangle mesh or a heightfield cannot be made. Triangles and vertices are named
/// by their index in the lists given (a file reader turns these into line numbers).
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum MeshError {
    /// No triangles.
    Empty,
    /// More than [`MAX_MESH_TRIANGLES`] triangles.
    TooManyTriangles(usize),
    /// More than [`MAX_MESH_VERTICES`] vertices.
    TooManyVertices(usize),
    /// A vertex coordinate beyond ±[`MAX_MAGNITUDE`] m.
    VertexOutOfRange { vertex: usize },
    /// A triangle names a vertex that does not exist.
    IndexOutOfRange {
        triangle: usize,
        index: u32,
        vertices: usize,
    },
    /// A triangle with no area (two corners equal, or all three on a line, within a
    /// relative 2⁻¹⁰ of its size).
    Degenerate { triangle: usize },
    /// A triangle with an edge longer than [`MAX_EDGE_LENGTH`] m along some axis.
    EdgeTooLong { triangle: usize },
    /// A third triangle on an edge that two triangles already share.
    NonManifold { triangle: usize },
    /// A heightfield with fewer than 2 rows or columns, or more triangles than allowed.
    GridSize { rows: u32, columns: u32 },
    /// A heightfield whose height list does not hold rows × columns values.
    HeightCount { expected: usize, got: usize },
    /// A heightfield scale component (`"x"`, `"y"` or `"z"`) that is not above 0 and at
    /// most [`MAX_MAGNITUDE`] m.
    Scale(&'static str),
    /// A height times the vertical scale beyond ±[`MAX_MAGNITUDE`] m.
    HeightOutOfRange { index: usize },
}

impl std::fmt::Display for MeshError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Self::Empty => write!(f, "the mesh has no triangles"),
            Self::TooManyTriangles(n) => write!(
                f,
                "{n} triangles: a mesh takes at most {MAX_MESH_TRIANGLES}"
            ),
            Self::TooManyVertices(n) => {
                write!(f, "{n} vertices: a mesh takes at most {MAX_MESH_VERTICES}")
            }
            Self::VertexOutOfRange { vertex } => write!(
                f,
                "vertices[{vertex}]: components must be within ±{MAX_MAGNITUDE} m"
            ),
            Self::IndexOutOfRange {
                triangle,
                index,
                vertices,
            } => write!(
                f,
                "triangles[{triangle}]: vertex index {index} is out of range (there are \
                 {vertices} vertices)"
            ),
            Self::Degenerate { triangle } => {
                write!(f, "triangles[{triangle}]: degenerate (no area)")
            }
            Self::EdgeTooLong { triangle } => write!(
                f,
                "triangles[{triangle}]: an edge is longer than {MAX_EDGE_LENGTH} m; split it"
            ),
            Self::NonManifold { triangle } => write!(
                f,
                "triangles[{triangle}]: non-manifold, a third triangle on an edge two \
                 triangles already share"
            ),
            Self::GridSize { rows, columns } => write!(
                f,
                "a {rows} × {columns} heightfield: it needs at least 2 rows and 2 columns \
                 and at most {MAX_MESH_TRIANGLES} triangles (2 per cell)"
            ),
            Self::HeightCount { expected, got } => write!(
                f,
                "heights holds {got} values; rows × columns is {expected}"
            ),
            Self::Scale(axis) => write!(
                f,
                "scale.{axis} must be above 0 and at most {MAX_MAGNITUDE} m"
            ),
            Self::HeightOutOfRange { index } => {
                write!(f, "heights[{index}] × scale.y is beyond ±{MAX_MAGNITUDE} m")
            }
        }
    }
}

impl std::error::Error for MeshError {}
