//! √x of I32F32 values, eight lanes to a vector, with the bits of the scalar `Real::sqrt`:
//! round(√(x·2³²)) on the raw bits x, correctly rounded to nearest (no ties occur), and 0
//! for x ≤ 0.
//!
//! The scalar form (`math::sqrt::sqrt_bits`) approximates and then corrects to the
//! correctly rounded root; here the root is computed digit by digit, which gives the same
//! integer. With n = x·2³² written in base 4, n = Σ dⱼ 4ʲ, the prefixes Nₖ of its digits
//! from the top and qₖ = ⌊√Nₖ⌋, rₖ = Nₖ − qₖ² satisfy
//!
//! ```text
//! N = 4·Nₖ + d,  4·rₖ + d ≥ 4·qₖ + 1  ⇒  qₖ₊₁ = 2qₖ + 1,  rₖ₊₁ = 4rₖ + d − (4qₖ + 1)
//!                otherwise             ⇒  qₖ₊₁ = 2qₖ,      rₖ₊₁ = 4rₖ + d
//! ```
//!
//! since (2q + 1)² = 4q² + 4q + 1. After the last digit q = ⌊√n⌋ and r = n − q², and
//! round(√n) = q + 1 exactly when n > q² + q (the square of q + ½ is q² + q + ¼ and n is
//! an integer), that is when r > q.
//!
//! Ranges: x < 2⁶³, so n < 2⁹⁵, q < 2⁴⁸ and r ≤ 2q < 2⁴⁹; 4r + 3 < 2⁵² fits a lane. The
//! digits of x·2³² are those of x followed by sixteen zero digits; the top digits that
//! are zero in every lane are skipped, as they leave q and r at zero (all of them when
//! every value is zero, as for one-point contacts' twist arms).
//!
//! # Values up to one
//!
//! The digits cost about 32 steps for values near one. When no value exceeds 1 (2³² raw),
//! as for the twist arms and tangent lengths of contacts between boxes up to about a
//! metre across, the roots come instead from Newton's method on integers
//! ([`lanes_below_one`], written once on the lanes of [`Wide`](crate::math::wide::Wide), for its
//! leading-zero counts), with 1 → 1 set apart (that form takes x < 2³²): the same
//! correctly rounded integers, about a fifth of the work.

use crate::math::sqrt::lanes_below_one;
use crate::math::wide::avx512::Avx512;
use core::arch::x86_64::{
    __m512i, _mm_cvtsi64_si128, _mm512_add_epi64, _mm512_cmpeq_epi64_mask, _mm512_cmpge_epu64_mask,
    _mm512_cmpgt_epu64_mask, _mm512_mask_add_epi64, _mm512_mask_mov_epi64, _mm512_mask_sub_epi64,
    _mm512_max_epi64, _mm512_or_si512, _mm512_reduce_max_epi64, _mm512_set1_epi64,
    _mm512_setzero_si512, _mm512_sll_epi64, _mm512_slli_epi64, _mm512_srli_epi64,
};

/// Base-4 digits of the 32 fractional bits that x·2³² appends to x.
const FRACTION_DIGITS: u32 = 16;

/// 1 as raw I32F32 bits.
const ONE: u64 = 1 << 32;

