//! [`ConvexHull`]: a convex polyhedron given by its vertices, faces and edges, made from a
//! set of points and always valid once made.
//!
//! A hull is described and stored as its points only: serialising writes the hull's
//! vertices, and reading them back rebuilds the same faces and edges (the construction is
//! deterministic and a hull's own vertices give back the same hull). A scene, a replay and
//! a snapshot therefore carry the source data, never derived tables.

use serde::{Deserialize, Serialize};

use crate::math::{Fx, Real, Vec3};

/// The most points a hull may be made from (and so the most vertices it can have).
pub const MAX_HULL_POINTS: usize = 1024;

/// One face of a hull: the plane n · x = `offset` with outward unit normal n, and its
/// vertices in [`ConvexHull::face_vertices`]`[first .. first + count]`, counter-clockwise
/// seen from outside.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct HullFace<R: Real = Fx> {
    /// Outward unit normal.
    pub normal: Vec3<R>,
    /// n · x for the face's points, m.
    pub offset: R,
    /// Index of the face's first vertex index in [`ConvexHull::face_vertices`].
    pub first: u16,
    /// Number of vertices of the face (at least 3).
    pub count: u16,
}

/// Why a set of points has no hull.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum HullError {
    /// Fewer than 4 points.
    TooFewPoints(usize),
    /// More than [`MAX_HULL_POINTS`] points.
    TooManyPoints(usize),
    /// The points span no volume: all coincide, or lie on one line or one plane (within the
    /// construction's tolerance). The string says which.
    Degenerate(&'static str),
    /// A coordinate beyond the engine's magnitude limit (m).
    OutOfRange { index: usize },
}

impl std::fmt::Display for HullError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Self::TooFewPoints(n) => write!(f, "a convex hull needs at least 4 points (got {n})"),
            Self::TooManyPoints(n) => write!(
                f,
                "a convex hull takes at most {MAX_HULL_POINTS} points (got {n})"
            ),
            Self::Degenerate(what) => write!(f, "the points span no volume: {what}"),
            Self::OutOfRange { index } => {
                write!(f, "points[{index}] is beyond the magnitude limit")
            }
        }
    }
}

impl std::error::Error for HullError {}

/// A convex polyhedron: the convex hull of the points it was made from.
///
/// Vertices are in a canonical order (independent of the order of the input points), and
/// every face is a convex polygon whose coplanar triangles have been merged.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(try_from = "Vec<Vec3<R>>", into = "Vec<Vec3<R>>", bound = "R: Real")]
pub struct ConvexHull<R: Real = Fx> {
    pub(crate) vertices: Vec<Vec3<R>>,
    pub(crate) faces: Vec<HullFace<R>>,
    pub(crate) face_vertices: Vec<u16>,
    /// Each edge once, as (lower index, higher index), sorted.
    pub(crate) edges: Vec<[u16; 2]>,
}

impl<R: Real> ConvexHull<R> {
    /// The vertices, m, in canonical order.
    pub fn vertices(&self) -> &[Vec3<R>] {
        &self.vertices
    }

    /// The faces.
    pub fn faces(&self) -> &[HullFace<R>] {
        &self.faces
    }

    /// The vertex indices of `face`, counter-clockwise seen from outside.
    pub fn face_indices(&self, face: &HullFace<R>) -> &[u16] {
        let first = usize::from(face.first);
        &self.face_vertices[first..first + usize::from(face.count)]
    }

    /// The edges, each as (lower, higher) vertex index, sorted.
    pub fn edges(&self) -> &[[u16; 2]] {
        &self.edges
    }

    /// The index of the vertex farthest along `direction` (any length): the first in
    /// canonical order among equals, so ties resolve the same way everywhere.
    pub fn support_index(&self, direction: Vec3<R>) -> usize {
        let mut best = 0;
        let mut best_dot = self.vertices[0].dot(direction);
        for (i, v) in self.vertices.iter().enumerate().skip(1) {
            let d = v.dot(direction);
            if d > best_dot {
                best = i;
                best_dot = d;
            }
        }
        best
    }

    /// The same hull moved by `offset` (m): every vertex v + t, every face offset
    /// d + n · t.
    pub fn translated(mut self, offset: Vec3<R>) -> Self {
        for v in &mut self.vertices {
            *v += offset;
        }
        for face in &mut self.faces {
            face.offset += face.normal.dot(offset);
        }
        self
    }

    /// The largest |v|² over the vertices (m²): the squared radius of the ball about the
    /// origin that holds the hull.
    pub fn reach_squared(&self) -> R {
        self.vertices
            .iter()
            .map(|v| v.length_squared())
            .fold(R::ZERO, R::max)
    }
}

impl<R: Real> TryFrom<Vec<Vec3<R>>> for ConvexHull<R> {
    type Error = HullError;

    fn try_from(points: Vec<Vec3<R>>) -> Result<Self, HullError> {
        Self::new(&points)
    }
}

impl<R: Real> From<ConvexHull<R>> for Vec<Vec3<R>> {
    fn from(hull: ConvexHull<R>) -> Self {
        hull.vertices
    }
}
