//! Weakly compressible SPH (Monaghan 1994; Becker & Teschner 2007): pressure from the
//! density through the Tait equation of state, applied explicitly.
//!
//! Pressure over rest density, in m²/s²: P̃ᵢ = pᵢ/ρ₀ = (c²/7) · ((ρᵢ/ρ₀)⁷ − 1), clamped at 0
//! (no tension, so the free surface does not clump). With c at least 10 × the fastest
//! flow the density varies by about (v/c)² < 1 %. Acceleration, m/s²:
//!
//! aᵢ = g − Σⱼ (P̃ᵢ/ρ̃ᵢ² + P̃ⱼ/ρ̃ⱼ² − α c min(vᵢⱼ·dᵢⱼ, 0)) V₀∇ᵢWᵢⱼ
//!        − Σ_b (P̃ᵢ/ρ̃ᵢ² − α c min(vᵢ·d_ib, 0)) V₀∇ᵢW_ib,
//!
//! (and the same over the rigid bodies' samples, with their volumes and velocities:
//! [`bodies`](super::bodies)),
//!
//! the symmetric SPH pressure gradient with ρ̃ = ρ/ρ₀ and, against boundary particles,
//! Akinci et al.'s (2012) one-sided term, plus Monaghan's
//! artificial viscosity on approaching pairs (vᵢⱼ = vᵢ − vⱼ, dᵢⱼ = (xᵢ − xⱼ)/H), with his
//! weight 1/(q² + 0.01) left out so that a pair costs no division, against the (resting)
//! boundary particles too (off by default). With the boundary mirroring the particle's
//! pressure instead (a factor 2 on the boundary term), water at rest in a tank gained
//! energy in the tank's corners and never came to rest. Magnitudes: ρ̃ is
//! near 1, so ρ̃⁷ stays below 2 for any flow the model is meant for; P̃ ≤ c²/7 ≈ 57 m²/s²
//! for c = 20 m/s and 1.4·10⁵ at the largest allowed c, 1000 m/s.

use super::system::FluidSystem;
use crate::math::{Real, Vec3};

impl<R: Real> FluidSystem<R> {
    /// Stage 4 for WCSPH: v ← v + Δt aᵢ (see the [module documentation](self)), then XSPH.
    pub(crate) fn wcsph_velocities(&mut self, dt: R, gravity: Vec3<R>) {
        let stiffness = self.settings.stiffness;
        let s = &mut self.scratch;
        // P̃ᵢ and P̃ᵢ/ρ̃ᵢ², one division per particle.
        s.pressure.clear();
        s.scalar.clear();
        for &rho in &s.density {
            let pressure = stiffness * (rho.max(R::ONE).powi(7) - R::ONE);
            s.pressure.push(pressure);
            s.scalar.push(pressure * (rho * rho).recip());
        }
        let damping = self.settings.viscosity * self.settings.speed_of_sound;
        let inv_support = self.settings.kernel.inv_support;
        let mass = self.particle_mass();
        let s = &mut self.scratch;
        s.delta.clear();
        let boundary = &s.boundary;
        for i in 0..self.positions.len() {
            let si = s.scalar[i];
            let (xi, vi) = (self.positions[i], self.velocities[i]);
            let mut push = Vec3::ZERO;
            for e in s.fluid.range(i) {
                let j = s.fluid.index[e] as usize;
                let d = (xi - self.positions[j]) * inv_support;
                let approach = (vi - self.velocities[j]).dot(d).min(R::ZERO);
                push += s.fluid.gradient(e) * (si + s.scalar[j] - damping * approach);
            }
            for e in s.walls.range(i) {
                let b = s.walls.index[e] as usize;
                let d = (xi - boundary[b]) * inv_support;
                let approach = vi.dot(d).min(R::ZERO);
                push += s.walls.gradient(e) * (si - damping * approach);
            }
            if s.bodies.active {
                let bodies = &mut s.bodies;
                for e in bodies.lists.range(i) {
                    let d = (xi - bodies.point(e)) * inv_support;
                    let approach = (vi - bodies.velocity(e)).dot(d).min(R::ZERO);
                    let term = bodies.lists.gradient(e) * (si - damping * approach);
                    push += term;
                    bodies.push(e, term * (mass * dt));
                }
            }
            s.delta.push((gravity - push) * dt);
        }
        for (v, dv) in self.velocities.iter_mut().zip(&s.delta) {
            *v += *dv;
        }
        self.smooth_velocities();
    }

    /// The pressure of each fluid particle in the last substep, Pa (empty before the
    /// first): WCSPH's Tait pressure, or the pressure DFSPH's corrections amount to.
    pub fn pressures(&self) -> Vec<R> {
        let rho0 = self.settings.rest_density;
        self.scratch.pressure.iter().map(|&p| p * rho0).collect()
    }
}
