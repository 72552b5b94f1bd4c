//! Rays against triangle meshes and heightfields, in the mesh's frame: the bounding-volume
//! tree pruned by the ray's slab test against the nearest hit so far, then each triangle
//! by its plane and its edges. A mesh is a surface: rays hit its triangles from either
//! side and are never inside it.

use core::cell::Cell;

use super::ray::{BoxProbe, Crossing, Ray, clamped_ratio};
use crate::math::{Real, Vec3};
use crate::rigid::mesh::TriMesh;

/// Pad (m) of the tree's boxes for the slab test: 2⁻¹⁶ m (see [`BoxProbe`]).
fn box_pad<R: Real>() -> R {
    R::from_ratio(1, 1 << 16)
}

/// Slack (m) by which a point may lie outside an edge and still hit: 2⁻²⁰ m, so that a
/// ray through an edge shared by two triangles hits at least one despite rounding.
fn edge_slack<R: Real>() -> R {
    R::from_ratio(1, 1 << 20)
}

/// The ray (in the mesh's frame) against `mesh`: the nearest triangle it crosses within
/// `max`, the lowest triangle index on ties, with that triangle's unit normal turned
/// towards the ray's origin.
pub(super) fn ray_mesh<R: Real>(mesh: &TriMesh<R>, ray: &Ray<R>) -> Option<Crossing<R>> {
    let probe = BoxProbe::new(ray, box_pad());
    // (distance, triangle, normal) of the nearest hit so far.
    let best: Cell<Option<(R, u32, Vec3<R>)>> = Cell::new(None);
    mesh.walk_tree(
        |bounds| {
            let reach = best.get().map_or(ray.max, |(d, _, _)| d);
            probe.reaches(bounds, reach)
        },
        |triangles| {
            for &t in triangles {
                let Some((distance, normal)) = ray_triangle(&mesh.corners(t), mesh.normal(t), ray)
                else {
                    continue;
                };
                let nearer = best
                    .get()
                    .is_none_or(|(d, bt, _)| distance < d || (distance == d && t < bt));
                if nearer {
                    best.set(Some((distance, t, normal)));
                }
            }
        },
    );
    best.get()
        .map(|(distance, _, normal)| Crossing::Enters { distance, normal })
}

/// The ray o + t d against the triangle with `corners` v_k and unit `normal` n: with
/// s = n · (o − v₀) (m, the origin's height above the plane) and v = n · d, the ray
/// reaches the plane at t = s / (−v) ≥ 0 when s and v have opposite signs (t = 0 when
/// s = 0; a ray parallel to the plane, v = 0, misses); the point p = o + t d hits when it
/// lies inside every edge, (v_{k+1} − v_k) × (p − v_k) · n ≥ −ε (|e_x| + |e_y| + |e_z|)
/// with ε = [`edge_slack`] (the left side is |e| times p's signed distance to the edge's
/// line). Distance t (m) within `max`, and ±n on the origin's side.
fn ray_triangle<R: Real>(
    corners: &[Vec3<R>; 3],
    normal: Vec3<R>,
    ray: &Ray<R>,
) -> Option<(R, Vec3<R>)> {
    let s = normal.dot(ray.origin - corners[0]);
    let v = normal.dot(ray.direction);
    let towards = (s > R::ZERO && v < R::ZERO) || (s < R::ZERO && v > R::ZERO);
    if v == R::ZERO || !(towards || s == R::ZERO) {
        return None;
    }
    let t = clamped_ratio(s.abs(), v.abs(), ray.limit());
    if t > ray.max {
        return None;
    }
    let p = ray.at(t);
    let slack = edge_slack::<R>();
    let inside = (0..3).all(|k| {
        let edge = corners[(k + 1) % 3] - corners[k];
        let bound = edge.x.abs() + edge.y.abs() + edge.z.abs();
        edge.cross(p - corners[k]).dot(normal) >= -(slack * bound)
    });
    let facing = if s > R::ZERO || (s == R::ZERO && v < R::ZERO) {
        normal
    } else {
        -normal
    };
    inside.then_some((t, facing))
}
