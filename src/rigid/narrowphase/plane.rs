//! Spheres, capsules and boxes against a plane (the half-space n·x ≤ d): signed distances of
//! the shape's lowest points.
//!
//! The plane is shape A: the manifold normal is the plane's outward normal n, pointing from
//! the solid half-space towards the other shape.

use super::segments::Segment;
use crate::math::{Real, Vec3};
use crate::rigid::manifold::{MAX_MANIFOLD_POINTS, Manifold, ManifoldPoint};
use crate::rigid::transform::Transform;

/// A plane in the world frame: the half-space n·x ≤ d, n unit, d in m.
#[derive(Clone, Copy, Debug)]
pub(super) struct WorldPlane<R: Real> {
    /// Outward unit normal n.
    pub normal: Vec3<R>,
    /// Offset d, m.
    pub offset: R,
}

impl<R: Real> WorldPlane<R> {
    /// The plane n_l·x ≤ d_l of a body placed by `xf`, in the world frame: n = R n_l and
    /// d = d_l + n·t (since n_l·Rᵀ(x − t) = n·x − n·t).
    #[inline]
    pub fn new(normal: Vec3<R>, offset: R, xf: &Transform<R>) -> Self {
        let normal = xf.vector(normal);
        Self {
            normal,
            offset: offset + normal.dot(xf.translation),
        }
    }

    /// Signed distance n·p − d (m) of `point` above the plane.
    #[inline(always)]
    pub fn distance(&self, point: Vec3<R>) -> R {
        self.normal.dot(point) - self.offset
    }

    /// The manifold point for a point of the other shape's surface at `surface` with
    /// separation `separation` (m): moved back half the separation along −n, midway between
    /// the two surfaces.
    #[inline(always)]
    fn point(&self, surface: Vec3<R>, separation: R, id: u32) -> ManifoldPoint<R> {
        ManifoldPoint {
            point: surface - self.normal * (separation * R::HALF),
            separation,
            id,
        }
    }

    /// A manifold with this plane's normal and no points.
    #[inline(always)]
    fn manifold(&self) -> Manifold<R> {
        Manifold {
            normal: self.normal,
            ..Manifold::EMPTY
        }
    }
}

/// Plane A against sphere B (centre `centre`, radius `radius`, m): separation
/// n·c − d − r, one point (id 0) at the sphere's lowest point c − n r moved half the
/// separation back; empty when the separation exceeds `margin`.
#[inline]
pub(super) fn plane_sphere<R: Real>(
    plane: &WorldPlane<R>,
    centre: Vec3<R>,
    radius: R,
    margin: R,
) -> Manifold<R> {
    let separation = plane.distance(centre) - radius;
    if separation > margin {
        return Manifold::EMPTY;
    }
    let mut manifold = plane.manifold();
    manifold.push(plane.point(centre - plane.normal * radius, separation, 0));
    manifold
}

/// Plane A against capsule B (segment `segment`, radius `radius`, m): each end e of the
/// segment within the margin gives a point with separation n·e − d − r at e − n r; ids 0
/// for the −h end and 1 for the +h end. A capsule lying on the plane gets both.
pub(super) fn plane_capsule<R: Real>(
    plane: &WorldPlane<R>,
    segment: &Segment<R>,
    radius: R,
    margin: R,
) -> Manifold<R> {
    let centre = plane.distance(segment.centre) - radius;
    let along = plane.normal.dot(segment.axis) * segment.half_length;
    if centre - along.abs() > margin {
        return Manifold::EMPTY;
    }
    let mut manifold = plane.manifold();
    for (id, s, separation) in [
        (0, -segment.half_length, centre - along),
        (1, segment.half_length, centre + along),
    ] {
        if separation <= margin {
            let surface = segment.at(s) - plane.normal * radius;
            manifold.push(plane.point(surface, separation, id));
        }
    }
    manifold
}

/// Plane A against box B (half extents `half_extents`, m, placed by `xf_box`).
///
/// Corner i (bit k of i set for +h_k along the box's axis k) is at c + Σ ±h_k r_k, so its
/// separation is D + Σ ±a_k with D = n·c − d and a_k = h_k (n·r_k). Empty when the lowest
/// corner, D − Σ|a_k|, is beyond the margin. Otherwise the corners within the margin, the
/// deepest first (lower index on ties), at most four: a box lying on a face gives its four
/// bottom corners, one on an edge two, one on a corner one. Id: the corner index i.
pub(super) fn plane_box<R: Real>(
    plane: &WorldPlane<R>,
    half_extents: Vec3<R>,
    xf_box: &Transform<R>,
    margin: R,
) -> Manifold<R> {
    let [r0, r1, r2] = xf_box.rotation.cols;
    let n = plane.normal;
    let a = [
        n.dot(r0) * half_extents.x,
        n.dot(r1) * half_extents.y,
        n.dot(r2) * half_extents.z,
    ];
    let centre = plane.distance(xf_box.translation);
    if centre - (a[0].abs() + a[1].abs() + a[2].abs()) > margin {
        return Manifold::EMPTY;
    }
    let edges = [
        r0 * half_extents.x,
        r1 * half_extents.y,
        r2 * half_extents.z,
    ];
    // Corners within the margin, as (separation, index), kept sorted by depth.
    let mut found = [(R::ZERO, 0u32); 8];
    let mut count = 0;
    for i in 0..8u32 {
        let pick = |k: usize, value: R| if i & (1 << k) != 0 { value } else { -value };
        let separation = centre + pick(0, a[0]) + pick(1, a[1]) + pick(2, a[2]);
        if separation > margin {
            continue;
        }
        // Insertion after every corner at least as deep: stable, so ties keep index order.
        let mut at = count;
        while at > 0 && found[at - 1].0 > separation {
            found[at] = found[at - 1];
            at -= 1;
        }
        found[at] = (separation, i);
        count += 1;
    }
    let mut manifold = plane.manifold();
    for &(separation, i) in &found[..count.min(MAX_MANIFOLD_POINTS)] {
        let pick = |k: usize| {
            if i & (1 << k) != 0 {
                edges[k]
            } else {
                -edges[k]
            }
        };
        let corner = xf_box.translation + pick(0) + pick(1) + pick(2);
        manifold.push(plane.point(corner, separation, i));
    }
    manifold
}
