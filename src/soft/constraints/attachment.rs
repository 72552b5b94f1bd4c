//! Attachments of vertices to kinematic targets: C = x − p (m, a vector), with p the
//! vertex's rest position plus its target's displacement, ∇C = I, so Σ w|∇C|² = w. As for
//! distances, the row keeps μ = α̃λ (m) and precomputed factors.
//!
//! Each target (a group of rows) is moved by inputs: its displacement goes in a straight
//! line from `start` (at the start of the tick) to `goal` over the tick's substeps.

use serde::{Deserialize, Serialize};

use crate::math::{Real, Vec3};

/// Attachment rows and their targets.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(bound = "")]
pub(crate) struct Attachments<R: Real> {
    /// Per target: the position of its first vertex at rest, m (what commands place).
    pub origin: Vec<Vec3<R>>,
    /// Per target: its displacement at the start of the tick, m.
    pub start: Vec<Vec3<R>>,
    /// Per target: its displacement at the end of the tick, m.
    pub goal: Vec<Vec3<R>>,
    /// Per row: the vertex.
    pub vertex: Vec<u32>,
    /// Per row: the target.
    pub target: Vec<u32>,
    /// Per row: the vertex's rest position, m.
    pub rest: Vec<Vec3<R>>,
    /// Per row: α, m/N.
    pub compliance: Vec<R>,
    /// Per row: μ = α̃λ per axis, m.
    pub lambda: Vec<Vec3<R>>,
}

impl<R: Real> Attachments<R> {
    /// Each target's displacement after `done` of `total` substeps of the tick, m:
    /// start + (goal − start)·done/total, written to `out`.
    pub fn displacements(&self, done: u64, total: u64, out: &mut Vec<Vec3<R>>) {
        let fraction = R::from_ratio(done as i64, total as i64);
        out.clear();
        out.extend(
            self.start
                .iter()
                .zip(&self.goal)
                .map(|(&s, &g)| s.lerp(g, fraction)),
        );
    }

    /// The share w/D and relaxation α̃/D of every row, D = w + α̃, for inverse masses
    /// `inv_mass` (1/kg) and 1/h² `inv_h2` (1/s²).
    pub fn factors(&self, inv_mass: &[R], inv_h2: R) -> (Vec<R>, Vec<R>) {
        (0..self.vertex.len())
            .map(|r| {
                let w = inv_mass[self.vertex[r] as usize];
                let alpha = self.compliance[r] * inv_h2;
                let denominator = w + alpha;
                if denominator > R::ZERO {
                    (w / denominator, alpha / denominator)
                } else {
                    (R::ZERO, R::ZERO)
                }
            })
            .unzip()
    }

    /// One Gauss–Seidel pass with the targets displaced by `displacement` (m): with
    /// μ = α̃λ (m) and r = −C − μ, x += (w/D) r, μ += (α̃/D) r.
    pub fn solve(
        &mut self,
        positions: &mut [Vec3<R>],
        displacement: &[Vec3<R>],
        share: &[R],
        relax: &[R],
    ) {
        for r in 0..self.vertex.len() {
            let i = self.vertex[r] as usize;
            let target = self.rest[r] + displacement[self.target[r] as usize];
            let residual = target - positions[i] - self.lambda[r];
            self.lambda[r] = self.lambda[r].add_scaled(residual, relax[r]);
            positions[i] = positions[i].add_scaled(residual, share[r]);
        }
    }
}
