//! Isometric bending of a cloth (Bergou et al. 2006), as a vector XPBD constraint.
//!
//! For an interior edge (x₀, x₁) with wings x₂, x₃, the discrete bending energy of a
//! surface with a flat rest state is E = ½ |Σₖ cₖ xₖ|², with cₖ = s Kₖ,
//! K = (c₀₃ + c₀₄, c₀₁ + c₀₂, −c₀₁ − c₀₃, −c₀₂ − c₀₄) built from the cotangents of the rest
//! angles between e₀ = x₁ − x₀ and e₁ = x₂ − x₀, e₂ = x₃ − x₀, e₃ = x₂ − x₁,
//! e₄ = x₃ − x₁ (c₀₁ = cot∠(e₀, e₁), c₀₂ = cot∠(e₀, e₂), c₀₃ = cot∠(−e₀, e₃),
//! c₀₄ = cot∠(−e₀, e₄)), and s² = 3/(A₀ + A₁) from the two triangle areas (m²). The
//! constraint is the vector C = Σₖ cₖ xₖ (zero on a flat sheet, the discrete mean-curvature
//! normal otherwise): its gradient ∇ₖC = cₖ I is constant, so Σ w|∇C|² = Σₖ wₖ cₖ² is too,
//! and a row costs no square root and no division; as for distances, the row keeps
//! μ = α̃λ and precomputed shares. With compliance α the potential is
//! ½ |C|²/α: the bending stiffness is 1/α (N·m).

use serde::{Deserialize, Serialize};

use super::arithmetic::{Arithmetic, Checked, Guarded};
use super::colour_runs::ColourRuns;
use crate::math::{Guard, Real, Vec3};

#[cfg(vector_kernels)]
mod kernel;
#[cfg(all(test, vector_kernels))]
mod tests;

/// Bending rows.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(bound = "")]
pub(crate) struct Hinges<R: Real> {
    /// (edge end, edge end, wing, wing).
    pub vertices: Vec<[u32; 4]>,
    /// cₖ, 1/m (C = Σ cₖ xₖ is dimensionless).
    pub coefficients: Vec<[R; 4]>,
    /// α, 1/(N·m).
    pub compliance: Vec<R>,
    /// μ = α̃λ per axis (dimensionless).
    pub lambda: Vec<Vec3<R>>,
}

/// cot∠(a, b) = (a·b)/|a × b|, 0 for parallel edges.
fn cotangent<R: Real>(a: Vec3<R>, b: Vec3<R>) -> R {
    let sine = a.cross(b).length();
    if sine == R::ZERO {
        R::ZERO
    } else {
        a.dot(b) / sine
    }
}

impl<R: Real> Hinges<R> {
    /// Adds the hinge `v` (edge, edge, wing, wing) at rest positions `x` with compliance
    /// `compliance`; returns false (adding nothing) when a triangle is degenerate.
    pub fn push(&mut self, v: [u32; 4], x: [Vec3<R>; 4], compliance: R) -> bool {
        let e0 = x[1] - x[0];
        let (e1, e2) = (x[2] - x[0], x[3] - x[0]);
        let (e3, e4) = (x[2] - x[1], x[3] - x[1]);
        let area = (e0.cross(e1).length() + e0.cross(e2).length()) * R::HALF;
        if area <= R::ZERO {
            return false;
        }
        let (c01, c02) = (cotangent(e0, e1), cotangent(e0, e2));
        let (c03, c04) = (cotangent(-e0, e3), cotangent(-e0, e4));
        let scale = (R::from_int(3) / area).sqrt();
        let k = [c03 + c04, c01 + c02, -c01 - c03, -c02 - c04];
        self.vertices.push(v);
        self.coefficients.push(k.map(|kk| kk * scale));
        self.compliance.push(compliance);
        self.lambda.push(Vec3::ZERO);
        true
    }

