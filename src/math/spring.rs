//! The damped spring shared by the particles' spring forces and the soft bodies'
//! spring-mass model: its constants and its force law.

use serde::{Deserialize, Serialize};

use super::{Fx, Real, Vec3};

/// A damped spring: F = −(k (ℓ − ℓ₀) + c (v_rel · û)) û on the first end and the opposite
/// force on the second, where ℓ is the length, û the unit vector from the second end to the
/// first and v_rel the first end's velocity minus the second's.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(bound = "", deny_unknown_fields)]
pub struct SpringDesc<R: Real = Fx> {
    /// k, N/m (≥ 0).
    pub stiffness: R,
    /// c, N·s/m (≥ 0). Default 0.
    #[serde(default)]
    pub damping: R,
    /// ℓ₀, m (≥ 0).
    pub rest_length: R,
}

/// Force on the first end of a damped spring, N:
/// F = −(k (ℓ − ℓ₀) + c (v_rel · û)) û, with `offset` d = x₁ − x₂ (m), ℓ = |d|, û = d/ℓ and
/// `relative_velocity` v_rel = v₁ − v₂ (m/s). The second end feels −F. Zero when the ends
/// coincide, since the spring then has no axis.
#[inline]
pub fn spring_force<R: Real>(
    spring: &SpringDesc<R>,
    offset: Vec3<R>,
    relative_velocity: Vec3<R>,
) -> Vec3<R> {
    let length_squared = offset.length_squared();
    if length_squared == R::ZERO {
        return Vec3::ZERO;
    }
    let length = length_squared.sqrt();
    let axis = offset * length.recip();
    let tension = spring.stiffness * (length - spring.rest_length)
        + spring.damping * relative_velocity.dot(axis);
    axis * -tension
}
