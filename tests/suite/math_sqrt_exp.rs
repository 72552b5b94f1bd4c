//! √x, 1/√x, eˣ, ln x and xʸ of the fixed-point formats: accuracy, edge cases, saturation
//! counting and bit-exact golden values.
//!
//! References: √ is compared with an exact `u128` integer square root, 1/√ with an exact
//! 256-bit integer comparison, and exp/ln/powf with `f64` on the exactly converted inputs
//! (the tolerances below include the `f64` reference's own error).

use core::cmp::Ordering;

use fixed::types::extra::{U8, U16, U24, U32, U60};
use fixstep::math::saturation::{count_saturations, reset_saturation_count, saturation_count};
use fixstep::math::{Fixed, FracBits, Fx, FxI40F24, FxI48F16, Real};
use proptest::prelude::*;

// ---------------------------------------------------------------------------------------
// Helpers
// ---------------------------------------------------------------------------------------

/// A small deterministic generator for the sweeps (SplitMix64).
struct SplitMix(u64);

impl SplitMix {
    fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        z ^ (z >> 31)
    }

    /// Uniform in [0, 1).
    fn unit(&mut self) -> f64 {
        (self.next() >> 11) as f64 / (1u64 << 53) as f64
    }

    /// Non-negative bits with a log-uniform magnitude: every bit length is equally likely.
    fn log_uniform_bits(&mut self) -> i64 {
        let shift = self.next() % 64;
        ((self.next() >> 1) >> shift) as i64
    }
}

fn frac_of<F: FracBits>() -> u32 {
    Fixed::<F>::FRAC_BITS
}

/// One ulp of a format, as f64.
fn ulp<F: FracBits>() -> f64 {
    (-(frac_of::<F>() as f64)).exp2()
}

/// round(√(bits · 2^frac)) exactly: the correctly rounded √ of the value, in raw bits.
fn reference_sqrt(bits: i64, frac: u32) -> i64 {
    if bits <= 0 {
        return 0;
    }
    let n = (bits as u128) << frac;
    let floor = n.isqrt();
    // Round up exactly when n − floor² > floor (ties are impossible for integers).
    (if n - floor * floor > floor {
        floor + 1
    } else {
        floor
    }) as i64
}

/// 256-bit product of two u128, as (high, low).
fn mul_u256(a: u128, b: u128) -> (u128, u128) {
    let mask = u64::MAX as u128;
    let (a_hi, a_lo) = (a >> 64, a & mask);
    let (b_hi, b_lo) = (b >> 64, b & mask);
    let lo_lo = a_lo * b_lo;
    let hi_lo = a_hi * b_lo;
    let lo_hi = a_lo * b_hi;
    let hi_hi = a_hi * b_hi;
    let middle = (lo_lo >> 64) + (hi_lo & mask) + (lo_hi & mask);
    let low = (lo_lo & mask) | (middle << 64);
    let high = hi_hi + (hi_lo >> 64) + (lo_hi >> 64) + (middle >> 64);
    (high, low)
}

/// Compares q²·n with 2^e exactly (q < 2^64, n < 2^124, e < 256).
fn compare_square_times(q: u128, n: u128, e: u32) -> Ordering {
    let product = mul_u256(q * q, n);
    let power = if e >= 128 {
        (1u128 << (e - 128), 0)
    } else {
        (0, 1u128 << e)
    };
    product.cmp(&power)
}

