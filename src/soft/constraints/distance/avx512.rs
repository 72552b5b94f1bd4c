//! The distance rows of I32F32 in AVX-512: eight rows side by side, one `i64` lane per
//! row, with the bits of the scalar row ([`Distances::solve_row`]).
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
//! products with them take the short form of [`mul_short`]). Then every product is of
//! values below 2⁴⁸ and below 2⁶² after rounding, and every sum or difference has two or
//! three such terms or checked values: no operation of the row leaves the `i64` range. (In the lanes that take
//! the series: |δ| ≤ 2³⁰ raw, so the series lies in (2³¹, 2³³) and y = y₀·series below
//! 2⁴⁷ + 1; |d|²y and d·y are below 2⁶¹, r below 2⁶² + 2⁴⁷.) The checked operators then
//! saturate nowhere and give the exact rounded values, which the kernel's exact residues
//! equal; and the scalar row, whether its guard stays clear or it reruns checked, gives the
//! checked operators' values.
//!
//! When every lane's |d| components are below 2³¹ raw (half a metre), the block takes
//! the short forms [`square_short`] for d·d and [`mul_short`] for d·y. Three products of
//! the series have short exact forms in the series lanes: with |δ| < 2³¹ raw, δ is its
//! own signed low half, so δ·δ is one 32×32-bit multiply, ⌊(δ² + 2³¹)/2³²⌋; δ·½ is
//! ⌊(δ·2³¹ + 2³¹)/2³²⌋ = ⌊(δ + 1)/2⌋; and s·3/8 (s = δ² ≥ 0, below 2²⁹) is
//! ⌊(s·3·2²⁹ + 2³¹)/2³²⌋ = ⌊(3s + 4)/8⌋.
//!
//! The kernel leaves to the scalar row the lanes where a check fails and the lanes whose q
//! is outside [3/4, 5/4] (1/|d| from a square root, or coincident ends): it writes nothing
//! in those lanes.
//!
//! The lane arithmetic (products from 32-bit halves, the bound check) is in
//! [`lanes`](crate::soft::lanes).

use core::any::Any;
use core::arch::x86_64::{
    __m512i, __mmask8, _mm512_cmpge_epi64_mask, _mm512_cmple_epi64_mask, _mm512_mask_storeu_epi64,
    _mm512_mul_epi32, _mm512_set1_epi64, _mm512_setzero_si512, _mm512_slli_epi64,
    _mm512_srai_epi64,
};

use super::{DistanceFactors, Distances};
use crate::math::{Fx, Real, Vec3};
use crate::soft::lanes::{
    LANES, add, gather3, lane3, load, mul, mul_short, out_of_bound, out_of_bound3, out_of_short,
    put3, splat, split, split3, square_short, sub,
};

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

/// One Gauss–Seidel pass over every row with the kernel when `R` is I32F32 and the
/// processor has AVX-512F; returns whether it ran (if not, nothing was written).
pub(super) fn solve<R: Real>(
    rows: &mut Distances<R>,
    positions: &mut [Vec3<R>],
    f: &DistanceFactors<R>,
) -> bool {
    if !crate::math::cpu::avx512f() {
        return false;
    }
    let (Some(rows), Some(f)) = (
        (rows as &mut dyn Any).downcast_mut::<Distances<Fx>>(),
        (f as &dyn Any).downcast_ref::<DistanceFactors<Fx>>(),
    ) else {
        return false;
    };
    // SAFETY: `R` is `Fx` (the downcasts succeeded), so the slice's type is unchanged.
    let positions = unsafe { &mut *(core::ptr::from_mut(positions) as *mut [Vec3<Fx>]) };
    // SAFETY: AVX-512F was detected on this processor just above.
    unsafe { solve_rows(rows, positions, f) };
    true
}

/// Every row in order: the independent blocks with the kernel and what it leaves, the
/// other rows, with the scalar row.
///
/// # Safety
/// The processor must have AVX-512F.
#[target_feature(enable = "avx512f")]
unsafe fn solve_rows(
    rows: &mut Distances<Fx>,
    positions: &mut [Vec3<Fx>],
    f: &DistanceFactors<Fx>,
) {
    let count = rows.a.len();
    for k in 0..count / LANES {
        let start = k * LANES;
        let done = if f.independent.get(k).copied().unwrap_or(false) {
            solve_block(rows, positions, f, start)
        } else {
            0
        };
        for l in 0..LANES {
            if done & (1 << l) == 0 {
                rows.solve_row(positions, f, start + l);
            }
        }
    }
    for c in count - count % LANES..count {
        rows.solve_row(positions, f, c);
    }
}

