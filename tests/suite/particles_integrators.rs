//! The six integrators on the harmonic oscillator x'' = −ω² x, built from the engine's own
//! anchored spring (k = 1 N/m, m = 1 kg, so ω = 1 rad/s), in `f64` and in I32F32.
//!
//! Expected values come from the exact solution x = cos ωt and from the exact one-step maps
//! tabulated in `/work/shared/reference/harmonic_oscillator_discrete_amplification.csv`
//! ("Exact one-step maps of common integrators applied to x'' = −w² x (theta = w·h)",
//! computed with mpmath); the rows used are copied below with their column names.

use fixstep::math::rng::Pcg32;
use fixstep::math::{Fx, Real, Vec3};
use fixstep::particles::{
    ForceDesc, Integrator, ParticleDesc, ParticleSystem, ParticlesDesc, SpringDesc,
};
use fixstep::world::Handle;

/// An oscillator: a 1 kg particle on a spring of stiffness `stiffness` (so ω² = k) and rest
/// length `rest` anchored at the origin, displaced by `amplitude` along x and released.
fn oscillator<R: Real>(
    integrator: Integrator,
    stiffness: R,
    rest: R,
    amplitude: R,
) -> ParticleSystem<R> {
    let desc = ParticlesDesc {
        integrator,
        particles: vec![ParticleDesc {
            position: Vec3::new(rest + amplitude, R::ZERO, R::ZERO),
            velocity: Vec3::ZERO,
            mass: R::ONE,
            group: 0,
            lifetime: R::ZERO,
        }],
        forces: vec![ForceDesc::AnchoredSpring {
            particle: 0,
            anchor: Vec3::ZERO,
            spring: SpringDesc {
                stiffness,
                damping: R::ZERO,
                rest_length: rest,
            },
        }],
        ..ParticlesDesc::default()
    };
    ParticleSystem::from_desc(&desc).expect("valid oscillator")
}

const BOB: Handle = Handle::new(0, 0);

/// Displacement from the rest length and velocity along x, as f64.
fn state<R: Real>(system: &ParticleSystem<R>, rest: f64) -> (f64, f64) {
    let x = system.position(BOB).unwrap().x.to_f64() - rest;
    let v = system.velocity(BOB).unwrap().x.to_f64();
    (x, v)
}

fn energy<R: Real>(system: &ParticleSystem<R>) -> f64 {
    (system.kinetic_energy() + system.potential_energy(Vec3::ZERO)).to_f64()
}

/// Phase-space error |(x, v) − (cos T, −sin T)| after integrating the unit oscillator
/// (displacement 1 from rest length 2) to T = 10 s with step 2^−`log2_inv_h` s.
fn error_at_t10<R: Real>(integrator: Integrator, log2_inv_h: u32) -> f64 {
    let mut system = oscillator(integrator, R::ONE, R::TWO, R::ONE);
    let h = R::from_ratio(1, 1 << log2_inv_h);
    let steps = 10 << log2_inv_h;
    let mut rng = Pcg32::new(1, 1);
    for _ in 0..steps {
        system.step(h, Vec3::ZERO, &mut rng);
    }
    let (x, v) = state(&system, 2.0);
    let t = 10.0f64;
    ((x - t.cos()).powi(2) + (v + t.sin()).powi(2)).sqrt()
}

/// Observed orders log2(e(h)/e(h/2)) over successive halvings of h = 2^−k, k in `ks`.
fn observed_orders<R: Real>(
    integrator: Integrator,
    ks: core::ops::RangeInclusive<u32>,
) -> Vec<f64> {
    let errors: Vec<f64> = ks.map(|k| error_at_t10::<R>(integrator, k)).collect();
    errors.windows(2).map(|e| (e[0] / e[1]).log2()).collect()
}

/// Step ranges (h = 2^−k) where each scheme's truncation error dominates rounding in
/// I32F32 (ulp 2.3·10⁻¹⁰) and the asymptotic regime has set in.
fn step_range(integrator: Integrator) -> core::ops::RangeInclusive<u32> {
    match integrator.order() {
        1 => 6..=9,
        2 => 3..=6,
        _ => 1..=4,
    }
}

fn assert_orders<R: Real>() {
    for integrator in Integrator::ALL {
        let orders = observed_orders::<R>(integrator, step_range(integrator));
        println!("{} {integrator}: observed orders {orders:.3?}", R::NAME);
        let expected = f64::from(integrator.order());
        for order in orders {
            assert!(
                (order - expected).abs() <= 0.2,
                "{} {integrator}: observed order {order:.3}, expected {expected}",
                R::NAME
            );
        }
    }
}

