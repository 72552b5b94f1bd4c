//! Rays against convex hulls, in the hull's frame: the hull is the intersection of the
//! half-spaces n_f · x ≤ c_f of its faces f (n_f the outward unit normal, c_f the offset
//! in m), and the ray x(t) = o + t·d (d unit, t in m) is clipped against each of them
//! (Cyrus–Beck).

use super::super::convex::ConvexHull;
use super::ray::{Crossing, Ray, clamped_ratio};
use crate::math::Real;

/// Ray (in the hull frame) against the solid hull.
///
/// With s_f = n_f · o − c_f (m, the origin's height above face f) and v_f = n_f · d: the
/// origin is inside when s_f ≤ 0 for every face. Otherwise the line is in face f's
/// half-space for t ≥ s_f / (−v_f) when v_f < 0 (the ray enters there), for
/// t ≤ (−s_f) / v_f when v_f > 0 (it leaves), and everywhere or nowhere (s_f ≤ 0 or
/// not) when v_f = 0. The ray hits when the largest entry is at most the smallest exit, is
/// ≥ 0 and within `max`: at that entry, with the normal of its face (the lowest face
/// index on ties: an edge or a vertex). A box's faces in the order −x, +x, −y, +y, −z, +z
/// give exactly the box's answer ([`ray_box`](super::ray::ray_box)).
pub(super) fn ray_hull<R: Real>(hull: &ConvexHull<R>, ray: &Ray<R>) -> Option<Crossing<R>> {
    let limit = ray.limit();
    let mut enter = -limit;
    let mut exit = limit;
    let mut entry_face = None;
    let mut inside = true;
    for (i, face) in hull.faces().iter().enumerate() {
        let s = face.normal.dot(ray.origin) - face.offset;
        let v = face.normal.dot(ray.direction);
        inside &= s <= R::ZERO;
        if v < R::ZERO {
            let t = clamped_ratio(s, -v, limit);
            if t > enter {
                enter = t;
                entry_face = Some(i);
            }
        } else if v > R::ZERO {
            exit = exit.min(clamped_ratio(-s, v, limit));
        } else if s > R::ZERO {
            return None;
        }
    }
    if inside {
        return Some(Crossing::Inside);
    }
    let face = entry_face?;
    (enter <= exit && exit >= R::ZERO && enter <= ray.max).then(|| Crossing::Enters {
        distance: enter.max(R::ZERO),
        normal: hull.faces()[face].normal,
    })
}
