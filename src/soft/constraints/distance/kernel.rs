//! The distance rows of I32F32 on the lanes of [`Wide`] (every backend): eight rows side by
//! side, one `i64` lane per row, with the bits of the scalar row ([`DistanceRun::solve_row`]).
//!
//! # Why side by side gives the same bits
//!
//! Gauss–Seidel visits the rows in order, each reading the positions the rows before it
//! wrote. Rows that share no vertex read nothing the others write, so solving eight such
//! rows together reads and writes exactly what solving them one after another does. The
//! blocks of eight consecutive rows that share no vertex are listed once per substep length
//! ([`independent_blocks`]); in colour order nearly every block is one (rows of one colour
//! share no vertex). The other blocks and the rows past the last multiple of eight take the
//! scalar row, and so does any lane the kernel leaves (below): since a block's lanes are
//! independent, solving such a lane after the others gives the same bits too.
//!
//! # Exactness
//!
//! The kernel computes every operation of the scalar row, in the same order, modulo 2⁶⁴.
//! It checks that every value it loads (the ends' positions, ℓ₀, y₀, μ, sₐ, s_b, ρ) and
//! d, |d|², |d|²y₀ and n̂ lie in [−2⁴⁶, 2⁴⁶) as raw bits (|x| < 16384 in I32F32), and the
//! residual r and the two steps sₐr and −s_b r in [−2³¹, 2³¹) (below half a metre; the
//! products with them take the short form of [`Wide::times`]). Then every product is of
//! values below 2⁴⁸ and below 2⁶² after rounding, and every sum or difference has two or
//! three such terms or checked values: no operation of the row leaves the `i64` range. (In the lanes that take
//! the series: |δ| ≤ 2³⁰ raw, so the series lies in (2³¹, 2³³) and y = y₀·series below
//! 2⁴⁷ + 1; |d|²y and d·y are below 2⁶¹, r below 2⁶² + 2⁴⁷.) The checked operators then
//! saturate nowhere and give the exact rounded values, which the kernel's exact residues
//! equal; and the scalar row, whether its guard stays clear or it reruns checked, gives the
//! checked operators' values.
//!
//! When every lane's |d| components are below 2³¹ raw (half a metre), the block takes
//! the short forms of [`Wide::times`] for d·d and d·y. Three products of
//! the series have short exact forms in the series lanes: with |δ| < 2³¹ raw, δ is its
//! own signed low half, so δ·δ is one 32×32-bit multiply, ⌊(δ² + 2³¹)/2³²⌋; δ·½ is
//! ⌊(δ·2³¹ + 2³¹)/2³²⌋ = ⌊(δ + 1)/2⌋; and s·3/8 (s = δ² ≥ 0, below 2²⁹) is
//! ⌊(s·3·2²⁹ + 2³¹)/2³²⌋ = ⌊(3s + 4)/8⌋.
//!
//! The kernel leaves to the scalar row the lanes where a check fails and the lanes whose q
//! is outside [3/4, 5/4] (1/|d| from a square root, or coincident ends): it writes nothing
//! in those lanes.
//!
//! The lane arithmetic (products from 32-bit halves, the bound checks) is
//! [`wide`](crate::math::wide)'s.

use super::DistanceRun;
use crate::math::over_real::{Scalars, Vectors};
use crate::math::wide::{LANES, Wide, backend, kernel_entry};
use crate::math::{Fx, Real, Vec3};

/// Whether rows 8k..8k+8 (ends `a`, `b`) share no vertex, for each whole block k.
pub(super) fn independent_blocks(a: &[u32], b: &[u32]) -> Vec<bool> {
    a.chunks_exact(LANES)
        .zip(b.chunks_exact(LANES))
        .map(|(a, b)| {
            let mut ends = [0u32; 2 * LANES];
            ends[..LANES].copy_from_slice(a);
            ends[LANES..].copy_from_slice(b);
            ends.sort_unstable();
            ends.windows(2).all(|w| w[0] != w[1])
        })
        .collect()
}