/// How far an rsqrt result `q` is from the true v = 2^(2F)/√(x·2^F), decided exactly:
/// 0 = correctly rounded (|q − v| ≤ ½), 1 = within one ulp, 2 = further.
fn rsqrt_error_class(bits: i64, frac: u32, q: i64) -> u32 {
    let n = (bits as u128) << frac;
    let q = q as u128;
    // q − d ≤ v  ⇔  (q − d)²·n ≤ 2^(4F), and v ≤ q + d  ⇔  (q + d)²·n ≥ 2^(4F); for
    // d = ½ both sides are multiplied by 4.
    let within = |below: u128, above: u128, e: u32| {
        (below == 0 || compare_square_times(below, n, e) != Ordering::Greater)
            && compare_square_times(above, n, e) != Ordering::Less
    };
    if within((2 * q).saturating_sub(1), 2 * q + 1, 4 * frac + 2) {
        0
    } else if within(q.saturating_sub(1), q + 1, 4 * frac) {
        1
    } else {
        2
    }
}

// ---------------------------------------------------------------------------------------
// √x: correctly rounded, compared exactly
// ---------------------------------------------------------------------------------------

fn assert_sqrt_exact<F: FracBits>(bits: i64) {
    let got = Fixed::<F>::from_bits(bits).sqrt().to_bits();
    assert_eq!(
        got,
        reference_sqrt(bits, frac_of::<F>()),
        "sqrt of bits {bits} with {} fractional bits",
        frac_of::<F>()
    );
}

/// Inputs that stress the rounding: every small value, powers of two and their
/// neighbours, the ends of the range, and the neighbours of exact squares and of the
/// rounding midpoints (q + ½)² of random roots q.
fn sqrt_sweep<F: FracBits>(samples: usize) {
    let frac = frac_of::<F>();
    for bits in 0..20_000 {
        assert_sqrt_exact::<F>(bits);
    }
    for shift in 0..63 {
        for delta in -2..=2 {
            assert_sqrt_exact::<F>((1i64 << shift).saturating_add(delta));
        }
    }
    for bits in [i64::MAX, i64::MAX - 1, i64::MIN, i64::MIN + 1, -1] {
        assert_sqrt_exact::<F>(bits);
    }
    let mut rng = SplitMix(0x5eed_0001 + u64::from(frac));
    let max_root = ((i64::MAX as u128) << frac).isqrt();
    for _ in 0..samples {
        assert_sqrt_exact::<F>(rng.log_uniform_bits());
        // n = q² and n = q² + q (the midpoint (q + ½)² rounded down), mapped back to bits.
        let q = (rng.next() as u128 >> (rng.next() % 64)).min(max_root);
        for n in [q * q, q * q + q] {
            let bits = (n >> frac) as i64;
            for delta in -1..=1 {
                assert_sqrt_exact::<F>(bits.saturating_add(delta).max(0));
            }
        }
    }
}

#[test]
fn sqrt_is_correctly_rounded_i32f32() {
    sqrt_sweep::<U32>(1_000_000);
}

#[test]
fn sqrt_is_correctly_rounded_i48f16() {
    sqrt_sweep::<U16>(1_000_000);
}

#[test]
fn sqrt_is_correctly_rounded_i40f24() {
    sqrt_sweep::<U24>(1_000_000);
}

#[test]
fn sqrt_is_correctly_rounded_at_the_extreme_formats() {
    sqrt_sweep::<U8>(50_000);
    sqrt_sweep::<U60>(50_000);
}

proptest! {
    #![proptest_config(crate::property_cases::fixed_cases(20_000))]

    #[test]
    fn sqrt_matches_exact_reference_over_all_bits(bits in 0..=i64::MAX, shift in 0u32..64) {
        // Both the uniform bits and a log-uniform magnitude.
        for b in [bits, bits >> shift] {
            prop_assert_eq!(Fx::from_bits(b).sqrt().to_bits(), reference_sqrt(b, 32));
            prop_assert_eq!(FxI48F16::from_bits(b).sqrt().to_bits(), reference_sqrt(b, 16));
            prop_assert_eq!(FxI40F24::from_bits(b).sqrt().to_bits(), reference_sqrt(b, 24));
        }
    }

    #[test]
    fn rsqrt_is_within_one_ulp_over_all_bits(bits in 1..=i64::MAX, shift in 0u32..64) {
        for b in [bits, (bits >> shift).max(1)] {
            prop_assert!(rsqrt_error_class(b, 32, Fx::from_bits(b).rsqrt().to_bits()) <= 1);
            prop_assert!(rsqrt_error_class(b, 16, FxI48F16::from_bits(b).rsqrt().to_bits()) <= 1);
            prop_assert!(rsqrt_error_class(b, 24, FxI40F24::from_bits(b).rsqrt().to_bits()) <= 1);
        }
    }
}

