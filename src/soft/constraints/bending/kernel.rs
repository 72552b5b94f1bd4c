//! The bending rows of I32F32 on the lanes of [`Wide`] (every backend): eight hinges side by
//! side, one `i64` lane per hinge, with the bits of the scalar row ([`HingeRun::solve_row`]).
//!
//! Hinges that share no vertex read nothing the others write, so solving eight of them
//! together gives the bits of solving them one after another; the blocks of eight
//! consecutive hinges that share no vertex are listed once per substep length
//! ([`Hinges::independent_blocks`]), nearly all of them in colour order. The other blocks,
//! the blocks where a check fails (before anything is written) and the rows past the last
//! multiple of eight take the scalar row.
//!
//! # Exactness
//!
//! The scalar row computes C = Σₖ cₖxₖ, r = (0 − C) − μ, μ + ρr and xₖ + sₖr per
//! component, each product rounded once and then added. The kernel computes the same
//! operations modulo 2⁶⁴ after checking that the corners' positions, the cₖ, μ, the shares
//! sₖ, ρ and r lie in [−2⁴⁶, 2⁴⁶) as raw bits: every product is then below 2⁶⁰, every sum
//! has at most four such terms or checked values, below 2⁶³, and nothing saturates, so
//! the kernel's exact values ([`Wide::mul`]) are the checked operators', which the scalar row
//! gives whether its guard stays clear or it reruns checked.

use super::{HingeRun, Hinges};
use crate::math::over_real::{Scalars, Vectors};
use crate::math::wide::{LANES, Wide, backend, kernel_entry};
use crate::math::{Fx, OverReal, Real, Vec3};

/// The family of `[[R; 4]]` (the hinges' shares) over the scalar formats.
struct Quads;

impl OverReal for Quads {
    type Of<R: Real> = [[R; 4]];
}

impl<R: Real> Hinges<R> {
    /// Whether hinges 8k..8k+8 share no vertex, for each whole block k.
    pub fn independent_blocks(&self) -> Vec<bool> {
        self.vertices
            .chunks_exact(LANES)
            .map(|block| {
                let mut corners = [0u32; 4 * LANES];
                for (k, hinge) in block.iter().enumerate() {
                    corners[4 * k..4 * k + 4].copy_from_slice(hinge);
                }
                corners.sort_unstable();
                corners.windows(2).all(|w| w[0] != w[1])
            })
            .collect()
    }
}

/// One pass over every hinge of `run` with the kernel when `R` is I32F32 and a backend
/// runs; returns whether it ran (if not, nothing was written).
pub(super) fn solve<R: Real>(run: &mut HingeRun<'_, R>, positions: &mut [Vec3<R>]) -> bool {
    let (
        Some(backend),
        Some(coefficients),
        Some(lambda),
        Some(positions),
        Some(shares),
        Some(relax),
    ) = (
        backend(),
        R::as_fixed::<Quads>(run.coefficients),
        R::as_fixed_mut::<Vectors>(&mut *run.lambda),
        R::as_fixed_mut::<Vectors>(positions),
        R::as_fixed::<Quads>(run.shares),
        R::as_fixed::<Scalars>(run.relax),
    )
    else {
        return false;
    };
    let mut rows = HingeRun {
        vertices: run.vertices,
        coefficients,
        lambda,
        shares,
        relax,
        independent: run.independent,
    };
    solve_rows(backend, &mut rows, positions);
    true
}

