//! Integer-only trigonometry for [`Fixed`](super::Fixed): sin, cos, atan2, asin and acos.
//!
//! Every kernel takes and returns raw fixed-point bits with `frac` fractional bits (the value
//! is `bits / 2^frac`, angles in radians) and uses only `i64`/`u64`/`i128`/`u128`
//! arithmetic whose every intermediate is proven in range for every input, so results are
//! bit-identical on every target and no input panics.
//!
//! # Internal formats
//!
//! * Polynomials run in Q62 (`value = bits / 2^62`): coefficients and partial sums lie in
//!   (−2, 2), the reduced argument is held in Q63 (it lies in [−1, 1]), and every product
//!   is an exact 64 × 64 → 128-bit multiply shifted back down.
//! * Angles up to π are assembled in Q61 and rounded to `frac` bits once, at the end.
//!
//! # Two accuracy tiers
//!
//! `frac` is a constant after inlining, so the polynomial degree is chosen per format:
//! formats with at most 32 fractional bits (I48F16, I40F24, I32F32) use short polynomials
//! whose error (≤ 2⁻³⁹) is far below their ulp, and finer formats (up to 60 bits) use longer
//! ones (error ≤ 2⁻⁶⁴). The result is then the correctly rounded value give or take the
//! polynomial error (0.507 ulp at most for I32F32), except that above about 56 fractional
//! bits the truncations of the Q62 arithmetic itself show: up to 1.8 ulp at 60 bits.
//!
//! The figures quoted for I48F16, I40F24 and I32F32 come from
//! `cargo test --release --test suite math_trig:: -- --ignored --nocapture` (`measure_max_errors`,
//! against `f64` references accurate to about 2⁻⁵²). Those for 48 and 60 fractional bits,
//! finer than an `f64` reference can resolve, were measured against mpmath at 90 digits
//! over 2.2·10⁵ samples per function and format.
//!
//! # Where the constants come from
//!
//! Each polynomial is the minimax (equi-oscillating, absolute error) fit computed with the
//! Remez exchange algorithm in 60-digit arithmetic (mpmath), then each coefficient is
//! rounded to the nearest Q62 integer; the quoted fit errors are the Remez levels. The
//! other constants are the named real numbers times a power of two, rounded to nearest.

/// 2/π · 2¹²⁸, rounded to nearest (the error is 0.14 of the last unit, 2⁻¹³⁰ relative):
/// enough bits that reducing any `i64` argument leaves an error below 2⁻⁷² quarter turns.
const TWO_OVER_PI_Q128: u128 = 216_630_482_969_909_636_093_804_454_941_121_895_873;

/// π · 2⁶¹.
const PI_Q61: i64 = 7_244_019_458_077_122_842;
/// π/2 · 2⁶¹.
const FRAC_PI_2_Q61: i64 = 3_622_009_729_038_561_421;

/// The widest format that uses the short polynomials.
const SHORT_POLYNOMIAL_MAX_FRAC: u32 = 32;

/// sin(πu/4) = u · S(u²) for u ∈ [−1, 1]: S in Q62, lowest degree first. Remez fit,
/// absolute error of u·S(u²) ≤ 1.7·10⁻¹² (2⁻³⁹·¹).
const SIN_SHORT: [i64; 5] = [
    3_622_009_728_952_589_137,
    -372_372_947_888_736_912,
    11_484_908_175_084_352,
    -168_655_895_521_900,
    1_422_997_593_724,
];

/// As [`SIN_SHORT`], degree 15: absolute error ≤ 7.0·10⁻²² (2⁻⁷⁰·³).
const SIN_LONG: [i64; 8] = [
    3_622_009_729_038_561_421,
    -372_372_949_609_452_717,
    11_484_917_819_725_215,
    -168_677_969_433_860,
    1_445_125_719_273,
    -8_103_873_062,
    32_042_507,
    -93_223,
];

/// cos(πu/4) = C(u²) for u ∈ [−1, 1]: C in Q62, lowest degree first. Remez fit, absolute
/// error ≤ 5.5·10⁻¹⁴ (2⁻⁴⁴·⁰).
const COS_SHORT: [i64; 6] = [
    4_611_686_018_427_131_976,
    -1_422_359_894_478_850_523,
    73_115_257_465_305_272,
    -1_503_371_308_015_513,
    16_558_146_380_112,
    -111_919_011_698,
];

