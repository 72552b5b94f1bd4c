//! Distance constraints: C = |xₐ − x_b| − ℓ₀ (m), ∇ₐC = n̂ = (xₐ − x_b)/|xₐ − x_b|,
//! ∇_bC = −n̂, so Σ w|∇C|² = wₐ + w_b.
//!
//! With D = wₐ + w_b + α̃ constant, the update of the [module](super) is carried in
//! position units, which fixed point resolves far better than λ itself (N·s², tiny for
//! light vertices and short substeps): the row keeps μ = α̃λ (m) and precomputes the
//! shares sₐ = wₐ/D, s_b = w_b/D and the relaxation ρ = α̃/D; then with r = −C − μ,
//! xₐ += sₐ r n̂, x_b −= s_b r n̂, μ += ρ r: exactly the XPBD update, no division.
//!
//! 1/|d| comes without a square root from the row's previous value y₀ (1/ℓ₀ at the start),
//! by the Taylor series of (1 + δ)^{−½} with δ = q − 1, q = |d|² y₀²:
//! y = y₀ (1 − δ/2 + 3δ²/8), whose relative error is about (5/16)|δ|³ plus that of y₀,
//! shrunk to its square times 3/2 by every solve. Since an edge changes length little
//! between substeps, δ is tiny and y is exact to the format's resolution after a few
//! solves; a compliant row's stretch under load is then exact. Rows with q outside
//! [3/4, 5/4] (the length changed by more than about 12% since the last solve: a crumpled
//! start, a violent impact) take the exact 1/√. y is state: it is kept per row, hashed and
//! snapshotted.
//!
//! Each row is written once, in an [`Arithmetic`], and runs guarded first: see
//! [`arithmetic`](super::arithmetic). Its products and sums are rounded one by one (no fused
//! dot product), the form the guarded operators reproduce.

use serde::{Deserialize, Serialize};

use super::arithmetic::{Arithmetic, Checked, Guarded};
use super::colour_runs::ColourRuns;
use crate::math::{Guard, Real, Vec3};

#[cfg(vector_kernels)]
mod kernel;
#[cfg(test)]
mod tests;

/// Distance constraint rows.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(bound = "")]
pub(crate) struct Distances<R: Real> {
    pub a: Vec<u32>,
    pub b: Vec<u32>,
    /// ℓ₀, m.
    pub rest: Vec<R>,
    /// 1/|d| at the row's last solve (1/ℓ₀ before the first), 1/m.
    pub inv_length: Vec<R>,
    /// α, m/N.
    pub compliance: Vec<R>,
    /// μ = α̃λ, m.
    pub lambda: Vec<R>,
}

/// The per-substep factors of one row kind: shares of each end and the relaxation.
#[derive(Clone, Debug, Default)]
pub(crate) struct DistanceFactors<R: Real> {
    /// sₐ = wₐ/D.
    pub share_a: Vec<R>,
    /// s_b = w_b/D.
    pub share_b: Vec<R>,
    /// ρ = α̃/D.
    pub relax: Vec<R>,
    /// Whether rows 8k..8k+8 share no vertex, for each k (the blocks the AVX-512 kernel
    /// may solve side by side).
    #[cfg(vector_kernels)]
    pub independent: Vec<bool>,
}

impl<R: Real> Distances<R> {
    /// Adds a row between vertices `a` and `b` at rest length `rest` (> 0, m) with
    /// compliance `compliance` (m/N).
    pub fn push(&mut self, a: u32, b: u32, rest: R, compliance: R) {
        self.a.push(a);
        self.b.push(b);
        self.rest.push(rest);
        self.inv_length.push(rest.recip());
        self.compliance.push(compliance);
        self.lambda.push(R::ZERO);
    }

    /// The factors for inverse masses `inv_mass` (1/kg) and 1/h² `inv_h2` (1/s²).
    pub fn factors(&self, inv_mass: &[R], inv_h2: R) -> DistanceFactors<R> {
        let mut f = DistanceFactors::default();
        for c in 0..self.a.len() {
            let (wa, wb) = (inv_mass[self.a[c] as usize], inv_mass[self.b[c] as usize]);
            let alpha = self.compliance[c] * inv_h2;
            let denominator = wa + wb + alpha;
            let (sa, sb, relax) = if denominator > R::ZERO {
                (wa / denominator, wb / denominator, alpha / denominator)
            } else {
                (R::ZERO, R::ZERO, R::ZERO)
            };
            f.share_a.push(sa);
            f.share_b.push(sb);
            f.relax.push(relax);
        }
        #[cfg(vector_kernels)]
        {
            f.independent = kernel::independent_blocks(&self.a, &self.b);
        }
        f
    }