/// √x of each lane of each vector of `values` (raw I32F32 bits), as `Real::sqrt` rounds
/// it (module documentation). The vectors go through the digits side by side, as many as
/// the largest value needs.
#[inline]
#[target_feature(enable = "avx512f,avx512dq")]
pub(crate) fn sqrt<const N: usize>(values: [__m512i; N]) -> [__m512i; N] {
    let zero = _mm512_setzero_si512();
    let one = _mm512_set1_epi64(1);
    let values = values.map(|x| _mm512_max_epi64(x, zero));
    let largest = values.iter().fold(zero, |m, &x| _mm512_max_epi64(m, x));
    let largest = _mm512_reduce_max_epi64(largest) as u64;
    // Every value 0 (or negative): every root is 0.
    if largest == 0 {
        return [zero; N];
    }
    if largest <= ONE
        && let Some(wide) = Avx512::detect()
    {
        // SAFETY: a value of the backend exists only where the processor has AVX-512F, CD
        // and DQ.
        return unsafe { up_to_one(wide, values) };
    }
    // Base-4 digits of the largest x, and x shifted so that its top digit is bits 63–62.
    let digits = (u64::BITS - largest.leading_zeros()).div_ceil(2);
    let shift = _mm_cvtsi64_si128(i64::from(64 - 2 * digits));
    let mut rest = values.map(|x| _mm512_sll_epi64(x, shift));
    let mut root = [zero; N];
    let mut remainder = [zero; N];
    for _ in 0..digits {
        for i in 0..N {
            let digit = _mm512_srli_epi64::<62>(rest[i]);
            rest[i] = _mm512_slli_epi64::<2>(rest[i]);
            let r = _mm512_or_si512(_mm512_slli_epi64::<2>(remainder[i]), digit);
            (root[i], remainder[i]) = next_digit(root[i], r);
        }
    }
    for _ in 0..FRACTION_DIGITS {
        for i in 0..N {
            let r = _mm512_slli_epi64::<2>(remainder[i]);
            (root[i], remainder[i]) = next_digit(root[i], r);
        }
    }
    core::array::from_fn(|i| {
        let up = _mm512_cmpgt_epu64_mask(remainder[i], root[i]);
        _mm512_mask_add_epi64(root[i], up, root[i], one)
    })
}

/// √x of values in [0, 1] (raw bits up to 2³²): [`lanes_below_one`] below 1, and 1 for 1,
/// whose root is itself.
///
/// # Safety
/// The processor must have AVX-512F, CD and DQ (as `wide` proves).
#[target_feature(enable = "avx512f,avx512cd,avx512dq")]
unsafe fn up_to_one<const N: usize>(wide: Avx512, values: [__m512i; N]) -> [__m512i; N] {
    let one = _mm512_set1_epi64(ONE as i64);
    let roots = lanes_below_one::sqrt(wide, values);
    core::array::from_fn(|i| {
        let at_one = _mm512_cmpeq_epi64_mask(values[i], one);
        _mm512_mask_mov_epi64(roots[i], at_one, one)
    })
}

/// One digit of the root: (qₖ₊₁, rₖ₊₁) from qₖ and 4rₖ + d (module documentation).
#[inline]
#[target_feature(enable = "avx512f,avx512dq")]
fn next_digit(root: __m512i, r: __m512i) -> (__m512i, __m512i) {
    let one = _mm512_set1_epi64(1);
    let trial = _mm512_or_si512(_mm512_slli_epi64::<2>(root), one);
    let fits = _mm512_cmpge_epu64_mask(r, trial);
    let doubled = _mm512_add_epi64(root, root);
    (
        _mm512_mask_add_epi64(doubled, fits, doubled, one),
        _mm512_mask_sub_epi64(r, fits, r, trial),
    )
}

#[cfg(test)]
mod tests {
    use super::sqrt;
    use crate::math::{Fx, Pcg32, Real};
    use crate::rigid::solver::avx512::has_kernels;
    use core::arch::x86_64::{__m512i, _mm512_loadu_si512, _mm512_storeu_si512};

    /// The kernel's results for `values`, in vectors of eight, two vectors at a time.
    fn kernel(values: &[i64; 16]) -> [i64; 16] {
        let mut out = [0i64; 16];
        // SAFETY: the test runs only where `has_kernels` holds (checked by the caller);
        // 64 readable and writable bytes at each pointer.
        unsafe {
            let load = |p: *const i64| _mm512_loadu_si512(p.cast());
            let roots: [__m512i; 2] = sqrt([load(values.as_ptr()), load(values[8..].as_ptr())]);
            _mm512_storeu_si512(out.as_mut_ptr().cast(), roots[0]);
            _mm512_storeu_si512(out[8..].as_mut_ptr().cast(), roots[1]);
        }
        out
    }