#[test]
fn sqrt_of_negative_is_zero_and_not_counted() {
    let (result, saturations) = count_saturations(|| Fx::from_int(-4).sqrt());
    assert_eq!(result, Fx::ZERO);
    assert_eq!(saturations, 0);
    assert_eq!(Fx::MIN.sqrt(), Fx::ZERO);
}

#[test]
fn sqrt_of_perfect_squares_is_exact() {
    for k in 0..=46_340 {
        assert_eq!(Fx::from_int(k * k).sqrt(), Fx::from_int(k));
    }
    assert_eq!(Fx::from_ratio(1, 4).sqrt(), Fx::HALF);
}

// ---------------------------------------------------------------------------------------
// 1/√x: within one ulp, compared exactly
// ---------------------------------------------------------------------------------------

/// Counts results that are not correctly rounded and asserts none is more than one ulp off.
fn rsqrt_sweep<F: FracBits>(samples: usize) -> usize {
    let frac = frac_of::<F>();
    let mut not_nearest = 0;
    let mut check = |bits: i64| {
        let q = Fixed::<F>::from_bits(bits).rsqrt().to_bits();
        if q == i64::MAX {
            // Saturated: the true value must be at least i64::MAX − 1.
            let n = (bits as u128) << frac;
            let below = compare_square_times(i64::MAX as u128 - 1, n, 4 * frac);
            assert_ne!(
                below,
                Ordering::Greater,
                "rsqrt of bits {bits} saturated early"
            );
            return;
        }
        match rsqrt_error_class(bits, frac, q) {
            0 => {}
            1 => not_nearest += 1,
            _ => panic!("rsqrt of bits {bits} with {frac} fractional bits is {q}: over 1 ulp"),
        }
    };
    for bits in 1..20_000 {
        check(bits);
    }
    for shift in 0..63 {
        for delta in -2..=2 {
            check((1i64 << shift).saturating_add(delta).max(1));
        }
    }
    check(i64::MAX);
    let mut rng = SplitMix(0x5eed_0002 + u64::from(frac));
    for _ in 0..samples {
        check(rng.log_uniform_bits().max(1));
    }
    not_nearest
}

#[test]
fn rsqrt_is_within_one_ulp_and_correctly_rounded_up_to_32_fraction_bits() {
    // Measured: every sampled result is the correctly rounded one for F ≤ 32.
    assert_eq!(
        rsqrt_sweep::<U32>(1_000_000),
        0,
        "I32F32 results not correctly rounded"
    );
    assert_eq!(
        rsqrt_sweep::<U16>(1_000_000),
        0,
        "I48F16 results not correctly rounded"
    );
    assert_eq!(
        rsqrt_sweep::<U24>(1_000_000),
        0,
        "I40F24 results not correctly rounded"
    );
    assert_eq!(
        rsqrt_sweep::<U8>(50_000),
        0,
        "I56F8 results not correctly rounded"
    );
    // With 60 fraction bits the results carry up to 63 significant bits, and true values
    // within about 2⁻⁴ ulp of a rounding midpoint may round the other way (still ≤ 1 ulp).
    assert!(rsqrt_sweep::<U60>(50_000) <= 10);
}

