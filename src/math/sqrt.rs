//! √x and 1/√x on raw fixed-point bits, in integer arithmetic only.
//!
//! Both kernels share one approximation stage. The input `x` (value `x / 2^F`) is
//! normalised so that `x · 2^F = M · 2^(2h)` with `M ∈ [2^62, 2^64)`, i.e. `a = M / 2^62`
//! lies in `[1, 4)`. Then:
//!
//! 1. a 256-entry table gives `y₀ ≈ 1/√a` to about 9 bits (1 bit of exponent parity and
//!    7 bits of mantissa select the entry);
//! 2. two Goldschmidt iterations refine `s ≈ √a` and `y ≈ 1/√a` together to a relative
//!    error below 2⁻³⁴;
//! 3. one correction from an *exact* residual (`M·2^60 − s²` for √, `1 − a·y²` for 1/√)
//!    brings the estimate to far below one unit of the result;
//! 4. √ then checks its rounded candidate against the exact square `x · 2^F` and moves it
//!    by one if needed, so the result is correctly rounded.
//!
//! Every step is an integer multiply, add or shift on `u64`/`i128` values whose ranges are
//! stated next to them, so the result is the same on every target, and no `i64` input
//! (including `i64::MIN` and `i64::MAX`) overflows an intermediate or panics.

use crate::math::saturation::record_saturation;

#[cfg(vector_kernels)]
pub(crate) mod lanes;
#[cfg(vector_kernels)]
pub(crate) mod lanes_below_one;

/// Seeds for `1/√a`, `a ∈ [1, 4)`, in Q16 (value · 2^16).
///
/// Entry `p·128 + j` covers `a ∈ [(1 + p)(1 + j/128), (1 + p)(1 + (j + 1)/128))`, where
/// `p` selects `[1, 2)` or `[2, 4)`. The entry is `2 / (√a₀ + √a₁)` for the interval ends
/// `a₀`, `a₁`, which minimises the largest relative error `|y₀·√a − 1|` over the interval:
/// at most `2⁻⁹` (plus `2⁻¹⁶` from storing 16 bits). Built at compile time from exact
/// integer square roots, so the table has no hand-typed constants.
const RSQRT_SEED_Q16: [u16; 256] = rsqrt_seed_table();

const fn rsqrt_seed_table() -> [u16; 256] {
    let mut table = [0u16; 256];
    // √128 · 2^50: interval ends are measured in units of 1/128, hence the √128.
    let sqrt_128 = (128u128 << 100).isqrt();
    let mut index = 0;
    while index < 256 {
        let scale = if index < 128 { 1 } else { 2 };
        // The interval ends, in units of 1/128.
        let low = (128 + (index % 128) as u128) * scale;
        let high = low + scale;
        // (√a₀ + √a₁) · √128 · 2^50.
        let sum = (low << 100).isqrt() + (high << 100).isqrt();
        // 2 / (√a₀ + √a₁) · 2^16, rounded to nearest; below 2^16 since a₀ ≥ 1 and a₁ > 1.
        table[index] = (((sqrt_128 << 17) + sum / 2) / sum) as u16;
        index += 1;
    }
    table
}

/// `x.leading_zeros()` for `x > 0`, in a form the compiler cannot prove to have a non-zero
/// operand. On x86-64 without LZCNT, a provably non-zero operand lets it emit a bare `bsr`,
/// whose output register keeps a false dependency on its previous value (often the previous
/// call's result), which serialises loops: measured 17.7 → 11 ns per √ call in a map loop.
/// With a possibly-zero operand it emits `mov $127, reg; bsr`, which breaks that chain.
#[inline(always)]
pub(crate) fn leading_zeros_positive(x: i64) -> u32 {
    // For x > 0, x >> 1 has exactly one more leading zero (and is 0 only for x = 1: 64 − 1).
    ((x as u64) >> 1).leading_zeros() - 1
}

/// `x · 2^frac = M · 2^(2h)` for `x > 0`: returns `(M, h, table index)` with
/// `M ∈ [2^62, 2^64)`.
///
/// `x << leading_zeros` puts the top bit of `x` at bit 63 without losing a bit; when the
/// exponent of that form is odd, one more right shift makes it even (bit 0 of the shifted
/// value is 0 because `x > 0` has at least one leading zero, so nothing is lost either).
#[inline(always)]
fn normalise(x: i64, frac: u32) -> (u64, i32, usize) {
    let lz = leading_zeros_positive(x);
    let top = (x as u64) << lz; // x · 2^lz ∈ [2^63, 2^64)
    // x · 2^frac = top · 2^(frac − lz); make the exponent even.
    let odd = (frac + lz) & 1;
    let m = top >> odd;
    // h = (frac − lz + odd) / 2, which is (frac + 1 − lz) >> 1 for either parity.
    let half_exponent = (frac as i32 + 1 - lz as i32) >> 1;
    // Table index: parity selects [2, 4) (even) or [1, 2) (odd); then 7 mantissa bits.
    let index = (((odd ^ 1) as usize) << 7) | ((top >> 56) & 127) as usize;
    (m, half_exponent, index)
}

