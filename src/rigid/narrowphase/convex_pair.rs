//! Contacts of any pair with a cylinder, a cone or a hull (placeholder until GJK, EPA and
//! face clipping land).

use super::plane::WorldPlane;
use crate::math::Real;
use crate::rigid::manifold::Manifold;
use crate::rigid::shape::Shape;
use crate::rigid::transform::Transform;

/// The manifold of two convex shapes, at least one a cylinder, a cone or a hull.
pub(super) fn convex_pair<R: Real>(
    _a: &Shape<R>,
    _xf_a: &Transform<R>,
    _b: &Shape<R>,
    _xf_b: &Transform<R>,
    _margin: R,
) -> Manifold<R> {
    Manifold::EMPTY
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
