//! eˣ, ln x and xʸ on raw fixed-point bits, in integer arithmetic only.
//!
//! All three work internally in Q62 (value · 2^62) with `i64`/`i128` integers and round
//! once, at the end, to the output's `frac` fractional bits. `powf` chains the two kernels
//! at that internal precision (`ln x` is never rounded to the output format first), so its
//! error stays near one ulp even when `y · ln x` amplifies the error of `ln x`.
//!
//! Constants are integer literals or are computed at compile time from integers; the
//! comment on each says how. Every intermediate has its range stated beside it: no `i64`
//! input (including `i64::MIN` and `i64::MAX`) overflows or panics, and the results are
//! bit-identical on every target.

use crate::math::saturation::{record_saturation, saturate_i128};
use crate::math::sqrt::leading_zeros_positive;

/// ln 2 · 2^120, rounded to nearest: `nint(log(2) · 2^120)` with mpmath at 120 digits.
const LN2_Q120: i128 = 0xb1_7217_f7d1_cf79_abc9_e3b3_9803_f2f7;

/// ln 2 / 32 in Q118 (= ln 2 · 2^113), rounded from [`LN2_Q120`].
const LN2_OVER_32_Q118: i128 = (LN2_Q120 + (1 << 6)) >> 7;

/// 2^62 / ln 2, rounded to nearest: `nint(2^62 / log(2))` with mpmath at 120 digits.
const INV_LN2_Q62: i64 = 0x5c55_1d94_ae0b_f85e;

/// 2^(j/32) · 2^62 for j = 0..32, rounded to nearest: `nint(2^(j/32) · 2^62)` with mpmath
/// at 120 digits.
const EXP2_FRAC_Q62: [u64; 32] = [
    0x4000_0000_0000_0000,
    0x4166_c34c_5615_d0ec,
    0x42d5_61b3_e624_3d8a,
    0x444c_0740_496d_4294,
    0x45ca_e0f1_f545_eb73,
    0x4752_1cc5_a2e6_a9e0,
    0x48e1_e9b9_d588_e19b,
    0x4a7a_77d4_7f7b_84b1,
    0x4c1b_f828_c6dc_54b8,
    0x4dc6_9cdc_eaa7_2a9c,
    0x4f7a_9930_48d0_88d7,
    0x5138_2181_8624_b40c,
    0x52ff_6b54_d8a8_9c75,
    0x54d0_ad5a_753e_077c,
    0x56ac_1f75_2150_a563,
    0x5891_fac0_e956_12c8,
    0x5a82_7999_fcef_3242,
    0x5c7d_d7a3_b17d_cf75,
    0x5e84_51cf_ac06_1b5f,
    0x6096_2665_3338_4a2b,
    0x62b3_9508_aa83_6d6f,
    0x64dc_dec3_3717_93d1,
    0x6712_460a_8fc2_4072,
    0x6954_0ec8_f895_722d,
    0x6ba2_7e65_6b4e_b57a,
    0x6dfd_dbcb_ed79_1bab,
    0x7066_6f76_154a_7089,
    0x72dc_8373_be41_a454,
    0x7560_6373_ee92_1c97,
    0x77f2_5ccd_ee6d_7ae6,
    0x7a92_be8a_9243_6616,
    0x7d41_d96d_b915_019d,
];

/// Taylor coefficients of eʳ, `1/i!` for i = 0..=7, in Q62, rounded to nearest.
const EXP_TAYLOR_Q62: [i64; 8] = {
    let mut coefficients = [0i64; 8];
    let mut factorial = 1i64;
    let mut i = 0;
    while i < 8 {
        if i > 0 {
            factorial *= i as i64;
        }
        coefficients[i] = ((1i64 << 62) + factorial / 2) / factorial;
        i += 1;
    }
    coefficients
};

