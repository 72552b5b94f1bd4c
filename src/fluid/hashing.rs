//! The canonical state of the fluid, for checksums.
//!
//! [`FluidSystem::hash_state`] writes, in order (integers little-endian, scalars as their
//! raw fixed-point bits, vectors x, y, z):
//!
//! 1. the settings: solver code (`u8`), spacing, support, rest density, speed of sound,
//!    viscosity α, XSPH ε, substeps (`u32`), density-error tolerance, iteration cap
//!    (`u32`), tank min and max, the kernel's H, 1/H, c_w, c_g and D₀, and the stiffness
//!    c²/7; then, only
//!    when the substeps adapt (a CFL number other than 0, which fluids recorded before it
//!    existed do not have), the CFL number; then, only when the fluid meets rigid bodies,
//!    their filter's layers and mask (`u32`);
//! 2. the particle count (`u64`), then each particle by id: position, velocity;
//! 3. the emitter count (`u64`), then each emitter in scene order: position, velocity,
//!    speed, direction, width (`u32`), remaining (`u32`), distance travelled.
//!
//! The boundary particles, grids and neighbour lists follow from this and are not hashed.

use super::system::FluidSystem;
use crate::math::{Real, StateHasher};
use crate::types::Handle;

impl<R: Real> FluidSystem<R> {
    /// Writes the complete simulation state into `h` in the canonical order documented in
    /// [this module](self).
    pub fn hash_state(&self, h: &mut StateHasher) {
        let s = &self.settings;
        h.write_u8(s.solver.code());
        h.write_real(s.spacing);
        h.write_real(s.support);
        h.write_real(s.rest_density);
        h.write_real(s.speed_of_sound);
        h.write_real(s.viscosity);
        h.write_real(s.xsph);
        h.write_u32(s.substeps);
        h.write_real(s.max_density_error);
        h.write_u32(s.max_iterations);
        h.write_vec3(s.tank.min);
        h.write_vec3(s.tank.max);
        h.write_real(s.kernel.support);
        h.write_real(s.kernel.inv_support);
        h.write_real(s.kernel.density_scale);
        h.write_real(s.kernel.gradient_scale);
        h.write_real(s.kernel.lattice_gradient_norm);
        h.write_real(s.stiffness);
        if s.cfl != R::ZERO {
            h.write_real(s.cfl);
        }
        if let Some(filter) = s.bodies {
            h.write_u32(filter.layers);
            h.write_u32(filter.mask);
        }
        h.write_len(self.positions.len());
        for (x, v) in self.positions.iter().zip(&self.velocities) {
            h.write_vec3(*x);
            h.write_vec3(*v);
        }
        h.write_len(self.emitters.len());
        for e in &self.emitters {
            h.write_vec3(e.position);
            h.write_vec3(e.velocity);
            h.write_real(e.speed);
            h.write_vec3(e.direction);
            h.write_u32(e.width);
            h.write_u32(e.remaining);
            h.write_real(e.travelled);
        }
    }

    /// One 32-bit digest per particle, by id: the low half of the hash of its position and
    /// velocity. Handles have generation 0 (particles are never removed).
    pub fn slot_digests(&self) -> Vec<(Handle, u32)> {
        self.positions
            .iter()
            .zip(&self.velocities)
            .enumerate()
            .map(|(i, (x, v))| {
                let mut h = StateHasher::new();
                h.write_vec3(*x);
                h.write_vec3(*v);
                (Handle::new(i as u32, 0), h.finish() as u32)
            })
            .collect()
    }
}