/// As [`COS_SHORT`], degree 14: absolute error ≤ 3.0·10⁻²⁰ (2⁻⁶⁴·⁸).
const COS_LONG: [i64; 8] = [
    4_611_686_018_427_387_904,
    -1_422_359_894_497_287_752,
    73_115_257_680_538_307,
    -1_503_372_227_060_799,
    16_559_920_913_075,
    -113_499_883_414,
    530_367_509,
    -1_779_277,
];

/// atan t = t · A(t²) for |t| ≤ tan(π/16)·(1 + 2⁻³⁰): A in Q62, lowest degree first. Remez
/// fit, absolute error ≤ 1.6·10⁻¹² (2⁻³⁹·²).
const ATAN_SHORT: [i64; 5] = [
    4_611_686_018_033_888_251,
    -1_537_228_472_671_874_226,
    922_308_664_306_614_800,
    -657_145_299_909_646_827,
    469_401_345_667_869_347,
];

/// As [`ATAN_SHORT`], degree 17: absolute error ≤ 7.9·10⁻²¹ (2⁻⁶⁶·⁸).
const ATAN_LONG: [i64; 9] = [
    4_611_686_018_427_387_901,
    -1_537_228_672_809_124_004,
    922_337_203_683_111_493,
    -658_812_287_866_164_748,
    512_409_504_671_087_666,
    -419_240_753_005_882_984,
    354_610_272_130_665_511,
    -304_276_882_564_199_299,
    229_866_132_578_374_169,
];

/// tan(π/16) · 2⁶⁴ and tan(3π/16) · 2⁶⁴: the boundaries between the three atan segments.
const TAN_PI_16_Q64: u64 = 3_669_285_534_148_243_471;
const TAN_3PI_16_Q64: u64 = 12_325_720_329_217_147_637;

/// tan(kπ/8) · 2⁶³ for the segment centres k = 0, 1, 2 (0, √2 − 1, 1).
const SEGMENT_TAN_Q63: [u64; 3] = [0, 3_820_445_788_478_006_404, 1 << 63];
/// kπ/8 · 2⁶¹ for k = 0, 1, 2.
const SEGMENT_ANGLE_Q61: [i64; 3] = [0, 905_502_432_259_640_355, 1_811_004_864_519_280_711];

/// a·b in Q62 for a, b in Q62, rounded toward −∞. Callers keep |a|, |b| < 2, so the
/// result fits.
#[inline(always)]
fn mul_q62(a: i64, b: i64) -> i64 {
    ((a as i128 * b as i128) >> 62) as i64
}

/// u·v in Q62 for u in Q63 (|u| ≤ 1) and v in Q62 (|v| < 2), rounded toward −∞.
#[inline(always)]
fn mul_q63_q62(u: i64, v: i64) -> i64 {
    ((u as i128 * v as i128) >> 63) as i64
}

/// u² in Q62 for u in Q63, rounded toward −∞: the high half of the exact square, which
/// fits (u² ≤ 2¹²⁶) and lets the compiler keep every later product a 64 × 64-bit multiply.
#[inline(always)]
fn square_q63_to_q62(u: i64) -> i64 {
    ((u as i128 * u as i128) >> 64) as i64
}

/// Σ cᵢ zⁱ by Horner's rule in Q62. Every coefficient set here has |partial sums| < 2 for
/// z ∈ [0, 1], so no step can overflow.
#[inline(always)]
fn horner_q62(coefficients: &[i64], z: i64) -> i64 {
    coefficients
        .iter()
        .rev()
        .fold(0, |acc, &coefficient| coefficient + mul_q62(acc, z))
}

/// Rounds a Q62 value to `frac` fractional bits (to nearest, ties toward +∞).
#[inline(always)]
fn round_q62(value: i64, frac: u32) -> i64 {
    (value + (1 << (61 - frac))) >> (62 - frac)
}

/// Rounds a Q61 value to `frac` fractional bits (to nearest, ties toward +∞).
#[inline(always)]
fn round_q61(value: i64, frac: u32) -> i64 {
    (value + (1 << (60 - frac))) >> (61 - frac)
}

