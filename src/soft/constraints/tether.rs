//! Long-range attachments (Kim, Chentanez and Müller 2012): each free vertex of a body
//! with pinned or attached vertices may not get farther from its nearest anchor than its
//! rest distance ℓ₀. The unilateral constraint C = |x − p| − ℓ₀ ≤ 0, with compliance 0 and
//! the anchor's current position p, is projected fully when violated: x ← x − (1 − ℓ₀/|x − p|)(x − p).
//! It stops the stretch that Gauss–Seidel otherwise leaves where a hanging sheet's weight
//! meets its pins, at one square root per taut tether and none for slack ones.

use serde::{Deserialize, Serialize};

use crate::math::{Real, Vec3};

#[cfg(vector_kernels)]
mod kernel;
#[cfg(all(test, vector_kernels))]
mod tests;

/// Tether rows.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(bound = "")]
pub(crate) struct Tethers<R: Real> {
    pub vertex: Vec<u32>,
    /// The anchor: a pinned or attached vertex (the attachment holds it at its target).
    pub anchor: Vec<u32>,
    /// ℓ₀, m.
    pub rest: Vec<R>,
}

impl<R: Real> Tethers<R> {
    /// One pass over every row. In I32F32 on a processor with AVX-512 or AVX2, the rows of
    /// the blocks marked in `independent` are solved eight at a time ([`kernel`]); the
    /// others run as before, with the same bits.
    pub fn solve(&self, positions: &mut [Vec3<R>], #[cfg(vector_kernels)] independent: &[bool]) {
        #[cfg(vector_kernels)]
        if kernel::solve(self, positions, independent) {
            return;
        }
        for t in 0..self.vertex.len() {
            self.solve_row(positions, t);
        }
    }

    /// Row `t`: x ← x − (1 − ℓ₀/|d|) d with d = x − p, when |d|² > ℓ₀².
    #[inline(always)]
    fn solve_row(&self, positions: &mut [Vec3<R>], t: usize) {
        let i = self.vertex[t] as usize;
        let d = positions[i] - positions[self.anchor[t] as usize];
        let length_squared = d.dot_fused(d);
        let rest = self.rest[t];
        if length_squared <= rest * rest {
            return;
        }
        let shrink = R::ONE - rest * length_squared.rsqrt();
        positions[i] = positions[i].add_scaled(d, -shrink);
    }
}
