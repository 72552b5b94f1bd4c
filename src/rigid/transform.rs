//! `Transform`: a rigid placement (rotation matrix and translation) used by collision.
//!
//! Bodies keep their orientation as a quaternion; collision code works with the rotation
//! matrix, computed once per body per step, because it transforms many points.

use crate::math::{Fx, Mat3, Quat, Real, Vec3};

/// x ↦ R x + t: a rotation `rotation` (orthonormal) followed by a translation
/// `translation` (m).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Transform<R: Real = Fx> {
    /// Rotation from the local frame to the world frame.
    pub rotation: Mat3<R>,
    /// Position of the local origin in the world frame, m.
    pub translation: Vec3<R>,
}

/// The family of [`Transform`]s, for [`Real::as_fixed`].
#[cfg(vector_kernels)]
pub(crate) struct TransformOf;

#[cfg(vector_kernels)]
impl crate::math::over_real::OverReal for TransformOf {
    type Of<R: Real> = Transform<R>;
}

impl<R: Real> Transform<R> {
    /// The identity placement.
    pub const IDENTITY: Self = Self {
        rotation: Mat3::IDENTITY,
        translation: Vec3::ZERO,
    };

    /// The placement of a body at `position` (m) with orientation `orientation` (unit).
    pub fn from_pose(position: Vec3<R>, orientation: Quat<R>) -> Self {
        Self {
            rotation: orientation.to_mat3(),
            translation: position,
        }
    }

    /// A local point in the world frame: R p + t.
    #[inline]
    pub fn point(&self, p: Vec3<R>) -> Vec3<R> {
        self.rotation * p + self.translation
    }

    /// A local direction in the world frame: R v.
    #[inline]
    pub fn vector(&self, v: Vec3<R>) -> Vec3<R> {
        self.rotation * v
    }

    /// A world point in the local frame: Rᵀ (p − t).
    #[inline]
    pub fn inverse_point(&self, p: Vec3<R>) -> Vec3<R> {
        self.inverse_vector(p - self.translation)
    }

    /// A world direction in the local frame: Rᵀ v.
    #[inline]
    pub fn inverse_vector(&self, v: Vec3<R>) -> Vec3<R> {
        let m = &self.rotation;
        Vec3::new(m.cols[0].dot(v), m.cols[1].dot(v), m.cols[2].dot(v))
    }

    /// The placement `self ∘ inner`: first `inner`, then `self` (a compound part placed in
    /// its body).
    pub fn compose(&self, inner: &Self) -> Self {
        Self {
            rotation: self.rotation * inner.rotation,
            translation: self.point(inner.translation),
        }
    }
}