/// `c_j = 1 / (1 + j/64)` for j = 0..=64 in Q62, rounded to nearest: `round(2^68 / (64 + j))`.
/// `c_0 = 1` and `c_64 = 1/2` are exact.
const LN_RECIPROCAL_Q62: [u64; 65] = {
    let mut table = [0u64; 65];
    let mut j = 0;
    while j < 65 {
        let divisor = 64 + j as u64;
        table[j] = (((1u128 << 68) + (divisor / 2) as u128) / divisor as u128) as u64;
        j += 1;
    }
    table
};

/// `−ln(c_j)` for the stored `c_j` of [`LN_RECIPROCAL_Q62`] (that is,
/// `nint(log(2^62 / LN_RECIPROCAL_Q62[j]) · 2^62)` with mpmath at 120 digits), so that
/// `ln m = −ln c_j + ln(m · c_j)` holds for the rounded `c_j` actually used.
const LN_OF_INVERSE_RECIPROCAL_Q62: [i64; 65] = [
    0x0,
    0xfe_0545_87e0_1f1e,
    0x1f8_29b0_e783_3005,
    0x2ee_8b1e_c65b_9f89,
    0x3e1_4618_022c_54cc,
    0x4d0_75e5_86f4_7425,
    0x5bc_34a2_b95a_d2e7,
    0x6a4_9b4e_92b5_58da,
    0x789_c1db_8abc_b97a,
    0x86b_bf3e_6847_2cb4,
    0x94a_a97c_0ffa_91a6,
    0xa26_95b6_65be_8f34,
    0xaff_9838_53c9_e9e4,
    0xbd5_c481_086c_848e,
    0xca9_2d4e_7a2b_5a3b,
    0xd79_e4a7_405f_f96d,
    0xe47_fbe3_cd4d_10d6,
    0xf13_83b7_1579_72f5,
    0xfdc_8c36_af1f_1547,
    0x10a3_24e2_7390_e35f,
    0x1167_5cab_aba6_0e04,
    0x1229_41fb_cf79_65a3,
    0x12e8_e2ba_e11d_309c,
    0x13a6_4c55_6945_e9c7,
    0x1461_8bc2_1c5e_c27d,
    0x151a_ad87_2df8_2d0a,
    0x15d1_bdbf_5809_ca50,
    0x1686_c81e_9b14_aec4,
    0x1739_d7f6_bbd0_069d,
    0x17ea_f83b_82af_c364,
    0x189a_3386_c142_5ab6,
    0x1947_941c_2116_faba,
    0x19f3_23ec_bf98_4bf2,
    0x1a9c_ec9a_9a08_498d,
    0x1b44_f77b_cc8f_628d,
    0x1beb_4d9d_a71b_7bf7,
    0x1c8f_f7c7_9a9a_21ab,
    0x1d32_fe7e_00eb_d561,
    0x1dd4_6a04_c1c4_a0bf,
    0x1e74_4261_d687_87e3,
    0x1f12_8f5f_af06_ecb4,
    0x1faf_588f_78f3_1eda,
    0x204a_a54b_4ba1_fd8e,
    0x20e4_7cb8_39be_809c,
    0x217c_e5c8_4a55_056d,
    0x2213_e73c_5a99_2dfb,
    0x22a9_87a5_e9ab_d354,
    0x233d_cd68_cf92_dd99,
    0x23d0_bebc_e081_a07c,
    0x2462_61af_7d7e_8506,
    0x24f2_bc25_1362_35d6,
    0x2581_d3da_891d_1773,
    0x260f_ae66_9e21_7c40,
    0x269c_513b_39c3_a62e,
    0x2727_c1a6_ac54_3353,
    0x27b2_04d4_e2ad_f547,
    0x283b_1fd0_8ce5_5cc9,
    0x28c3_1784_38bd_84fb,
    0x2949_f0bb_607d_7604,
    0x29cf_b023_6eb7_613a,
    0x2a54_5a4c_b78b_55dd,
    0x2ad7_f3ab_67e7_3282,
    0x2b5a_8098_6b3e_59f6,
    0x2bdc_0552_482c_eae2,
    0x2c5c_85fd_f473_de6b,
];

