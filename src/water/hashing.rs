//! The canonical state of the water surface, for checksums.
//!
//! [`WaterSystem::hash_state`] writes, in order (integers little-endian, scalars as their
//! raw fixed-point bits, vectors x, y, z):
//!
//! 1. the settings: origin, columns (`u32`), rows (`u32`), cell size, depth, wave speed,
//!    damping, density, border code (`u8`), substeps (`u32`); the floating particle groups'
//!    count (`u64`), then each: group (`u32`), volume, height, drag; then a flag (`u8`)
//!    whether bodies float and, when they do, their filter's layers and mask (`u32`), drag
//!    and angular drag;
//! 2. the heights by slot, then the flows across the x edges, then across the z edges
//!    (their counts follow from the grid).
//!
//! A world without a water surface hashes none of this (the part is absent), so scenes
//! from before the surface existed keep their checksums.

use super::system::WaterSystem;
use crate::math::{Real, StateHasher};

impl<R: Real> WaterSystem<R> {
    /// Writes the complete simulation state into `h` in the canonical order documented in
    /// [this module](self).
    pub fn hash_state(&self, h: &mut StateHasher) {
        let s = &self.settings;
        h.write_vec3(s.origin);
        h.write_u32(s.columns);
        h.write_u32(s.rows);
        h.write_real(s.cell_size);
        h.write_real(s.depth);
        h.write_real(s.wave_speed);
        h.write_real(s.damping);
        h.write_real(s.density);
        h.write_u8(s.border.code());
        h.write_u32(s.substeps);
        h.write_len(s.particles.len());
        for float in &s.particles {
            h.write_u32(u32::from(float.group));
            h.write_real(float.volume);
            h.write_real(float.height);
            h.write_real(float.drag);
        }
        h.write_u8(u8::from(s.bodies.is_some()));
        if let Some(bodies) = &s.bodies {
            h.write_u32(bodies.filter.layers);
            h.write_u32(bodies.filter.mask);
            h.write_real(bodies.drag);
            h.write_real(bodies.angular_drag);
        }
        for value in self.heights.iter().chain(&self.flow_x).chain(&self.flow_z) {
            h.write_real(*value);
        }
    }
}
