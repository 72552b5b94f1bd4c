//! The world positions of a face contact's points, all four at once: x ↦ R x + t (m), with
//! the bits of [`Transform::point`] for each point.
//!
//! On I32F32 the four transforms run in one kernel ([`kernel`]) when the processor has
//! AVX-512 or AVX2 and every operand lies within its bound; otherwise, and for every
//! other format, they run one by one.

#[cfg(vector_kernels)]
mod kernel;
#[cfg(test)]
mod tests;

#[cfg(vector_kernels)]
use crate::math::over_real::OverReal;
use crate::math::{Real, Vec3};
use crate::rigid::manifold::MAX_MANIFOLD_POINTS;
use crate::rigid::transform::Transform;

/// The first `count` of the local points `local` (m, in the frame `xf` places) in the world
/// frame: pᵢ ↦ R pᵢ + t, each as [`Transform::point`] computes it, saturations included
/// (entries past `count` are left zero, or hold the transform of the local entries there,
/// which the caller ignores).
#[inline]
pub(super) fn to_world<R: Real>(
    xf: &Transform<R>,
    local: &[Vec3<R>; MAX_MANIFOLD_POINTS],
    count: usize,
) -> [Vec3<R>; MAX_MANIFOLD_POINTS] {
    let mut world = [Vec3::ZERO; MAX_MANIFOLD_POINTS];
    #[cfg(vector_kernels)]
    if kernel::to_world(xf, local, &mut world) {
        return world;
    }
    for (w, &p) in world.iter_mut().zip(local).take(count) {
        *w = xf.point(p);
    }
    world
}

/// The family of a manifold's points, `[Vec3<R>; MAX_MANIFOLD_POINTS]`, for
/// [`Real::as_fixed`].
#[cfg(vector_kernels)]
struct ManifoldPointsOf;

#[cfg(vector_kernels)]
impl OverReal for ManifoldPointsOf {
    type Of<R: Real> = [Vec3<R>; MAX_MANIFOLD_POINTS];
}