/// One Gauss–Seidel pass over every row of `run` with the kernel when `R` is I32F32 and a
/// backend runs; returns whether it ran (if not, nothing was written).
pub(super) fn solve<R: Real>(run: &mut DistanceRun<'_, R>, positions: &mut [Vec3<R>]) -> bool {
    let Some(backend) = backend() else {
        return false;
    };
    let (
        Some(rest),
        Some(inv_length),
        Some(lambda),
        Some(share_a),
        Some(share_b),
        Some(relax),
        Some(positions),
    ) = (
        R::as_fixed::<Scalars>(run.rest),
        R::as_fixed_mut::<Scalars>(&mut *run.inv_length),
        R::as_fixed_mut::<Scalars>(&mut *run.lambda),
        R::as_fixed::<Scalars>(run.share_a),
        R::as_fixed::<Scalars>(run.share_b),
        R::as_fixed::<Scalars>(run.relax),
        R::as_fixed_mut::<Vectors>(positions),
    )
    else {
        return false;
    };
    let mut rows = DistanceRun {
        a: run.a,
        b: run.b,
        rest,
        inv_length,
        lambda,
        share_a,
        share_b,
        relax,
        independent: run.independent,
    };
    solve_rows(backend, &mut rows, positions);
    true
}

kernel_entry! {
    /// [`solve_rows_kernel`] with the instructions of `backend`.
    fn solve_rows(
        rows: &mut DistanceRun<'_, Fx>,
        positions: &mut [Vec3<Fx>],
    ) -> () = solve_rows_kernel;
}

/// Every row in order: the independent blocks with the kernel and what it leaves, the
/// other rows, with the scalar row.
#[inline(always)]
fn solve_rows_kernel<W: Wide>(w: W, rows: &mut DistanceRun<'_, Fx>, positions: &mut [Vec3<Fx>]) {
    let count = rows.a.len();
    for k in 0..count / LANES {
        let start = k * LANES;
        let done = if rows.independent.get(k).copied().unwrap_or(false) {
            solve_block(w, rows, positions, start)
        } else {
            0
        };
        for l in 0..LANES {
            if done & (1 << l) == 0 {
                rows.solve_row(positions, start + l);
            }
        }
    }
    for c in count - count % LANES..count {
        rows.solve_row(positions, c);
    }
}

/// Eight values from `start`.
#[inline(always)]
fn block(values: &[Fx], start: usize) -> &[Fx; LANES] {
    values[start..start + LANES]
        .try_into()
        .expect("eight values")
}

/// Eight values from `start`, to write.
#[inline(always)]
fn block_mut(values: &mut [Fx], start: usize) -> &mut [Fx; LANES] {
    (&mut values[start..start + LANES])
        .try_into()
        .expect("eight values")
}

