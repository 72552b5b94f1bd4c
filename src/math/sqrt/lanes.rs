//! √x per lane for any I32F32 x, on the lanes of [`Wide`] (every backend), with the bits
//! of the scalar [`Real::sqrt`](crate::math::Real::sqrt): round(√(x·2³²)) on the raw bits
//! x, correctly rounded to nearest (no ties occur), and 0 for x ≤ 0. The rigid solver's
//! tangent lengths and twist arms take their roots here.
//!
//! The scalar form ([`sqrt_bits`](super::sqrt_bits)) approximates and then corrects to the
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
//! ([`lanes_below_one`]), with 1 → 1 set apart (that form takes x < 2³²): the same
//! correctly rounded integers, about a fifth of the work.

use super::lanes_below_one;
use crate::math::wide::Wide;

/// Base-4 digits of the 32 fractional bits that x·2³² appends to x.
const FRACTION_DIGITS: u32 = 16;

/// 1 as raw I32F32 bits.
const ONE: i64 = 1 << 32;

/// √x of each lane of each vector of `values` (raw I32F32 bits), as `Real::sqrt` rounds
/// it (module documentation). The vectors go through the digits side by side, as many as
/// the largest value needs.
#[inline(always)]
pub(crate) fn sqrt<W: Wide, const N: usize>(w: W, values: [W::V; N]) -> [W::V; N] {
    let zero = w.zero();
    let mut x = [zero; N];
    let mut largest = zero;
    for i in 0..N {
        x[i] = w.max(values[i], zero);
        largest = w.max(largest, x[i]);
    }
    let largest = w.store_words(largest).into_iter().max().unwrap_or(0);
    // Every value 0 (or negative): every root is 0.
    if largest == 0 {
        return [zero; N];
    }
    if largest <= ONE {
        return up_to_one(w, x);
    }
    // Base-4 digits of the largest x, and x shifted so that its top digit is bits 63–62.
    let digits = (u64::BITS - largest.leading_zeros()).div_ceil(2);
    let mut rest = [zero; N];
    for i in 0..N {
        rest[i] = w.shift_left(x[i], 64 - 2 * digits);
    }
    let mut root = [zero; N];
    let mut remainder = [zero; N];
    for _ in 0..digits {
        for i in 0..N {
            let digit = w.shift_right_unsigned(rest[i], 62);
            rest[i] = w.shift_left(rest[i], 2);
            let r = w.or(w.shift_left(remainder[i], 2), digit);
            (root[i], remainder[i]) = next_digit(w, root[i], r);
        }
    }
    for _ in 0..FRACTION_DIGITS {
        for i in 0..N {
            let r = w.shift_left(remainder[i], 2);
            (root[i], remainder[i]) = next_digit(w, root[i], r);
        }
    }
    for i in 0..N {
        let up = w.greater_unsigned(remainder[i], root[i]);
        root[i] = w.select(up, w.add(root[i], w.splat(1)), root[i]);
    }
    root
}

/// √x of values in [0, 1] (raw bits up to 2³²): [`lanes_below_one`] below 1, and 1 for 1,
/// whose root is itself.
#[inline(always)]
fn up_to_one<W: Wide, const N: usize>(w: W, x: [W::V; N]) -> [W::V; N] {
    let one = w.splat(ONE);
    let mut roots = lanes_below_one::sqrt(w, x);
    for i in 0..N {
        roots[i] = w.select(w.equal(x[i], one), one, roots[i]);
    }
    roots
}

/// One digit of the root: (qₖ₊₁, rₖ₊₁) from qₖ and 4rₖ + d (module documentation).
#[inline(always)]
fn next_digit<W: Wide>(w: W, root: W::V, r: W::V) -> (W::V, W::V) {
    let one = w.splat(1);
    let trial = w.or(w.shift_left(root, 2), one);
    let fits = w.at_least_unsigned(r, trial);
    let doubled = w.add(root, root);
    (
        w.select(fits, w.add(doubled, one), doubled),
        w.select(fits, w.sub(r, trial), r),
    )
}

#[cfg(test)]
mod tests {
    use super::sqrt;
    use crate::math::wide::{Backend, Wide, backends, kernel_entry};
    use crate::math::{Fx, Pcg32, Real};

    kernel_entry! {
        /// Two vectors of roots with the instructions of `backend`.
        fn roots_on(values: &[i64; 16]) -> [i64; 16] = roots;
    }

    #[inline(always)]
    fn roots<W: Wide>(w: W, values: &[i64; 16]) -> [i64; 16] {
        let mut low = [0; 8];
        let mut high = [0; 8];
        low.copy_from_slice(&values[..8]);
        high.copy_from_slice(&values[8..]);
        let roots = sqrt(w, [w.load_words(low), w.load_words(high)]);
        let mut out = [0; 16];
        out[..8].copy_from_slice(&w.store_words(roots[0]));
        out[8..].copy_from_slice(&w.store_words(roots[1]));
        out
    }

    /// Compares the kernel of `backend` with `Real::sqrt` on every value, sixteen at a
    /// time; returns the mismatches.
    fn mismatches(backend: Backend, values: &[i64]) -> usize {
        let mut bad = 0;
        for chunk in values.chunks(16) {
            let mut batch = [0i64; 16];
            batch[..chunk.len()].copy_from_slice(chunk);
            let roots = roots_on(backend, &batch);
            for (x, root) in batch.iter().zip(roots) {
                if Fx::from_bits(*x).sqrt().to_bits() != root {
                    bad += 1;
                }
            }
        }
        bad
    }

    /// Zeros and negative values, edge values, exact squares and their neighbours,
    /// rounding midpoints and their neighbours, and random bits of every magnitude (one
    /// magnitude per batch, and magnitudes mixed).
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
        let values = inputs_up_to_one();
        assert!(values.len() > 25_000);
        assert!(
            values
                .chunks(16)
                .all(|batch| batch.iter().all(|&x| x <= 1 << 32))
        );
        for backend in backends() {
            assert_eq!(mismatches(backend, &values), 0, "{backend:?}");
        }
    }

    #[test]
    fn sqrt_matches_the_scalar_form() {
        let values = inputs();
        assert!(values.len() > 150_000);
        for backend in backends() {
            assert_eq!(mismatches(backend, &values), 0, "{backend:?}");
        }
    }
}
