//! Accuracy and edge cases of the integer trigonometry (sin, cos, sin_cos, atan2, asin,
//! acos) of the fixed-point formats, against `f64` references arranged so that their own
//! error (about 2⁻⁵²) is far below the bounds asserted.
//!
//! The bounds are "half an ulp of the format (the final rounding) plus the kernel's
//! internal error", the internal error being the measured maximum rounded up. The ignored
//! test `measure_max_errors` prints the figures quoted in `src/math/trig.rs`:
//! `cargo test --release --test suite math_trig:: -- --ignored --nocapture`.

use fixed::types::extra::{U16, U24, U32, U48, U60};
use fixstep::math::{Fixed, FracBits, Fx, FxI40F24, FxI48F16, Real};
use proptest::prelude::*;

/// π/2 · 2¹²⁵, rounded to nearest (mpmath): near-exact multiples of π/2 for the reduction
/// tests.
const FRAC_PI_2_Q125: i128 = 66_814_286_504_060_421_741_230_023_322_616_923_956;

fn ulp(frac: u32) -> f64 {
    (-f64::from(frac)).exp2()
}

fn frac_of<F: FracBits>() -> u32 {
    Fixed::<F>::FRAC_BITS
}

/// The allowed error of every kernel for a format: half an ulp for the final rounding plus
/// the internal error (polynomial, reduction, Q62 arithmetic) plus the reference's error.
fn bound(frac: u32) -> f64 {
    let internal = if frac <= 32 {
        2f64.powi(-38)
    } else {
        2f64.powi(-58)
    };
    0.5 * ulp(frac) + internal + 2f64.powi(-51)
}

/// (sin x, cos x) for x = bits / 2^frac, exact to about 2⁻⁵². `bits` can need 63
/// significant bits, more than an f64 holds, so x is split as high + low (each exact in
/// f64) and the angle-addition formulas combine the two halves.
fn reference_sin_cos(bits: i64, frac: u32) -> (f64, f64) {
    let low_bits = bits & 0xFF_FFFF;
    let high_bits = bits & !0xFF_FFFF;
    let (high, low) = (high_bits as f64 * ulp(frac), low_bits as f64 * ulp(frac));
    let (sin_high, cos_high) = high.sin_cos();
    let (sin_low, cos_low) = low.sin_cos();
    (
        sin_high * cos_low + cos_high * sin_low,
        cos_high * cos_low - sin_high * sin_low,
    )
}

/// (asin x, acos x) for x = bits / 2^frac clamped to [−1, 1], as atan2 of (x, √(1−x²)) with
/// 1 − x² = (1 − x)(1 + x) formed from exact integers, so the reference stays accurate next
/// to ±1.
fn reference_asin_acos(bits: i64, frac: u32) -> (f64, f64) {
    let one = 1i64 << frac;
    let clamped = bits.clamp(-one, one);
    let x = clamped as f64 * ulp(frac);
    let cosine = (((one - clamped) as f64) * ((one + clamped) as f64)).sqrt() * ulp(frac);
    (x.atan2(cosine), cosine.atan2(x))
}

/// Errors of (sin, cos) from `sin_cos`, after checking that `sin` and `cos` give the same
/// bits and that sin is odd and cos even.
fn sin_cos_errors<F: FracBits>(bits: i64) -> (f64, f64) {
    let x = Fixed::<F>::from_bits(bits);
    let (sin, cos) = x.sin_cos();
    assert_eq!(sin, x.sin(), "sin_cos().0 != sin() at bits {bits}");
    assert_eq!(cos, x.cos(), "sin_cos().1 != cos() at bits {bits}");
    if bits != i64::MIN {
        let minus = Fixed::<F>::from_bits(-bits);
        assert_eq!(
            minus.sin().to_bits(),
            -sin.to_bits(),
            "sin not odd at {bits}"
        );
        assert_eq!(minus.cos(), cos, "cos not even at {bits}");
    }
    let (sin_ref, cos_ref) = reference_sin_cos(bits, frac_of::<F>());
    (
        (sin.to_f64() - sin_ref).abs(),
        (cos.to_f64() - cos_ref).abs(),
    )
}

