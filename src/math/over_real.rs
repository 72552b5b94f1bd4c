//! Families of types built over a scalar format, and the compile-time view of a member as
//! the I32F32 one ([`Real::as_fixed`]): how a subsystem hands its data to the vector
//! kernels of [`wide`](super::wide), which compute on I32F32 bits, without a run-time type
//! test or a cast. For I32F32 the view is the identity; every other format (`f64`, I48F16,
//! I40F24) has none, so that its step compiles the plain path only.

use super::{Real, Vec3};

/// A family of types, one for each scalar format: `Of<R>` (a slice of `R`, a list of
/// vectors of `R`, a subsystem's structure over `R`…).
pub trait OverReal {
    /// The member for format `R`.
    type Of<R: Real>: ?Sized;
}

/// `R` itself.
pub struct Scalar;

impl OverReal for Scalar {
    type Of<R: Real> = R;
}

/// `[R]`.
pub struct Scalars;

impl OverReal for Scalars {
    type Of<R: Real> = [R];
}

/// `[Vec3<R>]`.
pub struct Vectors;

impl OverReal for Vectors {
    type Of<R: Real> = [Vec3<R>];
}

/// `Vec<R>`.
pub struct ScalarVec;

impl OverReal for ScalarVec {
    type Of<R: Real> = Vec<R>;
}

/// `Vec<Vec3<R>>`.
pub struct VectorVec;

impl OverReal for VectorVec {
    type Of<R: Real> = Vec<Vec3<R>>;
}
