//! The world positions of a face contact's points, all four at once: x ↦ R x + t (m), with
//! the bits of [`Transform::point`] for each point.
//!
//! On I32F32 the four transforms run in one AVX-512 kernel (`world_points/avx512.rs`)
//! when the processor has it and every operand lies within its bound; otherwise, and for
//! every other format, they run one by one.

#[cfg(target_arch = "x86_64")]
mod avx512;
#[cfg(test)]
mod tests;

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
    #[cfg(target_arch = "x86_64")]
    if avx512::to_world(xf, local, &mut world) {
        return world;
    }
    for (w, &p) in world.iter_mut().zip(local).take(count) {
        *w = xf.point(p);
    }
    world
}
