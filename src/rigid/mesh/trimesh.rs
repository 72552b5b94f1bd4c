//! [`TriMesh`]: static level geometry as a list of vertices and triangles, with the tables
//! collision needs (face normals, active features, a bounding-volume tree) derived from
//! them when the mesh is made.

use std::sync::Arc;

use super::bvh::Bvh;
use super::edges::feature_flags;
use super::{MAX_EDGE_LENGTH, MAX_MESH_TRIANGLES, MAX_MESH_VERTICES, MeshError};
use crate::math::{Fx, Real, Vec3};
use crate::rigid::aabb::Aabb;
use crate::rigid::build::MAX_MAGNITUDE;

/// A triangle mesh: vertices (m, in the body's frame) and triangles as triples of vertex
/// indices, counter-clockwise seen from the side the face normal points to.
///
/// Made by [`TriMesh::new`], which checks the data and derives the tables; a mesh is
/// immutable afterwards and shares them between clones (a snapshot copies a pointer).
/// Equality and serialisation look at the vertices and triangles only.
#[derive(Clone, Debug)]
pub struct TriMesh<R: Real = Fx> {
    pub(crate) data: Arc<MeshData<R>>,
}

/// The source data of a mesh and what is derived from it.
#[derive(Debug)]
pub(crate) struct MeshData<R: Real> {
    pub vertices: Vec<Vec3<R>>,
    pub triangles: Vec<[u32; 3]>,
    /// Unit face normal of each triangle, (v₁ − v₀) × (v₂ − v₀) normalised.
    pub normals: Vec<Vec3<R>>,
    /// Active edges and corners of each triangle (`edges.rs`).
    pub flags: Vec<u8>,
    pub bvh: Bvh<R>,
}

impl<R: Real> PartialEq for TriMesh<R> {
    fn eq(&self, other: &Self) -> bool {
        Arc::ptr_eq(&self.data, &other.data)
            || (self.data.vertices == other.data.vertices
                && self.data.triangles == other.data.triangles)
    }
}

impl<R: Real> TriMesh<R> {
    /// The mesh of `vertices` (m) and `triangles` (vertex indices).
    ///
    /// Errors: no triangles; more than [`MAX_MESH_TRIANGLES`] triangles or
    /// [`MAX_MESH_VERTICES`] vertices; a coordinate beyond ±100 000 m; an index out of
    /// range; a degenerate triangle (no area within a relative 2⁻¹⁰); an edge longer than
    /// [`MAX_EDGE_LENGTH`] m along an axis; an edge shared by three or more triangles.
    /// Vertices that no triangle uses are allowed.
    pub fn new(vertices: Vec<Vec3<R>>, triangles: Vec<[u32; 3]>) -> Result<Self, MeshError> {
        if triangles.is_empty() {
            return Err(MeshError::Empty);
        }
        if triangles.len() > MAX_MESH_TRIANGLES {
            return Err(MeshError::TooManyTriangles(triangles.len()));
        }
        if vertices.len() > MAX_MESH_VERTICES {
            return Err(MeshError::TooManyVertices(vertices.len()));
        }
        let limit = R::from_int(MAX_MAGNITUDE);
        if let Some(vertex) = vertices
            .iter()
            .position(|v| v.abs().max_component() > limit)
        {
            return Err(MeshError::VertexOutOfRange { vertex });
        }
        let mut normals = Vec::with_capacity(triangles.len());
        for (triangle, tri) in triangles.iter().enumerate() {
            if let Some(&index) = tri.iter().find(|&&i| i as usize >= vertices.len()) {
                return Err(MeshError::IndexOutOfRange {
                    triangle,
                    index,
                    vertices: vertices.len(),
                });
            }
            let [a, b, c] = tri.map(|i| vertices[i as usize]);
            normals.push(face_normal(a, b, c).map_err(|e| e(triangle))?);
        }
        let flags = feature_flags(&vertices, &triangles, &normals)?;
        let bounds: Vec<Aabb<R>> = triangles
            .iter()
            .map(|tri| {
                let [a, b, c] = tri.map(|i| vertices[i as usize]);
                Aabb {
                    min: a.min_elem(b).min_elem(c),
                    max: a.max_elem(b).max_elem(c),
                }
            })
            .collect();
        let centroids: Vec<Vec3<R>> = triangles
            .iter()
            .map(|tri| {
                let [a, b, c] = tri.map(|i| vertices[i as usize]);
                a + b + c
            })
            .collect();
        let bvh = Bvh::build(&bounds, &centroids);
        Ok(Self {
            data: Arc::new(MeshData {
                vertices,
                triangles,
                normals,
                flags,
                bvh,
            }),
        })
    }

