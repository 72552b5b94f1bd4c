//! `Pcg32`: the engine's seeded, deterministic random number generator.
//!
//! # Algorithm
//!
//! PCG-XSH-RR 64/32 (M. E. O'Neill, "PCG: A Family of Simple Fast Space-Efficient
//! Statistically Good Algorithms for Random Number Generation", 2014; reference code
//! `pcg_basic.c` of <https://github.com/imneme/pcg-c-basic>, `pcg32` of
//! <https://github.com/imneme/pcg-c>). The state is a 64-bit LCG
//! `state ← state · 6364136223846793005 + increment (mod 2⁶⁴)` with an odd increment that
//! selects one of 2⁶³ streams; each step outputs the old state permuted by an xorshift and a
//! data-dependent rotation (XSH-RR). The period is 2⁶⁴ on every stream.
//!
//! Everything here is integer arithmetic on `u64`/`u32`, so the sequence is the same on every
//! target. [`Pcg32::new`], [`Pcg32::next_u32`], [`Pcg32::below`] and [`Pcg32::advance`] are
//! bit-identical to the reference `pcg32_srandom_r`, `pcg32_random_r`, `pcg32_boundedrand_r`
//! and `pcg32_advance_r`: seed 42, stream 54 reproduces the reference `check-pcg32` output.
//!
//! # Snapshots
//!
//! The generator is its two `u64` words, `state` and `increment`, serialized in that order
//! (bincode with fixed-int encoding writes them as 16 little-endian bytes). Restoring a
//! snapshot continues the sequence exactly. The type is deliberately not `Copy`, so that a
//! stream cannot be duplicated by accident; `clone` it to fork one on purpose.

use core::cmp::Ordering;

use serde::{Deserialize, Serialize};

use super::real::Real;
use super::state_hash::StateHasher;
use super::vec3::Vec3;

/// The LCG multiplier of the 64-bit PCG generators (`PCG_DEFAULT_MULTIPLIER_64`).
const MULTIPLIER: u64 = 6_364_136_223_846_793_005;

/// A PCG32 generator (PCG-XSH-RR 64/32). See the module documentation.
#[derive(Clone, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub struct Pcg32 {
    /// The LCG state.
    state: u64,
    /// The LCG increment: `2 · stream + 1`, always odd.
    increment: u64,
}

impl Pcg32 {
    /// A generator seeded as the reference `pcg32_srandom_r(seed, stream)`: the increment is
    /// `(stream << 1) | 1`, the state starts at 0, steps once, adds `seed` and steps again.
    ///
    /// Generators with different streams never share their sequences, whatever the seeds;
    /// the top bit of `stream` is unused.
    pub const fn new(seed: u64, stream: u64) -> Self {
        let mut rng = Self {
            state: 0,
            increment: (stream << 1) | 1,
        };
        rng.step();
        rng.state = rng.state.wrapping_add(seed);
        rng.step();
        rng
    }

    /// One LCG step.
    #[inline(always)]
    const fn step(&mut self) {
        self.state = self
            .state
            .wrapping_mul(MULTIPLIER)
            .wrapping_add(self.increment);
    }

    /// The next 32 uniformly distributed bits (`pcg32_random_r`): the XSH-RR output of the
    /// current state, then one step.
    #[inline]
    pub fn next_u32(&mut self) -> u32 {
        let old = self.state;
        self.step();
        let xorshifted = (((old >> 18) ^ old) >> 27) as u32;
        let rotation = (old >> 59) as u32;
        xorshifted.rotate_right(rotation)
    }

    /// 64 uniformly distributed bits from two draws: the first draw is the low half, the
    /// second the high half (`first | second << 32`).
    #[inline]
    pub fn next_u64(&mut self) -> u64 {
        let low = self.next_u32() as u64;
        let high = self.next_u32() as u64;
        low | (high << 32)
    }

    /// A uniformly distributed integer in `[0, n)`, exactly as the reference
    /// `pcg32_boundedrand_r`: draws below the threshold `2³² mod n` are rejected, and an
    /// accepted draw `r` gives `r mod n`. There is no modulo bias. A draw is accepted with
    /// probability above ½ and above `1 − n/2³²`; `below(1)` takes exactly one draw.
    ///
    /// # Panics
    ///
    /// If `n` is 0.
    #[inline]
    pub fn below(&mut self, n: u32) -> u32 {
        assert!(n != 0, "Pcg32::below: the bound must be positive");
        let threshold = n.wrapping_neg() % n;
        loop {
            let r = self.next_u32();
            if r >= threshold {
                return r % n;
            }
        }
    }

    /// A uniformly distributed value in `[0, 1)`, built exactly from integer bits.
    ///
    /// With `p` the precision of `R` just below 1 (`F` for fixed point, 53 for `f64`), it is
    /// `k / 2^p` where `k` is the top `p` bits of one [`next_u32`](Self::next_u32) when
    /// `p ≤ 32`, otherwise of one [`next_u64`](Self::next_u64). Every multiple of `2^−p` in
    /// `[0, 1)` is equally likely and the conversion through [`Real::from_ratio`] is exact, so
    /// no rounding and no floating point is involved for the fixed-point formats:
    ///
    /// | format | `p` | draws | result |
    /// |---|---|---|---|
    /// | I32F32 ([`Fx`](super::Fx)) | 32 | 1 × `next_u32` | raw bits = the draw |
    /// | I40F24 | 24 | 1 × `next_u32` | raw bits = draw >> 8 |
    /// | I48F16 | 16 | 1 × `next_u32` | raw bits = draw >> 16 |
    /// | `f64` | 53 | 1 × `next_u64` | (draw >> 11) · 2⁻⁵³ |
    #[inline]
    pub fn unit<R: Real>(&mut self) -> R {
        let p = unit_bits::<R>();
        let k = if p <= 32 {
            (self.next_u32() >> (32 - p)) as i64
        } else {
            (self.next_u64() >> (64 - p)) as i64
        };
        R::from_ratio(k, 1i64 << p)
    }