/// One Goldschmidt iteration on `s ≈ √a` (Q61) and `y ≈ 1/√a` (Q62):
/// `d = 1 − s·y`, `s ← s·(1 + d/2)`, `y ← y·(1 + d/2)`.
///
/// If `s·y = 1 − d`, both relative errors go from `e` to about `−(3/2)e²`; the two updates
/// are independent multiplies, so one iteration costs two multiplies of latency. Both
/// values stay below 2^62.1, so every product is a signed 64×64→128-bit multiply.
#[inline(always)]
fn goldschmidt_step(s: i64, y: i64) -> (i64, i64) {
    // s·y in Q62 (Q61 · Q62 = Q123); it is within 2⁻⁸ of 1, so d = 1 − s·y is small.
    let sy = ((s as i128 * y as i128) >> 61) as i64;
    let d = (1i64 << 62) - sy;
    // s·d/2 is (s · d) >> 63 in Q61 (d is Q62); likewise for y in Q62.
    let s = s + ((s as i128 * d as i128) >> 63) as i64;
    let y = y + ((y as i128 * d as i128) >> 63) as i64;
    (s, y)
}

/// `(s, y)` with `s ≈ √a` in Q61 and `y ≈ 1/√a` in Q62, `a = m / 2^62 ∈ [1, 4)`, both
/// with relative error below 2⁻³⁴ (seed error 2⁻⁹ → 2⁻¹⁷·⁴ → 2⁻³⁴·²).
///
/// Ranges: `y ∈ (2^61, 2^62 + 2^28)`, `s ∈ [2^61, 2^62 + 2^28)`.
#[inline(always)]
fn sqrt_rsqrt_estimate(m: u64, index: usize) -> (i64, i64) {
    let y = (RSQRT_SEED_Q16[index] as i64) << 46;
    // a · y₀ ≈ √a: (m/2 in Q61) · (y₀ in Q62) = Q123, shifted to Q61.
    let s = (((m >> 1) as i64 as i128 * y as i128) >> 62) as i64;
    let (s, y) = goldschmidt_step(s, y);
    goldschmidt_step(s, y)
}

/// √x for `x` with `frac` fractional bits: `round(√(x · 2^frac))`, **correctly rounded to
/// nearest** (exact ties cannot occur). Negative input gives 0.
///
/// Method: table seed and two Goldschmidt iterations for `s ≈ √a` (see the module docs),
/// then Newton's correction from the exact residual,
/// `√(M·2^60) ≈ s + (M·2^60 − s²)·y/2^124` (error below 1.03 units of Q61), rounded and
/// shifted to the output scale. The candidate `q` is then at most one away from the
/// correctly rounded result, and one exact comparison of `x·2^frac` with `q² − q` and
/// `q² + q` (the squares of `q ∓ ½`, less ¼) picks the correctly rounded neighbour. No
/// division.
///
/// Max error measured: 0.5 ulp, i.e. every result equal to the exactly rounded integer
/// reference, over 10⁷ random inputs (uniform and log-uniform bits) per format for I32F32,
/// I48F16 and I40F24 (10⁶ for I56F8 and I4F60), plus dense sweeps of small values, powers
/// of two and the neighbours of exact squares and of rounding midpoints. The exact final
/// check makes this hold for every input, not only the sampled ones.
#[inline(always)]
pub(crate) fn sqrt_bits(x: i64, frac: u32) -> i64 {
    if x <= 0 {
        return 0;
    }
    let (m, half_exponent, index) = normalise(x, frac);
    let (s, y) = sqrt_rsqrt_estimate(m, index);
    // Exact residual M·2^60 − s² (both terms below 2^124), where √(M·2^60) is √a in Q61.
    // |s − √(M·2^60)| ≤ 2^28, so |residual| < 2^91.
    let residual = ((m as i128) << 60) - s as i128 * s as i128;
    // Newton: √(M·2^60) ≈ s + residual / (2s), with 1/(2s) = y / 2^124.
    // |residual >> 32| < 2^59, so the product is a plain signed 64×64-bit one.
    let correction = ((residual >> 32) as i64 as i128 * y as i128) >> 92;
    // root_q61 is within 1.03 of √(M·2^60) ∈ [2^61, 2^62]: below 1 from the truncations,
    // 2⁻⁶ from the error of y and 2⁻⁶ from the Newton error (s − √(M·2^60))²/2s.
    let root_q61 = (s + correction as i64) as u64;
    // √(x · 2^frac) = √M · 2^h = root_q61 · 2^(h − 30); the shift 30 − h is between 0 and
    // 57 since h ∈ [−27, 30]. Then |root − √(x·2^frac)| ≤ ½ + 1.03 < 1.5 (1.03 when the
    // shift is 0), so root is at most one away from the correctly rounded result.
    let shift = (30 - half_exponent) as u32;
    let mut root = (root_q61 + ((1 << shift) >> 1)) >> shift;
    // Exact rounding check against n = x · 2^frac (< 2^123; root < 2^62, so root² < 2^124):
    // round(√n) = q  ⇔  q² − q < n ≤ q² + q.
    let n = (x as u128) << frac;
    let square = root as u128 * root as u128;
    if n > square + root as u128 {
        root += 1;
    } else if n + root as u128 <= square {
        root -= 1;
    }
    root as i64
}

