//! The separating-axis test of eight I32F32 box pairs at once, one `i64` lane per pair,
//! with the bits of [`separating_axes`]: the same sums of products,
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
//! same first best axes, by masked updates in the scalar's order. Written once against
//! [`Wide`], it runs with the AVX-512 or the AVX2 backend, whichever the processor has
//! ([`backend`]).
//!
//! # Exactness
//!
//! Every value that enters a product (the inputs, d, t, C, the chosen face's separation,
//! the threshold and its square, the margin's square, |L|², s_ij and s_ij²) is checked to
//! lie in [−2⁴⁶, 2⁴⁶) as raw bits, and every sum has at most four terms, each such a value
//! or a product below 2⁶⁰: no operation of the scalar form saturates, and the kernel's
//! wrapping arithmetic gives its exact results ([`Wide::mul`]). A lane that fails a check is not
//! written and is left to the caller, even where the scalar test would have stopped
//! before the value that failed.

#[cfg(doc)]
use super::separating_axes;
use super::{Axes, BoxPair, Choice, LANES};
use crate::math::over_real::{OverReal, Scalar};
use crate::math::wide::{Wide, backend, kernel_entry};
use crate::math::{Fx, Real};
use crate::rigid::narrowphase::tolerance::parallel_sine_squared;

/// Input words per lane: A's axes (9), B's axes (9), A's and B's centres (3 + 3), A's and
/// B's half extents (3 + 3).
const WORDS: usize = 30;
const A_AXES: usize = 0;
const B_AXES: usize = 9;
const A_CENTRE: usize = 18;
const B_CENTRE: usize = 21;
const A_HALF: usize = 24;
const B_HALF: usize = 27;

/// The family of lists of box pairs, `[BoxPair<'a, R>]`, for [`Real::as_fixed`].
struct BoxPairsOf<'a>(core::marker::PhantomData<&'a ()>);

