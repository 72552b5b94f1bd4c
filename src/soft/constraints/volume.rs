//! Volume constraints of the tetrahedra of a lattice: C = 6V − 6V₀ (m³) with
//! 6V = (x₁ − x₀)·((x₂ − x₀) × (x₃ − x₀)), whose gradients are ∇₁C = (x₂ − x₀) × (x₃ − x₀),
//! ∇₂C = (x₃ − x₀) × (x₁ − x₀), ∇₃C = (x₁ − x₀) × (x₂ − x₀), ∇₀C = −(∇₁C + ∇₂C + ∇₃C).
//! The denominator Σ w|∇C|² + α̃ changes with the shape, so each row divides twice.

use serde::{Deserialize, Serialize};

use crate::math::{Real, Vec3};

/// Volume rows.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(bound = "")]
pub(crate) struct Tetrahedra<R: Real> {
    pub vertices: Vec<[u32; 4]>,
    /// 6V₀, m³ (signed).
    pub rest_volume: Vec<R>,
    /// α, 1/(N·m²).
    pub compliance: Vec<R>,
    /// μ = α̃λ, m³.
    pub lambda: Vec<R>,
}

/// 6V of the tetrahedron x and the gradients of 6V with respect to its corners.
fn six_volume<R: Real>(x: [Vec3<R>; 4]) -> (R, [Vec3<R>; 4]) {
    let (e1, e2, e3) = (x[1] - x[0], x[2] - x[0], x[3] - x[0]);
    let g1 = e2.cross(e3);
    let g2 = e3.cross(e1);
    let g3 = e1.cross(e2);
    (e1.dot(g1), [-(g1 + g2 + g3), g1, g2, g3])
}

impl<R: Real> Tetrahedra<R> {
    /// Adds the tetrahedron `v` at rest positions `x` with compliance `compliance`.
    pub fn push(&mut self, v: [u32; 4], x: [Vec3<R>; 4], compliance: R) {
        self.vertices.push(v);
        self.rest_volume.push(six_volume(x).0);
        self.compliance.push(compliance);
        self.lambda.push(R::ZERO);
    }

    /// One Gauss–Seidel pass with 1/h² `inv_h2` (1/s²). The row keeps μ = α̃λ (m³); with
    /// W the largest corner inverse mass, D̂ = Σ (wₖ/W)|∇ₖC|² + α̃/W and r = −C − μ,
    /// xₖ += ∇ₖC (wₖ/W)(r/D̂) and μ += (α̃/W)(r/D̂): the XPBD update, scaled so that no
    /// factor underflows for light vertices.
    pub fn solve(&mut self, positions: &mut [Vec3<R>], inv_mass: &[R], inv_h2: R) {
        for t in 0..self.vertices.len() {
            let v = self.vertices[t].map(|i| i as usize);
            let w = v.map(|i| inv_mass[i]);
            let heaviest = w[0].max(w[1]).max(w[2].max(w[3]));
            if heaviest <= R::ZERO {
                continue;
            }
            let inv_heaviest = heaviest.recip();
            let relative = w.map(|wk| wk * inv_heaviest);
            let (volume, gradients) = six_volume(v.map(|i| positions[i]));
            let alpha = self.compliance[t] * inv_h2 * inv_heaviest;
            let mut denominator = alpha;
            for k in 0..4 {
                denominator += relative[k] * gradients[k].length_squared();
            }
            if denominator <= R::ZERO {
                continue;
            }
            let step = (self.rest_volume[t] - volume - self.lambda[t]) / denominator;
            self.lambda[t] += alpha * step;
            for k in 0..4 {
                positions[v[k]] = positions[v[k]].add_scaled(gradients[k], relative[k] * step);
            }
        }
    }
}
