//! The scalar's arithmetic policy: rounding, saturation, division by zero, conversions and
//! serialisation. The reference for rounding is exact rational arithmetic on i128.

use fixstep::math::saturation::{count_saturations, reset_saturation_count, saturation_count};
use fixstep::math::{Fx, FxI40F24, FxI48F16, Real};
use proptest::prelude::*;

/// round(a·b / 2^32) with ties toward +∞, on exact integers: the documented multiply.
fn reference_mul(a: i64, b: i64, frac: u32) -> i128 {
    let p = a as i128 * b as i128;
    (p + (1i128 << (frac - 1))).div_euclid(1i128 << frac)
}

/// round(a·2^frac / b) with ties away from zero, exact.
fn reference_div(a: i64, b: i64, frac: u32) -> i128 {
    let n = (a as i128) << frac;
    let d = b as i128;
    let q = n / d;
    let r = n % d;
    if 2 * r.abs() >= d.abs() {
        q + if (n < 0) == (d < 0) { 1 } else { -1 }
    } else {
        q
    }
}

fn saturate(v: i128) -> i64 {
    v.clamp(i64::MIN as i128, i64::MAX as i128) as i64
}

proptest! {
    #![proptest_config(crate::property_cases::fixed_cases(4096))]

    #[test]
    fn multiply_rounds_to_nearest_and_saturates(a: i64, b: i64) {
        let exact = reference_mul(a, b, 32);
        let ((got,), sats) = count_saturations(|| ((Fx::from_bits(a) * Fx::from_bits(b)).to_bits(),));
        prop_assert_eq!(got, saturate(exact));
        prop_assert_eq!(sats, u64::from(exact != saturate(exact) as i128));
    }

    #[test]
    fn multiply_of_moderate_values_is_exactly_rounded(a in -(1i64 << 45)..(1i64 << 45), b in -(1i64 << 45)..(1i64 << 45)) {
        prop_assert_eq!((Fx::from_bits(a) * Fx::from_bits(b)).to_bits() as i128, reference_mul(a, b, 32));
        prop_assert_eq!((FxI48F16::from_bits(a) * FxI48F16::from_bits(b >> 20)).to_bits() as i128, reference_mul(a, b >> 20, 16));
    }

    #[test]
    fn divide_rounds_to_nearest_and_saturates(a: i64, b in any::<i64>().prop_filter("nonzero", |b| *b != 0)) {
        let exact = reference_div(a, b, 32);
        let (got, sats) = count_saturations(|| (Fx::from_bits(a) / Fx::from_bits(b)).to_bits());
        prop_assert_eq!(got, saturate(exact));
        prop_assert_eq!(sats, u64::from(exact != saturate(exact) as i128));
        let exact24 = reference_div(a, b, 24);
        prop_assert_eq!((FxI40F24::from_bits(a) / FxI40F24::from_bits(b)).to_bits(), saturate(exact24));
    }

    #[test]
    fn add_sub_neg_abs_saturate(a: i64, b: i64) {
        let (x, y) = (Fx::from_bits(a), Fx::from_bits(b));
        prop_assert_eq!((x + y).to_bits(), a.saturating_add(b));
        prop_assert_eq!((x - y).to_bits(), a.saturating_sub(b));
        prop_assert_eq!((-x).to_bits(), a.checked_neg().unwrap_or(i64::MAX));
        prop_assert_eq!(x.abs().to_bits(), a.checked_abs().unwrap_or(i64::MAX));
    }

    #[test]
    fn f64_round_trip_is_exact_for_53_bit_values(bits in -(1i64 << 52)..(1i64 << 52)) {
        let x = Fx::from_bits(bits);
        prop_assert_eq!(Fx::from_f64(x.to_f64()), x);
    }

    #[test]
    fn decimal_strings_round_trip(bits: i64) {
        let x = Fx::from_bits(bits);
        prop_assert_eq!(Fx::parse_decimal(&x.to_string()).unwrap(), x);
    }
}

#[test]
fn division_by_zero_is_defined_and_counted() {
    reset_saturation_count();
    assert_eq!(Fx::from_int(3) / Fx::ZERO, Fx::MAX);
    assert_eq!(Fx::from_int(-3) / Fx::ZERO, Fx::MIN);
    assert_eq!(Fx::ZERO / Fx::ZERO, Fx::ZERO);
    assert_eq!(Fx::ZERO.recip(), Fx::MAX);
    assert_eq!(FxI48F16::from_int(-1) / FxI48F16::ZERO, FxI48F16::MIN);
    assert_eq!(Fx::from_ratio(5, 0), Fx::MAX);
    assert_eq!(saturation_count(), 6);
}

#[test]
fn saturation_is_counted_once_per_event_and_not_on_the_normal_path() {
    let (_, none) = count_saturations(|| {
        let mut acc = Fx::ZERO;
        for i in 0..1000 {
            acc += Fx::from_int(i) * Fx::HALF - Fx::ONE / Fx::from_int(i + 1);
        }
        acc
    });
    assert_eq!(none, 0);
    let (values, three) = count_saturations(|| {
        [
            Fx::MAX + Fx::ONE,
            Fx::MIN - Fx::ONE,
            Fx::from_int(100_000) * Fx::from_int(100_000),
        ]
    });
    assert_eq!(values, [Fx::MAX, Fx::MIN, Fx::MAX]);
    assert_eq!(three, 3);
    let (neg_min, one) = count_saturations(|| -Fx::MIN);
    assert_eq!((neg_min, one), (Fx::MAX, 1));
}

