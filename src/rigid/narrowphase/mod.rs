//! Narrowphase (placeholder until the narrowphase branch lands).

use super::manifold::Manifold;
use super::shape::Shape;
use super::transform::Transform;
use crate::math::Real;

/// Contacts between two convex shapes within `margin` (m).
pub fn collide<R: Real>(
    _a: &Shape<R>,
    _xf_a: &Transform<R>,
    _b: &Shape<R>,
    _xf_b: &Transform<R>,
    _margin: R,
) -> Manifold<R> {
    Manifold::EMPTY
}
