//! The wave step of I32F32 in one pass over the rows, eight edges or cells at a time on
//! the lanes of [`Wide`]: with the processor's backend, or on [`Portable`] lanes where
//! there is none (the `scalar` cap), with the bits of the scalar step ([`super`]).
//!
//! # One pass
//!
//! Row k (cells nk … nk + n − 1) takes, in order: the new flows of its x edges; the new
//! flows of the z edges to row k + 1 (which read row k + 1 before anything changes it);
//! on an open border, the outflow of its border cells; then its heights, from the
//! transfers t = (h/s) q of its four edges:
//!
//! ```text
//! u_i ← u_i + X[i] − X[i + 1] + P[i] − N[i]
//! X[i + 1] = t of the x edge from cell i (X[0] = X[n] = 0)
//! P[i] = t of the z edge from row k − 1 (0 on row 0), N[i] = t of the edge to row k + 1
//! ```
//!
//! N becomes P of the next row. Every value is a function of the values before the step
//! only, as in the scalar step, which takes all flows, then the outflow, then all heights;
//! and each cell takes its terms in the scalar step's order (outflow, left, right, up,
//! down). The grid is read and written once, with three rows of transfers beside it.
//!
//! # Exactness and range
//!
//! The scalar step rounds each product once ([`Fx`]'s `*`: ⌊(a·b + 2³¹)/2³²⌋) and adds
//! exactly unless a sum leaves the format. The factors p = h c²/s, κ = 1 − γh and h/s are
//! checked once per step to lie within [−2⁴⁶, 2⁴⁶) as raw bits. Per block of eight edges,
//! with a = u_low, b = u_high and q the old flow:
//!
//! * **narrow** (heights and flows within about ¼ m, m²/s, as in any calm or wavy pond):
//!   when a, b and q lie within [−2ⁿ, 2ⁿ), n ≤ 30 the largest for which the rise b − a,
//!   q − p(b − a) and the new flow q′ are sure to lie within [−2³¹, 2³¹) (worked out once
//!   per step from p and κ in `i128`, [`narrow_input_bits`]), each product has a small
//!   factor there and is [`Wide::times`]`::<true>`: two signed 32 × 32 → 64-bit multiplies
//!   (`_mm256_mul_epi32` on AVX2, one instruction per four lanes), exact in 64 bits. Every
//!   product is then below 2⁴⁵ + 1 and every sum below 2⁴⁸: nothing leaves the format;
//! * **wide** (heights or flows up to 2¹⁴): else, when a, b, q, the rise, q − p(b − a)
//!   and q′ lie within [−2⁴⁶, 2⁴⁶), the full [`Wide::mul`];
//! * else the block takes the scalar operators, lane by lane, before anything of it is
//!   written.
//!
//! A block of heights adds five terms within [−2⁴⁶, 2⁴⁶), below 2⁴⁹, where the scalar
//! step's sums never saturate either and integer sums do not depend on their order; a
//! block with a term outside takes the scalar operators in the scalar order. When the
//! narrow tier made every transfer a row reads (each below 2⁴⁵ + 1), only u is checked.
//! The bounds are checked on the magnitudes x ^ (x >> 63) of a block, or-ed together,
//! with one test ([`Wide::below_power`]). A run's last, partial block is padded with calm
//! water.

use super::super::system::WaveScratch;
use super::{Factors, for_each_border_cell_of_row};
use crate::math::over_real::{Scalar, Scalars};
use crate::math::wide::portable::Portable;
use crate::math::wide::{LANES, Wide, backend, kernel_entry};
use crate::math::{Fx, Real};

/// The bound of every factor and term: |x| < 2⁴⁶ as raw bits.
const BOUND_BITS: u32 = 46;

