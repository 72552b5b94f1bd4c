//! The separating-axis test of eight I32F32 box pairs at once in AVX-512 (F and DQ), one
//! `i64` lane per pair, with the bits of [`separating_axes`]: the same sums of products,
//! each product rounded on its own as the scalar `*` rounds it, and the same comparisons,
//!
//! ```text
//! t_i = a_i·d,  C_ij = a_i·b_j,  (t_B)_j = Σ_i t_i C_ij
//! s_A,i = |t_i| − (hA_i + Σ_j hB_j |C_ij|),  s_B,j = |(t_B)_j| − (hB_j + Σ_i hA_i |C_ij|)
//! s_ij = |t_i2 C_i1j − t_i1 C_i2j| − (hA_i1 |C_i2j| + hA_i2 |C_i1j| + hB_j1 |C_ij2| + hB_j2 |C_ij1|)
//! ```
//!
//! The scalar test stops at the first separating axis and picks the first best face and
//! edge axes in order; the kernel computes every axis of every lane and keeps, per lane,
//! whether any axis separates (then the result is `None`, whichever axis it was) and the
//! same first best axes, by masked updates in the scalar's order.
//!
//! # Exactness
//!
//! Every value that enters a product (the inputs, d, t, C, the chosen face's separation,
//! the threshold and its square, the margin's square, |L|², s_ij and s_ij²) is checked to
//! lie in [−2⁴⁶, 2⁴⁶) as raw bits, and every sum has at most four terms, each such a value
//! or a product below 2⁶⁰: no operation of the scalar form saturates, and the kernel's
//! wrapping arithmetic gives its exact results
//! ([`solver::avx512`](crate::rigid::solver::avx512)). A lane that fails a check is not
//! written and is left to the caller, even where the scalar test would have stopped
//! before the value that failed.

use core::any::Any;
use core::arch::x86_64::{
    __m512i, __mmask8, _mm512_abs_epi64, _mm512_cmpge_epi64_mask, _mm512_cmpgt_epi64_mask,
    _mm512_cmplt_epi64_mask, _mm512_loadu_si512, _mm512_set1_epi64, _mm512_setzero_si512,
    _mm512_storeu_si512,
};

#[cfg(doc)]
use super::separating_axes;
use super::{Axes, BoxPair, Choice, LANES};
use crate::math::{Fx, Real};
use crate::rigid::narrowphase::tolerance::parallel_sine_squared;
use crate::rigid::solver::avx512::{
    add, has_kernels, mul, out_of_bound, out_of_bound3, select, splat, sub,
};

/// Input words per lane: A's axes (9), B's axes (9), A's and B's centres (3 + 3), A's and
/// B's half extents (3 + 3).
const WORDS: usize = 30;
const A_AXES: usize = 0;
const B_AXES: usize = 9;
const A_CENTRE: usize = 18;
const B_CENTRE: usize = 21;
const A_HALF: usize = 24;
const B_HALF: usize = 27;

