//! [`HeightField`]: terrain as a regular grid of heights, collided as the triangle mesh it
//! describes.

use super::trimesh::TriMesh;
use super::{MAX_MESH_TRIANGLES, MeshError};
use crate::math::{Fx, Real, Vec3};
use crate::rigid::build::MAX_MAGNITUDE;

/// A grid of `rows` × `columns` heights, centred on the body's origin.
///
/// Sample (r, c), `heights[r × columns + c]`, is the point
/// ((c / (columns − 1) − ½) s_x, h s_y, (r / (rows − 1) − ½) s_z), s = `scale` (m): the
/// grid spans s_x along x and s_z along z, and a height of 1 is s_y metres up. Cell
/// (r, c) holds two triangles, 2 (r (columns − 1) + c) and the next, split along its
/// diagonal from (r, c) to (r + 1, c + 1) and facing +y.
///
/// The collision code sees the grid as its [`TriMesh`], made with the field; equality and
/// serialisation look at the grid only.
#[derive(Clone, Debug)]
pub struct HeightField<R: Real = Fx> {
    rows: u32,
    columns: u32,
    scale: Vec3<R>,
    heights: Vec<R>,
    mesh: TriMesh<R>,
}

impl<R: Real> PartialEq for HeightField<R> {
    fn eq(&self, other: &Self) -> bool {
        self.rows == other.rows
            && self.columns == other.columns
            && self.scale == other.scale
            && self.heights == other.heights
    }
}

impl<R: Real> HeightField<R> {
    /// The heightfield of `rows` × `columns` `heights` (row by row) at `scale` (m).
    ///
    /// Errors: fewer than 2 rows or columns, or more than [`MAX_MESH_TRIANGLES`]
    /// triangles; a height list of another length; a scale component not above 0 or
    /// beyond 100 000 m; a height times s_y beyond ±100 000 m.
    pub fn new(
        rows: u32,
        columns: u32,
        scale: Vec3<R>,
        heights: Vec<R>,
    ) -> Result<Self, MeshError> {
        let cells = (u64::from(rows.max(1)) - 1) * (u64::from(columns.max(1)) - 1);
        if rows < 2 || columns < 2 || 2 * cells > MAX_MESH_TRIANGLES as u64 {
            return Err(MeshError::GridSize { rows, columns });
        }
        let expected = rows as usize * columns as usize;
        if heights.len() != expected {
            return Err(MeshError::HeightCount {
                expected,
                got: heights.len(),
            });
        }
        let limit = R::from_int(MAX_MAGNITUDE);
        for (axis, s) in [("x", scale.x), ("y", scale.y), ("z", scale.z)] {
            if s <= R::ZERO || s > limit {
                return Err(MeshError::Scale(axis));
            }
        }
        // |h| ≤ limit / s_y, checked without forming a product that could saturate.
        let height_limit = limit / scale.y;
        if let Some(index) = heights.iter().position(|h| h.abs() > height_limit) {
            return Err(MeshError::HeightOutOfRange { index });
        }
        let mut vertices = Vec::with_capacity(expected);
        let (last_row, last_column) = (i64::from(rows) - 1, i64::from(columns) - 1);
        for r in 0..rows {
            let z = scale.z * R::from_ratio(i64::from(r), last_row) - scale.z * R::HALF;
            for c in 0..columns {
                let x = scale.x * R::from_ratio(i64::from(c), last_column) - scale.x * R::HALF;
                let h = heights[(r * columns + c) as usize];
                vertices.push(Vec3::new(x, h * scale.y, z));
            }
        }
        let mut triangles = Vec::with_capacity(2 * cells as usize);
        for r in 0..rows - 1 {
            for c in 0..columns - 1 {
                let v00 = r * columns + c;
                let (v01, v10, v11) = (v00 + 1, v00 + columns, v00 + columns + 1);
                triangles.push([v00, v10, v11]);
                triangles.push([v00, v11, v01]);
            }
        }
        let mesh = TriMesh::new(vertices, triangles)?;
        Ok(Self {
            rows,
            columns,
            scale,
            heights,
            mesh,
        })
    }

    /// Number of rows (samples along z).
    pub fn rows(&self) -> u32 {
        self.rows
    }

    /// Number of columns (samples along x).
    pub fn columns(&self) -> u32 {
        self.columns
    }

    /// The scale (m): the grid's size along x and z, and the height unit along y.
    pub fn scale(&self) -> Vec3<R> {
        self.scale
    }

    /// The heights, row by row.
    pub fn heights(&self) -> &[R] {
        &self.heights
    }

    /// The grid as a triangle mesh (two triangles per cell, see the type's documentation).
    pub fn mesh(&self) -> &TriMesh<R> {
        &self.mesh
    }
}
