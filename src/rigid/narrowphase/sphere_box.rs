//! Sphere against box: the closest point of the box to the sphere's centre, or, for a centre
//! inside the box, the nearest face.

use super::tolerance::{side, unit_from_squared};
use crate::math::{Real, Vec3};
use crate::rigid::manifold::{Manifold, ManifoldPoint};
use crate::rigid::transform::Transform;

/// The contact of sphere A (centre `centre`, radius `radius`, m) with box B (half extents
/// `half_extents`, m, placed by `xf_box`). One point, id 0.
///
/// In the box frame the centre is p = Rᵀ(c − t) and its closest box point is
/// q = clamp(p, −h, h). Outside the box, with d = p − q: the normal (A to B) is −R d/|d|
/// and the separation |d| − r; empty when |d|² > (r + margin)², tested before any square
/// root. When |d| is within 0.24 mm of zero (`tiny_length_squared`: the centre on or in the
/// box) the sphere is pushed out through the nearest face: the axis k of least depth
/// h_k − |p_k| (lowest k on ties), box normal sign(p_k) e_k (+ for p_k = 0), separation
/// −(h_k − |p_k|) − r. The point is the box surface point moved half the separation along
/// the normal towards the sphere: midway between the two surfaces.
pub(super) fn sphere_box<R: Real>(
    centre: Vec3<R>,
    radius: R,
    half_extents: Vec3<R>,
    xf_box: &Transform<R>,
    margin: R,
) -> Manifold<R> {
    let p = xf_box.inverse_point(centre);
    let h = half_extents;
    let q = Vec3::new(
        p.x.clamp(-h.x, h.x),
        p.y.clamp(-h.y, h.y),
        p.z.clamp(-h.z, h.z),
    );
    let d = p - q;
    let distance_squared = d.length_squared();
    let reach = radius + margin;
    if distance_squared > reach * reach {
        return Manifold::EMPTY;
    }
    // Box-to-sphere normal and separation, in the box frame, and the box surface point.
    let (outward, separation, surface) = match unit_from_squared(d, distance_squared) {
        Some((n, distance)) => (n, distance - radius, q),
        None => {
            let depth = h - p.abs();
            let axis = if depth.x <= depth.y && depth.x <= depth.z {
                0
            } else if depth.y <= depth.z {
                1
            } else {
                2
            };
            let sign = side(p[axis]);
            let mut outward = Vec3::ZERO;
            let mut surface = p;
            match axis {
                0 => (outward.x, surface.x) = (sign, sign * h.x),
                1 => (outward.y, surface.y) = (sign, sign * h.y),
                _ => (outward.z, surface.z) = (sign, sign * h.z),
            }
            (outward, -depth[axis] - radius, surface)
        }
    };
    let mut manifold = Manifold {
        normal: -xf_box.vector(outward),
        ..Manifold::EMPTY
    };
    manifold.push(ManifoldPoint {
        point: xf_box.point(surface + outward * (separation * R::HALF)),
        separation,
        id: 0,
    });
    manifold
}