/// Tests the pairs `pairs` (at most [`LANES`]) with the kernel when `R` is I32F32 and the
/// processor has AVX-512F and DQ, writing lane l's result to `out[l]`. Returns the lanes
/// it is done with; the caller tests the others.
pub(super) fn separating_axes_lanes<R: Real>(
    pairs: &[BoxPair<'_, R>],
    margin: R,
    out: &mut [Option<Axes<R>>; LANES],
) -> u8 {
    if !has_kernels() {
        return 0;
    }
    let Some(&margin) = (&margin as &dyn Any).downcast_ref::<Fx>() else {
        return 0;
    };
    // SAFETY: `R` is `Fx` (the downcast succeeded), so the types are unchanged.
    let (pairs, out) = unsafe {
        (
            &*(core::ptr::from_ref(pairs) as *const [BoxPair<'_, Fx>]),
            &mut *(core::ptr::from_mut(out) as *mut [Option<Axes<Fx>>; LANES]),
        )
    };
    let count = pairs.len().min(LANES);
    // The lanes' inputs, word by word (zero in lanes past `count`).
    let mut words = [[0i64; LANES]; WORDS];
    for (l, pair) in pairs.iter().take(count).enumerate() {
        let (a, b) = (&pair.xf_a.rotation.cols, &pair.xf_b.rotation.cols);
        for m in 0..3 {
            for k in 0..3 {
                words[A_AXES + 3 * m + k][l] = a[m][k].to_bits();
                words[B_AXES + 3 * m + k][l] = b[m][k].to_bits();
            }
            words[A_CENTRE + m][l] = pair.xf_a.translation[m].to_bits();
            words[B_CENTRE + m][l] = pair.xf_b.translation[m].to_bits();
            words[A_HALF + m][l] = pair.half_a[m].to_bits();
            words[B_HALF + m][l] = pair.half_b[m].to_bits();
        }
    }
    // SAFETY: AVX-512F and DQ were detected on this processor just above.
    let lanes = unsafe { test_block(&words, margin) };
    let live = if count == LANES {
        u8::MAX
    } else {
        (1u8 << count) - 1
    };
    let done = live & !lanes.unchecked;
    let fx = Fx::from_bits;
    for (l, slot) in out.iter_mut().enumerate().take(count) {
        if done & (1 << l) == 0 {
            continue;
        }
        *slot = if lanes.separated & (1 << l) != 0 {
            None
        } else {
            let code = lanes.choice[l];
            let choice = match code {
                0..3 => Choice::Face {
                    of_b: false,
                    axis: code as usize,
                },
                3..6 => Choice::Face {
                    of_b: true,
                    axis: code as usize - 3,
                },
                _ => Choice::Edge {
                    i: (code as usize - 6) / 3,
                    j: (code as usize - 6) % 3,
                },
            };
            let mut axes = Axes {
                c: [[Fx::ZERO; 3]; 3],
                t: [Fx::ZERO; 3],
                tb: [Fx::ZERO; 3],
                choice,
            };
            for i in 0..3 {
                for j in 0..3 {
                    axes.c[i][j] = fx(lanes.c[i][j][l]);
                }
                axes.t[i] = fx(lanes.t[i][l]);
                axes.tb[i] = fx(lanes.tb[i][l]);
            }
            Some(axes)
        };
    }
    done
}

/// The kernel's results, lane by lane.
struct Block {
    c: [[[i64; LANES]; 3]; 3],
    t: [[i64; LANES]; 3],
    tb: [[i64; LANES]; 3],
    /// 0–2 A's face axis, 3–5 B's face axis + 3, 6 + 3i + j the edge axis a_i × b_j.
    choice: [i64; LANES],
    /// The lanes that some axis separates.
    separated: u8,
    /// The lanes that failed a check (see the module documentation).
    unchecked: u8,
}

#[inline]
#[target_feature(enable = "avx512f,avx512dq")]
fn load(words: &[i64; LANES]) -> __m512i {
    // SAFETY: eight `i64`: 64 readable bytes.
    unsafe { _mm512_loadu_si512(words.as_ptr().cast()) }
}

#[inline]
#[target_feature(enable = "avx512f,avx512dq")]
fn store(words: &mut [i64; LANES], value: __m512i) {
    // SAFETY: eight `i64`: 64 writable bytes.
    unsafe { _mm512_storeu_si512(words.as_mut_ptr().cast(), value) }
}

/// The scalar [`Vec3::dot`](crate::math::Vec3::dot): x₀y₀ + x₁y₁ + x₂y₂, each product
/// rounded.
#[inline]
#[target_feature(enable = "avx512f,avx512dq")]
fn dot(x: [__m512i; 3], y: [__m512i; 3]) -> __m512i {
    add(add(mul(x[0], y[0]), mul(x[1], y[1])), mul(x[2], y[2]))
}

/// The lanes where `greater` holds between two signed quantities p and q known through
/// their signs (`p_nonneg`, `q_nonneg`) and, when the signs agree, a comparison of
/// magnitudes that is reversed for two negatives: true when p ≥ 0 > q, false when
/// p < 0 ≤ q, `larger` (p² against q², scaled) when both are ≥ 0, `smaller` when both < 0.
#[inline]
fn by_signs(p_nonneg: __mmask8, q_nonneg: __mmask8, larger: __mmask8, smaller: __mmask8) -> u8 {
    (p_nonneg & !q_nonneg) | (p_nonneg & q_nonneg & larger) | (!p_nonneg & !q_nonneg & smaller)
}

/// The kernel (see the module documentation).
///
/// # Safety
/// The processor must have AVX-512F and AVX-512DQ.
#[target_feature(enable = "avx512f,avx512dq")]
unsafe fn test_block(words: &[[i64; LANES]; WORDS], margin: Fx) -> Block {
    let w = |k: usize| load(&words[k]);
    let vector = |k: usize| [w(k), w(k + 1), w(k + 2)];
    let a = [vector(A_AXES), vector(A_AXES + 3), vector(A_AXES + 6)];
    let b = [vector(B_AXES), vector(B_AXES + 3), vector(B_AXES + 6)];
    let (ca, cb) = (vector(A_CENTRE), vector(B_CENTRE));
    let (ha, hb) = (vector(A_HALF), vector(B_HALF));
    let margin = splat(margin);
    let zero = _mm512_setzero_si512();
    let mut unchecked = out_of_bound(margin);
    for v in [a[0], a[1], a[2], b[0], b[1], b[2], ca, cb, ha, hb] {
        unchecked |= out_of_bound3(v);
    }
    let d = [sub(cb[0], ca[0]), sub(cb[1], ca[1]), sub(cb[2], ca[2])];
    unchecked |= out_of_bound3(d);
    let t = [dot(a[0], d), dot(a[1], d), dot(a[2], d)];
    unchecked |= out_of_bound3(t);
    let mut c = [[zero; 3]; 3];
    let mut abs = [[zero; 3]; 3];
    for i in 0..3 {
        for j in 0..3 {
            c[i][j] = dot(a[i], b[j]);
            abs[i][j] = _mm512_abs_epi64(c[i][j]);
        }
        unchecked |= out_of_bound3(c[i]);
    }

    // Face axes: the first deepest of A's, then of B's (strictly deeper replaces).
    let mut separated: u8 = 0;
    let mut face_a = (_mm512_set1_epi64(i64::MIN), zero);
    let mut face_b = (_mm512_set1_epi64(i64::MIN), zero);
    let mut tb = [zero; 3];
    for i in 0..3 {
        let reach = add(
            add(add(ha[i], mul(hb[0], abs[i][0])), mul(hb[1], abs[i][1])),
            mul(hb[2], abs[i][2]),
        );
        let separation = sub(_mm512_abs_epi64(t[i]), reach);
        separated |= _mm512_cmpgt_epi64_mask(separation, margin);
        let deeper = _mm512_cmpgt_epi64_mask(separation, face_a.0);
        face_a = (
            select(deeper, separation, face_a.0),
            select(deeper, _mm512_set1_epi64(i as i64), face_a.1),
        );
    }
    for j in 0..3 {
        tb[j] = add(
            add(mul(t[0], c[0][j]), mul(t[1], c[1][j])),
            mul(t[2], c[2][j]),
        );
        let reach = add(
            add(add(hb[j], mul(ha[0], abs[0][j])), mul(ha[1], abs[1][j])),
            mul(ha[2], abs[2][j]),
        );
        let separation = sub(_mm512_abs_epi64(tb[j]), reach);
        separated |= _mm512_cmpgt_epi64_mask(separation, margin);
        let deeper = _mm512_cmpgt_epi64_mask(separation, face_b.0);
        face_b = (
            select(deeper, separation, face_b.0),
            select(deeper, _mm512_set1_epi64(3 + j as i64), face_b.1),
        );
    }
    let bias_b = splat(Fx::from_ratio(1, 1 << 11));
    let of_b = _mm512_cmpgt_epi64_mask(face_b.0, add(face_a.0, bias_b));
    let face_separation = select(of_b, face_b.0, face_a.0);
    let mut choice = select(of_b, face_b.1, face_a.1);
    unchecked |= out_of_bound(face_separation);

    // Edge axes, in the scalar's order, the first best kept.
    let threshold = add(
        add(face_separation, splat(Fx::from_ratio(1, 1 << 10))),
        mul(
            _mm512_abs_epi64(face_separation),
            splat(Fx::from_ratio(1, 16)),
        ),
    );
    unchecked |= out_of_bound(threshold);
    let threshold_squared = mul(threshold, threshold);
    let margin_squared = mul(margin, margin);
    unchecked |= out_of_bound(threshold_squared) | out_of_bound(margin_squared);
    let threshold_nonneg = _mm512_cmpge_epi64_mask(threshold, zero);
    let parallel = splat(parallel_sine_squared::<Fx>());
    let mut square = [[zero; 3]; 3];
    for i in 0..3 {
        for j in 0..3 {
            square[i][j] = mul(c[i][j], c[i][j]);
        }
    }
    let mut edge_found: u8 = 0;
    // s, s² and |L|² of the best edge axis so far.
    let (mut best_s, mut best_s2, mut best_l) = (zero, zero, zero);
    for i in 0..3 {
        let (i1, i2) = ((i + 1) % 3, (i + 2) % 3);
        for j in 0..3 {
            let (j1, j2) = ((j + 1) % 3, (j + 2) % 3);
            let length_squared = add(square[i1][j], square[i2][j]);
            let tested = _mm512_cmpgt_epi64_mask(length_squared, parallel);
            let ra = add(mul(ha[i1], abs[i2][j]), mul(ha[i2], abs[i1][j]));
            let rb = add(mul(hb[j1], abs[i][j2]), mul(hb[j2], abs[i][j1]));
            let along = sub(mul(t[i2], c[i1][j]), mul(t[i1], c[i2][j]));
            let s = sub(_mm512_abs_epi64(along), add(ra, rb));
            let s2 = mul(s, s);
            unchecked |=
                tested & (out_of_bound(length_squared) | out_of_bound(s) | out_of_bound(s2));
            let positive = _mm512_cmpgt_epi64_mask(s, zero);
            let nonneg = _mm512_cmpge_epi64_mask(s, zero);
            let margin_reach = mul(margin_squared, length_squared);
            separated |= tested & positive & _mm512_cmpgt_epi64_mask(s2, margin_reach);
            let face_reach = mul(threshold_squared, length_squared);
            let beats_face = by_signs(
                nonneg,
                threshold_nonneg,
                _mm512_cmpgt_epi64_mask(s2, face_reach),
                _mm512_cmplt_epi64_mask(s2, face_reach),
            );
            let (lhs, rhs) = (mul(s2, best_l), mul(best_s2, length_squared));
            let beats_best = by_signs(
                nonneg,
                _mm512_cmpge_epi64_mask(best_s, zero),
                _mm512_cmpgt_epi64_mask(lhs, rhs),
                _mm512_cmplt_epi64_mask(lhs, rhs),
            );
            let take = tested & beats_face & (!edge_found | beats_best);
            edge_found |= take;
            best_s = select(take, s, best_s);
            best_s2 = select(take, s2, best_s2);
            best_l = select(take, length_squared, best_l);
            choice = select(take, _mm512_set1_epi64(6 + 3 * i as i64 + j as i64), choice);
        }
    }

    let mut lanes = Block {
        c: [[[0; LANES]; 3]; 3],
        t: [[0; LANES]; 3],
        tb: [[0; LANES]; 3],
        choice: [0; LANES],
        separated,
        unchecked,
    };
    for (row, values) in lanes.c.iter_mut().zip(c) {
        for (words, value) in row.iter_mut().zip(values) {
            store(words, value);
        }
    }
    for ((t_words, tb_words), (t, tb)) in lanes
        .t
        .iter_mut()
        .zip(&mut lanes.tb)
        .zip(t.into_iter().zip(tb))
    {
        store(t_words, t);
        store(tb_words, tb);
    }
    store(&mut lanes.choice, choice);
    lanes
}