/// Runs the wave step on `heights`, `flow_x`, `flow_z` of an n-column grid (`columns`)
/// when `R` is I32F32 and the factors lie within the bound; returns whether it ran (if
/// not, nothing was written).
pub(super) fn wave_step<R: Real>(
    heights: &mut [R],
    flow_x: &mut [R],
    flow_z: &mut [R],
    columns: usize,
    factors: &Factors<R>,
    scratch: &mut WaveScratch,
) -> bool {
    let fixed = |x: &R| R::as_fixed::<Scalar>(x).copied();
    let (Some(u), Some(qx), Some(qz), Some(push), Some(keep), Some(carry)) = (
        R::as_fixed_mut::<Scalars>(heights),
        R::as_fixed_mut::<Scalars>(flow_x),
        R::as_fixed_mut::<Scalars>(flow_z),
        fixed(&factors.push),
        fixed(&factors.keep),
        fixed(&factors.carry),
    ) else {
        return false;
    };
    let leave = match &factors.leave {
        Some(leave) => match fixed(leave) {
            Some(leave) => Some(leave),
            None => return false,
        },
        None => None,
    };
    let within = |x: Fx| x.to_bits().unsigned_abs() < 1 << BOUND_BITS;
    if !within(push) || !within(keep) || !within(carry) {
        return false;
    }
    let factors = Factors {
        push,
        keep,
        carry,
        leave,
    };
    match backend() {
        Some(backend) => step_on(backend, u, qx, qz, columns, factors, scratch),
        None => step_kernel(Portable, u, qx, qz, columns, factors, scratch),
    }
    true
}

kernel_entry! {
    /// [`step_kernel`] with the instructions of `backend`.
    fn step_on(
        u: &mut [Fx],
        qx: &mut [Fx],
        qz: &mut [Fx],
        n: usize,
        factors: Factors<Fx>,
        scratch: &mut WaveScratch,
    ) -> () = step_kernel;
}

/// The factors p, κ and h/s in every lane, and the bound n of the narrow tier's inputs.
#[derive(Clone, Copy)]
struct Lanes<V> {
    push: V,
    keep: V,
    carry: V,
    narrow_bits: Option<u32>,
}

/// The largest n ≤ 30 such that heights and old flows within [−2ⁿ, 2ⁿ) keep every small
/// factor of the narrow products within [−2³¹, 2³¹), for the factors p (`push`) and κ
/// (`keep`); `None` if there is none. The rise is then below 2ⁿ⁺¹ ≤ 2³¹; p times it,
/// rounded, at most 2ⁿ⁺¹|p|/2³² + 1; q − p·rise at most 2ⁿ plus that; and q′ at most
/// |q − p·rise|·|κ|/2³² + 1, all as raw bits, computed exactly in `i128`.
fn narrow_input_bits(push: Fx, keep: Fx) -> Option<u32> {
    let p = i128::from(push.to_bits().unsigned_abs());
    let kappa = i128::from(keep.to_bits().unsigned_abs());
    (0..=30).rev().find(|&n| {
        let pushed = (1 << n) + (((1 << (n + 1)) * p) >> 32) + 1;
        let new = ((pushed * kappa) >> 32) + 1;
        pushed < 1 << 31 && new < 1 << 31
    })
}

/// The step, row by row ([module](self) documentation).
#[inline(always)]
fn step_kernel<W: Wide>(
    w: W,
    u: &mut [Fx],
    qx: &mut [Fx],
    qz: &mut [Fx],
    n: usize,
    factors: Factors<Fx>,
    scratch: &mut WaveScratch,
) {
    let rows = u.len() / n;
    let lanes = Lanes {
        push: w.splat(factors.push.to_bits()),
        keep: w.splat(factors.keep.to_bits()),
        carry: w.splat(factors.carry.to_bits()),
        narrow_bits: narrow_input_bits(factors.push, factors.keep),
    };
    let WaveScratch { x, previous, next } = scratch;
    for buffer in [&mut *x, &mut *previous, &mut *next] {
        buffer.clear();
        buffer.resize(n + 1, Fx::ZERO);
    }
    let mut previous_narrow = true;
    for k in 0..rows {
        let row = n * k..n * (k + 1);
        let edges = (n - 1) * k..(n - 1) * (k + 1);
        let x_narrow = flow_run(
            w,
            &lanes,
            &factors,
            &mut qx[edges],
            &u[row.start..row.end - 1],
            &u[row.start + 1..row.end],
            &mut x[1..n],
        );
        let next_narrow = if k + 1 < rows {
            flow_run(
                w,
                &lanes,
                &factors,
                &mut qz[row.clone()],
                &u[row.clone()],
                &u[row.end..row.end + n],
                &mut next[..n],
            )
        } else {
            next.fill(Fx::ZERO);
            true
        };
        if let Some(leave) = factors.leave {
            for_each_border_cell_of_row(n, rows, k, |cell, outer_edges| {
                let t = leave * u[cell];
                for _ in 0..outer_edges {
                    u[cell] -= t;
                }
            });
        }
        if x_narrow && previous_narrow && next_narrow {
            height_run::<W, true>(w, &mut u[row], x, previous, next);
        } else {
            height_run::<W, false>(w, &mut u[row], x, previous, next);
        }
        core::mem::swap(previous, next);
        previous_narrow = next_narrow;
    }
}