/// Taylor coefficients of ln(1 + t), `(−1)^(k+1)/k` for k = 1..=8 (index k − 1), in Q62,
/// rounded to nearest.
const LN1P_TAYLOR_Q62: [i64; 8] = {
    let mut coefficients = [0i64; 8];
    let mut k = 1;
    while k <= 8 {
        let magnitude = ((1i64 << 62) + k / 2) / k;
        coefficients[(k - 1) as usize] = if k % 2 == 1 { magnitude } else { -magnitude };
        k += 1;
    }
    coefficients
};

/// `|z| ≥ 64` (Q62) saturates or underflows eᶻ for every supported format: e⁶⁴ > 2⁹² is
/// above `i64::MAX / 2^8`, and e⁻⁶⁴ < 2⁻⁹² is below half an ulp of `2^-60`.
const EXP_ARGUMENT_LIMIT_Q62: i128 = 64 << 62;

/// `a · b / 2^62`, rounded (ties toward +∞), for Q62 operands whose product fits `i64`.
#[inline(always)]
fn mul_q62(a: i64, b: i64) -> i64 {
    ((a as i128 * b as i128 + (1 << 61)) >> 62) as i64
}

/// eᶻ for `z` in Q62 (any `i128`), rounded to `frac` fractional bits.
///
/// Range reduction: `z = N·(ln 2)/32 + r` with `N = round(32 z / ln 2)`, `|r| ≤ ln 2 / 64`,
/// computed against a 118-bit ln 2 so that `r` is exact to 2⁻⁶² even for `|N|` near 3000.
/// With `N = 32k + j`, `eᶻ = 2^k · 2^(j/32) · eʳ`: the table gives `2^(j/32)`, a degree-7
/// Taylor polynomial gives `eʳ` (truncation error `r⁸/8! < 2⁻⁶⁷`), and `k` is a shift.
#[inline]
fn exp_q62(z: i128, frac: u32) -> i64 {
    if z >= EXP_ARGUMENT_LIMIT_Q62 {
        record_saturation();
        return i64::MAX;
    }
    if z <= -EXP_ARGUMENT_LIMIT_Q62 {
        return 0;
    }
    // |z| < 2^68, so z/64 (Q56) fits i64. (z/64 · 2^62/ln 2) is 32z/ln 2 in Q113.
    let scaled = (z >> 6) as i64 as i128 * INV_LN2_Q62 as i128;
    let n = ((scaled + (1 << 112)) >> 113) as i64; // |n| ≤ 2955
    // r = z − n·ln2/32 in Q118: |z · 2^56| < 2^124 and |n · ln2/32 · 2^118| < 2^125.
    let r_q118 = (z << 56) - n as i128 * LN2_OVER_32_Q118;
    // |r| ≤ ln2/64 (plus 2⁻⁵⁶ from the rounding of 32/ln2), so |r| < 2^56 in Q62.
    let r = ((r_q118 + (1 << 55)) >> 56) as i64;
    // Horner: eʳ ≈ Σ rⁱ/i!, in Q62; the value stays in [0.989, 1.011].
    let mut exp_r = EXP_TAYLOR_Q62[7];
    for &coefficient in EXP_TAYLOR_Q62[..7].iter().rev() {
        exp_r = coefficient + mul_q62(exp_r, r);
    }
    let j = (n & 31) as usize;
    let k = n >> 5; // floor(n / 32)
    // Result bits = 2^(j/32) · eʳ · 2^(k + frac), and 2^(j/32) · eʳ ∈ [0.989, 2.03).
    let exponent = k + frac as i64;
    if exponent >= 64 {
        record_saturation();
        return i64::MAX;
    }
    if exponent <= -3 {
        return 0; // below 2.03 / 8 < ½ ulp
    }
    // Q62 · Q62 = Q124, below 2^125.1; shifted right by 124 − exponent ∈ [61, 126].
    let product = EXP2_FRAC_Q62[j] as u128 * exp_r as u128;
    let shift = (124 - exponent) as u32;
    let result = (product + (1 << (shift - 1))) >> shift;
    if result > i64::MAX as u128 {
        record_saturation();
        return i64::MAX;
    }
    result as i64
}