/// The kernel on rows `start..start + 8`, which share no vertex: returns the lanes it
/// solved and wrote.
#[inline]
#[target_feature(enable = "avx512f")]
fn solve_block(
    rows: &mut Distances<Fx>,
    positions: &mut [Vec3<Fx>],
    f: &DistanceFactors<Fx>,
    start: usize,
) -> __mmask8 {
    let block = start..start + LANES;
    let (Some(xa), Some(xb)) = (
        gather3(positions, &rows.a[block.clone()]),
        gather3(positions, &rows.b[block.clone()]),
    ) else {
        return 0;
    };
    let rest = load(&rows.rest[block.clone()]);
    let previous = load(&rows.inv_length[block.clone()]);
    let mu = load(&rows.lambda[block.clone()]);
    let share_a = load(&f.share_a[block.clone()]);
    let share_b = load(&f.share_b[block.clone()]);
    let relax = load(&f.relax[block.clone()]);
    let mut bad = out_of_bound3(xa)
        | out_of_bound3(xb)
        | out_of_bound(rest)
        | out_of_bound(previous)
        | out_of_bound(mu)
        | out_of_bound(share_a)
        | out_of_bound(share_b)
        | out_of_bound(relax);

    let d = [sub(xa[0], xb[0]), sub(xa[1], xb[1]), sub(xa[2], xb[2])];
    bad |= out_of_bound3(d);
    // Edges shorter than half a metre in every lane (the usual case) take the short
    // products.
    let short = out_of_short(d[0]) | out_of_short(d[1]) | out_of_short(d[2]) == 0;
    let ends = d;
    let d = split3(d);
    let length_squared = if short {
        add(
            add(square_short(ends[0]), square_short(ends[1])),
            square_short(ends[2]),
        )
    } else {
        add(add(mul(d[0], d[0]), mul(d[1], d[1])), mul(d[2], d[2]))
    };
    bad |= out_of_bound(length_squared);
    let (length_squared, previous) = (split(length_squared), split(previous));
    let scaled = mul(length_squared, previous);
    bad |= out_of_bound(scaled);
    let q = mul(split(scaled), previous);
    let series_lanes = _mm512_cmpge_epi64_mask(q, splat(Fx::from_ratio(3, 4)))
        & _mm512_cmple_epi64_mask(q, splat(Fx::from_ratio(5, 4)));
    // In the series lanes |δ| ≤ 2³⁰ raw: the three products below take their short forms.
    let delta = sub(q, splat(Fx::ONE));
    let one = _mm512_set1_epi64(1);
    let half = _mm512_srai_epi64::<1>(add(delta, one));
    let square = _mm512_srai_epi64::<32>(add(
        _mm512_mul_epi32(delta, delta),
        _mm512_set1_epi64(1 << 31),
    ));
    let triple = add(_mm512_slli_epi64::<1>(square), square);
    let quadratic = _mm512_srai_epi64::<3>(add(triple, _mm512_set1_epi64(4)));
    let linear = sub(splat(Fx::ONE), half);
    let series = add(linear, quadratic);
    let inv_length = mul(previous, split(series));
    let y = split(inv_length);
    let length = mul(length_squared, y);
    let shortfall = sub(rest, length);
    let residual = sub(shortfall, mu);
    bad |= out_of_short(residual);
    let new_mu = add(mu, mul_short(split(relax), residual));
    let direction = if short {
        [
            mul_short(y, ends[0]),
            mul_short(y, ends[1]),
            mul_short(y, ends[2]),
        ]
    } else {
        [mul(d[0], y), mul(d[1], y), mul(d[2], y)]
    };
    bad |= out_of_bound3(direction);
    let step_a = mul_short(split(share_a), residual);
    let minus_b = sub(_mm512_setzero_si512(), mul_short(split(share_b), residual));
    bad |= out_of_short(step_a) | out_of_short(minus_b);
    let direction = split3(direction);
    let new_a = [
        add(xa[0], mul_short(direction[0], step_a)),
        add(xa[1], mul_short(direction[1], step_a)),
        add(xa[2], mul_short(direction[2], step_a)),
    ];
    let new_b = [
        add(xb[0], mul_short(direction[0], minus_b)),
        add(xb[1], mul_short(direction[1], minus_b)),
        add(xb[2], mul_short(direction[2], minus_b)),
    ];

    let solved = series_lanes & !bad;
    if solved != 0 {
        for l in 0..LANES {
            if solved & (1 << l) != 0 {
                let (a, b) = (rows.a[start + l] as usize, rows.b[start + l] as usize);
                put3(&mut positions[a], lane3(new_a, l));
                put3(&mut positions[b], lane3(new_b, l));
            }
        }
        store(&mut rows.lambda[block.clone()], solved, new_mu);
        store(&mut rows.inv_length[block], solved, inv_length);
    }
    solved
}

/// Writes the lanes of `lanes` of `value` to eight values.
#[inline]
#[target_feature(enable = "avx512f")]
fn store(values: &mut [Fx], lanes: __mmask8, value: __m512i) {
    let values = &mut values[..LANES];
    // SAFETY: eight `Fx`, each one `i64`: 64 writable bytes.
    unsafe { _mm512_mask_storeu_epi64(values.as_mut_ptr().cast(), lanes, value) }
}