/// The kernel on rows `start..start + 8`, which share no vertex: returns the lanes it
/// solved and wrote.
#[inline(always)]
fn solve_block<W: Wide>(
    w: W,
    rows: &mut DistanceRun<'_, Fx>,
    positions: &mut [Vec3<Fx>],
    start: usize,
) -> u8 {
    let ends = start..start + LANES;
    let (Some(xa), Some(xb)) = (
        w.gather_vectors(positions, &rows.a[ends.clone()]),
        w.gather_vectors(positions, &rows.b[ends]),
    ) else {
        return 0;
    };
    let rest = w.load(block(rows.rest, start));
    let previous = w.load(block(rows.inv_length, start));
    let mu = w.load(block(rows.lambda, start));
    let share_a = w.load(block(rows.share_a, start));
    let share_b = w.load(block(rows.share_b, start));
    let relax = w.load(block(rows.relax, start));
    let mut bad = w.out_of_bound3(xa)
        | w.out_of_bound3(xb)
        | w.out_of_bound(rest)
        | w.out_of_bound(previous)
        | w.out_of_bound(mu)
        | w.out_of_bound(share_a)
        | w.out_of_bound(share_b)
        | w.out_of_bound(relax);

    let d = w.sub3(xa, xb);
    bad |= w.out_of_bound3(d);
    // Edges shorter than half a metre in every lane (the usual case) take the short
    // products.
    let short = w.beyond3::<true>(d) == 0;
    let length_squared = if short {
        w.add(
            w.add(w.times::<true>(d[0], d[0]), w.times::<true>(d[1], d[1])),
            w.times::<true>(d[2], d[2]),
        )
    } else {
        w.add(
            w.add(w.mul(d[0], d[0]), w.mul(d[1], d[1])),
            w.mul(d[2], d[2]),
        )
    };
    bad |= w.out_of_bound(length_squared);
    let scaled = w.mul(length_squared, previous);
    bad |= w.out_of_bound(scaled);
    let q = w.mul(scaled, previous);
    let series_lanes = !w.greater(w.splat(Fx::from_ratio(3, 4).to_bits()), q)
        & !w.greater(q, w.splat(Fx::from_ratio(5, 4).to_bits()));
    // In the series lanes |δ| ≤ 2³⁰ raw: the three products below take their short forms.
    let one = Fx::ONE.to_bits();
    let delta = w.sub(q, w.splat(one));
    let half = w.shift_right(w.add(delta, w.splat(1)), 1);
    let square = w.high(w.mul_low_halves(delta, delta));
    let triple = w.add(w.shift_left(square, 1), square);
    let quadratic = w.shift_right(w.add(triple, w.splat(4)), 3);
    let linear = w.sub(w.splat(one), half);
    let series = w.add(linear, quadratic);
    let inv_length = w.mul(previous, series);
    let y = inv_length;
    let length = w.mul(length_squared, y);
    let shortfall = w.sub(rest, length);
    let residual = w.sub(shortfall, mu);
    bad |= w.beyond::<true>(residual);
    let new_mu = w.add(mu, w.times::<true>(residual, relax));
    let direction = if short {
        w.times3::<true>(d, y)
    } else {
        [w.mul(d[0], y), w.mul(d[1], y), w.mul(d[2], y)]
    };
    bad |= w.out_of_bound3(direction);
    let step_a = w.times::<true>(residual, share_a);
    let minus_b = w.sub(w.zero(), w.times::<true>(residual, share_b));
    bad |= w.beyond::<true>(step_a) | w.beyond::<true>(minus_b);
    let new_a = w.add3(xa, along(w, step_a, direction));
    let new_b = w.add3(xb, along(w, minus_b, direction));

    let solved = series_lanes & !bad;
    if solved != 0 {
        let new_a = [
            w.store_words(new_a[0]),
            w.store_words(new_a[1]),
            w.store_words(new_a[2]),
        ];
        let new_b = [
            w.store_words(new_b[0]),
            w.store_words(new_b[1]),
            w.store_words(new_b[2]),
        ];
        let lane = |v: &[[i64; LANES]; 3], l: usize| {
            Vec3::new(
                Fx::from_bits(v[0][l]),
                Fx::from_bits(v[1][l]),
                Fx::from_bits(v[2][l]),
            )
        };
        for l in 0..LANES {
            if solved & (1 << l) != 0 {
                let (a, b) = (rows.a[start + l] as usize, rows.b[start + l] as usize);
                positions[a] = lane(&new_a, l);
                positions[b] = lane(&new_b, l);
            }
        }
        w.store_lanes(block_mut(rows.lambda, start), solved, new_mu);
        w.store_lanes(block_mut(rows.inv_length, start), solved, inv_length);
    }
    solved
}

/// step · n̂ for a step below 2³¹ raw (the short product).
#[inline(always)]
fn along<W: Wide>(w: W, step: W::V, direction: [W::V; 3]) -> [W::V; 3] {
    [
        w.times::<true>(step, direction[0]),
        w.times::<true>(step, direction[1]),
        w.times::<true>(step, direction[2]),
    ]
}
