//! Overlap of two placed shapes: whether they share a point.

use super::super::collide::for_each_manifold;
use super::super::shape::Shape;
use super::super::transform::Transform;
use crate::math::Real;

/// Whether `a` placed by `xf_a` and `b` placed by `xf_b` overlap or touch: some pair of
/// their parts (a compound's parts, a mesh's triangles, or the shape itself; a plane as
/// its half-space) has a narrowphase point with separation ≤ 0 m, as the collide stage
/// finds them. Two planes, and two meshes, never overlap here.
pub(super) fn shapes_overlap<R: Real>(
    a: &Shape<R>,
    xf_a: &Transform<R>,
    b: &Shape<R>,
    xf_b: &Transform<R>,
) -> bool {
    let mut found = false;
    for_each_manifold(a, xf_a, b, xf_b, R::ZERO, |_, _, _| found = true);
    found
}