/// Splits the angle `magnitude / 2^frac` (radians) as (n + u/2)·π/2 with n an integer and
/// u ∈ [−1, 1), returning (n mod 4, u in Q63).
///
/// The quarter-turn count is `magnitude · (2/π) / 2^frac`. With 2/π in Q128, the exact
/// product is 192 bits wide; the low 64 bits only matter below 2⁻⁸ of the last fraction
/// bit kept, so they are dropped and the remaining 128 bits are `hi + (lo >> 64)`
/// (< 2¹²⁸: `magnitude` ≤ 2⁶³). Shifting right by `frac` leaves the quarter turns in Q64;
/// the error from the constant and the dropped bits is below 2⁻⁷² quarter turns for every
/// input, so even the largest arguments are reduced correctly.
#[inline(always)]
fn reduce_quarter_turns(magnitude: u64, frac: u32) -> (u32, i64) {
    let low = magnitude as u128 * (TWO_OVER_PI_Q128 as u64) as u128;
    let high = magnitude as u128 * (TWO_OVER_PI_Q128 >> 64);
    let turns_q64 = (high + (low >> 64)) >> frac;
    // Round the count to nearest: the fraction f ∈ [0, 1) read as a signed Q64 number is
    // f − round(f) ∈ [−1/2, 1/2), which is u = 2(f − round(f)) read as Q63.
    let quadrant = ((turns_q64 + (1 << 63)) >> 64) as u32 & 3;
    (quadrant, turns_q64 as u64 as i64)
}

/// (sin(πu/4), cos(πu/4)) in Q62 for u ∈ [−1, 1) in Q63.
#[inline(always)]
fn sin_cos_eighth_turn_q62(u: i64, frac: u32) -> (i64, i64) {
    let z = square_q63_to_q62(u);
    let (sin_coefficients, cos_coefficients): (&[i64], &[i64]) =
        if frac <= SHORT_POLYNOMIAL_MAX_FRAC {
            (&SIN_SHORT, &COS_SHORT)
        } else {
            (&SIN_LONG, &COS_LONG)
        };
    (
        mul_q63_q62(u, horner_q62(sin_coefficients, z)),
        horner_q62(cos_coefficients, z),
    )
}

/// sin x and cos x together, from one range reduction. x in radians (raw bits with `frac`
/// fractional bits); results in [−1, 1] with the same `frac`.
///
/// Method: |x| = (n + u/2)·π/2 exactly (multiplication by 2/π held to 128 bits, see
/// `reduce_quarter_turns`), then sin(πu/4) = u·S(u²) and cos(πu/4) = C(u²) by minimax
/// polynomials in Q62 (|πu/4| ≤ π/4), then the quadrant identities
/// sin(nπ/2 + θ) = (sin θ, cos θ, −sin θ, −cos θ)[n mod 4] and
/// cos(nπ/2 + θ) = (cos θ, −sin θ, −cos θ, sin θ)[n mod 4], and sin(−x) = −sin x.
/// Both results are rounded to nearest; sin is exactly odd and cos exactly even.
///
/// Max error measured over 10⁷ samples per format (half uniform over all `i64` bit
/// patterns, half dense over [−4π, 4π]), the same for sin and cos:
///
/// | format | max error | in ulp |
/// |---|---|---|
/// | I32F32 | 1.181·10⁻¹⁰ (2⁻³²·⁹⁸) | 0.5073 (half an ulp + 2⁻³⁹·¹) |
/// | I40F24 | 2.980·10⁻⁸ (2⁻²⁵·⁰⁰) | 0.5000 (half an ulp + 2⁻³⁹·¹) |
/// | I48F16 | 7.629·10⁻⁶ (2⁻¹⁷·⁰⁰) | 0.5000 (correctly rounded in every sample) |
/// | 48 fractional bits | 1.78·10⁻¹⁵ | 0.5002 |
/// | 60 fractional bits | 1.50·10⁻¹⁸ | 1.73 |
#[inline]
pub(crate) fn sin_cos_bits(x: i64, frac: u32) -> (i64, i64) {
    let (quadrant, u) = reduce_quarter_turns(x.unsigned_abs(), frac);
    let (sin_theta, cos_theta) = sin_cos_eighth_turn_q62(u, frac);
    let (mut sin, mut cos) = if quadrant & 1 == 0 {
        (sin_theta, cos_theta)
    } else {
        (cos_theta, -sin_theta)
    };
    if quadrant & 2 != 0 {
        sin = -sin;
        cos = -cos;
    }
    let sin = round_q62(sin, frac);
    (if x < 0 { -sin } else { sin }, round_q62(cos, frac))
}

/// sin x, x in radians; same method and error as [`sin_cos_bits`] (it is its first half).
///
/// Max error measured against f64: see [`sin_cos_bits`].
#[inline]
pub(crate) fn sin_bits(x: i64, frac: u32) -> i64 {
    sin_cos_bits(x, frac).0
}

