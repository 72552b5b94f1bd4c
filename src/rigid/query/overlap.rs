//! Overlap of two placed shapes: whether they share a point.

use super::super::narrowphase::collide;
use super::super::shape::Shape;
use super::super::transform::Transform;
use super::parts::for_each_part;
use crate::math::Real;

/// Whether `a` placed by `xf_a` and `b` placed by `xf_b` overlap or touch: some pair of
/// their convex parts (a compound's parts, or the shape itself; a plane as its half-space)
/// has a narrowphase point with separation ≤ 0 m. Two planes never overlap here.
pub(super) fn shapes_overlap<R: Real>(
    a: &Shape<R>,
    xf_a: &Transform<R>,
    b: &Shape<R>,
    xf_b: &Transform<R>,
) -> bool {
    let mut found = false;
    for_each_part(a, xf_a, |part_a, placed_a| {
        if found {
            return;
        }
        for_each_part(b, xf_b, |part_b, placed_b| {
            found = found || collide(part_a, placed_a, part_b, placed_b, R::ZERO).count > 0;
        });
    });
    found
}