#[test]
fn multiply_ties_round_toward_positive_infinity() {
    // 2^-32 · 0.5 = 2^-33 is exactly half an ulp.
    let ulp = Fx::EPSILON;
    assert_eq!((ulp * Fx::HALF).to_bits(), 1);
    assert_eq!((-ulp * Fx::HALF).to_bits(), 0);
    // The `fixed` crate would round both toward −∞; the engine's policy differs on purpose.
    assert_eq!((ulp.to_fixed() * Fx::HALF.to_fixed()).to_bits(), 0);
}

#[test]
fn constants_are_correctly_rounded() {
    let pi_q32 = (std::f64::consts::PI * 4294967296.0).round() as i64;
    assert_eq!(Fx::PI.to_bits(), pi_q32);
    assert_eq!(
        Fx::TAU.to_bits(),
        (std::f64::consts::TAU * 4294967296.0).round() as i64
    );
    assert_eq!(
        FxI48F16::PI.to_bits(),
        (std::f64::consts::PI * 65536.0).round() as i64
    );
    assert_eq!(
        FxI40F24::PI.to_bits(),
        (std::f64::consts::PI * 16777216.0).round() as i64
    );
    assert_eq!(Fx::ONE.to_bits(), 1 << 32);
    assert_eq!(Fx::HALF + Fx::HALF, Fx::ONE);
    assert_eq!(Fx::from_ratio(1, 3).to_bits(), 1431655765);
    assert_eq!(Fx::from_ratio(-2, 3).to_bits(), -2863311531);
    assert_eq!(Fx::NAME, "I32F32");
    assert_eq!(FxI48F16::NAME, "I48F16");
    assert_eq!(FxI40F24::NAME, "I40F24");
}

#[test]
fn conversions_saturate_and_reject_nan() {
    reset_saturation_count();
    assert_eq!(Fx::from_f64(1e300), Fx::MAX);
    assert_eq!(Fx::from_f64(f64::NEG_INFINITY), Fx::MIN);
    assert_eq!(Fx::from_f64(f64::NAN), Fx::ZERO);
    assert_eq!(Fx::from_int(i32::MIN).to_f64(), i32::MIN as f64);
    assert_eq!(FxI48F16::from_int(i32::MAX).to_f64(), i32::MAX as f64);
    assert_eq!(saturation_count(), 3);
    assert_eq!(
        Fx::parse_decimal(" -9.81 ").unwrap(),
        Fx::from_ratio(-981, 100)
    );
    let err = Fx::parse_decimal("nine").unwrap_err();
    assert!(err.to_string().contains("`nine` is not a number"), "{err}");
}

#[test]
fn powi_by_squaring() {
    assert_eq!(Fx::from_int(3).powi(4), Fx::from_int(81));
    assert_eq!(Fx::from_int(2).powi(-2), Fx::from_ratio(1, 4));
    assert_eq!(Fx::from_int(7).powi(0), Fx::ONE);
    assert_eq!(2.0f64.powi(10), 1024.0);
}

#[test]
fn binary_encoding_is_the_raw_little_endian_bits() {
    let config = bincode::config::standard().with_fixed_int_encoding();
    let x = Fx::from_bits(0x0102_0304_0506_0708);
    let bytes = bincode::serde::encode_to_vec(x, config).unwrap();
    assert_eq!(bytes, 0x0102_0304_0506_0708i64.to_le_bytes());
    let (back, used): (Fx, usize) = bincode::serde::decode_from_slice(&bytes, config).unwrap();
    assert_eq!((back, used), (x, 8));
}

#[derive(serde::Serialize, serde::Deserialize, Debug, PartialEq)]
struct Scene {
    g: Fx,
    h: FxI48F16,
}

#[test]
fn human_readable_encoding_accepts_numbers_and_strings() {
    let parsed: Scene = ron::from_str("(g: -9.81, h: \"0.5\")").unwrap();
    assert_eq!(parsed.g, Fx::from_f64(-9.81));
    assert_eq!(parsed.h, FxI48F16::HALF);
    let integer: Scene = ron::from_str("(g: 3, h: -2)").unwrap();
    assert_eq!(
        (integer.g, integer.h),
        (Fx::from_int(3), FxI48F16::from_int(-2))
    );
    // Writing and reading back gives the same bits, whether or not the value is exact in f64.
    for bits in [
        0,
        1,
        -1,
        1 << 40,
        i64::MAX,
        i64::MIN,
        Fx::from_f64(-9.81).to_bits(),
    ] {
        let scene = Scene {
            g: Fx::from_bits(bits),
            h: FxI48F16::from_bits(bits),
        };
        let text = ron::to_string(&scene).unwrap();
        assert_eq!(ron::from_str::<Scene>(&text).unwrap(), scene, "{text}");
    }
    assert_eq!(
        ron::to_string(&Scene {
            g: Fx::HALF,
            h: FxI48F16::ZERO
        })
        .unwrap(),
        "(g:0.5,h:0.0)"
    );
    let too_big = ron::from_str::<Scene>("(g: 1e12, h: 0)")
        .unwrap_err()
        .to_string();
    assert!(too_big.contains("range of I32F32"), "{too_big}");
    let not_finite = ron::from_str::<Scene>("(g: inf, h: 0)")
        .unwrap_err()
        .to_string();
    assert!(not_finite.contains("not a finite number"), "{not_finite}");
}