fn atan2_error<F: FracBits>(y: i64, x: i64) -> f64 {
    let angle = Fixed::<F>::from_bits(y).atan2(Fixed::<F>::from_bits(x));
    let pi = Fixed::<F>::PI.to_bits();
    assert!(
        (-pi..=pi).contains(&angle.to_bits()),
        "atan2({y}, {x}) = {angle} outside [-PI, PI]"
    );
    let reference = if x == 0 && y == 0 {
        0.0
    } else {
        (y as f64).atan2(x as f64)
    };
    (angle.to_f64() - reference).abs()
}

/// Errors of (asin, acos), after checking asin is odd.
fn asin_acos_errors<F: FracBits>(bits: i64) -> (f64, f64) {
    let x = Fixed::<F>::from_bits(bits);
    let (asin, acos) = (x.asin(), x.acos());
    if bits != i64::MIN {
        assert_eq!(
            Fixed::<F>::from_bits(-bits).asin().to_bits(),
            -asin.to_bits()
        );
    }
    let (asin_ref, acos_ref) = reference_asin_acos(bits, frac_of::<F>());
    (
        (asin.to_f64() - asin_ref).abs(),
        (acos.to_f64() - acos_ref).abs(),
    )
}

fn assert_sin_cos<F: FracBits>(bits: i64) {
    let (sin_error, cos_error) = sin_cos_errors::<F>(bits);
    let limit = bound(frac_of::<F>());
    assert!(
        sin_error <= limit && cos_error <= limit,
        "F={} bits={bits}: sin error {sin_error:e}, cos error {cos_error:e}, bound {limit:e}",
        frac_of::<F>()
    );
}

fn assert_atan2<F: FracBits>(y: i64, x: i64) {
    let error = atan2_error::<F>(y, x);
    let limit = bound(frac_of::<F>());
    assert!(
        error <= limit,
        "F={} atan2({y}, {x}) error {error:e}, bound {limit:e}",
        frac_of::<F>()
    );
}

fn assert_asin_acos<F: FracBits>(bits: i64) {
    let (asin_error, acos_error) = asin_acos_errors::<F>(bits);
    let limit = bound(frac_of::<F>());
    assert!(
        asin_error <= limit && acos_error <= limit,
        "F={} bits={bits}: asin error {asin_error:e}, acos error {acos_error:e}, bound {limit:e}",
        frac_of::<F>()
    );
}

/// π/2 in Q(frac + 60): k times it stays below 2¹²⁴ for every representable k·π/2, and its
/// error moves k·π/2 by less than one ulp.
fn frac_pi_2_wide(frac: u32) -> i128 {
    FRAC_PI_2_Q125 >> (65 - frac)
}

/// The bits nearest k·π/2, plus `offset` ulps.
fn near_multiple_of_half_pi(k: i64, offset: i64, frac: u32) -> i64 {
    let rounded = (i128::from(k) * frac_pi_2_wide(frac) + (1 << 59)) >> 60;
    (rounded + i128::from(offset)).clamp(i64::MIN.into(), i64::MAX.into()) as i64
}

/// The largest k for which k·π/2 is representable.
fn max_half_pi_multiple(frac: u32) -> i64 {
    ((i128::from(i64::MAX) << 60) / frac_pi_2_wide(frac)) as i64
}

