//! Density by kernel summation, normalised by the rest density.

use super::system::{FluidSystem, PARTICLE_CHUNK};
use crate::math::Real;
use crate::parallel::for_each_mut;

impl<R: Real> FluidSystem<R> {
    /// Stage 3: ρᵢ/ρ₀ = V₀W(0) + Σⱼ V₀Wᵢⱼ + Σ_b V₀W_ib over fluid neighbours j and boundary
    /// neighbours b (dimensionless; 1 inside the fluid at rest), and + Σ_b V₀W_ib over
    /// the rigid bodies' samples ([`bodies`](super::bodies)). V₀W(0) = c_w.
    pub(crate) fn compute_density(&mut self) {
        let s = &mut self.scratch;
        let own = self.settings.kernel.density_scale;
        s.density.clear();
        s.density.resize(self.positions.len(), own);
        let (fluid, walls, bodies) = (&s.fluid, &s.walls, &s.bodies);
        for_each_mut(&mut s.density, PARTICLE_CHUNK, |i, rho| {
            for &w in &fluid.value[fluid.range(i)] {
                *rho += w;
            }
            for &w in &walls.value[walls.range(i)] {
                *rho += w;
            }
            if bodies.active {
                let lists = &bodies.lists;
                for &w in &lists.value[lists.range(i)] {
                    *rho += w;
                }
            }
        });
    }
}