#[test]
fn rsqrt_of_zero_and_negative_saturates_and_counts() {
    reset_saturation_count();
    assert_eq!(Fx::ZERO.rsqrt(), Fx::MAX);
    assert_eq!(saturation_count(), 1);
    assert_eq!(Fx::from_int(-1).rsqrt(), Fx::MAX);
    assert_eq!(FxI48F16::MIN.rsqrt(), FxI48F16::MAX);
    assert_eq!(saturation_count(), 3);
    // Ordinary values do not count.
    assert_eq!(Fx::from_int(4).rsqrt(), Fx::HALF);
    assert_eq!(Fx::ONE.rsqrt(), Fx::ONE);
    assert_eq!(saturation_count(), 3);
}

#[test]
fn rsqrt_saturates_only_when_the_result_does_not_fit() {
    // I32F32: 1/√(2^-32) = 2^16 fits.
    let (r, sats) = count_saturations(|| Fx::EPSILON.rsqrt());
    assert_eq!((r, sats), (Fx::from_int(65_536), 0));
    // I4F60: 1/√(2^-60) = 2^30 does not fit in ±8.
    let (r, sats) = count_saturations(|| Fixed::<U60>::EPSILON.rsqrt());
    assert_eq!((r, sats), (Fixed::<U60>::MAX, 1));
    // Tiny results round to zero without counting (I56F8: 1/√(2^55) < 2^-9).
    let (r, sats) = count_saturations(|| Fixed::<U8>::MAX.rsqrt());
    assert_eq!((r, sats), (Fixed::<U8>::ZERO, 0));
}

// ---------------------------------------------------------------------------------------
// eˣ
// ---------------------------------------------------------------------------------------

/// Asserts |error| ≤ 0.5 ulp + 2⁻¹⁰ ulp + 2⁻⁵⁰·|result|: correctly rounded up to the
/// noise of the f64 reference (below 2⁻¹² ulp for results under 2^40 ulps, relative 2⁻⁵²
/// above). Returns the largest error in ulps over results below 2^40 ulps, and the largest
/// relative error over results of at least 2^26 ulps (where ½ ulp is below 2⁻²⁶ relative).
fn exp_sweep<F: FracBits>(samples: usize) -> (f64, f64) {
    let frac = frac_of::<F>();
    let scale = 1.0 / ulp::<F>();
    // The representable range: e^x · 2^F < 2^63 and e^x · 2^F ≥ ½.
    let hi = (63 - frac as i32) as f64 * core::f64::consts::LN_2;
    let lo = -(frac as f64 + 1.0) * core::f64::consts::LN_2;
    let relative_from = (1u64 << 26) as f64;
    let (mut max_ulps, mut max_relative) = (0.0f64, 0.0f64);
    let mut check = |bits: i64| {
        let x = Fixed::<F>::from_bits(bits);
        let exact = x.to_f64().exp() * scale; // in ulps
        let got = x.exp().to_bits();
        if exact >= 9.2e18 {
            // At the top of the range only check that saturation is not premature.
            assert!(got >= 9.1e18 as i64, "exp({}) = {got} bits", x.to_f64());
            return;
        }
        let error = (got as f64 - exact).abs();
        assert!(
            error <= 0.5 + 1.0 / 1024.0 + exact * (-50f64).exp2(),
            "exp({}) with {frac} fractional bits: {got} bits, exact {exact}",
            x.to_f64()
        );
        if exact < (1u64 << 40) as f64 {
            max_ulps = max_ulps.max(error);
        }
        if exact >= relative_from {
            max_relative = max_relative.max(error / exact);
        }
    };
    // Dense: every input in a window around 0, then an even grid over the whole range.
    for bits in -20_000..20_000 {
        check(bits);
    }
    let lo_bits = (lo * scale) as i64 - 4;
    let hi_bits = (hi * scale) as i64;
    let step = ((hi_bits - lo_bits) / samples as i64).max(1);
    let mut bits = lo_bits;
    while bits < hi_bits {
        check(bits);
        bits += step;
    }
    let mut rng = SplitMix(0x5eed_0003 + u64::from(frac));
    for _ in 0..samples {
        check(((lo + (hi - lo) * rng.unit()) * scale) as i64);
    }
    (max_ulps, max_relative)
}