    /// The shares wₖcₖ/D (m) and relaxation α̃/D of every row, with D = Σₖ wₖcₖ² + α̃,
    /// for inverse masses `inv_mass` (1/kg) and 1/h² `inv_h2` (1/s²).
    pub fn factors(&self, inv_mass: &[R], inv_h2: R) -> (Vec<[R; 4]>, Vec<R>) {
        let mut shares = Vec::with_capacity(self.vertices.len());
        let mut relax = Vec::with_capacity(self.vertices.len());
        for h in 0..self.vertices.len() {
            let c = self.coefficients[h];
            let w = self.vertices[h].map(|i| inv_mass[i as usize]);
            let alpha = self.compliance[h] * inv_h2;
            let mut denominator = alpha;
            for k in 0..4 {
                denominator += w[k] * c[k] * c[k];
            }
            if denominator > R::ZERO {
                shares.push([0, 1, 2, 3].map(|k| w[k] * c[k] / denominator));
                relax.push(alpha / denominator);
            } else {
                shares.push([R::ZERO; 4]);
                relax.push(R::ZERO);
            }
        }
        (shares, relax)
    }

    /// One Gauss–Seidel pass: with μ = α̃λ and r = −C − μ, xₖ += (wₖcₖ/D) r and
    /// μ += (α̃/D) r. Each row is computed with guarded arithmetic and, if its guard trips,
    /// again with the checked operators (see [`arithmetic`](super::arithmetic)). In I32F32
    /// on a processor with AVX-512 or AVX2, the blocks marked in `independent` are solved
    /// eight rows at a time with the same bits ([`kernel`]).
    pub fn solve(
        &mut self,
        positions: &mut [Vec3<R>],
        shares: &[[R; 4]],
        relax: &[R],
        #[cfg(vector_kernels)] independent: &[bool],
    ) {
        HingeRun {
            vertices: &self.vertices,
            coefficients: &self.coefficients,
            lambda: &mut self.lambda,
            shares,
            relax,
            #[cfg(vector_kernels)]
            independent,
        }
        .solve(positions);
    }

    /// One pass as [`Hinges::solve`], each run of `runs` (rows sharing no vertex) split
    /// across the workers: each chunk of a run solves its rows on its own copy of their
    /// corners (`moved`), which are then written back vertex by vertex. No row of a run
    /// reads what another writes, so the bits are those of [`Hinges::solve`].
    pub fn solve_split(
        &mut self,
        positions: &mut [Vec3<R>],
        (shares, relax): (&[[R; 4]], &[R]),
        runs: &ColourRuns<4>,
        moved: &mut Vec<Vec3<R>>,
    ) {
        for (k, rows) in runs.runs.iter().enumerate() {
            let vertices = &self.vertices[rows.clone()];
            let coefficients = &self.coefficients[rows.clone()];
            let lambda = &mut self.lambda[rows.clone()];
            let (shares, relax) = (&shares[rows.clone()], &relax[rows.clone()]);
            if rows.len() <= ROW_CHUNK {
                HingeRun {
                    vertices,
                    coefficients,
                    lambda,
                    shares,
                    relax,
                    #[cfg(vector_kernels)]
                    independent: &runs.independent,
                }
                .solve(positions);
                continue;
            }
            moved.clear();
            moved.resize(4 * rows.len(), Vec3::ZERO);
            let jobs: Vec<_> = vertices
                .chunks(ROW_CHUNK)
                .zip(coefficients.chunks(ROW_CHUNK))
                .zip(lambda.chunks_mut(ROW_CHUNK))
                .zip(shares.chunks(ROW_CHUNK))
                .zip(relax.chunks(ROW_CHUNK))
                .zip(moved.chunks_mut(4 * ROW_CHUNK))
                .map(
                    |(((((corners, coefficients), lambda), shares), relax), own)| {
                        let local = HingeRun {
                            vertices: &runs.local_rows[..corners.len()],
                            coefficients,
                            lambda,
                            shares,
                            relax,
                            #[cfg(vector_kernels)]
                            independent: &runs.independent,
                        };
                        (corners, local, own)
                    },
                )
                .collect();
            let x: &[Vec3<R>] = positions;
            crate::parallel::for_each_job(jobs, |(corners, mut local, own)| {
                for (i, row) in corners.iter().enumerate() {
                    for (k, &v) in row.iter().enumerate() {
                        own[4 * i + k] = x[v as usize];
                    }
                }
                local.solve(own);
            });
            let moved: &[Vec3<R>] = moved;
            crate::parallel::scatter_sorted(positions, runs.touches(k), |x, slot| {
                *x = moved[slot];
            });
        }
    }
}

