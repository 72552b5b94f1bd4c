//! Sphere against sphere: one point on the line of centres.

use super::tolerance::unit_from_squared;
use crate::math::{Real, Vec3};
use crate::rigid::manifold::{Manifold, ManifoldPoint};

/// The contact of sphere A (centre `centre_a`, radius `radius_a`, m) with sphere B.
///
/// With d = c_B − c_A: the normal is d/|d| and the separation |d| − r_A − r_B (m); the point
/// c_A + n (r_A + separation/2) lies midway between the two surfaces. Empty when
/// |d|² > (r_A + r_B + margin)², tested before any square root. Centres closer than
/// 0.24 mm (see `tiny_length_squared`) have no usable direction and get the normal +y.
/// One point, id 0.
#[inline]
pub(super) fn sphere_sphere<R: Real>(
    centre_a: Vec3<R>,
    radius_a: R,
    centre_b: Vec3<R>,
    radius_b: R,
    margin: R,
) -> Manifold<R> {
    ball_contact(centre_a, radius_a, centre_b, radius_b, margin, || Vec3::Y)
}

/// The contact of two balls, as [`sphere_sphere`], with the normal `fallback()` when the
/// centres are too close to give a direction (the separation is then −r_A − r_B). A sphere
/// against a capsule is this with the capsule's closest segment point as ball B.
#[inline]
pub(super) fn ball_contact<R: Real>(
    centre_a: Vec3<R>,
    radius_a: R,
    centre_b: Vec3<R>,
    radius_b: R,
    margin: R,
    fallback: impl FnOnce() -> Vec3<R>,
) -> Manifold<R> {
    let d = centre_b - centre_a;
    let distance_squared = d.length_squared();
    let radii = radius_a + radius_b;
    let reach = radii + margin;
    if distance_squared > reach * reach {
        return Manifold::EMPTY;
    }
    let (normal, distance) =
        unit_from_squared(d, distance_squared).unwrap_or_else(|| (fallback(), R::ZERO));
    let separation = distance - radii;
    let mut manifold = Manifold {
        normal,
        ..Manifold::EMPTY
    };
    manifold.push(ManifoldPoint {
        point: centre_a + normal * (radius_a + separation * R::HALF),
        separation,
        id: 0,
    });
    manifold
}
