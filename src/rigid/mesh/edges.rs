//! Active edges and vertices: which features of a triangle may push a body along a
//! direction other than the triangle's face normal (Jolt's and Bullet's internal-edge
//! removal).
//!
//! A body sliding over a flat mesh touches the edges between triangles; a contact found
//! on such an edge would have a normal tilted towards the edge and bump the body. An edge
//! is *active* when it is a real corner of the surface: on the mesh's boundary, between
//! triangles wound inconsistently (no inside to judge by), or convex with the two faces'
//! normals more than about 5° apart ([`flat_cosine`], Jolt's default). Flat and concave edges are inactive, and a
//! vertex is active when one of its edges is. The narrowphase replaces the normal of a
//! contact on an inactive feature by the triangle's face normal (`narrowphase/triangle.rs`).
//!
//! Vertices at exactly the same position count as one (meshes exported with split
//! vertices still find their neighbours); the welding sorts positions by value, so it
//! depends on the data only.

use super::MeshError;
use crate::math::{Real, Vec3};

/// Bit k of a triangle's flags: its edge k (corner k to corner k + 1 mod 3) is active.
pub(crate) const EDGE_ACTIVE: u8 = 1;
/// Bit 3 + k of a triangle's flags: its corner k is active.
pub(crate) const VERTEX_ACTIVE: u8 = 1 << 3;

/// Cosine of the angle between two faces' normals below which a convex edge is active:
/// 0.9962, about 5° (Jolt's `mActiveEdgeCosThresholdAngle`).
fn flat_cosine<R: Real>() -> R {
    R::from_ratio(9962, 10_000)
}

/// The flags of every triangle (see [`EDGE_ACTIVE`] and [`VERTEX_ACTIVE`]), or the first
/// triangle that makes an edge non-manifold. `normals` are the unit face normals.
pub(super) fn feature_flags<R: Real>(
    vertices: &[Vec3<R>],
    triangles: &[[u32; 3]],
    normals: &[Vec3<R>],
) -> Result<Vec<u8>, MeshError> {
    let welded = weld(vertices);
    // Every edge as (low welded vertex, high welded vertex, triangle, edge), sorted: the
    // triangles sharing an edge come together, in ascending order.
    let mut edges: Vec<(u32, u32, u32, u8)> = Vec::with_capacity(3 * triangles.len());
    for (t, tri) in triangles.iter().enumerate() {
        for k in 0..3 {
            let a = welded[tri[k] as usize];
            let b = welded[tri[(k + 1) % 3] as usize];
            edges.push((a.min(b), a.max(b), t as u32, k as u8));
        }
    }
    edges.sort_unstable();
    let mut flags = vec![0u8; triangles.len()];
    let mut vertex_active = vec![false; vertices.len()];
    let mut start = 0;
    while start < edges.len() {
        let (a, b, t1, k1) = edges[start];
        let mut end = start + 1;
        while end < edges.len() && edges[end].0 == a && edges[end].1 == b {
            end += 1;
        }
        let active = match end - start {
            1 => true,
            2 => {
                let (_, _, t2, k2) = edges[start + 1];
                corner(vertices, triangles, normals, (t1, k1), (t2, k2))
            }
            _ => {
                return Err(MeshError::NonManifold {
                    triangle: edges[start + 2].2 as usize,
                });
            }
        };
        if active {
            for &(_, _, t, k) in &edges[start..end] {
                flags[t as usize] |= EDGE_ACTIVE << k;
            }
            vertex_active[a as usize] = true;
            vertex_active[b as usize] = true;
        }
        start = end;
    }
    for (t, tri) in triangles.iter().enumerate() {
        for (k, &v) in tri.iter().enumerate() {
            if vertex_active[welded[v as usize] as usize] {
                flags[t] |= VERTEX_ACTIVE << k;
            }
        }
    }
    Ok(flags)
}

/// True when the edge shared by triangle t1 (its edge k1) and t2 (its edge k2) is a
/// corner of the surface: wound inconsistently, or convex (t2's far corner p below t1's
/// plane, n₁ · (p − v) < 0) with n₁ · n₂ below [`flat_cosine`].
fn corner<R: Real>(
    vertices: &[Vec3<R>],
    triangles: &[[u32; 3]],
    normals: &[Vec3<R>],
    (t1, k1): (u32, u8),
    (t2, k2): (u32, u8),
) -> bool {
    let (tri1, tri2) = (triangles[t1 as usize], triangles[t2 as usize]);
    let (k1, k2) = (usize::from(k1), usize::from(k2));
    // Consistent winding runs the shared edge in opposite directions.
    let same_direction = vertices[tri1[k1] as usize] == vertices[tri2[k2] as usize];
    if same_direction {
        return true;
    }
    let (n1, n2) = (normals[t1 as usize], normals[t2 as usize]);
    let far = vertices[tri2[(k2 + 2) % 3] as usize];
    let convex = n1.dot(far - vertices[tri1[k1] as usize]) < R::ZERO;
    convex && n1.dot(n2) < flat_cosine()
}

/// For each vertex, the lowest index of a vertex at exactly the same position.
fn weld<R: Real>(vertices: &[Vec3<R>]) -> Vec<u32> {
    let mut order: Vec<u32> = (0..vertices.len() as u32).collect();
    let key = |v: &Vec3<R>| {
        (
            v.x.canonical_bits(),
            v.y.canonical_bits(),
            v.z.canonical_bits(),
        )
    };
    order.sort_unstable_by_key(|&i| (key(&vertices[i as usize]), i));
    let mut welded = vec![0u32; vertices.len()];
    let mut first = 0;
    for (n, &i) in order.iter().enumerate() {
        if n == 0 || vertices[i as usize] != vertices[order[n - 1] as usize] {
            first = i;
        }
        welded[i as usize] = first;
    }
    welded
}
