//! The Wendland C2 kernel in normalised form.
//!
//! With support radius H and q = r/H ∈ [0, 1],
//!
//! W(r) = σ/H³ · f(q),  f(q) = (1 − q)⁴ (1 + 4q),  σ = 21/(2π)  (1/m³),
//! ∇ᵢW(xᵢ − xⱼ) = −(20 σ/H⁴) (1 − q)³ · q r̂ = −(20 σ/H⁴) (1 − q)³ · d,
//!
//! where d = (xᵢ − xⱼ)/H is the normalised offset (|d| = q). The gradient is a multiple of
//! d, so no direction has to be normalised; one square root per pair gives q.
//!
//! # Scaling: no power of H is ever formed
//!
//! The solvers never need W or ∇W alone, only the particle volume times them: V₀W
//! (dimensionless) and V₀∇W (1/m). Both are written as a precomputed constant times a
//! polynomial in q:
//!
//! V₀W = c_w f(q),  V₀∇W = −c_g (1 − q)³ d,  c_g = 20 c_w / H.
//!
//! In the continuum c_w = V₀σ/H³ = σ/s³ for a support of s spacings (0.42 for s = 2) and
//! c_g = 20 c_w/H. Both are *calibrated* on the rest lattice instead, which a coarse
//! support (33 neighbours at s = 2) needs:
//!
//! - c_w = 1 / Σₖ f(qₖ) over the lattice sites k within the support, the particle itself
//!   included, so that a particle inside the fluid at rest has ρ/ρ₀ = 1 exactly;
//! - c_g = 1 / (H Σₖ (1 − qₖ)³ dₖₓ²), so that the discrete gradient of a linear field is
//!   exact on the lattice: Σₖ V₀∇Wₖ ⊗ (xₖ − x) = I. Without it the SPH pressure force of a
//!   hydrostatic column at s = 2 is a third short, and WCSPH settles at 1.5 ρgh.
//!
//! Magnitudes, for spacings 0.001 to 1 m and supports 1.5 to 4 spacings: d and q are in
//! [0, 1] (offsets are scaled by 1/H before they are squared, so q² never falls below the
//! format's resolution as r² = 10⁻⁸ m² would); c_w is 0.01 to 2; c_g at most 2.7·10⁴ 1/m.
//! Every intermediate fits I32F32 (±2.1·10⁹), I40F24 and I48F16 with room to spare; the
//! textbook poly6 constant 315/(64π H⁹) would be 10¹⁸ at H = 1 cm.

use serde::{Deserialize, Serialize};

use crate::math::{Fx, Real, Vec3};

/// The kernel constants of one fluid.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(bound = "")]
pub struct Kernel<R: Real = Fx> {
    /// H, m.
    pub support: R,
    /// 1/H, 1/m.
    pub inv_support: R,
    /// c_w: V₀W = c_w f(q) (dimensionless).
    pub density_scale: R,
    /// c_g (calibrated, about 20 c_w / H): V₀∇W = −c_g (1 − q)³ d, 1/m.
    pub gradient_scale: R,
    /// Σₖ |V₀∇Wₖ|² over the rest lattice, 1/m²: DFSPH's denominator for a particle inside
    /// the fluid at rest.
    pub lattice_gradient_norm: R,
}

/// f(q) = (1 − q)⁴ (1 + 4q) for q ∈ [0, 1]: the Wendland C2 shape, f(0) = 1.
#[inline(always)]
pub fn wendland_shape<R: Real>(q: R) -> R {
    let t = R::ONE - q;
    let t2 = t * t;
    t2 * t2 * (R::ONE + R::from_int(4) * q)
}

/// The continuous normalisation σ = 21/(2π) of the 3D Wendland C2 kernel, such that
/// ∫ σ/H³ f(|x|/H) dx = 1 over the ball of radius H.
pub fn wendland_sigma<R: Real>() -> R {
    R::from_int(21) / (R::TWO * R::PI)
}

impl<R: Real> Kernel<R> {
    /// The kernel of support `support` spacings for particles `spacing` metres apart,
    /// calibrated on the rest lattice (see the [module documentation](self)).
    pub fn calibrated(spacing: R, support: R) -> Self {
        let radius = spacing * support;
        let inv_support = radius.recip();
        let reach = lattice_reach(support);
        let step = support.recip();
        let mut sum = R::ZERO;
        let mut moment = R::ZERO;
        for k in -reach..=reach {
            for j in -reach..=reach {
                for i in -reach..=reach {
                    let d = Vec3::new(R::from_int(i), R::from_int(j), R::from_int(k)) * step;
                    let q2 = d.length_squared();
                    if q2 < R::ONE {
                        let q = q2.sqrt();
                        sum += wendland_shape(q);
                        let t = R::ONE - q;
                        moment += t * t * t * d.x * d.x;
                    }
                }
            }
        }
        let gradient_scale = (moment * radius).recip();
        let mut norm = R::ZERO;
        for k in -reach..=reach {
            for j in -reach..=reach {
                for i in -reach..=reach {
                    let d = Vec3::new(R::from_int(i), R::from_int(j), R::from_int(k)) * step;
                    let q2 = d.length_squared();
                    if q2 < R::ONE {
                        let t = R::ONE - q2.sqrt();
                        let g = gradient_scale * t * t * t;
                        norm += g * g * q2;
                    }
                }
            }
        }
        Self {
            support: radius,
            inv_support,
            density_scale: sum.recip(),
            gradient_scale,
            lattice_gradient_norm: norm,
        }
    }

    /// V₀W and V₀∇ᵢW for the offset `offset` = xᵢ − xⱼ, or `None` beyond the support.
    ///
    /// V₀W = c_w (1 − q)⁴ (1 + 4q) (dimensionless); V₀∇W = −c_g (1 − q)³ d (1/m), with
    /// d = offset/H and q = |d|.
    ///
    /// A cheap test first rejects offsets with a component beyond H: most candidates from
    /// the 27 cells around a particle fail it.
    #[inline(always)]
    pub fn evaluate(&self, offset: Vec3<R>) -> Option<(R, Vec3<R>)> {
        let support = self.support;
        if offset.x.abs() >= support || offset.y.abs() >= support || offset.z.abs() >= support {
            return None;
        }
        let d = offset * self.inv_support;
        let q2 = d.length_squared();
        if q2 >= R::ONE {
            return None;
        }
        Some(self.evaluate_within(d, q2))
    }

    /// V₀W and V₀∇ᵢW for the normalised offset `d` = (xᵢ − xⱼ)/H with `q2` = |d|² < 1:
    /// the second half of [`Kernel::evaluate`], for searches that test the support
    /// themselves. One square root.
    #[inline(always)]
    pub fn evaluate_within(&self, d: Vec3<R>, q2: R) -> (R, Vec3<R>) {
        let q = q2.sqrt();
        let t = R::ONE - q;
        let t3 = t * t * t;
        let value = self.density_scale * (t3 * t * (R::ONE + R::from_int(4) * q));
        let gradient = d * -(self.gradient_scale * t3);
        (value, gradient)
    }
}

/// The largest lattice offset, in spacings, that can lie within a support of `support`
/// spacings: ⌈support⌉, found by counting so that no float is involved.
pub fn lattice_reach<R: Real>(support: R) -> i32 {
    let mut reach = 0;
    while R::from_int(reach) < support {
        reach += 1;
    }
    reach
}