#[test]
fn exp_is_correctly_rounded_up_to_reference_noise() {
    for (ulps, relative) in [
        exp_sweep::<U32>(1_000_000),
        exp_sweep::<U16>(1_000_000),
        exp_sweep::<U24>(1_000_000),
        exp_sweep::<U8>(50_000),
    ] {
        // The specification: relative error ≤ 2⁻²⁶ where representable, ≤ 2 ulp when small.
        assert!(
            ulps <= 2.0 && relative <= (-26f64).exp2(),
            "{ulps} ulp, {relative}"
        );
    }
}

#[test]
fn exp_exact_values_and_edges() {
    assert_eq!(Fx::ZERO.exp(), Fx::ONE);
    assert_eq!(FxI48F16::ZERO.exp(), FxI48F16::ONE);
    assert_eq!(Fixed::<U60>::ZERO.exp(), Fixed::<U60>::ONE);
    // Far below the range: 0, not counted.
    for x in [Fx::MIN, Fx::from_int(-23), Fx::from_int(-1_000_000)] {
        assert_eq!(count_saturations(|| x.exp()), (Fx::ZERO, 0));
    }
    // Monotone across the representable range of I32F32, sampled.
    let mut previous = Fx::ZERO;
    let mut bits = -23i64 << 32;
    while bits < 21i64 << 32 {
        let value = Fx::from_bits(bits).exp();
        assert!(value >= previous);
        previous = value;
        bits += 1 << 20;
    }
}

#[test]
fn exp_of_huge_input_saturates_and_counts() {
    reset_saturation_count();
    assert_eq!(Fx::from_int(22).exp(), Fx::MAX);
    assert_eq!(saturation_count(), 1);
    assert_eq!(Fx::MAX.exp(), Fx::MAX);
    assert_eq!(FxI48F16::MAX.exp(), FxI48F16::MAX);
    assert_eq!(saturation_count(), 3);
    // e^21 fits in I32F32 and does not count.
    assert!(Fx::from_int(21).exp() < Fx::MAX);
    assert_eq!(saturation_count(), 3);
}

// ---------------------------------------------------------------------------------------
// ln x
// ---------------------------------------------------------------------------------------

/// Largest |error| in ulps, after asserting it is at most 0.5 ulp + 2⁻¹⁰ ulp. The f64
/// reference is good to about 2⁻⁴⁷ absolute, below 2⁻¹⁵ ulp for F ≤ 32.
fn ln_sweep<F: FracBits>(samples: usize) -> f64 {
    let frac = frac_of::<F>();
    let scale = 1.0 / ulp::<F>();
    let mut max_ulps = 0.0f64;
    let mut check = |bits: i64| {
        let x = Fixed::<F>::from_bits(bits);
        let exact = x.to_f64().ln() * scale;
        let got = x.ln().to_bits();
        let error = (got as f64 - exact).abs();
        max_ulps = max_ulps.max(error);
        assert!(
            error <= 0.5 + 1.0 / 1024.0,
            "ln({}) with {frac} fractional bits: {got} bits, exact {exact}",
            x.to_f64()
        );
    };
    let one = 1i64 << frac;
    for bits in 1..20_000 {
        check(bits);
    }
    for bits in (one - 20_000).max(1)..one + 20_000 {
        check(bits);
    }
    for bits in [i64::MAX, i64::MAX - 1, 1i64 << 62] {
        check(bits);
    }
    let mut rng = SplitMix(0x5eed_0004 + u64::from(frac));
    for _ in 0..samples {
        check(rng.log_uniform_bits().max(1));
        check((one as f64 * (0.5 + 1.5 * rng.unit())) as i64);
    }
    max_ulps
}