proptest! {
    #![proptest_config(crate::property_cases::fixed_cases(4096))]

    #[test]
    fn sin_cos_of_every_bit_pattern(bits: i64) {
        assert_sin_cos::<U32>(bits);
        assert_sin_cos::<U24>(bits);
        assert_sin_cos::<U16>(bits);
        assert_sin_cos::<U48>(bits);
        assert_sin_cos::<U60>(bits);
    }

    #[test]
    fn sin_cos_near_multiples_of_half_pi(k: i64, offset in -1000i64..1000) {
        for frac in [16u32, 24, 32] {
            let k = k % max_half_pi_multiple(frac);
            let bits = near_multiple_of_half_pi(k, offset, frac);
            match frac {
                16 => assert_sin_cos::<U16>(bits),
                24 => assert_sin_cos::<U24>(bits),
                _ => assert_sin_cos::<U32>(bits),
            }
        }
    }

    #[test]
    fn atan2_of_every_bit_pattern(y: i64, x: i64) {
        assert_atan2::<U32>(y, x);
        assert_atan2::<U24>(y, x);
        assert_atan2::<U16>(y, x);
        assert_atan2::<U48>(y, x);
    }

    #[test]
    fn atan2_of_mixed_magnitudes(y: i64, x: i64, y_shift in 0u32..64, x_shift in 0u32..64) {
        let (y, x) = (y >> y_shift, x >> x_shift);
        assert_atan2::<U32>(y, x);
        assert_atan2::<U24>(y, x);
        assert_atan2::<U16>(y, x);
        assert_atan2::<U48>(y, x);
    }

    #[test]
    fn asin_acos_inside_the_domain(unit in -(1i64 << 32)..=(1i64 << 32)) {
        assert_asin_acos::<U32>(unit);
        assert_asin_acos::<U24>(unit >> 8);
        assert_asin_acos::<U16>(unit >> 16);
        assert_asin_acos::<U48>(unit << 16);
        assert_asin_acos::<U60>(unit << 28);
    }

    #[test]
    fn asin_acos_clamp_outside_the_domain(bits: i64) {
        let x = Fx::from_bits(bits);
        let clamped = Real::clamp(x, -Fx::ONE, Fx::ONE);
        prop_assert_eq!(x.asin(), clamped.asin());
        prop_assert_eq!(x.acos(), clamped.acos());
        assert_asin_acos::<U32>(bits);
        assert_asin_acos::<U16>(bits);
    }
}

#[test]
fn sin_cos_dense_over_four_turns() {
    // [−4π, 4π] in about 2·10⁶ steps; the odd step visits every residue of the low bits.
    let span = Fx::from_f64(4.0 * core::f64::consts::PI).to_bits();
    for bits in (-span..=span).step_by(53_681) {
        assert_sin_cos::<U32>(bits);
    }
    let span = FxI40F24::from_f64(4.0 * core::f64::consts::PI).to_bits();
    for bits in (-span..=span).step_by(211) {
        assert_sin_cos::<U24>(bits);
    }
    // I48F16: every value in [−4π, 4π].
    let span = FxI48F16::from_f64(4.0 * core::f64::consts::PI).to_bits();
    for bits in -span..=span {
        assert_sin_cos::<U16>(bits);
    }
}

#[test]
fn sin_cos_at_special_points() {
    for bits in [0, 1, -1, i64::MAX, i64::MIN, i64::MAX - 1, i64::MIN + 1] {
        assert_sin_cos::<U32>(bits);
        assert_sin_cos::<U16>(bits);
        assert_sin_cos::<U60>(bits);
    }
    assert_eq!(Fx::ZERO.sin(), Fx::ZERO);
    assert_eq!(Fx::ZERO.cos(), Fx::ONE);
    assert_eq!(Fx::FRAC_PI_2.sin(), Fx::ONE);
    assert_eq!(Fx::PI.cos(), -Fx::ONE);
    assert_eq!(FxI48F16::FRAC_PI_2.sin(), FxI48F16::ONE);
    // The largest multiples of π/2 the formats hold, and their neighbours.
    for frac in [16u32, 24, 32] {
        let k_max = max_half_pi_multiple(frac);
        for k in [k_max, k_max - 1, k_max - 2, k_max - 3, -k_max] {
            for offset in -3..=3 {
                let bits = near_multiple_of_half_pi(k, offset, frac);
                match frac {
                    16 => assert_sin_cos::<U16>(bits),
                    24 => assert_sin_cos::<U24>(bits),
                    _ => assert_sin_cos::<U32>(bits),
                }
            }
        }
    }
}

