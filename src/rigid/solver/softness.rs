//! Soft constraints (Box2D v3's "soft step"): a contact behaves like a stiff, heavily
//! damped spring rather than a rigid rod, which pushes overlapping bodies apart without
//! adding energy.

use crate::math::Real;

/// The coefficients of a soft constraint for substep h.
///
/// For a spring of natural frequency ω = 2π f (rad/s) and damping ratio ζ, implicit
/// integration over h gives
///
/// ```text
/// a₁ = 2ζ + hω,   a₂ = hω a₁,   a₃ = 1 / (1 + a₂)
/// bias_rate = ω / a₁        (1/s: velocity bias per metre of overlap)
/// mass_scale = a₂ a₃        (fraction of the rigid impulse applied)
/// impulse_scale = a₃        (fraction of the accumulated impulse that is kept)
/// ```
///
/// and the impulse of one iteration is λ = −m_eff · mass_scale · (v + bias_rate·C) −
/// impulse_scale · λ_acc for a position error C (m).
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Softness<R: Real> {
    pub bias_rate: R,
    pub mass_scale: R,
    pub impulse_scale: R,
}

impl<R: Real> Softness<R> {
    /// The soft constraint of frequency `hertz` (Hz) and damping ratio `zeta` over a
    /// substep of `h` seconds; `hertz == 0` gives a rigid constraint with no bias.
    pub fn new(hertz: R, zeta: R, h: R) -> Self {
        if hertz <= R::ZERO {
            return Self {
                bias_rate: R::ZERO,
                mass_scale: R::ONE,
                impulse_scale: R::ZERO,
            };
        }
        let omega = R::TAU * hertz;
        let a1 = zeta * R::TWO + h * omega;
        let a2 = h * omega * a1;
        let a3 = R::ONE / (R::ONE + a2);
        Self {
            bias_rate: omega / a1,
            mass_scale: a2 * a3,
            impulse_scale: a3,
        }
    }
}
