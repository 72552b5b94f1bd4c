//! The convex parts of a shape, placed in the world frame.

use super::super::shape::Shape;
use super::super::transform::Transform;
use crate::math::Real;

/// Calls `f(part, placement)` for each part of a compound placed by `xf` (its part
/// placement composed with `xf`), in order, or once for any other shape.
pub(super) fn for_each_part<R: Real>(
    shape: &Shape<R>,
    xf: &Transform<R>,
    mut f: impl FnMut(&Shape<R>, &Transform<R>),
) {
    match shape {
        Shape::Compound { parts } => {
            for part in parts {
                let local = Transform::from_pose(part.translation, part.rotation);
                f(&part.shape, &xf.compose(&local));
            }
        }
        _ => f(shape, xf),
    }
}
