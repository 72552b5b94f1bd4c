//! Long-range attachments (Kim, Chentanez and Müller 2012): each free vertex of a body
//! with pinned or attached vertices may not get farther from its nearest anchor than its
//! rest distance ℓ₀. The unilateral constraint C = |x − p| − ℓ₀ ≤ 0, with compliance 0 and
//! the anchor's current position p, is projected fully when violated: x ← x − (1 − ℓ₀/|x − p|)(x − p).
//! It stops the stretch that Gauss–Seidel otherwise leaves where a hanging sheet's weight
//! meets its pins, at one square root per taut tether and none for slack ones.

use serde::{Deserialize, Serialize};

use crate::math::{Real, Vec3};

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
    /// One pass over every row.
    pub fn solve(&self, positions: &mut [Vec3<R>]) {
        for t in 0..self.vertex.len() {
            let i = self.vertex[t] as usize;
            let d = positions[i] - positions[self.anchor[t] as usize];
            let length_squared = d.dot_fused(d);
            let rest = self.rest[t];
            if length_squared <= rest * rest {
                continue;
            }
            let shrink = R::ONE - rest * length_squared.rsqrt();
            positions[i] = positions[i].add_scaled(d, -shrink);
        }
    }
}