#[test]
fn ln_is_correctly_rounded_up_to_reference_noise() {
    // The specification: absolute error ≤ 2⁻²⁶, or ≤ 1 ulp where the ulp is coarser.
    assert!(ln_sweep::<U32>(1_000_000) * (-32f64).exp2() <= (-26f64).exp2());
    assert!(ln_sweep::<U16>(1_000_000) <= 1.0);
    assert!(ln_sweep::<U24>(1_000_000) <= 1.0);
    assert!(ln_sweep::<U8>(50_000) <= 1.0);
}

#[test]
fn ln_exact_values_and_edges() {
    assert_eq!(Fx::ONE.ln(), Fx::ZERO);
    assert_eq!(FxI48F16::ONE.ln(), FxI48F16::ZERO);
    assert_eq!(Fx::TWO.ln(), Fx::from_f64(core::f64::consts::LN_2));
    assert_eq!(
        Fx::EPSILON.ln(),
        Fx::from_f64(-32.0 * core::f64::consts::LN_2)
    );
    // I4F60 holds ±8: ln of its smallest value (−41.6) saturates and counts.
    assert_eq!(
        count_saturations(|| Fixed::<U60>::EPSILON.ln()),
        (Fixed::<U60>::MIN, 1)
    );
    assert_eq!(
        count_saturations(|| Fixed::<U60>::ONE.ln()),
        (Fixed::<U60>::ZERO, 0)
    );
}

#[test]
fn ln_of_zero_and_negative_saturates_and_counts() {
    reset_saturation_count();
    assert_eq!(Fx::ZERO.ln(), Fx::MIN);
    assert_eq!(saturation_count(), 1);
    assert_eq!(Fx::from_int(-3).ln(), Fx::MIN);
    assert_eq!(FxI40F24::MIN.ln(), FxI40F24::MIN);
    assert_eq!(saturation_count(), 3);
    let _ = Fx::from_int(3).ln();
    assert_eq!(saturation_count(), 3);
}

// ---------------------------------------------------------------------------------------
// xʸ
// ---------------------------------------------------------------------------------------

/// Error of `x.powf(y)` against f64 on the exact inputs, in ulps, with the bound
/// 0.5 ulp + 2⁻¹⁰ ulp + 2⁻⁵⁰·|result| (the last term covers the f64 reference and the
/// amplification of the kernels' 2⁻⁶² errors by |y ln x|). Returns (ulps, relative).
fn powf_error<F: FracBits>(x: Fixed<F>, y: Fixed<F>) -> (f64, f64) {
    let scale = 1.0 / ulp::<F>();
    let exact = x.to_f64().powf(y.to_f64());
    let got = x.powf(y).to_bits();
    let error = (got as f64 - exact * scale).abs();
    let bound = 0.5 + 1.0 / 1024.0 + exact * scale * (-50f64).exp2();
    assert!(
        error <= bound,
        "{}^{} with {} fractional bits: {got} bits, exact {}",
        x.to_f64(),
        y.to_f64(),
        frac_of::<F>(),
        exact * scale
    );
    (error, error / (exact * scale))
}

/// The damping use: d^dt for d ∈ (0, 1] and frame times around 1/60 s.
fn powf_damping_sweep<F: FracBits>() {
    let frac = frac_of::<F>();
    let one = 1i64 << frac;
    let dts = [
        Fixed::<F>::from_ratio(1, 60),
        Fixed::<F>::from_ratio(1, 120),
        Fixed::<F>::from_ratio(1, 30),
        Fixed::<F>::from_ratio(1, 240),
    ];
    let step = (one / 50_000).max(1);
    let mut bits = step;
    while bits <= one {
        for dt in dts {
            powf_error(Fixed::<F>::from_bits(bits), dt);
        }
        bits += step;
    }
    // Every representable d in the smallest and the largest window.
    for bits in (1..5_000).chain(one - 5_000..=one) {
        powf_error(Fixed::<F>::from_bits(bits), dts[0]);
    }
}

