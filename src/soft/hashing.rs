//! The canonical state of the soft bodies, for checksums.
//!
//! [`SoftSystem::hash_state`] writes, in order (integers little-endian, scalars as their
//! raw fixed-point bits, vectors x, y, z):
//!
//! 1. the solver settings: substeps, iterations (`u32`);
//! 2. the vertex count (`u64`), then each vertex in index order: position, velocity,
//!    inverse mass;
//! 3. the multipliers μ = α̃λ of the last substep: the distance rows' count (`u64`), then
//!    each row's μ and its kept inverse length 1/|d|; the hinges' count and μs (vectors),
//!    the tetrahedra's, the attachment rows';
//! 4. the attachment target count (`u64`), then each target's start and goal displacement.
//!
//! Topology, rest lengths, compliances, masses, springs and colliders do not change during
//! a run and are part of the scene, which replays check by its own hash; they are not
//! hashed here.

use super::system::SoftSystem;
use crate::math::{Real, StateHasher};
use crate::types::Handle;

impl<R: Real> SoftSystem<R> {
    /// Writes the complete simulation state into `h` in the canonical order documented in
    /// [this module](self).
    pub fn hash_state(&self, h: &mut StateHasher) {
        h.write_u32(self.settings.substeps);
        h.write_u32(self.settings.iterations);
        h.write_len(self.vertices.len());
        for i in 0..self.vertices.len() {
            self.hash_vertex(i, h);
        }
        h.write_len(self.distances.lambda.len());
        for (&l, &y) in self.distances.lambda.iter().zip(&self.distances.inv_length) {
            h.write_real(l);
            h.write_real(y);
        }
        h.write_len(self.hinges.lambda.len());
        for &l in &self.hinges.lambda {
            h.write_vec3(l);
        }
        h.write_len(self.tetrahedra.lambda.len());
        for &l in &self.tetrahedra.lambda {
            h.write_real(l);
        }
        h.write_len(self.attachments.lambda.len());
        for &l in &self.attachments.lambda {
            h.write_vec3(l);
        }
        h.write_len(self.attachments.start.len());
        for (&s, &g) in self.attachments.start.iter().zip(&self.attachments.goal) {
            h.write_vec3(s);
            h.write_vec3(g);
        }
    }

    /// Item 2 of the [hash order](self) for vertex `i`.
    fn hash_vertex(&self, i: usize, h: &mut StateHasher) {
        h.write_vec3(self.vertices.position[i]);
        h.write_vec3(self.vertices.velocity[i]);
        h.write_real(self.vertices.inv_mass[i]);
    }

    /// One 32-bit digest per vertex, in index order (handle = index, generation 0): the
    /// low 32 bits of the XXH3-64 of item 2 of the [hash order](self).
    pub fn slot_digests(&self) -> Vec<(Handle, u32)> {
        (0..self.vertices.len())
            .map(|i| {
                let mut h = StateHasher::new();
                self.hash_vertex(i, &mut h);
                (Handle::new(i as u32, 0), h.finish() as u32)
            })
            .collect()
    }
}