#[test]
fn atan2_axes_zero_and_extremes() {
    let atan2 = |y: i64, x: i64| Fx::from_bits(y).atan2(Fx::from_bits(x));
    assert_eq!(atan2(0, 0), Fx::ZERO);
    assert_eq!(atan2(0, 1), Fx::ZERO);
    assert_eq!(atan2(0, i64::MAX), Fx::ZERO);
    assert_eq!(atan2(0, -1), Fx::PI);
    assert_eq!(atan2(0, i64::MIN), Fx::PI);
    assert_eq!(atan2(1, 0), Fx::FRAC_PI_2);
    assert_eq!(atan2(i64::MIN, 0), -Fx::FRAC_PI_2);
    assert_eq!(atan2(5, 5), Fx::from_f64(core::f64::consts::FRAC_PI_4));
    assert_eq!(
        atan2(-7, -7),
        Fx::from_f64(-3.0 * core::f64::consts::FRAC_PI_4)
    );
    let extremes = [0, 1, -1, i64::MAX, i64::MIN, i64::MAX - 1, i64::MIN + 1];
    for y in extremes {
        for x in extremes {
            assert_atan2::<U32>(y, x);
            assert_atan2::<U24>(y, x);
            assert_atan2::<U16>(y, x);
            assert_atan2::<U48>(y, x);
            assert_atan2::<U60>(y, x);
        }
    }
}

#[test]
fn atan2_small_integer_grid() {
    // Every (y, x) with |x|, |y| ≤ 64 raw units: all octant boundaries and segment splits.
    for y in -64..=64 {
        for x in -64..=64 {
            assert_atan2::<U32>(y, x);
            assert_atan2::<U16>(y, x);
        }
    }
}

#[test]
fn atan2_dense_around_the_circle() {
    // Points on circles of several radii, every 2⁻¹⁴ turn, in all four quadrants.
    for radius in [1e-9, 3e-4, 1.0, 1234.5, 2.0e9] {
        for step in 0..(1 << 14) {
            let angle = std::f64::consts::TAU * f64::from(step) / f64::from(1 << 14);
            let y = Fx::from_f64(radius * angle.sin()).to_bits();
            let x = Fx::from_f64(radius * angle.cos()).to_bits();
            assert_atan2::<U32>(y, x);
        }
    }
}

#[test]
fn asin_acos_dense_and_next_to_one() {
    let one = 1i64 << 32;
    for bits in (-one..=one).step_by(2_011) {
        assert_asin_acos::<U32>(bits);
    }
    for distance in 0..100_000 {
        assert_asin_acos::<U32>(one - distance);
        assert_asin_acos::<U32>(distance - one);
    }
    // I48F16: every value in [−1, 1]; I40F24: every value within 2⁻¹² of ±1.
    for bits in -(1 << 16)..=(1 << 16) {
        assert_asin_acos::<U16>(bits);
    }
    for distance in 0..(1 << 12) {
        assert_asin_acos::<U24>((1 << 24) - distance);
        assert_asin_acos::<U24>(distance - (1 << 24));
    }
    assert_eq!(Fx::ONE.asin(), Fx::FRAC_PI_2);
    assert_eq!((-Fx::ONE).asin(), -Fx::FRAC_PI_2);
    assert_eq!(Fx::ONE.acos(), Fx::ZERO);
    assert_eq!((-Fx::ONE).acos(), Fx::PI);
    assert_eq!(Fx::ZERO.asin(), Fx::ZERO);
    assert_eq!(Fx::MAX.asin(), Fx::FRAC_PI_2);
    assert_eq!(Fx::MIN.acos(), Fx::PI);
}

/// Splitmix64: a reproducible stream for the measurement sweep.
struct Stream(u64);

impl Stream {
    fn next(&mut self) -> i64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        (z ^ (z >> 31)) as i64
    }
}