kernel_entry! {
    /// [`solve_rows_kernel`] with the instructions of `backend`.
    fn solve_rows(rows: &mut HingeRun<'_, Fx>, positions: &mut [Vec3<Fx>]) -> () = solve_rows_kernel;
}

/// Every hinge in order: the independent blocks with the kernel, the rest with the scalar
/// row.
#[inline(always)]
fn solve_rows_kernel<W: Wide>(w: W, rows: &mut HingeRun<'_, Fx>, positions: &mut [Vec3<Fx>]) {
    let count = rows.vertices.len();
    for k in 0..count / LANES {
        let start = k * LANES;
        let solved = rows.independent.get(k).copied().unwrap_or(false)
            && solve_block(w, rows, positions, start);
        if !solved {
            for h in start..start + LANES {
                rows.solve_row(positions, h);
            }
        }
    }
    for h in count - count % LANES..count {
        rows.solve_row(positions, h);
    }
}

/// The kernel on hinges `start..start + 8`, which share no vertex; returns false, having
/// written nothing, when a check fails.
#[inline(always)]
fn solve_block<W: Wide>(
    w: W,
    rows: &mut HingeRun<'_, Fx>,
    positions: &mut [Vec3<Fx>],
    start: usize,
) -> bool {
    let block = start..start + LANES;
    let mut corners = [[0u32; LANES]; 4];
    for (l, hinge) in rows.vertices[block.clone()].iter().enumerate() {
        for k in 0..4 {
            corners[k][l] = hinge[k];
        }
    }
    let (Some(x0), Some(x1), Some(x2), Some(x3)) = (
        w.gather_vectors(positions, &corners[0]),
        w.gather_vectors(positions, &corners[1]),
        w.gather_vectors(positions, &corners[2]),
        w.gather_vectors(positions, &corners[3]),
    ) else {
        return false;
    };
    let x = [x0, x1, x2, x3];
    let (Some(coefficients), Some(block_shares), Some(relax)) = (
        eight(rows.coefficients, start),
        eight(rows.shares, start),
        rows.relax.get(block.clone()),
    ) else {
        return false;
    };
    let c = w.load_columns(coefficients);
    let s = w.load_columns(block_shares);
    let Some(mu) = w.load_run(rows.lambda, start) else {
        return false;
    };
    let relax = w.load(relax.try_into().expect("eight values"));
    let mut bad = w.out_of_bound3(mu) | w.out_of_bound(relax);
    for k in 0..4 {
        bad |= w.out_of_bound3(x[k]) | w.out_of_bound(c[k]) | w.out_of_bound(s[k]);
    }
    let zero = w.zero();
    let mut value = [zero; 3];
    for k in 0..4 {
        for i in 0..3 {
            value[i] = w.add(value[i], w.mul(x[k][i], c[k]));
        }
    }
    let residual = [
        w.sub(w.sub(zero, value[0]), mu[0]),
        w.sub(w.sub(zero, value[1]), mu[1]),
        w.sub(w.sub(zero, value[2]), mu[2]),
    ];
    bad |= w.out_of_bound3(residual);
    if bad != 0 {
        return false;
    }
    let new_mu = [
        w.store_words(w.add(mu[0], w.mul(residual[0], relax))),
        w.store_words(w.add(mu[1], w.mul(residual[1], relax))),
        w.store_words(w.add(mu[2], w.mul(residual[2], relax))),
    ];
    let mut moved = [[[0; LANES]; 3]; 4];
    for k in 0..4 {
        for i in 0..3 {
            moved[k][i] = w.store_words(w.add(x[k][i], w.mul(residual[i], s[k])));
        }
    }
    let lane = |v: &[[i64; LANES]; 3], l: usize| {
        Vec3::new(
            Fx::from_bits(v[0][l]),
            Fx::from_bits(v[1][l]),
            Fx::from_bits(v[2][l]),
        )
    };
    for l in 0..LANES {
        for k in 0..4 {
            positions[corners[k][l] as usize] = lane(&moved[k], l);
        }
        rows.lambda[start + l] = lane(&new_mu, l);
    }
    true
}

/// Rows `start..start + 8`, if they exist.
#[inline(always)]
fn eight(rows: &[[Fx; 4]], start: usize) -> Option<&[[Fx; 4]; LANES]> {
    rows.get(start..start + LANES)?.try_into().ok()
}