#[test]
fn powf_damping_factors_are_accurate() {
    powf_damping_sweep::<U32>();
    powf_damping_sweep::<U16>();
    powf_damping_sweep::<U24>();
}

/// Random x ∈ (0, 16] and y ∈ [−24, 24], keeping results in [2^-20, 2^20].
fn powf_sweep<F: FracBits>(samples: usize) -> (f64, f64) {
    let (mut max_ulps, mut max_relative) = (0.0f64, 0.0f64);
    let mut rng = SplitMix(0x5eed_0005 + u64::from(frac_of::<F>()));
    let mut done = 0;
    while done < samples {
        let x = Fixed::<F>::from_f64(16.0 * rng.unit());
        let y = Fixed::<F>::from_f64(48.0 * rng.unit() - 24.0);
        if x <= Fixed::<F>::ZERO {
            continue;
        }
        let exact = x.to_f64().powf(y.to_f64());
        if !((-20f64).exp2()..=20f64.exp2()).contains(&exact) {
            continue;
        }
        let (ulps, relative) = powf_error(x, y);
        max_ulps = max_ulps.max(ulps);
        // The relative error of the specification: 2⁻²⁰ wherever one ulp allows it.
        if exact * (-20f64).exp2() >= ulp::<F>() {
            assert!(relative <= (-20f64).exp2());
            max_relative = max_relative.max(relative);
        }
        done += 1;
    }
    (max_ulps, max_relative)
}

#[test]
fn powf_is_accurate_over_its_range() {
    for (ulps, relative) in [
        powf_sweep::<U32>(1_000_000),
        powf_sweep::<U16>(1_000_000),
        powf_sweep::<U24>(1_000_000),
    ] {
        // The specification: relative error ≤ 2⁻²⁰ for results in [2⁻²⁰, 2²⁰] (where one
        // ulp is that fine), and at most one ulp elsewhere in that range.
        assert!(
            ulps <= 1.0 && relative <= (-20f64).exp2(),
            "{ulps} ulp, {relative}"
        );
    }
}

proptest! {
    #![proptest_config(crate::property_cases::fixed_cases(20_000))]

    #[test]
    fn powf_matches_f64(x in 1e-3f64..64.0, y in -6.0f64..6.0) {
        let (x, y) = (Fx::from_f64(x), Fx::from_f64(y));
        let exact = x.to_f64().powf(y.to_f64());
        prop_assume!(exact < 2.0e9);
        powf_error(x, y);
    }
}

#[test]
fn powf_special_cases() {
    reset_saturation_count();
    let three = Fx::from_int(3);
    // 0^y.
    assert_eq!(Fx::ZERO.powf(three), Fx::ZERO);
    assert_eq!(Fx::ZERO.powf(Fx::ZERO), Fx::ONE);
    assert_eq!(saturation_count(), 0);
    assert_eq!(Fx::ZERO.powf(-three), Fx::MAX);
    assert_eq!(saturation_count(), 1);
    // Negative base: 0, counted.
    assert_eq!(Fx::from_int(-2).powf(Fx::TWO), Fx::ZERO);
    assert_eq!(saturation_count(), 2);
    // Exact identities.
    for x in [Fx::EPSILON, Fx::HALF, Fx::from_int(7), Fx::MAX] {
        assert_eq!(x.powf(Fx::ZERO), Fx::ONE);
    }
    for y in [Fx::MIN, -three, Fx::HALF, Fx::MAX] {
        assert_eq!(Fx::ONE.powf(y), Fx::ONE);
    }
    assert_eq!(Fx::TWO.powf(Fx::from_int(10)), Fx::from_int(1024));
    assert_eq!(Fx::from_int(9).powf(Fx::HALF), three);
    assert_eq!(saturation_count(), 2);
    // Overflow saturates and counts; underflow is 0 and does not.
    assert_eq!(Fx::TWO.powf(Fx::from_int(40)), Fx::MAX);
    assert_eq!(Fx::MAX.powf(Fx::MAX), Fx::MAX);
    assert_eq!(saturation_count(), 4);
    assert_eq!(Fx::TWO.powf(Fx::from_int(-40)), Fx::ZERO);
    assert_eq!(Fx::EPSILON.powf(Fx::MAX), Fx::ZERO);
    assert_eq!(saturation_count(), 4);
}

