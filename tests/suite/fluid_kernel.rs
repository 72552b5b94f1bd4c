//! The Wendland C2 kernel: its normalisation integrates to 1, the gradient is the
//! derivative of the value, the lattice calibrations stay close to the continuum, and
//! every constant is in range for all the fixed-point formats.

use fixstep::fluid::kernel::{Kernel, wendland_shape, wendland_sigma};
use fixstep::math::saturation::count_saturations;
use fixstep::math::{Fx, FxI40F24, FxI48F16, Real, Vec3};

/// ∫ σ/H³ f(|x|/H) dx over the ball = 4π σ ∫₀¹ f(q) q² dq, by Simpson's rule.
#[test]
fn normalisation_integrates_to_one() {
    let sigma: f64 = wendland_sigma::<f64>();
    let n = 2000;
    let h = 1.0 / n as f64;
    let mut sum = 0.0;
    for k in 0..=n {
        let q = k as f64 * h;
        let weight = if k == 0 || k == n {
            1.0
        } else if k % 2 == 1 {
            4.0
        } else {
            2.0
        };
        sum += weight * wendland_shape(q) * q * q;
    }
    let integral = 4.0 * std::f64::consts::PI * sigma * sum * h / 3.0;
    assert!((integral - 1.0).abs() < 1e-9, "∫W = {integral}");
}

/// V₀∇W from `evaluate` against a central difference of V₀W, in f64 and in I32F32.
fn gradient_matches_difference<R: Real>(tolerance: f64) {
    let kernel = Kernel::<R>::calibrated(R::from_ratio(1, 100), R::TWO);
    // The calibrated c_g differs from the continuum 20 c_w / H by the lattice factor.
    let factor = kernel.gradient_scale.to_f64()
        / (20.0 * kernel.density_scale.to_f64() * kernel.inv_support.to_f64());
    let value = |p: [f64; 3]| {
        kernel
            .evaluate(Vec3::from_f64(p[0], p[1], p[2]))
            .map_or(0.0, |(w, _)| w.to_f64())
    };
    for p in [
        [0.003, 0.004, -0.002],
        [0.011, -0.005, 0.007],
        [-0.014, 0.002, 0.0],
    ] {
        let (_, g) = kernel
            .evaluate(Vec3::from_f64(p[0], p[1], p[2]))
            .expect("inside");
        let g = g.to_f64();
        for axis in 0..3 {
            let eps = 1e-5;
            let (mut a, mut b) = (p, p);
            a[axis] += eps;
            b[axis] -= eps;
            let numeric = (value(a) - value(b)) / (2.0 * eps) * factor;
            assert!(
                (g[axis] - numeric).abs() <= tolerance * (1.0 + numeric.abs()),
                "axis {axis} at {p:?}: {} vs {numeric}",
                g[axis]
            );
        }
    }
}

#[test]
fn gradient_is_the_derivative_of_the_value() {
    gradient_matches_difference::<f64>(1e-5);
    gradient_matches_difference::<Fx>(1e-3);
}

/// The lattice calibration of c_w stays within 10 % of the continuum σ/s³ from a support of
/// two spacings up (25 % at the coarsest, 1.5), and c_g within 50 % of 20 c_w / H (a
/// factor 2 at 1.5, where only the 18 nearest sites are in reach).
#[test]
fn calibration_is_close_to_the_continuum() {
    for support in [1.5, 2.0, 2.5, 3.0, 4.0] {
        let k = Kernel::<f64>::calibrated(0.01, support);
        let continuum = wendland_sigma::<f64>() / (support * support * support);
        let ratio = k.density_scale / continuum;
        let bound = if support < 2.0 { 0.25 } else { 0.1 };
        assert!(
            (ratio - 1.0).abs() < bound,
            "s = {support}: c_w ratio {ratio}"
        );
        let g = k.gradient_scale / (20.0 * k.density_scale * k.inv_support);
        let range = if support < 2.0 { 0.5..2.0 } else { 0.5..1.5 };
        assert!(range.contains(&g), "s = {support}: c_g ratio {g}");
    }
}

/// The constants and a kernel evaluation at the extreme spacings and supports do not
/// saturate in any fixed-point format, and give nonzero values.
fn constants_in_range<R: Real>() {
    for spacing in [R::from_ratio(1, 1000), R::ONE] {
        for support in [R::from_ratio(3, 2), R::from_int(4)] {
            let (k, saturations) = count_saturations(|| {
                let k = Kernel::<R>::calibrated(spacing, support);
                let near = k.evaluate(Vec3::new(spacing * R::HALF, R::ZERO, R::ZERO));
                (k, near)
            });
            assert_eq!(
                saturations,
                0,
                "{} spacing {spacing} support {support}",
                R::NAME
            );
            assert!(k.0.density_scale > R::ZERO && k.0.gradient_scale > R::ZERO);
            let (w, g) = k.1.expect("within the support");
            assert!(
                w > R::ZERO && g.x < R::ZERO,
                "{} spacing {spacing}",
                R::NAME
            );
        }
    }
}

#[test]
fn constants_fit_every_format() {
    constants_in_range::<Fx>();
    constants_in_range::<FxI40F24>();
    constants_in_range::<FxI48F16>();
}
