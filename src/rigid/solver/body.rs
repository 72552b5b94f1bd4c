//! The solver's copy of a moving body: velocities, the motion accumulated during the step,
//! and inverse mass properties in the world frame.

use crate::math::{Mat3, Real, Vec3};

/// One awake dynamic or kinematic body in the solver, or the shared static body at index
/// [`STATIC_BODY`] (all zeros: never moves, infinite mass).
///
/// Laid out in order and aligned to 64 bytes, so that for the 8-byte formats v, ω and the
/// first two components of Δp fill one cache line, which the AVX-512 kernels load and
/// store whole.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
#[repr(C, align(64))]
pub(crate) struct SolverBody<R: Real> {
    /// Linear velocity, m/s.
    pub v: Vec3<R>,
    /// Angular velocity, world frame, rad/s.
    pub w: Vec3<R>,
    /// Displacement of the centre of mass since the step began, m.
    pub dp: Vec3<R>,
    /// Rotation since the step began, as a rotation vector Σ h ω (rad); small, so the
    /// motion of an anchor r is dθ × r to first order.
    pub dtheta: Vec3<R>,
    /// 1/m, 1/kg.
    pub inv_mass: R,
    /// World-frame inverse inertia R I⁻¹ Rᵀ at the start of the step, 1/(kg·m²).
    pub inv_inertia: Mat3<R>,
}

/// The family of solver body lists, `[SolverBody<R>]`, for [`Real::as_fixed`].
#[cfg(vector_kernels)]
pub(crate) struct SolverBodiesOf;

#[cfg(vector_kernels)]
impl crate::math::over_real::OverReal for SolverBodiesOf {
    type Of<R: Real> = [SolverBody<R>];
}

/// The solver index of every static body (and of bodies the solver does not move).
pub(crate) const STATIC_BODY: u32 = 0;

/// Two distinct bodies of the solver array, mutably. Index [`STATIC_BODY`] is never written
/// (its inverse mass is zero, so the impulses applied to it are zero), which lets a
/// constraint against a static body use a scratch copy.
pub(crate) fn pair<R: Real>(
    bodies: &mut [SolverBody<R>],
    a: u32,
    b: u32,
) -> (&mut SolverBody<R>, &mut SolverBody<R>) {
    let (a, b) = (a as usize, b as usize);
    debug_assert_ne!(a, b);
    if a < b {
        let (lo, hi) = bodies.split_at_mut(b);
        (&mut lo[a], &mut hi[0])
    } else {
        let (lo, hi) = bodies.split_at_mut(a);
        (&mut hi[0], &mut lo[b])
    }
}
