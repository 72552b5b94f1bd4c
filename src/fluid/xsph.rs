//! XSPH velocity smoothing (Monaghan 1989), the fluid's artificial viscosity.

use super::system::FluidSystem;
use crate::math::{Real, Vec3};

impl<R: Real> FluidSystem<R> {
    /// vᵢ ← vᵢ + ε Σⱼ (V₀Wᵢⱼ ρ₀/ρⱼ) (vⱼ − vᵢ) over fluid neighbours (m/s): each particle
    /// moves a fraction ε towards the kernel-weighted mean velocity around it. Walls are
    /// free-slip. Jacobi: every change is computed from the velocities before any is made.
    pub(crate) fn smooth_velocities(&mut self) {
        let epsilon = self.settings.xsph;
        if epsilon == R::ZERO {
            return;
        }
        let s = &mut self.scratch;
        // ρ₀/ρⱼ, one division per particle.
        s.inv_density.clear();
        s.inv_density
            .extend(s.density.iter().map(|&rho| rho.recip()));
        s.delta.clear();
        for i in 0..self.positions.len() {
            let vi = self.velocities[i];
            let mut sum = Vec3::ZERO;
            for e in s.fluid.range(i) {
                let j = s.fluid.index[e] as usize;
                sum += (self.velocities[j] - vi) * (s.fluid.value[e] * s.inv_density[j]);
            }
            s.delta.push(sum * epsilon);
        }
        for (v, dv) in self.velocities.iter_mut().zip(&s.delta) {
            *v += *dv;
        }
    }
}