/// cos x, x in radians; same method and error as [`sin_cos_bits`] (it is its second half).
///
/// Max error measured against f64: see [`sin_cos_bits`].
#[inline]
pub(crate) fn cos_bits(x: i64, frac: u32) -> i64 {
    sin_cos_bits(x, frac).1
}

/// atan(num / den) ∈ [0, π/2] in Q61 for `num`, `den` not both zero (any scale: only the
/// ratio matters).
///
/// With a = max(num, den) and b = min(num, den), θ = atan(b/a) ∈ [0, π/4] (and the result
/// is π/2 − θ when num > den). θ is split as kπ/8 + atan t with |t| ≤ tan(π/16), using
/// tan(θ − kπ/8) = (b − c·a) / (a + c·b), c = tan(kπ/8), so that one 128-by-64-bit division
/// gives t; atan t = t·A(t²) by a minimax polynomial in Q62.
#[inline(always)]
fn atan_ratio_q61(num: u64, den: u64, frac: u32) -> i64 {
    let swapped = num > den;
    let (small, large) = if swapped { (den, num) } else { (num, den) };
    // Normalise so that a ∈ [2⁶³, 2⁶⁴): the truncations below are then relative to 2⁻⁶².
    let shift = large.leading_zeros();
    let (a, b) = (large << shift, small << shift);
    let above = |tan_q64: u64| b > ((a as u128 * tan_q64 as u128) >> 64) as u64;
    let segment = usize::from(above(TAN_PI_16_Q64)) + usize::from(above(TAN_3PI_16_Q64));
    let c = SEGMENT_TAN_Q63[segment];
    // In Q127: b·2⁶³ and c·a are below 2¹²⁷, so the numerator fits an i128; a·2⁶³ and c·b
    // are below 2¹²⁷ each, so the denominator (≥ 2¹²⁶) fits a u128.
    let numerator = ((b as i128) << 63) - c as i128 * a as i128;
    let denominator = ((a as u128) << 63) + c as u128 * b as u128;
    // Keep the top 64 bits of each; |numerator| ≤ 0.2·denominator, so the Q64 quotient
    // is below 2⁶⁴ and the division never overflows. t is then held in Q63.
    let numerator_top = (numerator.unsigned_abs() >> 64) as u64;
    let denominator_top = (denominator >> 64) as u64;
    let t_q64 = ((numerator_top as u128) << 64) / denominator_top as u128;
    let t_magnitude = ((t_q64 + 1) >> 1) as i64;
    let t = if numerator < 0 {
        -t_magnitude
    } else {
        t_magnitude
    };
    let coefficients: &[i64] = if frac <= SHORT_POLYNOMIAL_MAX_FRAC {
        &ATAN_SHORT
    } else {
        &ATAN_LONG
    };
    let atan_t = mul_q63_q62(t, horner_q62(coefficients, square_q63_to_q62(t)));
    let theta = SEGMENT_ANGLE_Q61[segment] + (atan_t >> 1);
    if swapped {
        FRAC_PI_2_Q61 - theta
    } else {
        theta
    }
}

/// atan2(y, x): the angle of the point (x, y) from the +x axis, in radians, in (−π, π];
/// `atan2(0, 0)` is 0. Both inputs and the result have `frac` fractional bits; every pair
/// of `i64` values is valid (`i64::MIN` included).
///
/// Method: θ = atan(min(|x|,|y|) / max(|x|,|y|)) ∈ [0, π/4] by a segment reduction and a
/// minimax polynomial (see `atan_ratio_q61`), then the octant identities
/// atan2 = π/2 − θ when |y| > |x|, π − that when x < 0, and atan2(−y, x) = −atan2(y, x).
/// One 128-by-64-bit division; rounded to nearest once at the end.
///
/// The exact angle of a point with y < 0 just below the negative x axis is within half an
/// ulp of −π, so, as with IEEE `atan2(−0.0, −1.0)`, it can round to −[`PI`]: results lie in
/// [−PI, PI], with +PI for y = 0, x < 0.
///
/// Max error measured over 10⁷ samples per format (both components with random signs and
/// random magnitudes from 1 to 2⁶³ raw units):
///
/// | format | max error | in ulp |
/// |---|---|---|
/// | I32F32 | 1.180·10⁻¹⁰ (2⁻³²·⁹⁸) | 0.5066 (half an ulp + 2⁻³⁹·²) |
/// | I40F24 | 2.980·10⁻⁸ (2⁻²⁵·⁰⁰) | 0.5000 (half an ulp + 2⁻³⁹·⁵) |
/// | I48F16 | 7.629·10⁻⁶ (2⁻¹⁷·⁰⁰) | 0.5000 (half an ulp + 2⁻⁴⁰·⁹) |
/// | 48 fractional bits | 1.78·10⁻¹⁵ | 0.5001 |
/// | 60 fractional bits | 1.03·10⁻¹⁸ | 1.19 |
///
/// [`PI`]: super::Real::PI
#[inline]
pub(crate) fn atan2_bits(y: i64, x: i64, frac: u32) -> i64 {
    if x == 0 && y == 0 {
        return 0;
    }
    let first_quadrant = atan_ratio_q61(y.unsigned_abs(), x.unsigned_abs(), frac);
    let upper_half = if x < 0 {
        PI_Q61 - first_quadrant
    } else {
        first_quadrant
    };
    let angle = round_q61(upper_half, frac);
    if y < 0 { -angle } else { angle }
}