    /// Compares the kernel with `Real::sqrt` on every value; returns the mismatches.
    fn mismatches(values: &[i64]) -> usize {
        let mut bad = 0;
        for chunk in values.chunks(16) {
            let mut batch = [0i64; 16];
            batch[..chunk.len()].copy_from_slice(chunk);
            let roots = kernel(&batch);
            for (x, root) in batch.iter().zip(roots) {
                if Fx::from_bits(*x).sqrt().to_bits() != root {
                    bad += 1;
                }
            }
        }
        bad
    }

    /// Zeros and negative values, edge values, exact squares and their neighbours, rounding midpoints and their
    /// neighbours, and random bits of every magnitude (one magnitude per batch, and
    /// magnitudes mixed), against the scalar form.
    fn inputs() -> Vec<i64> {
        // First a batch of zeros and negative values only.
        let mut values = vec![0, -1, i64::MIN, 0, -(1 << 40), 0, 0, -2];
        values.extend([0; 8]);
        values.extend([
            i64::MIN,
            i64::MIN + 1,
            -1,
            0,
            1,
            2,
            3,
            4,
            i64::MAX,
            i64::MAX - 1,
        ]);
        for bits in 0..63 {
            let p = 1i64 << bits;
            values.extend([p - 1, p, p + 1]);
        }
        // x·2³² = q² ± {0, 1} and (q + ½)² ± ¼ → x near q²/2³² and (q² + q)/2³².
        let mut rng = Pcg32::new(0x5eed, 3);
        for _ in 0..4000 {
            let q = u128::from(rng.next_u64() >> (17 + rng.below(47)));
            for target in [q * q, q * q + q] {
                let x = (target >> 32) as i64;
                values.extend([x - 1, x, x + 1]);
            }
        }
        for _ in 0..10_000 {
            let magnitude = rng.below(64);
            let batch: Vec<i64> = (0..16)
                .map(|_| (rng.next_u64() >> magnitude) as i64)
                .collect();
            values.extend(batch);
            values.push((rng.next_u64() >> rng.below(64)) as i64);
        }
        values
    }

    /// Batches of sixteen values up to 1 (2³² raw), which take the Newton form: 1 itself
    /// in every lane position, the values just below it, zeros and negative values, the
    /// values around the squares and rounding midpoints of random roots, and random bits.
    fn inputs_up_to_one() -> Vec<i64> {
        const ONE: i64 = 1 << 32;
        let mut values = Vec::new();
        for lane in 0..16 {
            let mut batch = [ONE - 1; 16];
            batch[lane] = ONE;
            batch[(lane + 5) % 16] = 0;
            batch[(lane + 9) % 16] = -ONE;
            values.extend(batch);
        }
        values.extend([ONE; 16]);
        let mut rng = Pcg32::new(0x0ae, 7);
        for _ in 0..4000 {
            let q = u128::from(rng.next_u32());
            for target in [q * q, q * q + q] {
                let x = (target >> 32) as i64;
                values.extend([x - 1, x, x + 1]);
            }
        }
        for _ in 0..4000 {
            values.push(i64::from(rng.next_u32()) >> rng.below(32));
            if rng.below(8) == 0 {
                values.push(ONE);
            }
        }
        values.resize(values.len().next_multiple_of(16), ONE);
        values
    }

    #[test]
    fn values_up_to_one_take_newton_and_match_the_scalar_form() {
        if !has_kernels() || !crate::math::cpu::avx512cd() {
            return;
        }
        let values = inputs_up_to_one();
        assert!(values.len() > 25_000);
        assert!(
            values
                .chunks(16)
                .all(|batch| batch.iter().all(|&x| x <= 1 << 32))
        );
        assert_eq!(mismatches(&values), 0);
    }

    #[test]
    fn sqrt_matches_the_scalar_form() {
        if !has_kernels() {
            return;
        }
        let values = inputs();
        assert!(values.len() > 150_000);
        assert_eq!(mismatches(&values), 0);
    }
}