/// Rows a [`HingeRun`] chunk of a parallel pass holds (a multiple of the kernels' eight
/// lanes); fixed, so the chunks depend on the rows only.
pub(crate) const ROW_CHUNK: usize = 256;

/// Consecutive bending rows to solve in order: their slices of the rows and factors.
pub(crate) struct HingeRun<'a, R: Real> {
    /// Each row's corners in the positions the run is solved on.
    pub vertices: &'a [[u32; 4]],
    /// cₖ, 1/m.
    pub coefficients: &'a [[R; 4]],
    /// μ = α̃λ per axis.
    pub lambda: &'a mut [Vec3<R>],
    /// wₖcₖ/D, m.
    pub shares: &'a [[R; 4]],
    /// α̃/D.
    pub relax: &'a [R],
    /// Whether rows 8k..8k+8 of the run share no vertex, for each k listed.
    #[cfg(vector_kernels)]
    pub independent: &'a [bool],
}

impl<R: Real> HingeRun<'_, R> {
    /// Every row of the run, in order, on `positions` (see [`Hinges::solve`]).
    pub fn solve(&mut self, positions: &mut [Vec3<R>]) {
        #[cfg(vector_kernels)]
        if kernel::solve(self, positions) {
            return;
        }
        for h in 0..self.vertices.len() {
            self.solve_row(positions, h);
        }
    }

    /// Row `h`, guarded first, checked if the guard trips.
    #[inline(always)]
    fn solve_row(&mut self, positions: &mut [Vec3<R>], h: usize) {
        let v = self.vertices[h].map(|i| i as usize);
        let input = HingeInput {
            x: v.map(|i| positions[i]),
            c: self.coefficients[h],
            mu: self.lambda[h],
            shares: self.shares[h],
            relax: self.relax[h],
        };
        let mut guarded = Guarded(Guard::new());
        let mut output = hinge(&mut guarded, &input);
        if !guarded.0.is_clear() {
            output = hinge(&mut Checked, &input);
        }
        let (x, mu) = output;
        for k in 0..4 {
            positions[v[k]] = x[k];
        }
        self.lambda[h] = mu;
    }
}

/// What one hinge reads.
struct HingeInput<R: Real> {
    x: [Vec3<R>; 4],
    c: [R; 4],
    mu: Vec3<R>,
    shares: [R; 4],
    relax: R,
}

/// One hinge's update in the arithmetic `o`: the new corner positions and μ.
#[inline(always)]
fn hinge<R: Real, A: Arithmetic<R>>(o: &mut A, i: &HingeInput<R>) -> ([Vec3<R>; 4], Vec3<R>) {
    let mut value = Vec3::ZERO;
    for (&corner, &c) in i.x.iter().zip(&i.c) {
        value = o.add_scaled3(value, corner, c);
    }
    let negative = o.sub3(Vec3::ZERO, value);
    let residual = o.sub3(negative, i.mu);
    let mu = o.add_scaled3(i.mu, residual, i.relax);
    let mut x = i.x;
    for (corner, &share) in x.iter_mut().zip(&i.shares) {
        *corner = o.add_scaled3(*corner, residual, share);
    }
    (x, mu)
}