    /// A value in `[lo, hi)`: `lo + (hi − lo) · u` with `u` from [`unit`](Self::unit), in the
    /// format's own arithmetic, drawing again whenever rounding gives `hi` itself.
    ///
    /// The result is one of the `2^p` equally likely points `lo + (hi − lo) · k/2^p`, each
    /// rounded to nearest by the format's multiply. For fixed point with `hi − lo < 1`
    /// several `k` give the same value and `lo` itself is half as likely as the other values;
    /// with `hi − lo > 1` not every value of the format can occur.
    ///
    /// If `lo < hi` does not hold, the result is `lo` and nothing is drawn. `hi − lo` must be
    /// representable: for fixed point it saturates otherwise, and for `f64` it must be finite.
    #[inline]
    pub fn range<R: Real>(&mut self, lo: R, hi: R) -> R {
        if lo.partial_cmp(&hi) != Some(Ordering::Less) {
            return lo;
        }
        let width = hi - lo;
        loop {
            let value = lo + width * self.unit::<R>();
            if value < hi {
                return value;
            }
        }
    }

    /// A random direction: a unit vector, uniformly distributed on the sphere up to the
    /// format's resolution. No trigonometry is used.
    ///
    /// Rejection sampling in the cube: draw `x`, `y`, `z` in that order, each `2u − 1` with
    /// `u` from [`unit`](Self::unit) (exact, in `[−1, 1)`), until `1/64 ≤ |v|² ≤ 1`, then
    /// return `v / |v|` ([`Vec3::normalize_or_zero`]). The acceptance region is a spherical
    /// shell, so the direction stays uniform; its inner radius 1/8 keeps short, coarsely
    /// quantised fixed-point vectors out. About 52 % of triples are accepted (≈ 5.7 draws
    /// per vector on average for [`Fx`](super::Fx)).
    pub fn unit_vector<R: Real>(&mut self) -> Vec3<R> {
        let min_length_squared = R::from_ratio(1, 64);
        loop {
            let x = self.signed_unit::<R>();
            let y = self.signed_unit::<R>();
            let z = self.signed_unit::<R>();
            let v = Vec3::new(x, y, z);
            let length_squared = v.length_squared();
            if length_squared <= R::ONE && length_squared >= min_length_squared {
                return v.normalize_or_zero();
            }
        }
    }

    /// `2u − 1` with `u` from [`unit`](Self::unit): exact, in `[−1, 1)`.
    #[inline]
    fn signed_unit<R: Real>(&mut self) -> R {
        R::TWO * self.unit::<R>() - R::ONE
    }

    /// Jumps `delta` steps ahead in O(log delta), as the reference `pcg32_advance_r`
    /// (`pcg_advance_lcg_64`; F. B. Brown, "Random Number Generation with Arbitrary Stride",
    /// Trans. Am. Nucl. Soc., 1994): the LCG map is raised to the power `delta` by repeated
    /// squaring. Steps count draws of [`next_u32`](Self::next_u32). The period is 2⁶⁴, so
    /// `advance(k.wrapping_neg())` goes back `k` steps.
    pub fn advance(&mut self, delta: u64) {
        let mut step_mult = MULTIPLIER;
        let mut step_plus = self.increment;
        let mut acc_mult = 1u64;
        let mut acc_plus = 0u64;
        let mut remaining = delta;
        while remaining > 0 {
            if remaining & 1 == 1 {
                acc_mult = acc_mult.wrapping_mul(step_mult);
                acc_plus = acc_plus.wrapping_mul(step_mult).wrapping_add(step_plus);
            }
            step_plus = step_mult.wrapping_add(1).wrapping_mul(step_plus);
            step_mult = step_mult.wrapping_mul(step_mult);
            remaining >>= 1;
        }
        self.state = acc_mult.wrapping_mul(self.state).wrapping_add(acc_plus);
    }

    /// Adds the generator to a checksum: `state` then `increment`, each as a `u64`.
    pub fn hash_state(&self, hasher: &mut StateHasher) {
        hasher.write_u64(self.state);
        hasher.write_u64(self.increment);
    }
}

/// The precision `p` of `R` just below 1: the largest `p` such that every multiple of `2^−p`
/// in `[0, 1)` is exactly representable, read from the canonical bits of `ONE`.
///
/// - Fixed point (`EPSILON` is the raw value 1): `ONE` is `2^F` raw, so `p = F`, the number
///   of trailing zeros of `ONE`'s bits.
/// - IEEE binary (`f64`): `ONE` is the odd exponent bias above an all-zero stored mantissa,
///   so the trailing zeros count the stored mantissa bits (52); with the implicit leading
///   bit the precision is one more (53).
#[inline(always)]
fn unit_bits<R: Real>() -> u32 {
    let one_zeros = R::ONE.canonical_bits().trailing_zeros();
    if R::EPSILON.canonical_bits() == 1 {
        one_zeros
    } else {
        one_zeros + 1
    }
}