/// 1/√x for `x` with `frac` fractional bits: `round(2^(2·frac) / √(x · 2^frac))`.
/// `x ≤ 0` gives `i64::MAX` and counts a saturation; so does a result above `i64::MAX`
/// (`frac > 41` with tiny `x`). Results below half an ulp are 0.
///
/// Method: the shared table seed and Goldschmidt estimate `y ≈ 1/√a` (relative error
/// `ε < 2⁻³⁴`), then one Newton step from the exact residual
/// `ε = 1 − a·y²` (computed to 2⁻¹²⁵ with three 64×64-bit products):
/// `1/√a = y·(1 − ε)^(−½) ≈ y·(1 + ε/2)`, leaving a relative error of `3ε²/8 < 2⁻⁶⁷`
/// before the final rounding. No division.
///
/// Max error measured, against an exact 256-bit integer comparison over 10⁷ random inputs
/// (uniform and log-uniform bits) per format (10⁶ for I56F8 and I4F60) plus dense sweeps:
/// 0.5 ulp (every result correctly rounded) for I32F32, I48F16, I40F24 and I56F8; 1 ulp for
/// I4F60, whose results carry up to 63 significant bits: there 30 of 10⁶ results, each
/// within the method's 2⁻⁴ ulp of a rounding midpoint, rounded the other way.
#[inline(always)]
pub(crate) fn rsqrt_bits(x: i64, frac: u32) -> i64 {
    if x <= 0 {
        record_saturation();
        return i64::MAX;
    }
    let (m, half_exponent, index) = normalise(x, frac);
    let (_, y) = sqrt_rsqrt_estimate(m, index);
    // ε·2^125 = 2^125 − M·y²/2^61 (M is a in Q62, y² is Q124). Split y² = hi·2^64 + lo so
    // that each product fits u128: M·y²/2^61 = 8·(M·hi) + (M·lo)/2^61. a·y² is within
    // 2⁻³³ of 1, so 8·(M·hi) < 2^125 + 2^93.
    let y_squared = (y as u64 as u128) * (y as u64 as u128);
    let high = m as u128 * (y_squared >> 64);
    let low = m as u128 * (y_squared as u64 as u128);
    let a_y_squared = (high << 3) + (low >> 61);
    let epsilon_q125 = (1i128 << 125) - a_y_squared as i128;
    // y·(1 + ε/2) with 32 extra fraction bits (Q94): y·ε/2 in Q94 is
    // (y · (ε·2^125 >> 30)) >> 64, with |ε·2^125 >> 30| < 2^63 and y < 2^62.1.
    let y_q94 = ((y as i128) << 32) + ((y as i128 * (epsilon_q125 >> 30)) >> 64);
    // 1/√(x·2^frac) = y·2^(−31−h), so the result 2^(2F)/√(x·2^frac) is
    // y_q94 · 2^(2F − 31 − h − 94) = y_q94 >> (125 + h − 2F).
    let shift = 125 + half_exponent - 2 * frac as i32;
    // y_q94 ∈ (2^93, 2^94]: a shift of 30 or less leaves at least 2^63.
    if shift <= 30 {
        record_saturation();
        return i64::MAX;
    }
    // y_q94 / 2^96 < 1/4 rounds to 0.
    if shift >= 96 {
        return 0;
    }
    let shift = shift as u32;
    let result = (y_q94 + (1i128 << (shift - 1))) >> shift;
    if result > i64::MAX as i128 {
        record_saturation();
        return i64::MAX;
    }
    result as i64
}
