//! Density by kernel summation, normalised by the rest density.

use super::system::FluidSystem;
use crate::math::Real;

impl<R: Real> FluidSystem<R> {
    /// Stage 3: ρᵢ/ρ₀ = V₀W(0) + Σⱼ V₀Wᵢⱼ + Σ_b V₀W_ib over fluid neighbours j and boundary
    /// neighbours b (dimensionless; 1 inside the fluid at rest), and + Σ_b V₀W_ib over
    /// the rigid bodies' samples ([`bodies`](super::bodies)). V₀W(0) = c_w.
    pub(crate) fn compute_density(&mut self) {
        let s = &mut self.scratch;
        let own = self.settings.kernel.density_scale;
        s.density.clear();
        for i in 0..self.positions.len() {
            let mut rho = own;
            for &w in &s.fluid.value[s.fluid.range(i)] {
                rho += w;
            }
            for &w in &s.walls.value[s.walls.range(i)] {
                rho += w;
            }
            if s.bodies.active {
                let lists = &s.bodies.lists;
                for &w in &lists.value[lists.range(i)] {
                    rho += w;
                }
            }
            s.density.push(rho);
        }
    }
}