impl<'a> OverReal for BoxPairsOf<'a> {
    type Of<R: Real> = [BoxPair<'a, R>];
}

/// The family of the lanes' results, `[Option<Axes<R>>; LANES]`, for [`Real::as_fixed`].
struct AxesLanesOf;

impl OverReal for AxesLanesOf {
    type Of<R: Real> = [Option<Axes<R>>; LANES];
}

/// Tests the pairs `pairs` (at most [`LANES`]) with the kernel when `R` is I32F32 and the
/// processor has AVX-512 (F and DQ) or AVX2, writing lane l's result to `out[l]`. Returns
/// the lanes it is done with; the caller tests the others.
pub(super) fn separating_axes_lanes<R: Real>(
    pairs: &[BoxPair<'_, R>],
    margin: R,
    out: &mut [Option<Axes<R>>; LANES],
) -> u8 {
    let Some(backend) = backend() else {
        return 0;
    };
    let (Some(&margin), Some(pairs), Some(out)) = (
        R::as_fixed::<Scalar>(&margin),
        R::as_fixed::<BoxPairsOf>(pairs),
        R::as_fixed_mut::<AxesLanesOf>(out),
    ) else {
        return 0;
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
    let lanes = test_on(backend, &words, margin);
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

kernel_entry! {
    /// [`test_block`] with the instructions of `backend`.
    fn test_on(words: &[[i64; LANES]; WORDS], margin: Fx) -> Block = test_block;
}

/// The lanes where `greater` holds between two signed quantities p and q known through
/// their signs (`p_nonneg`, `q_nonneg`) and, when the signs agree, a comparison of
/// magnitudes that is reversed for two negatives: true when p ≥ 0 > q, false when
/// p < 0 ≤ q, `larger` (p² against q², scaled) when both are ≥ 0, `smaller` when both < 0.
#[inline(always)]
fn by_signs(p_nonneg: u8, q_nonneg: u8, larger: u8, smaller: u8) -> u8 {
    (p_nonneg & !q_nonneg) | (p_nonneg & q_nonneg & larger) | (!p_nonneg & !q_nonneg & smaller)
}

/// Three consecutive words of the inputs as lanes.
#[inline(always)]
fn vector<W: Wide>(w: W, words: &[[i64; LANES]; WORDS], k: usize) -> [W::V; 3] {
    [
        w.load_words(words[k]),
        w.load_words(words[k + 1]),
        w.load_words(words[k + 2]),
    ]
}

/// The lanes where a ≥ b, signed.
#[inline(always)]
fn at_least<W: Wide>(w: W, a: W::V, b: W::V) -> u8 {
    !w.greater(b, a)
}

/// The kernel (see the module documentation).
#[inline(always)]
fn test_block<W: Wide>(w: W, words: &[[i64; LANES]; WORDS], margin: Fx) -> Block {
    let a = [
        vector(w, words, A_AXES),
        vector(w, words, A_AXES + 3),
        vector(w, words, A_AXES + 6),
    ];
    let b = [
        vector(w, words, B_AXES),
        vector(w, words, B_AXES + 3),
        vector(w, words, B_AXES + 6),
    ];
    let (ca, cb) = (vector(w, words, A_CENTRE), vector(w, words, B_CENTRE));
    let (ha, hb) = (vector(w, words, A_HALF), vector(w, words, B_HALF));
    let margin = w.splat(margin.to_bits());
    let zero = w.zero();
    let mut unchecked = w.out_of_bound(margin);
    for v in [a[0], a[1], a[2], b[0], b[1], b[2], ca, cb, ha, hb] {
        unchecked |= w.out_of_bound3(v);
    }
    let d = w.sub3(cb, ca);
    unchecked |= w.out_of_bound3(d);
    let t = [
        w.rounded_dot(a[0], d),
        w.rounded_dot(a[1], d),
        w.rounded_dot(a[2], d),
    ];
    unchecked |= w.out_of_bound3(t);
    let mut c = [[zero; 3]; 3];
    let mut abs = [[zero; 3]; 3];
    for i in 0..3 {
        for j in 0..3 {
            c[i][j] = w.rounded_dot(a[i], b[j]);
            abs[i][j] = w.abs(c[i][j]);
        }
        unchecked |= w.out_of_bound3(c[i]);
    }

    // Face axes: the first deepest of A's, then of B's (strictly deeper replaces).
    let mut separated: u8 = 0;
    let lowest = w.splat(i64::MIN);
    let (mut deepest_a, mut axis_a) = (lowest, zero);
    let (mut deepest_b, mut axis_b) = (lowest, zero);
    let mut tb = [zero; 3];
    for i in 0..3 {
        let reach = w.add(
            w.add(
                w.add(ha[i], w.mul(hb[0], abs[i][0])),
                w.mul(hb[1], abs[i][1]),
            ),
            w.mul(hb[2], abs[i][2]),
        );
        let separation = w.sub(w.abs(t[i]), reach);
        separated |= w.greater(separation, margin);
        let deeper = w.greater(separation, deepest_a);
        deepest_a = w.select(deeper, separation, deepest_a);
        axis_a = w.select(deeper, w.splat(i as i64), axis_a);
    }
    for j in 0..3 {
        tb[j] = w.add(
            w.add(w.mul(t[0], c[0][j]), w.mul(t[1], c[1][j])),
            w.mul(t[2], c[2][j]),
        );
        let reach = w.add(
            w.add(
                w.add(hb[j], w.mul(ha[0], abs[0][j])),
                w.mul(ha[1], abs[1][j]),
            ),
            w.mul(ha[2], abs[2][j]),
        );
        let separation = w.sub(w.abs(tb[j]), reach);
        separated |= w.greater(separation, margin);
        let deeper = w.greater(separation, deepest_b);
        deepest_b = w.select(deeper, separation, deepest_b);
        axis_b = w.select(deeper, w.splat(3 + j as i64), axis_b);
    }
    let bias_b = w.splat(Fx::from_ratio(1, 1 << 11).to_bits());
    let of_b = w.greater(deepest_b, w.add(deepest_a, bias_b));
    let face_separation = w.select(of_b, deepest_b, deepest_a);
    let mut choice = w.select(of_b, axis_b, axis_a);
    unchecked |= w.out_of_bound(face_separation);

    // Edge axes, in the scalar's order, the first best kept.
    let threshold = w.add(
        w.add(
            face_separation,
            w.splat(Fx::from_ratio(1, 1 << 10).to_bits()),
        ),
        w.mul(
            w.abs(face_separation),
            w.splat(Fx::from_ratio(1, 16).to_bits()),
        ),
    );
    unchecked |= w.out_of_bound(threshold);
    let threshold_squared = w.mul(threshold, threshold);
    let margin_squared = w.mul(margin, margin);
    unchecked |= w.out_of_bound(threshold_squared) | w.out_of_bound(margin_squared);
    let threshold_nonneg = at_least(w, threshold, zero);
    let parallel = w.splat(parallel_sine_squared::<Fx>().to_bits());
    let mut square = [[zero; 3]; 3];
    for i in 0..3 {
        for j in 0..3 {
            square[i][j] = w.mul(c[i][j], c[i][j]);
        }
    }
    let mut edge_found: u8 = 0;
    // s, s² and |L|² of the best edge axis so far.
    let (mut best_s, mut best_s2, mut best_l) = (zero, zero, zero);
    for i in 0..3 {
        let (i1, i2) = ((i + 1) % 3, (i + 2) % 3);
        for j in 0..3 {
            let (j1, j2) = ((j + 1) % 3, (j + 2) % 3);
            let length_squared = w.add(square[i1][j], square[i2][j]);
            let tested = w.greater(length_squared, parallel);
            let ra = w.add(w.mul(ha[i1], abs[i2][j]), w.mul(ha[i2], abs[i1][j]));
            let rb = w.add(w.mul(hb[j1], abs[i][j2]), w.mul(hb[j2], abs[i][j1]));
            let along = w.sub(w.mul(t[i2], c[i1][j]), w.mul(t[i1], c[i2][j]));
            let s = w.sub(w.abs(along), w.add(ra, rb));
            let s2 = w.mul(s, s);
            unchecked |=
                tested & (w.out_of_bound(length_squared) | w.out_of_bound(s) | w.out_of_bound(s2));
            let positive = w.greater(s, zero);
            let nonneg = at_least(w, s, zero);
            let margin_reach = w.mul(margin_squared, length_squared);
            separated |= tested & positive & w.greater(s2, margin_reach);
            let face_reach = w.mul(threshold_squared, length_squared);
            let beats_face = by_signs(
                nonneg,
                threshold_nonneg,
                w.greater(s2, face_reach),
                w.greater(face_reach, s2),
            );
            let (lhs, rhs) = (w.mul(s2, best_l), w.mul(best_s2, length_squared));
            let beats_best = by_signs(
                nonneg,
                at_least(w, best_s, zero),
                w.greater(lhs, rhs),
                w.greater(rhs, lhs),
            );
            let take = tested & beats_face & (!edge_found | beats_best);
            edge_found |= take;
            best_s = w.select(take, s, best_s);
            best_s2 = w.select(take, s2, best_s2);
            best_l = w.select(take, length_squared, best_l);
            choice = w.select(take, w.splat(6 + 3 * i as i64 + j as i64), choice);
        }
    }

    let mut lanes = Block {
        c: [[[0; LANES]; 3]; 3],
        t: [[0; LANES]; 3],
        tb: [[0; LANES]; 3],
        choice: w.store_words(choice),
        separated,
        unchecked,
    };
    for (row, values) in lanes.c.iter_mut().zip(c) {
        for (words, value) in row.iter_mut().zip(values) {
            *words = w.store_words(value);
        }
    }
    for i in 0..3 {
        lanes.t[i] = w.store_words(t[i]);
        lanes.tb[i] = w.store_words(tb[i]);
    }
    lanes
}