/// The new flows q′ = (q − p (b − a))·κ of eight edges and their transfers (h/s) q′, from
/// the heights a (low side) and b (high side) and the old flows q, and whether the narrow
/// tier took them (each transfer then below 2⁴⁵ + 1); `None` where a lane leaves the
/// bounds ([module](self) documentation).
#[inline(always)]
fn flow_block<W: Wide>(
    w: W,
    lanes: &Lanes<W::V>,
    a: W::V,
    b: W::V,
    q: W::V,
) -> Option<(W::V, W::V, bool)> {
    let inputs = w.or(w.or(w.magnitude(a), w.magnitude(b)), w.magnitude(q));
    let rise = w.sub(b, a);
    if let Some(bits) = lanes.narrow_bits
        && w.below_power(inputs, bits)
    {
        let pushed = w.sub(q, w.times::<true>(rise, lanes.push));
        let new = w.times::<true>(pushed, lanes.keep);
        return Some((new, w.times::<true>(new, lanes.carry), true));
    }
    if !w.below_power(inputs, BOUND_BITS) {
        return None;
    }
    let pushed = w.sub(q, w.mul(lanes.push, rise));
    let new = w.mul(pushed, lanes.keep);
    let factors = w.or(
        w.or(w.magnitude(rise), w.magnitude(pushed)),
        w.magnitude(new),
    );
    if w.below_power(factors, BOUND_BITS) {
        return Some((new, w.mul(new, lanes.carry), false));
    }
    None
}

/// One edge with the scalar operators: q′ = (q − p (high − low))·κ, t = (h/s) q′.
#[inline(always)]
fn flow_one(q: &mut Fx, low: Fx, high: Fx, t: &mut Fx, factors: &Factors<Fx>) {
    *q = (*q - factors.push * (high - low)) * factors.keep;
    *t = factors.carry * *q;
}

/// [`flow_block`] over a run of edges: `q[j]` between the cells `low[j]` and `high[j]`,
/// its transfer written to `t[j]`; returns whether the narrow tier took them all.
#[inline(always)]
fn flow_run<W: Wide>(
    w: W,
    lanes: &Lanes<W::V>,
    factors: &Factors<Fx>,
    q: &mut [Fx],
    low: &[Fx],
    high: &[Fx],
    t: &mut [Fx],
) -> bool {
    let len = q.len();
    assert!(low.len() >= len && high.len() >= len && t.len() >= len);
    let mut all_narrow = true;
    let mut j = 0;
    while j + LANES <= len {
        // SAFETY: words j … j + 7 lie in each slice (j + 8 ≤ len ≤ their lengths), and
        // `Fx` is an `i64` (`repr(transparent)`).
        let (a, b, old) = unsafe {
            (
                w.load_at(low.as_ptr().add(j).cast()),
                w.load_at(high.as_ptr().add(j).cast()),
                w.load_at(q.as_ptr().add(j).cast()),
            )
        };
        if let Some((new, transfer, narrow)) = flow_block(w, lanes, a, b, old) {
            // SAFETY: as above.
            unsafe {
                w.store_at(q.as_mut_ptr().add(j).cast(), new);
                w.store_at(t.as_mut_ptr().add(j).cast(), transfer);
            }
            all_narrow &= narrow;
        } else {
            all_narrow = false;
            for i in j..j + LANES {
                flow_one(&mut q[i], low[i], high[i], &mut t[i], factors);
            }
        }
        j += LANES;
    }
    if j == len {
        return all_narrow;
    }
    let padded = |values: &[Fx]| {
        let mut words = [0; LANES];
        for (word, value) in words.iter_mut().zip(&values[j..len]) {
            *word = value.to_bits();
        }
        w.load_words(words)
    };
    let (a, b, old) = (padded(low), padded(high), padded(q));
    if let Some((new, transfer, narrow)) = flow_block(w, lanes, a, b, old) {
        let (new, transfer) = (w.store_words(new), w.store_words(transfer));
        for i in j..len {
            q[i] = Fx::from_bits(new[i - j]);
            t[i] = Fx::from_bits(transfer[i - j]);
        }
        all_narrow && narrow
    } else {
        for i in j..len {
            flow_one(&mut q[i], low[i], high[i], &mut t[i], factors);
        }
        false
    }
}

