//! Weakly compressible SPH (Monaghan 1994; Becker & Teschner 2007): pressure from the
//! density through the Tait equation of state, applied explicitly.
//!
//! Pressure over rest density, in m²/s²: P̃ᵢ = pᵢ/ρ₀ = (c²/7) · ((ρᵢ/ρ₀)⁷ − 1), clamped at 0
//! (no tension, so the free surface does not clump). With c at least 10 × the fastest
//! flow the density varies by about (v/c)² < 1 %. Acceleration, m/s²:
//!
//! aᵢ = g − Σⱼ (P̃ᵢ/ρ̃ᵢ² + P̃ⱼ/ρ̃ⱼ²) V₀∇ᵢWᵢⱼ − Σ_b 2 P̃ᵢ/ρ̃ᵢ² V₀∇ᵢW_ib,
//!
//! the symmetric SPH pressure gradient with ρ̃ = ρ/ρ₀, in which each boundary particle
//! mirrors the pressure and density of the fluid particle it pushes. Magnitudes: ρ̃ is
//! near 1, so ρ̃⁷ stays below 2 for any flow the model is meant for; P̃ ≤ c²/7 ≈ 57 m²/s²
//! for c = 20 m/s and 1.4·10⁵ at the largest allowed c, 1000 m/s.

use super::system::FluidSystem;
use crate::math::{Real, Vec3};

impl<R: Real> FluidSystem<R> {
    /// Stage 4 for WCSPH: v ← v + Δt aᵢ (see the [module documentation](self)), then XSPH.
    pub(crate) fn wcsph_velocities(&mut self, dt: R, gravity: Vec3<R>) {
        let stiffness = self.settings.stiffness;
        let s = &mut self.scratch;
        // P̃ᵢ/ρ̃ᵢ², one division per particle.
        s.scalar.clear();
        s.scalar.extend(s.density.iter().map(|&rho| {
            let ratio = rho.max(R::ONE);
            let pressure = stiffness * (ratio.powi(7) - R::ONE);
            pressure * (rho * rho).recip()
        }));
        for i in 0..self.positions.len() {
            let si = s.scalar[i];
            let mut push = Vec3::ZERO;
            for e in s.fluid.range(i) {
                let j = s.fluid.index[e] as usize;
                push += s.fluid.gradient[e] * (si + s.scalar[j]);
            }
            let mut wall = Vec3::ZERO;
            for &g in &s.walls.gradient[s.walls.range(i)] {
                wall += g;
            }
            push += wall * (si + si);
            self.velocities[i] += (gravity - push) * dt;
        }
        self.smooth_velocities();
    }

    /// Pressure of each fluid particle by the Tait equation, p = ρ₀ (c²/7)((ρ/ρ₀)⁷ − 1)
    /// clamped at 0, Pa, from the densities of the last substep (empty before the first).
    pub fn pressures(&self) -> Vec<R> {
        let stiffness = self.settings.stiffness * self.settings.rest_density;
        self.scratch
            .density
            .iter()
            .map(|&rho| stiffness * (rho.max(R::ONE).powi(7) - R::ONE))
            .collect()
    }
}