    /// One Gauss–Seidel pass over every row, in order, moving `positions` (m). Each row
    /// is computed with guarded arithmetic and, if its guard trips, again with the checked
    /// operators (see [`arithmetic`](super::arithmetic)). In I32F32 on a processor with
    /// AVX-512 or AVX2, blocks of rows that share no vertex are solved eight at a time by a
    /// kernel that gives the same bits ([`kernel`]).
    pub fn solve(&mut self, positions: &mut [Vec3<R>], f: &DistanceFactors<R>) {
        self.run(f, 0..self.a.len()).solve(positions);
    }

    /// Rows `rows` with their factors `f`, to solve in place.
    pub fn run<'a>(
        &'a mut self,
        f: &'a DistanceFactors<R>,
        rows: core::ops::Range<usize>,
    ) -> DistanceRun<'a, R> {
        DistanceRun {
            a: &self.a[rows.clone()],
            b: &self.b[rows.clone()],
            rest: &self.rest[rows.clone()],
            inv_length: &mut self.inv_length[rows.clone()],
            lambda: &mut self.lambda[rows.clone()],
            share_a: &f.share_a[rows.clone()],
            share_b: &f.share_b[rows.clone()],
            relax: &f.relax[rows.clone()],
            #[cfg(vector_kernels)]
            independent: if rows.start.is_multiple_of(crate::math::wide::LANES) {
                f.independent
                    .get(rows.start / crate::math::wide::LANES..)
                    .unwrap_or(&[])
            } else {
                &[]
            },
        }
    }

    /// One pass as [`Distances::solve`], each run of `runs` (rows sharing no vertex)
    /// split across the workers: each chunk of a run solves its rows on its own copy of
    /// their ends (`moved`), which are then written back vertex by vertex. No row of a run
    /// reads what another writes, so the bits are those of [`Distances::solve`].
    pub fn solve_split(
        &mut self,
        positions: &mut [Vec3<R>],
        f: &DistanceFactors<R>,
        runs: &ColourRuns<2>,
        moved: &mut Vec<Vec3<R>>,
    ) {
        for (k, rows) in runs.runs.iter().enumerate() {
            if rows.len() <= ROW_CHUNK {
                let mut run = self.run(f, rows.clone());
                #[cfg(vector_kernels)]
                {
                    run.independent = &runs.independent;
                }
                run.solve(positions);
                continue;
            }
            moved.clear();
            moved.resize(2 * rows.len(), Vec3::ZERO);
            let run = self.run(f, rows.clone());
            let (ends_a, ends_b) = (run.a, run.b);
            let jobs: Vec<_> = ends_a
                .chunks(ROW_CHUNK)
                .zip(ends_b.chunks(ROW_CHUNK))
                .zip(run.rest.chunks(ROW_CHUNK))
                .zip(run.inv_length.chunks_mut(ROW_CHUNK))
                .zip(run.lambda.chunks_mut(ROW_CHUNK))
                .zip(run.share_a.chunks(ROW_CHUNK))
                .zip(run.share_b.chunks(ROW_CHUNK))
                .zip(run.relax.chunks(ROW_CHUNK))
                .zip(moved.chunks_mut(2 * ROW_CHUNK))
                .map(
                    |(
                        (((((((a, b), rest), inv_length), lambda), share_a), share_b), relax),
                        own,
                    )| {
                        let n = a.len();
                        let local = DistanceRun {
                            a: &runs.local[0][..n],
                            b: &runs.local[1][..n],
                            rest,
                            inv_length,
                            lambda,
                            share_a,
                            share_b,
                            relax,
                            #[cfg(vector_kernels)]
                            independent: &runs.independent,
                        };
                        (a, b, local, own)
                    },
                )
                .collect();
            let x: &[Vec3<R>] = positions;
            crate::parallel::for_each_job(jobs, |(a, b, mut local, own)| {
                for (i, (&a, &b)) in a.iter().zip(b).enumerate() {
                    own[2 * i] = x[a as usize];
                    own[2 * i + 1] = x[b as usize];
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

/// Rows a [`DistanceRun`] chunk of a parallel pass holds (a multiple of the kernels' eight
/// lanes); fixed, so the chunks depend on the rows only.
pub(crate) const ROW_CHUNK: usize = 256;

/// Consecutive distance rows to solve in order: their slices of the rows and of the
/// factors.
pub(crate) struct DistanceRun<'a, R: Real> {
    /// The ends' indices in the positions the run is solved on.
    pub a: &'a [u32],
    pub b: &'a [u32],
    /// ℓ₀, m.
    pub rest: &'a [R],
    /// 1/|d| at each row's last solve, 1/m.
    pub inv_length: &'a mut [R],
    /// μ = α̃λ, m.
    pub lambda: &'a mut [R],
    /// sₐ, s_b and ρ (see [`DistanceFactors`]).
    pub share_a: &'a [R],
    pub share_b: &'a [R],
    pub relax: &'a [R],
    /// Whether rows 8k..8k+8 of the run share no vertex, for each k listed.
    #[cfg(vector_kernels)]
    pub independent: &'a [bool],
}

impl<R: Real> DistanceRun<'_, R> {
    /// Every row of the run, in order, on `positions` (see [`Distances::solve`]).
    pub fn solve(&mut self, positions: &mut [Vec3<R>]) {
        #[cfg(vector_kernels)]
        if kernel::solve(self, positions) {
            return;
        }
        for c in 0..self.a.len() {
            self.solve_row(positions, c);
        }
    }

    /// Row `c`, guarded first, checked if the guard trips.
    #[inline(always)]
    fn solve_row(&mut self, positions: &mut [Vec3<R>], c: usize) {
        let (a, b) = (self.a[c] as usize, self.b[c] as usize);
        let input = RowInput {
            xa: positions[a],
            xb: positions[b],
            rest: self.rest[c],
            previous: self.inv_length[c],
            mu: self.lambda[c],
            share_a: self.share_a[c],
            share_b: self.share_b[c],
            relax: self.relax[c],
        };
        let mut guarded = Guarded(Guard::new());
        let mut output = row(&mut guarded, &input);
        if !guarded.0.is_clear() {
            output = row(&mut Checked, &input);
        }
        if let Some(out) = output {
            positions[a] = out.xa;
            positions[b] = out.xb;
            self.lambda[c] = out.mu;
            self.inv_length[c] = out.inv_length;
        }
    }
}

/// What one row reads.
struct RowInput<R: Real> {
    xa: Vec3<R>,
    xb: Vec3<R>,
    rest: R,
    previous: R,
    mu: R,
    share_a: R,
    share_b: R,
    relax: R,
}

/// What one row writes.
struct RowOutput<R: Real> {
    xa: Vec3<R>,
    xb: Vec3<R>,
    mu: R,
    inv_length: R,
}

/// One row's update (see the [module](self)) in the arithmetic `o`; `None` when the ends
/// coincide (no axis).
#[inline(always)]
fn row<R: Real, A: Arithmetic<R>>(o: &mut A, i: &RowInput<R>) -> Option<RowOutput<R>> {
    let d = o.sub3(i.xa, i.xb);
    let length_squared = o.length_squared3(d);
    let scaled = o.mul(length_squared, i.previous);
    let q = o.mul(scaled, i.previous);
    let inv_length = if q >= R::from_ratio(3, 4) && q <= R::from_ratio(5, 4) {
        let delta = o.sub(q, R::ONE);
        let half = o.mul(delta, R::HALF);
        let square = o.mul(delta, delta);
        let quadratic = o.mul(square, R::from_ratio(3, 8));
        let linear = o.sub(R::ONE, half);
        let series = o.add(linear, quadratic);
        o.mul(i.previous, series)
    } else if length_squared > R::ZERO {
        length_squared.rsqrt()
    } else {
        return None;
    };
    let length = o.mul(length_squared, inv_length);
    let shortfall = o.sub(i.rest, length);
    let residual = o.sub(shortfall, i.mu);
    let relaxed = o.mul(i.relax, residual);
    let mu = o.add(i.mu, relaxed);
    let direction = Vec3::new(
        o.mul(d.x, inv_length),
        o.mul(d.y, inv_length),
        o.mul(d.z, inv_length),
    );
    let step_a = o.mul(i.share_a, residual);
    let step_b = o.mul(i.share_b, residual);
    let xa = o.add_scaled3(i.xa, direction, step_a);
    let minus_b = o.sub(R::ZERO, step_b);
    let xb = o.add_scaled3(i.xb, direction, minus_b);
    Some(RowOutput {
        xa,
        xb,
        mu,
        inv_length,
    })
}
