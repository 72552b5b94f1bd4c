//! XSPH velocity smoothing (Monaghan 1989), the fluid's artificial viscosity.

use super::row_sums;
use super::system::FluidSystem;
use crate::math::Real;

impl<R: Real> FluidSystem<R> {
    /// vᵢ ← vᵢ + ε Σⱼ (V₀Wᵢⱼ ρ₀/ρⱼ) (vⱼ − vᵢ) over fluid neighbours (m/s): each particle
    /// moves a fraction ε towards the kernel-weighted mean velocity around it. Walls are
    /// free-slip; rigid bodies in the fluid count as neighbours moving with their surface
    /// (ρ_b = ρ₀) and take the opposite momentum ([`drag`](super::bodies::BodiesInFluid::drag)),
    /// the water's friction on them. Jacobi: every change is computed from the velocities
    /// before any is made.
    pub(crate) fn smooth_velocities(&mut self) {
        let epsilon = self.settings.xsph;
        if epsilon == R::ZERO {
            return;
        }
        let mass = self.particle_mass();
        let s = &mut self.scratch;
        // ρ₀/ρⱼ, one division per particle.
        s.inv_density.clear();
        s.inv_density
            .extend(s.density.iter().map(|&rho| rho.recip()));
        row_sums::smoothing_sums(&s.fluid, &self.velocities, &s.inv_density, &mut s.delta);
        if s.bodies.active {
            s.bodies
                .drag(&self.velocities, &mut s.delta, mass * epsilon);
        }
        for (v, &sum) in self.velocities.iter_mut().zip(&s.delta) {
            *v += sum * epsilon;
        }
    }
}
