//! The constant-density solver of Divergence-Free SPH (Bender & Koschier 2015, 2017).
//!
//! Why DFSPH rather than PBF or IISPH: like IISPH it iterates a pressure solve to a
//! tolerance on the density error, which PBF does not (PBF runs a fixed number of
//! constraint projections on positions and its error depends on that count); unlike IISPH
//! its per-particle factor is computed once per substep, so an iteration is two plain
//! passes over the neighbour lists with no per-pair division and no d_ij terms to store.
//! Each iteration is Jacobi (every particle reads the values of the previous pass), so the
//! result does not depend on the order particles are visited in.
//!
//! Per substep of length Δt, with ρ̃ = ρ/ρ₀ and V₀∇W from the [kernel](super::kernel):
//!
//! - factor: Dᵢ = |Σⱼ V₀∇Wᵢⱼ + Σ_b V₀∇W_ib|² + Σⱼ |V₀∇Wᵢⱼ|² (1/m²), αᵢ = 1/(Δt² Dᵢ) (s⁻²·m²),
//!   computed as (1/Δt)/(Δt Dᵢ) so that Δt² (10⁻⁸ s²) is never formed. Dᵢ is taken at
//!   least 1/16 of its value D₀ inside the fluid at rest: only a particle with few
//!   neighbours (a splash, which is never compressed) falls below, and its factor would
//!   leave the range;
//! - predicted density: ρ̃*ᵢ = ρ̃ᵢ + Δt Σⱼ (vᵢ − vⱼ)·V₀∇Wᵢⱼ + Δt Σ_b vᵢ·V₀∇W_ib;
//! - stiffness: kᵢ = max(ρ̃*ᵢ − 1, 0) αᵢ (m²/s², ρ₀κᵢ/ρᵢ in the paper's terms);
//! - correction: vᵢ ← vᵢ − Δt (Σⱼ (kᵢ + kⱼ) V₀∇Wᵢⱼ + Σ_b kᵢ V₀∇W_ib),
//!
//! repeated until the mean of max(ρ̃*ᵢ − 1, 0) is at most the tolerance (or the iteration
//! cap). The corrections amount to the pressure force of P̃ᵢ/ρ̃ᵢ² = Σ kᵢ over the
//! iterations, so the pressure is p = ρ₀ ρ̃ᵢ² Σ kᵢ. The divergence-free half of DFSPH is not used: the XSPH smoothing damps the
//! velocity noise it would remove. Magnitudes at spacing 5 mm, Δt = 10⁻⁴ s: Dᵢ ≈ 10⁵,
//! αᵢ ≈ 10³, kᵢ ≈ 1, corrections ≈ 10⁻² m/s.

use super::row_sums;
use super::system::FluidSystem;
use crate::math::{Real, Vec3};

impl<R: Real> FluidSystem<R> {
    /// Stage 4 for DFSPH: v ← v + Δt g, XSPH, then the constant-density iterations (see the
    /// [module documentation](self)).
    pub(crate) fn dfsph_velocities(&mut self, dt: R, gravity: Vec3<R>) {
        self.compute_factors(dt);
        for v in &mut self.velocities {
            *v = v.add_scaled(gravity, dt);
        }
        self.smooth_velocities();
        let n = self.positions.len();
        let tolerance = self.settings.max_density_error * R::from_int(n as i32);
        let s = &mut self.scratch;
        s.pressure.clear();
        s.pressure.resize(n, R::ZERO);
        let mut iterations = 0;
        while iterations < self.settings.max_iterations {
            if self.predict_stiffness(dt) <= tolerance {
                break;
            }
            self.correct_velocities(dt);
            iterations += 1;
        }
        let s = &mut self.scratch;
        for (p, &rho) in s.pressure.iter_mut().zip(&s.density) {
            *p *= rho * rho;
        }
        s.last_iterations += iterations;
    }

    /// αᵢ = (1/Δt) / (Δt max(Dᵢ, D₀/16)) into `factor`, and
    /// Σ_b V₀∇W_ib into `wall_gradient`.
    fn compute_factors(&mut self, dt: R) {
        let inv_dt = dt.recip();
        let floor = self.settings.kernel.lattice_gradient_norm * R::from_ratio(1, 16);
        let s = &mut self.scratch;
        s.factor.clear();
        s.wall_gradient.clear();
        for i in 0..self.positions.len() {
            let mut sum = Vec3::ZERO;
            let mut squares = R::ZERO;
            for g in s.fluid.range(i).map(|e| s.fluid.gradient(e)) {
                sum += g;
                squares += g.length_squared();
            }
            let mut wall = Vec3::ZERO;
            for g in s.walls.range(i).map(|e| s.walls.gradient(e)) {
                wall += g;
            }
            s.wall_gradient.push(wall);
            let d = ((sum + wall).length_squared() + squares).max(floor);
            s.factor.push(inv_dt / (dt * d));
        }
    }

    /// kᵢ = max(ρ̃*ᵢ − 1, 0) αᵢ into `scalar`; returns Σ max(ρ̃*ᵢ − 1, 0).
    fn predict_stiffness(&mut self, dt: R) -> R {
        let s = &mut self.scratch;
        row_sums::density_rates(&s.fluid, &self.velocities, &mut s.rate);
        s.scalar.clear();
        let mut total = R::ZERO;
        for (i, &vi) in self.velocities.iter().enumerate() {
            let change = s.rate[i] + vi.dot(s.wall_gradient[i]);
            let error = (s.density[i] + change * dt - R::ONE).max(R::ZERO);
            total += error;
            s.scalar.push(error * s.factor[i]);
        }
        total
    }

    /// vᵢ ← vᵢ − Δt (Σⱼ (kᵢ + kⱼ) V₀∇Wᵢⱼ + Σ_b kᵢ V₀∇W_ib), Jacobi.
    fn correct_velocities(&mut self, dt: R) {
        let s = &mut self.scratch;
        row_sums::pressure_pushes(&s.fluid, &s.scalar, &mut s.delta);
        for (i, v) in self.velocities.iter_mut().enumerate() {
            let ki = s.scalar[i];
            s.pressure[i] += ki;
            *v -= (s.delta[i] + s.wall_gradient[i] * ki) * dt;
        }
    }
}