/// u + left − right + up − down for eight cells; `None` where a term leaves the bound.
/// With `NARROW` transfers (each below 2⁴⁵ + 1, from the narrow tier or padding) only u
/// is checked.
#[inline(always)]
fn height_block<W: Wide, const NARROW: bool>(w: W, terms: [W::V; 5]) -> Option<W::V> {
    let [u, left, right, up, down] = terms;
    let magnitudes = if NARROW {
        w.magnitude(u)
    } else {
        let (x, z) = (
            w.or(w.magnitude(left), w.magnitude(right)),
            w.or(w.magnitude(up), w.magnitude(down)),
        );
        w.or(w.magnitude(u), w.or(x, z))
    };
    if !w.below_power(magnitudes, BOUND_BITS) {
        return None;
    }
    Some(w.sub(w.add(w.sub(w.add(u, left), right), up), down))
}

/// The heights of one row: `u[i] += x[i] − x[i + 1] + up[i] − down[i]` ([`height_block`]).
#[inline(always)]
fn height_run<W: Wide, const NARROW: bool>(w: W, u: &mut [Fx], x: &[Fx], up: &[Fx], down: &[Fx]) {
    let len = u.len();
    assert!(x.len() > len && up.len() >= len && down.len() >= len);
    let one = |u: &mut [Fx], i: usize| u[i] = u[i] + x[i] - x[i + 1] + up[i] - down[i];
    let mut j = 0;
    while j + LANES <= len {
        // SAFETY: j + 8 ≤ len, so words j … j + 8 of `x` (longer than `u`) and j … j + 7 of
        // `u`, `up` and `down` exist.
        let terms = unsafe {
            [
                w.load_at(u.as_ptr().add(j).cast()),
                w.load_at(x.as_ptr().add(j).cast()),
                w.load_at(x.as_ptr().add(j + 1).cast()),
                w.load_at(up.as_ptr().add(j).cast()),
                w.load_at(down.as_ptr().add(j).cast()),
            ]
        };
        if let Some(new) = height_block::<W, NARROW>(w, terms) {
            // SAFETY: as above.
            unsafe { w.store_at(u.as_mut_ptr().add(j).cast(), new) };
        } else {
            for i in j..j + LANES {
                one(u, i);
            }
        }
        j += LANES;
    }
    if j == len {
        return;
    }
    let padded = |values: &[Fx], from: usize| {
        let mut words = [0; LANES];
        for (word, value) in words.iter_mut().zip(&values[from..from + len - j]) {
            *word = value.to_bits();
        }
        w.load_words(words)
    };
    let terms = [
        padded(u, j),
        padded(x, j),
        padded(x, j + 1),
        padded(up, j),
        padded(down, j),
    ];
    if let Some(new) = height_block::<W, NARROW>(w, terms) {
        let new = w.store_words(new);
        for i in j..len {
            u[i] = Fx::from_bits(new[i - j]);
        }
    } else {
        for i in j..len {
            one(u, i);
        }
    }
}