/// For x clamped to [−1, 1]: (|x|, √(1 − x²)) both in Q63 (as u64: 1 is 2⁶³).
///
/// |x| scaled to Q63 is exact (frac ≤ 63), so 1 − x² is exact in Q126 and its integer
/// square root is correct to the last of 63 fraction bits, even next to |x| = 1.
#[inline(always)]
fn sine_and_cosine_q63(x: i64, frac: u32) -> (u64, u64) {
    let sine = x.unsigned_abs().min(1 << frac) << (63 - frac);
    let cosine = ((1u128 << 126) - sine as u128 * sine as u128).isqrt() as u64;
    (sine, cosine)
}

/// asin x ∈ [−π/2, π/2], in radians; x is clamped to [−1, 1].
///
/// Method: asin x = atan2(x, √(1 − x²)) with 1 − x² computed exactly and its square root
/// correctly truncated in Q63, so the accuracy is that of the atan kernel everywhere,
/// including next to ±1 where the derivative of asin is unbounded. Odd by construction.
///
/// Max error measured over 10⁷ samples per format (half uniform over [−1, 1], half within
/// 2⁻¹⁰ of ±1):
///
/// | format | max error | in ulp |
/// |---|---|---|
/// | I32F32 | 1.180·10⁻¹⁰ (2⁻³²·⁹⁸) | 0.5066 (half an ulp + 2⁻³⁹·²) |
/// | I40F24 | 2.980·10⁻⁸ (2⁻²⁵·⁰⁰) | 0.5000 (half an ulp + 2⁻³⁹·⁵) |
/// | I48F16 | 7.629·10⁻⁶ (2⁻¹⁷·⁰⁰) | 0.5000 (correctly rounded in every sample) |
/// | 48 fractional bits | 1.78·10⁻¹⁵ | 0.5001 |
/// | 60 fractional bits | 1.11·10⁻¹⁸ | 1.28 |
#[inline]
pub(crate) fn asin_bits(x: i64, frac: u32) -> i64 {
    let (sine, cosine) = sine_and_cosine_q63(x, frac);
    let angle = round_q61(atan_ratio_q61(sine, cosine, frac), frac);
    if x < 0 { -angle } else { angle }
}

/// acos x ∈ [0, π], in radians; x is clamped to [−1, 1].
///
/// Method: acos x = atan2(√(1 − x²), x), computed as for [`asin_bits`]:
/// θ = atan(√(1 − x²) / |x|) and acos x = θ for x ≥ 0, π − θ for x < 0.
///
/// Max error measured over 10⁷ samples per format (half uniform over [−1, 1], half within
/// 2⁻¹⁰ of ±1):
///
/// | format | max error | in ulp |
/// |---|---|---|
/// | I32F32 | 1.180·10⁻¹⁰ (2⁻³²·⁹⁸) | 0.5066 (half an ulp + 2⁻³⁹·²) |
/// | I40F24 | 2.980·10⁻⁸ (2⁻²⁵·⁰⁰) | 0.5000 (half an ulp + 2⁻³⁹·³) |
/// | I48F16 | 7.629·10⁻⁶ (2⁻¹⁷·⁰⁰) | 0.5000 (correctly rounded in every sample) |
/// | 48 fractional bits | 1.78·10⁻¹⁵ | 0.5001 |
/// | 60 fractional bits | 1.01·10⁻¹⁸ | 1.16 |
#[inline]
pub(crate) fn acos_bits(x: i64, frac: u32) -> i64 {
    let (sine, cosine) = sine_and_cosine_q63(x, frac);
    let theta = atan_ratio_q61(cosine, sine, frac);
    round_q61(if x < 0 { PI_Q61 - theta } else { theta }, frac)
}