// ---------------------------------------------------------------------------------------
// Extremes and determinism
// ---------------------------------------------------------------------------------------

/// Every function on every extreme input of the narrowest and widest formats: no panic
/// (debug builds check every integer overflow), and the documented saturation values.
fn extremes<F: FracBits>() {
    let specials = [
        i64::MIN,
        i64::MIN + 1,
        -(1 << 40),
        -1,
        0,
        1,
        2,
        1 << 40,
        i64::MAX - 1,
        i64::MAX,
    ];
    for &a in &specials {
        let x = Fixed::<F>::from_bits(a);
        let _ = (x.sqrt(), x.rsqrt(), x.exp(), x.ln());
        for &b in &specials {
            let _ = x.powf(Fixed::<F>::from_bits(b));
        }
    }
}

#[test]
fn extreme_inputs_do_not_panic() {
    extremes::<U8>();
    extremes::<U16>();
    extremes::<U24>();
    extremes::<U32>();
    extremes::<U60>();
}

/// FNV-1a over the little-endian bytes of each result.
fn fnv(hash: &mut u64, value: i64) {
    for byte in value.to_le_bytes() {
        *hash = (*hash ^ u64::from(byte)).wrapping_mul(0x0100_0000_01b3);
    }
}

/// Results on a fixed input set, hashed. The expected values were recorded on x86_64; any
/// other target (i686, aarch64, s390x, wasm32) must give the same bits.
fn golden_hash<F: FracBits>() -> [u64; 5] {
    let mut hashes = [0xcbf2_9ce4_8422_2325u64; 5];
    let mut rng = SplitMix(0x601d);
    for _ in 0..4_000 {
        let a = Fixed::<F>::from_bits(rng.log_uniform_bits());
        let b = Fixed::<F>::from_bits((rng.next() as i64) >> (rng.next() % 64));
        fnv(&mut hashes[0], a.sqrt().to_bits());
        fnv(&mut hashes[1], a.rsqrt().to_bits());
        fnv(&mut hashes[2], b.exp().to_bits());
        fnv(&mut hashes[3], a.ln().to_bits());
        fnv(&mut hashes[4], a.powf(b).to_bits());
    }
    hashes
}

#[test]
fn results_are_bit_identical_to_the_recorded_ones() {
    let recorded = [
        golden_hash::<U32>(),
        golden_hash::<U16>(),
        golden_hash::<U24>(),
    ];
    assert_eq!(recorded, GOLDEN);
}

/// FNV-1a hashes of [sqrt, rsqrt, exp, ln, powf] results per format, recorded on x86_64.
const GOLDEN: [[u64; 5]; 3] = [
    // I32F32
    [
        0x7c80e8ebc3d0c84e,
        0xeb7d5ee7616cf9dd,
        0xd34413cbb349a4f1,
        0xe0b80dc4eface847,
        0x37f4e764cd9a43a7,
    ],
    // I48F16
    [
        0x5e0d7a1320526259,
        0x9def1ef8e057c03c,
        0xa20f7301f828fde9,
        0x3623692e8f9467aa,
        0x75c14dac31246e95,
    ],
    // I40F24
    [
        0xd8517c5e8356ec94,
        0x370ea06336b9aa7f,
        0xeb090da73e8593b7,
        0xf92420ae07f40710,
        0x0236755be53f26ce,
    ],
];