/// Max absolute error of each kernel over 10⁷ samples per format, printed as the figures
/// quoted in the kernels' documentation.
fn measure<F: FracBits>() {
    const SAMPLES: i64 = 10_000_000;
    let frac = frac_of::<F>();
    let mut stream = Stream(u64::from(frac));
    let (mut sin_max, mut cos_max, mut atan2_max, mut asin_max, mut acos_max) =
        (0f64, 0f64, 0f64, 0f64, 0f64);
    // sin/cos: half all bit patterns, half dense over [−4π, 4π].
    let span = Fixed::<F>::from_f64(4.0 * core::f64::consts::PI).to_bits();
    for i in 0..SAMPLES {
        let bits = if i % 2 == 0 {
            stream.next()
        } else {
            -span + ((2 * span) as i128 * i128::from(i) / i128::from(SAMPLES)) as i64
        };
        let (sin_error, cos_error) = sin_cos_errors::<F>(bits);
        sin_max = sin_max.max(sin_error);
        cos_max = cos_max.max(cos_error);
    }
    // atan2: both components with random magnitudes (random shifts) and signs.
    for _ in 0..SAMPLES {
        let shifts = stream.next() as u64;
        let y = stream.next() >> (shifts % 64);
        let x = stream.next() >> ((shifts >> 8) % 64);
        atan2_max = atan2_max.max(atan2_error::<F>(y, x));
    }
    // asin/acos: half uniform over [−1, 1], half within 2⁻¹⁰ of ±1.
    let one = 1i64 << frac;
    for i in 0..SAMPLES {
        let r = stream.next().rem_euclid(2 * one + 1) - one;
        let bits = if i % 2 == 0 {
            r
        } else {
            let near = (r.unsigned_abs() as i64) >> 10;
            if r < 0 { near - one } else { one - near }
        };
        let (asin_error, acos_error) = asin_acos_errors::<F>(bits);
        asin_max = asin_max.max(asin_error);
        acos_max = acos_max.max(acos_error);
    }
    let show = |name: &str, error: f64| {
        let beyond_rounding = error - 0.5 * ulp(frac);
        let excess = if beyond_rounding > 0.0 {
            format!("half an ulp + 2^{:.1}", beyond_rounding.log2())
        } else {
            "within half an ulp".to_owned()
        };
        println!(
            "F={frac:2} {name:5} max error {error:.3e} (2^{:.2}) = {:.4} ulp: {excess}",
            error.log2(),
            error / ulp(frac)
        );
    };
    show("sin", sin_max);
    show("cos", cos_max);
    show("atan2", atan2_max);
    show("asin", asin_max);
    show("acos", acos_max);
}

#[test]
#[ignore = "slow: 5·10⁷ samples per format; prints the figures quoted in trig.rs"]
fn measure_max_errors() {
    measure::<U32>();
    measure::<U24>();
    measure::<U16>();
    measure::<U48>();
}

/// FNV-1a over the little-endian bytes of every result of every kernel, for 2·10⁴ inputs
/// per format.
fn digest_of_results<F: FracBits>(digest: &mut u64) {
    let mut stream = Stream(0x7419);
    let mut feed = |value: Fixed<F>| {
        for byte in value.to_bits().to_le_bytes() {
            *digest = (*digest ^ u64::from(byte)).wrapping_mul(0x0100_0000_01B3);
        }
    };
    for _ in 0..20_000 {
        let shifts = stream.next() as u64;
        let a = Fixed::<F>::from_bits(stream.next() >> (shifts % 64));
        let b = Fixed::<F>::from_bits(stream.next() >> ((shifts >> 8) % 64));
        let (sin, cos) = a.sin_cos();
        feed(sin);
        feed(cos);
        feed(a.atan2(b));
        feed(a.asin());
        feed(a.acos());
    }
}

/// The kernels are part of the determinism contract: replays and checksums depend on their
/// exact bits, on every target. This digest pins them; a deliberate change to a kernel must
/// update it (and invalidates recorded replays).
#[test]
fn results_are_pinned_bit_for_bit() {
    let mut digest = 0xCBF2_9CE4_8422_2325;
    digest_of_results::<U32>(&mut digest);
    digest_of_results::<U24>(&mut digest);
    digest_of_results::<U16>(&mut digest);
    digest_of_results::<U60>(&mut digest);
    assert_eq!(digest, 0x25E6_69F0_7506_0919, "digest {digest:#018x}");
}
