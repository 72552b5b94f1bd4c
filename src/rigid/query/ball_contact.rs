//! The contact of a small ball (a soft-body vertex of radius r) with a body's shape: the
//! unit normal n̂ out of the shape and the depth δ > 0 (m) by which the ball overlaps it,
//! so that moving the ball by δ n̂ just separates them. Every shape answers, meshes and
//! heightfields (two-sided surfaces) included.
//!
//! With `from` the ball's centre at the start of its step, in the shape's current frame
//! (its path relative to the shape), the rules are, in order:
//! 1. a plane n̂·x ≤ c: n̂, δ = r − (n̂·x − c);
//! 2. a path at least r long that enters the shape (a fast ball, or one that crossed a
//!    mesh's surface): the entry point e and the normal there, δ = r + (e − x)·n̂, so the
//!    ball goes back to the side it came from;
//! 3. the centre outside, at distance d < r from the nearest surface point q:
//!    n̂ = (x − q)/d, δ = r − d;
//! 4. the centre inside: as rule 2 when the path enters the shape, otherwise along the ray
//!    from the shape's centre through x (a convex shape's centre is inside it): the
//!    surface point e it leaves by, δ = r + (e − x)·n̂.

use super::point::project_point;
use super::ray::{Crossing, Ray, ray_shape};
use super::unit_direction;
use crate::math::{Real, Vec3};
use crate::rigid::aabb::Aabb;
use crate::rigid::shape::Shape;
use crate::rigid::transform::Transform;

/// The contact (n̂, δ) of a ball of radius `r` centred at `x` (m), which started its step
/// at `from`, with `shape` placed by `xf`, if they overlap (see the [module](self)).
pub(crate) fn ball_contact<R: Real>(
    shape: &Shape<R>,
    xf: &Transform<R>,
    x: Vec3<R>,
    from: Vec3<R>,
    r: R,
) -> Option<(Vec3<R>, R)> {
    if let Shape::Plane { normal, offset } = shape {
        let n = xf.vector(*normal);
        let depth = r - (n.dot(x) - (*offset + n.dot(xf.translation)));
        return (depth > R::ZERO).then_some((n, depth));
    }
    let path = x - from;
    let long = path.length_squared() >= r * r;
    if long && let Some(contact) = entry(shape, xf, from, x, r) {
        return Some(contact);
    }
    let nearest = project_point(shape, xf, x);
    if !nearest.inside {
        if nearest.distance >= r || nearest.distance == R::ZERO {
            return None;
        }
        let normal = unit_direction(x - nearest.point)?;
        return Some((normal, r - nearest.distance));
    }
    if !long && let Some(contact) = entry(shape, xf, from, x, r) {
        return Some(contact);
    }
    let outward = unit_direction(x - xf.translation).unwrap_or(Vec3::Y);
    let reach = Aabb::of_shape(shape, xf).map_or(R::ONE, |b| (b.max - b.min).length());
    let outside = x.add_scaled(outward, reach);
    let ray = Ray::new(outside, -outward, reach + reach);
    match ray_shape(shape, xf, &ray)? {
        Crossing::Enters { distance, normal } => {
            let exit = ray.at(distance);
            Some((normal, r + (exit - x).dot(normal)))
        }
        Crossing::Inside => None,
    }
}

/// Rule 2: where the path `from` → `x` enters the shape, as a contact of the ball at `x`.
fn entry<R: Real>(
    shape: &Shape<R>,
    xf: &Transform<R>,
    from: Vec3<R>,
    x: Vec3<R>,
    r: R,
) -> Option<(Vec3<R>, R)> {
    let path = x - from;
    let direction = unit_direction(path)?;
    let ray = Ray::new(from, direction, path.length());
    match ray_shape(shape, xf, &ray)? {
        Crossing::Enters { distance, normal } => {
            let depth = r + (ray.at(distance) - x).dot(normal);
            (depth > R::ZERO).then_some((normal, depth))
        }
        Crossing::Inside => None,
    }
}