/// ln(x / 2^frac) in Q62 for `x > 0`; the result is below 45 in magnitude.
///
/// With `x / 2^frac = m · 2^e`, `m ∈ [1, 2)`: `ln = e·ln 2 − ln c_j + ln(1 + t)`, where
/// `c_j = 1/(1 + j/64)` for the nearest `j ∈ 0..=64` and `1 + t = m·c_j` exactly (a 128-bit
/// product), so `|t| ≤ 2⁻⁷`. ln(1 + t) is the degree-8 Taylor polynomial (truncation error
/// `|t|⁹/9 < 2⁻⁶⁶`). For `m` near 1, `j = 0` and `c_0 = 1`, so `ln 1 = 0` exactly and small
/// logarithms keep their relative precision.
#[inline]
fn ln_q62(x: i64, frac: u32) -> i128 {
    let lz = leading_zeros_positive(x);
    let top = (x as u64) << lz; // m · 2^63, in [2^63, 2^64)
    let exponent = 63 - lz as i64 - frac as i64; // |exponent| ≤ 60
    // Nearest j to (m − 1) · 64, in 0..=64.
    let j = (((top - (1 << 63)) + (1 << 56)) >> 57) as usize;
    // m · c_j in Q125 (Q63 · Q62); it is 1 + t with |t| ≤ 2⁻⁷, so below 2^126.
    let product = top as u128 * LN_RECIPROCAL_Q62[j] as u128;
    let t = (((product as i128 - (1 << 125)) + (1 << 62)) >> 63) as i64; // Q62, |t| < 2^55
    let mut series = LN1P_TAYLOR_Q62[7];
    for &coefficient in LN1P_TAYLOR_Q62[..7].iter().rev() {
        series = coefficient + mul_q62(series, t);
    }
    let ln_1p = mul_q62(series, t);
    // e · ln 2 in Q62, from the Q120 constant: |e · LN2_Q120| < 2^126.
    let exponent_part = (exponent as i128 * LN2_Q120 + (1 << 57)) >> 58;
    exponent_part + LN_OF_INVERSE_RECIPROCAL_Q62[j] as i128 + ln_1p as i128
}

/// eˣ for `x` with `frac` fractional bits, rounded to nearest.
///
/// Results above `i64::MAX` saturate to `i64::MAX` and count one saturation; results below
/// half an ulp are 0 (not counted).
///
/// Method: `x` is widened to Q62 and passed to the shared kernel: `x = N·ln2/32 + r` with a
/// 118-bit ln 2, `eˣ = 2^(N div 32) · 2^((N mod 32)/32) · eʳ`, a 32-entry table for the
/// middle factor and a degree-7 Taylor polynomial in Q62 for `eʳ`, `|r| ≤ ln2/64`; one
/// rounding at the end.
///
/// Error: the kernel's value before the final rounding is within about 3·2⁻⁶³ relative
/// (table and polynomial rounding; truncation `r⁸/8! < 2⁻⁶⁷`), so results are correctly
/// rounded except within a sliver of a rounding midpoint. Max error measured against
/// `f64::exp` of the exact input, over 10⁷ random inputs across the representable range
/// per format plus dense sweeps (I32F32, I48F16, I40F24; 10⁶ for I56F8): 0.5 ulp for
/// results below 2⁴⁰ ulps (where f64 resolves 2⁻¹² ulp); above that the relative error is
/// below 2⁻⁵⁰, the f64 reference's own limit. The largest relative error over results of
/// at least 2²⁶ ulps is the final rounding's 2⁻²⁷.
#[inline]
pub(crate) fn exp_bits(x: i64, frac: u32) -> i64 {
    // |x| < 2^63 and frac ≥ 8, so x · 2^(62 − frac) < 2^117.
    exp_q62((x as i128) << (62 - frac), frac)
}