#[test]
fn global_orders_in_f64() {
    assert_orders::<f64>();
}

#[test]
fn global_orders_in_fixed_point() {
    assert_orders::<Fx>();
}

/// Explicit Euler multiplies the energy by ρ² = 1 + (ωh)² every step (CSV column
/// `expEuler_rho`, rows θ = 0.1, 0.2, 0.5).
#[test]
fn explicit_euler_energy_grows_by_one_plus_theta_squared() {
    const ROWS: [(f64, f64); 3] = [
        (0.1, 1.00498756211209),
        (0.2, 1.01980390271856),
        (0.5, 1.11803398874989),
    ];
    for (theta, rho) in ROWS {
        let per_step = |e0: f64, e1: f64, n: f64| (e1 / e0).powf(1.0 / n);
        let expected = rho * rho;
        let n = 40;
        // ω = 1, so h = θ. The amplitude grows to ρ⁴⁰ ≤ 87 m: a 1000 m rest length keeps the
        // spring from passing through its anchor.
        let rest = 1000;
        let mut fixed = oscillator::<Fx>(
            Integrator::ExplicitEuler,
            Fx::ONE,
            Fx::from_int(rest),
            Fx::ONE,
        );
        let mut float = oscillator::<f64>(Integrator::ExplicitEuler, 1.0, f64::from(rest), 1.0);
        let (e0_fixed, e0_float) = (energy(&fixed), energy(&float));
        let mut rng = Pcg32::new(1, 1);
        for _ in 0..n {
            fixed.step(Fx::from_f64(theta), Vec3::ZERO, &mut rng);
            float.step(theta, Vec3::ZERO, &mut rng);
        }
        for (name, factor) in [
            ("I32F32", per_step(e0_fixed, energy(&fixed), f64::from(n))),
            ("f64", per_step(e0_float, energy(&float), f64::from(n))),
        ] {
            let relative = ((factor - 1.0) / (expected - 1.0) - 1.0).abs();
            println!("θ = {theta}: {name} growth {factor:.9} vs 1 + θ² = {expected:.9}");
            assert!(
                relative < 0.01,
                "{name} θ = {theta}: per-step growth {factor} is not 1 + θ² = {expected} within 1%"
            );
        }
    }
}

/// Semi-implicit Euler is stable iff ωh < 2. At ωh = 1.9 the displacement stays within
/// A/√(1 − θ²/4) (the maximum on the map's invariant ellipse), over 10⁴ steps. At ωh = 2.1
/// and 2.5 it grows by the spectral radius |λ| = θ²/2 − 1 + θ√(θ²/4 − 1) per step (2.5: CSV
/// `sympEuler_rho` = 4.0).
#[test]
fn semi_implicit_euler_stability_limit() {
    let rest = 1000;
    let amplitude = Fx::from_ratio(1, 1000);
    let mut rng = Pcg32::new(1, 1);

    let theta = 1.9f64;
    let mut system = oscillator(
        Integrator::SemiImplicitEuler,
        Fx::ONE,
        Fx::from_int(rest),
        amplitude,
    );
    let bound = amplitude.to_f64() / (1.0 - theta * theta / 4.0).sqrt();
    let mut largest = 0.0f64;
    for _ in 0..10_000 {
        system.step(Fx::from_f64(theta), Vec3::ZERO, &mut rng);
        largest = largest.max(state(&system, f64::from(rest)).0.abs());
    }
    println!("θ = 1.9: max |x| = {largest:.9}, bound {bound:.9}");
    assert!(
        largest <= bound * 1.0001,
        "θ = 1.9 exceeded {bound}: {largest}"
    );
    assert!(
        largest >= bound * 0.99,
        "θ = 1.9 never approached {bound}: {largest}"
    );

    for (theta, steps, csv_rho) in [(2.1f64, 20, None), (2.5, 8, Some(4.0))] {
        let rho = theta * theta / 2.0 - 1.0 + theta * (theta * theta / 4.0 - 1.0).sqrt();
        if let Some(csv_rho) = csv_rho {
            assert!((rho - csv_rho).abs() < 1e-12);
        }
        let mut system = oscillator(
            Integrator::SemiImplicitEuler,
            Fx::ONE,
            Fx::from_int(rest),
            amplitude,
        );
        let mut displacements = Vec::new();
        for _ in 0..steps {
            system.step(Fx::from_f64(theta), Vec3::ZERO, &mut rng);
            displacements.push(state(&system, f64::from(rest)).0);
        }
        let last = displacements[steps - 1].abs();
        let growth = last / displacements[steps - 2].abs();
        println!(
            "θ = {theta}: |x| = {last:.3} after {steps} steps, growth {growth:.4} vs ρ = {rho:.4}"
        );
        assert!(
            (growth / rho - 1.0).abs() < 0.01,
            "θ = {theta}: growth {growth}, expected {rho}"
        );
        assert!(
            last > 100.0 * amplitude.to_f64(),
            "θ = {theta} did not diverge"
        );
    }
}

