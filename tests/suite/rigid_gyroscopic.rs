//! The implicit gyroscopic update against Euler's equations for a torque-free body,
//! I ω̇ = −ω × (I ω) in the body frame.
//!
//! The reference is Euler's equations integrated in `f64` by classical RK4 at a step 600
//! times smaller than the engine's (h = 1/36000 s), whose error is far below the 2 % the
//! flip period must match (the acceptance test of the `spinner` scene in the rigid-body
//! issue). Angular momentum and energy are invariants of the exact flow, and the implicit
//! midpoint rule conserves both (they are quadratic), so they may drift only by rounding.

use fixstep::math::{Fx, Mat3, Quat, Real, Vec3};
use fixstep::rigid::gyroscopic::{step, step_body_frame};

/// Principal moments of a box of 1 kg with side lengths 1, 2, 3 m... chosen as I = (1, 2, 3)
/// kg·m² directly: y is the intermediate axis.
const MOMENTS: [f64; 3] = [1.0, 2.0, 3.0];

/// A spin of 4 rad/s about the intermediate axis with a small perturbation.
const OMEGA0: [f64; 3] = [0.01, 4.0, 0.01];

fn euler_rhs(w: [f64; 3]) -> [f64; 3] {
    let [i1, i2, i3] = MOMENTS;
    [
        (i2 - i3) * w[1] * w[2] / i1,
        (i3 - i1) * w[2] * w[0] / i2,
        (i1 - i2) * w[0] * w[1] / i3,
    ]
}

fn rk4(w: [f64; 3], h: f64) -> [f64; 3] {
    let add =
        |a: [f64; 3], b: [f64; 3], s: f64| [a[0] + s * b[0], a[1] + s * b[1], a[2] + s * b[2]];
    let k1 = euler_rhs(w);
    let k2 = euler_rhs(add(w, k1, h / 2.0));
    let k3 = euler_rhs(add(w, k2, h / 2.0));
    let k4 = euler_rhs(add(w, k3, h));
    let mut out = w;
    for i in 0..3 {
        out[i] += h / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]);
    }
    out
}

/// Times (s) at which ω_y changes sign, over `duration` seconds, for a stepper of step `h`.
fn sign_changes(mut next: impl FnMut() -> f64, h: f64, duration: f64) -> Vec<f64> {
    let mut times = Vec::new();
    let mut previous = OMEGA0[1];
    let steps = (duration / h).round() as usize;
    for n in 1..=steps {
        let wy = next();
        if wy.signum() != previous.signum() {
            times.push(n as f64 * h);
        }
        previous = wy;
    }
    times
}

/// The mean time between successive flips (two sign changes make a full period).
fn period(times: &[f64]) -> f64 {
    assert!(times.len() >= 3, "too few flips: {times:?}");
    2.0 * (times[times.len() - 1] - times[0]) / (times.len() - 1) as f64
}

fn inertia<R: Real>() -> Mat3<R> {
    Mat3::from_diagonal(Vec3::new(
        R::from_f64(MOMENTS[0]),
        R::from_f64(MOMENTS[1]),
        R::from_f64(MOMENTS[2]),
    ))
}

fn reference_period() -> f64 {
    let h = 1.0 / 36000.0;
    let mut w = OMEGA0;
    period(&sign_changes(
        || {
            w = rk4(w, h);
            w[1]
        },
        h,
        60.0,
    ))
}

fn engine_period<R: Real>() -> f64 {
    let h = 1.0 / 60.0;
    let i = inertia::<R>();
    let mut w = Vec3::new(
        R::from_f64(OMEGA0[0]),
        R::from_f64(OMEGA0[1]),
        R::from_f64(OMEGA0[2]),
    );
    let dt = R::from_ratio(1, 60);
    period(&sign_changes(
        || {
            w = step_body_frame(w, i, dt);
            w.y.to_f64()
        },
        h,
        60.0,
    ))
}

#[test]
fn intermediate_axis_flip_period_matches_eulers_equations() {
    let reference = reference_period();
    for (name, measured) in [
        ("f64", engine_period::<f64>()),
        ("I32F32", engine_period::<Fx>()),
    ] {
        let error = (measured - reference).abs() / reference;
        assert!(
            error < 0.02,
            "{name}: flip period {measured:.4} s vs {reference:.4} s ({:.2} %)",
            error * 100.0
        );
    }
}

#[test]
fn energy_and_angular_momentum_are_conserved_over_flips() {
    let i = inertia::<Fx>();
    let dt = Fx::from_ratio(1, 60);
    let mut w = Vec3::new(
        Fx::from_f64(OMEGA0[0]),
        Fx::from_f64(OMEGA0[1]),
        Fx::from_f64(OMEGA0[2]),
    );
    let energy = |w: Vec3<Fx>| {
        let w = w.to_f64();
        0.5 * (0..3).map(|k| MOMENTS[k] * w[k] * w[k]).sum::<f64>()
    };
    let momentum = |w: Vec3<Fx>| {
        let w = w.to_f64();
        (0..3)
            .map(|k| (MOMENTS[k] * w[k]).powi(2))
            .sum::<f64>()
            .sqrt()
    };
    let (e0, l0) = (energy(w), momentum(w));
    for _ in 0..1800 {
        w = step_body_frame(w, i, dt);
    }
    // 1800 steps of I32F32 rounding (2⁻³³ per operation) stay far below 10⁻⁶.
    assert!((energy(w) - e0).abs() / e0 < 1e-6, "E {e0} → {}", energy(w));
    assert!(
        (momentum(w) - l0).abs() / l0 < 1e-6,
        "|L| {l0} → {}",
        momentum(w)
    );
}

#[test]
fn world_frame_step_agrees_with_the_body_frame_step() {
    let orientation = Quat::<Fx>::from_axis_angle(
        Vec3::new(Fx::ONE, Fx::ONE, Fx::ZERO).normalize_or_zero(),
        Fx::from_ratio(7, 10),
    );
    let i = inertia::<Fx>();
    let dt = Fx::from_ratio(1, 60);
    let omega_body = Vec3::new(Fx::from_ratio(1, 2), Fx::from_int(3), Fx::from_ratio(-1, 4));
    let world = step(orientation.rotate(omega_body), orientation, i, dt);
    let expected = orientation.rotate(step_body_frame(omega_body, i, dt));
    let difference = (world - expected).length().to_f64();
    assert!(difference < 1e-7, "{difference}");
}

#[test]
fn a_body_without_inertia_keeps_its_angular_velocity() {
    let omega = Vec3::new(Fx::ONE, Fx::TWO, Fx::from_int(3));
    assert_eq!(
        step_body_frame(omega, Mat3::ZERO, Fx::from_ratio(1, 60)),
        omega
    );
}