/// ln x for `x` with `frac` fractional bits, rounded to nearest. `x ≤ 0` gives `i64::MIN`
/// and counts one saturation; so does a logarithm outside the format's range, which only
/// happens for `frac > 57` (e.g. I4F60 holds ±8, and ln of its smallest value is −41.6).
///
/// Method: normalise `x = m · 2^e` with `leading_zeros`, then
/// `ln x = e·ln 2 − ln c_j + ln(m·c_j)` with a 65-entry table of `c_j = 1/(1 + j/64)` and
/// `−ln c_j`, and a degree-8 Taylor polynomial for `ln(1 + t)`, `|t| ≤ 2⁻⁷`, in Q62; one
/// rounding at the end.
///
/// Error: about 2⁻⁶¹ absolute before the final rounding. Max error measured against
/// `f64::ln`, over 10⁷ random inputs (log-uniform over all bit lengths, and uniform in
/// [½, 2)) per format plus dense sweeps near 0 and 1 (I32F32, I48F16, I40F24; 10⁶ for
/// I56F8): 0.5 ulp, i.e. correctly rounded to the reference's resolution (2⁻¹⁵ ulp at
/// F = 32).
#[inline]
pub(crate) fn ln_bits(x: i64, frac: u32) -> i64 {
    if x <= 0 {
        record_saturation();
        return i64::MIN;
    }
    // |ln| < 45 always fits for frac ≤ 57; with more fraction bits the format's range
    // (±2^(63 − frac)) can be exceeded, which saturates and is counted.
    saturate_i128((ln_q62(x, frac) + (1 << (61 - frac))) >> (62 - frac))
}

/// xʸ for `x`, `y` with `frac` fractional bits, rounded to nearest.
///
/// * `x > 0`: `e^(y · ln x)`, with `ln x` kept in Q62 (not rounded to `frac` bits) and
///   `y · ln x` formed exactly in `i128` (saturating far beyond the range where the result
///   is `i64::MAX` or 0), then the exp kernel of [`exp_bits`]. Results above `i64::MAX`
///   saturate and are counted; results below half an ulp are 0. `x^0 = 1` and `1^y = 1`
///   exactly.
/// * `x = 0`: `0^y` is 0 for `y > 0` and 1 for `y = 0`; for `y < 0` it is `i64::MAX`
///   (the limit +∞), counted as a saturation like a division by zero.
/// * `x < 0`: not defined for fractional `y`; returns 0 and counts a saturation.
///
/// Error: `ln x` carries about 2⁻⁶¹ absolute and `y · ln x` is exact before its final
/// truncation to Q62, so the relative error before the final rounding is about
/// `2⁻⁶¹·(1 + |y|)`. Max error measured against `f64::powf` of the exact inputs, 10⁷
/// samples per format (I32F32, I48F16, I40F24; 10⁶ for I56F8): 0.5 ulp for `x ∈ (0, 16]`,
/// `y ∈ [−24, 24]` with results in [2⁻²⁰, 2²⁰] (relative error at most 2⁻²¹ wherever one ulp
/// is below 2⁻²⁰ of the result), and 0.5 ulp for damping factors `d^(1/60)`, `d ∈ (0, 1]`.
#[inline]
pub(crate) fn powf_bits(x: i64, y: i64, frac: u32) -> i64 {
    if x < 0 {
        record_saturation();
        return 0;
    }
    if x == 0 {
        return match y.signum() {
            1 => 0,
            0 => 1 << frac,
            _ => {
                record_saturation();
                i64::MAX
            }
        };
    }
    // y (value y/2^frac) times ln x (Q62) is Q(62 + frac); |ln x| < 2^68, |y| ≤ 2^63.
    let z = (y as i128).saturating_mul(ln_q62(x, frac)) >> frac;
    exp_q62(z, frac)
}