/// Symplectic schemes keep the energy error of the oscillator within the bound set by their
/// modified invariant, with no drift, over 10⁵ steps at ωh = 1/16 in I32F32:
/// semi-implicit Euler (θ/2)/(1 − θ/2); velocity Verlet θ²/4; leapfrog (drift–kick–drift)
/// (θ²/4)/(1 − θ²/4); Störmer–Verlet, whose velocity (x_{n+1} − x_n)/h + ½h a_n is
/// v_VV (1 + θ²/2) + O(θ⁴), 3θ²/4 to leading order.
#[test]
fn symplectic_energy_is_bounded_without_drift() {
    let theta = 1.0 / 16.0;
    let h = Fx::from_ratio(1, 16);
    let cases = [
        (
            Integrator::SemiImplicitEuler,
            (theta / 2.0) / (1.0 - theta / 2.0),
        ),
        (Integrator::VelocityVerlet, theta * theta / 4.0),
        (
            Integrator::Leapfrog,
            (theta * theta / 4.0) / (1.0 - theta * theta / 4.0),
        ),
        (
            Integrator::StormerVerlet,
            0.75 * theta * theta * (1.0 + theta * theta),
        ),
    ];
    const STEPS: usize = 100_000;
    const WINDOW: usize = 10_000;
    for (integrator, bound) in cases {
        let mut system = oscillator(integrator, Fx::ONE, Fx::TWO, Fx::ONE);
        let e0 = energy(&system);
        let mut rng = Pcg32::new(1, 1);
        let (mut first_window, mut last_window) = (0.0f64, 0.0f64);
        for n in 0..STEPS {
            system.step(h, Vec3::ZERO, &mut rng);
            let deviation = (energy(&system) - e0).abs() / e0;
            if n < WINDOW {
                first_window = first_window.max(deviation);
            }
            if n >= STEPS - WINDOW {
                last_window = last_window.max(deviation);
            }
        }
        println!(
            "{integrator}: max |ΔE|/E first 10⁴ steps {first_window:.3e}, last 10⁴ {last_window:.3e}, bound {bound:.3e}"
        );
        assert!(
            first_window.max(last_window) <= bound * 1.001,
            "{integrator} exceeds {bound}"
        );
        assert!(
            (last_window - first_window).abs() < 1e-6,
            "{integrator}: energy envelope drifted from {first_window} to {last_window}"
        );
    }
}

/// RK4 is slightly dissipative: energy factor ρ² = 1 − θ⁶/72 + θ⁸/576 per step (CSV column
/// `RK4_rho` at θ = 1: 0.993905036823047).
#[test]
fn rk4_energy_decays_by_its_amplification_factor() {
    let csv_rho: f64 = 0.993905036823047;
    let expected = csv_rho * csv_rho;
    assert!((expected - (1.0 - 1.0 / 72.0 + 1.0 / 576.0)).abs() < 1e-12);
    let n = 50;
    let mut fixed = oscillator::<Fx>(Integrator::Rk4, Fx::ONE, Fx::TWO, Fx::ONE);
    let mut float = oscillator::<f64>(Integrator::Rk4, 1.0, 2.0, 1.0);
    let (e0_fixed, e0_float) = (energy(&fixed), energy(&float));
    let mut rng = Pcg32::new(1, 1);
    for _ in 0..n {
        fixed.step(Fx::ONE, Vec3::ZERO, &mut rng);
        float.step(1.0, Vec3::ZERO, &mut rng);
    }
    for (name, e0, e1) in [
        ("I32F32", e0_fixed, energy(&fixed)),
        ("f64", e0_float, energy(&float)),
    ] {
        let factor = (e1 / e0).powf(1.0 / f64::from(n));
        println!("{name}: RK4 energy factor {factor:.12} vs {expected:.12}");
        assert!(
            ((1.0 - factor) / (1.0 - expected) - 1.0).abs() < 0.01,
            "{name}: RK4 energy factor {factor}, expected {expected}"
        );
    }
}
