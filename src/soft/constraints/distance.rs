//! Distance constraints: C = |xₐ − x_b| − ℓ₀ (m), ∇ₐC = n̂ = (xₐ − x_b)/|xₐ − x_b|,
//! ∇_bC = −n̂, so Σ w|∇C|² = wₐ + w_b.
//!
//! With D = wₐ + w_b + α̃ constant, the update of the [module](super) is carried in
//! position units, which fixed point resolves far better than λ itself (N·s², tiny for
//! light vertices and short substeps): the row keeps μ = α̃λ (m) and precomputes the
//! shares sₐ = wₐ/D, s_b = w_b/D and the relaxation ρ = α̃/D; then with r = −C − μ,
//! xₐ += sₐ r n̂, x_b −= s_b r n̂, μ += ρ r: exactly the XPBD update, no division.
//!
//! 1/|d| comes without a square root from the row's previous value y₀ (1/ℓ₀ at the start),
//! by the Taylor series of (1 + δ)^{−½} with δ = q − 1, q = |d|² y₀²:
//! y = y₀ (1 − δ/2 + 3δ²/8), whose relative error is about (5/16)|δ|³ plus that of y₀,
//! shrunk to its square times 3/2 by every solve. Since an edge changes length little
//! between substeps, δ is tiny and y is exact to the format's resolution after a few
//! solves; a compliant row's stretch under load is then exact. Rows with q outside
//! [3/4, 5/4] (the length changed by more than about 12% since the last solve: a crumpled
//! start, a violent impact) take the exact 1/√. y is state: it is kept per row, hashed and
//! snapshotted.

use serde::{Deserialize, Serialize};

use crate::math::{Real, Vec3};

/// Distance constraint rows.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(bound = "")]
pub(crate) struct Distances<R: Real> {
    pub a: Vec<u32>,
    pub b: Vec<u32>,
    /// ℓ₀, m.
    pub rest: Vec<R>,
    /// 1/|d| at the row's last solve (1/ℓ₀ before the first), 1/m.
    pub inv_length: Vec<R>,
    /// α, m/N.
    pub compliance: Vec<R>,
    /// μ = α̃λ, m.
    pub lambda: Vec<R>,
}

/// The per-substep factors of one row kind: shares of each end and the relaxation.
#[derive(Clone, Debug, Default)]
pub(crate) struct DistanceFactors<R: Real> {
    /// sₐ = wₐ/D.
    pub share_a: Vec<R>,
    /// s_b = w_b/D.
    pub share_b: Vec<R>,
    /// ρ = α̃/D.
    pub relax: Vec<R>,
}

impl<R: Real> Distances<R> {
    /// Adds a row between vertices `a` and `b` at rest length `rest` (> 0, m) with
    /// compliance `compliance` (m/N).
    pub fn push(&mut self, a: u32, b: u32, rest: R, compliance: R) {
        self.a.push(a);
        self.b.push(b);
        self.rest.push(rest);
        self.inv_length.push(rest.recip());
        self.compliance.push(compliance);
        self.lambda.push(R::ZERO);
    }

    /// The factors for inverse masses `inv_mass` (1/kg) and 1/h² `inv_h2` (1/s²).
    pub fn factors(&self, inv_mass: &[R], inv_h2: R) -> DistanceFactors<R> {
        let mut f = DistanceFactors::default();
        for c in 0..self.a.len() {
            let (wa, wb) = (inv_mass[self.a[c] as usize], inv_mass[self.b[c] as usize]);
            let alpha = self.compliance[c] * inv_h2;
            let denominator = wa + wb + alpha;
            let (sa, sb, relax) = if denominator > R::ZERO {
                (wa / denominator, wb / denominator, alpha / denominator)
            } else {
                (R::ZERO, R::ZERO, R::ZERO)
            };
            f.share_a.push(sa);
            f.share_b.push(sb);
            f.relax.push(relax);
        }
        f
    }

    /// One Gauss–Seidel pass over every row, in order, moving `positions` (m).
    pub fn solve(&mut self, positions: &mut [Vec3<R>], f: &DistanceFactors<R>) {
        let fast_low = R::from_ratio(3, 4);
        let fast_high = R::from_ratio(5, 4);
        let three_eighths = R::from_ratio(3, 8);
        for c in 0..self.a.len() {
            let (a, b) = (self.a[c] as usize, self.b[c] as usize);
            let d = positions[a] - positions[b];
            let length_squared = d.dot_fused(d);
            let previous = self.inv_length[c];
            let q = length_squared * previous * previous;
            let inv_length = if q >= fast_low && q <= fast_high {
                let delta = q - R::ONE;
                let series = R::ONE - delta * R::HALF + delta * delta * three_eighths;
                previous * series
            } else if length_squared > R::ZERO {
                length_squared.rsqrt()
            } else {
                continue;
            };
            self.inv_length[c] = inv_length;
            let length = length_squared * inv_length;
            let residual = self.rest[c] - length - self.lambda[c];
            self.lambda[c] += f.relax[c] * residual;
            let direction = d * inv_length;
            positions[a] = positions[a].add_scaled(direction, f.share_a[c] * residual);
            positions[b] = positions[b].add_scaled(direction, -(f.share_b[c] * residual));
        }
    }
}