    /// The vertices, m, as given.
    pub fn vertices(&self) -> &[Vec3<R>] {
        &self.data.vertices
    }

    /// The triangles, as given.
    pub fn triangles(&self) -> &[[u32; 3]] {
        &self.data.triangles
    }

    /// The corners of triangle `t`, m, in the mesh's frame.
    #[inline]
    pub fn corners(&self, t: u32) -> [Vec3<R>; 3] {
        self.data.triangles[t as usize].map(|i| self.data.vertices[i as usize])
    }

    /// The unit face normal of triangle `t`.
    #[inline]
    pub fn normal(&self, t: u32) -> Vec3<R> {
        self.data.normals[t as usize]
    }

    /// The bounds of every triangle, m, in the mesh's frame.
    pub fn bounds(&self) -> Aabb<R> {
        self.data.bvh.root_bounds().unwrap_or_default()
    }

    /// Calls `visit(t)` for each triangle t whose bounding box overlaps `aabb` (in the
    /// mesh's frame), in the tree's order (not ascending: sort when order matters).
    pub fn for_each_triangle_in(&self, aabb: &Aabb<R>, visit: impl FnMut(u32)) {
        self.data.bvh.for_each_overlap(aabb, visit);
    }

    /// Visits the mesh's tree: `enter(bounds)` (mesh frame) decides whether a node's subtree
    /// is searched, `leaf(triangles)` receives each leaf entered (see `bvh.rs`).
    pub(crate) fn walk_tree(&self, enter: impl FnMut(&Aabb<R>) -> bool, leaf: impl FnMut(&[u32])) {
        self.data.bvh.walk(enter, leaf);
    }

    /// How many edges are active (corners of the surface; see `edges.rs`), counting an
    /// edge shared by two triangles once per triangle.
    pub fn active_edge_count(&self) -> usize {
        self.data
            .flags
            .iter()
            .map(|f| (f & 0b111).count_ones() as usize)
            .sum()
    }

    /// Number of nodes in the bounding-volume tree.
    pub fn tree_node_count(&self) -> usize {
        self.data.bvh.nodes.len()
    }

    /// Bytes held by the mesh and its derived tables (not counting the struct itself).
    pub fn heap_bytes(&self) -> usize {
        let d = &self.data;
        d.vertices.capacity() * core::mem::size_of::<Vec3<R>>()
            + d.triangles.capacity() * core::mem::size_of::<[u32; 3]>()
            + d.normals.capacity() * core::mem::size_of::<Vec3<R>>()
            + d.flags.capacity()
            + d.bvh.heap_bytes()
    }
}

/// The unit normal of triangle (a, b, c): e₁ × e₂ normalised, e₁ = b − a, e₂ = c − a. The
/// edges are first divided by their largest component L, so that the cross product
/// neither overflows nor loses its bits; the triangle is degenerate when the scaled
/// |e₁ × e₂| is below 2⁻¹⁰ (its smallest angle under about 0.06° for a fat triangle).
type TriangleError = fn(usize) -> MeshError;
fn face_normal<R: Real>(a: Vec3<R>, b: Vec3<R>, c: Vec3<R>) -> Result<Vec3<R>, TriangleError> {
    let (e1, e2, e3) = (b - a, c - a, c - b);
    let span = e1
        .abs()
        .max_elem(e2.abs())
        .max_elem(e3.abs())
        .max_component();
    if span > R::from_int(MAX_EDGE_LENGTH) {
        return Err(|triangle| MeshError::EdgeTooLong { triangle });
    }
    if span == R::ZERO {
        return Err(|triangle| MeshError::Degenerate { triangle });
    }
    let scale = span.recip();
    let cross = (e1 * scale).cross(e2 * scale);
    let degenerate = R::from_ratio(1, 1 << 20);
    if cross.length_squared() < degenerate {
        return Err(|triangle| MeshError::Degenerate { triangle });
    }
    cross
        .try_normalize()
        .map(|(n, _)| n)
        .ok_or(|triangle| MeshError::Degenerate { triangle })
}
