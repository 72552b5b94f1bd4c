//! The Kepler problem q'' = −q/|q|³ (e = 0.5, μ = 1) through the engine's point gravity.
//!
//! Reference data, copied below with their provenance:
//! * `/work/shared/reference/kepler_e0.5_reference.csv`: the exact state at t = 10 from
//!   Kepler's equation (mpmath, 30 digits), q0 = (0.5, 0), p0 = (0, √3), H = −0.5,
//!   L = 0.866025403784439;
//! * `/work/shared/reference/kepler_e0.5_integrator_convergence_float64.csv`: position errors
//!   at t = 10 of textbook explicit Euler, semi-implicit Euler, velocity Verlet and RK4 in
//!   IEEE float64 with h = 10/N, and their maximum energy errors.

use fixstep::math::rng::Pcg32;
use fixstep::math::{Fx, Real, Vec3};
use fixstep::particles::{ForceDesc, Integrator, ParticleDesc, ParticleSystem, ParticlesDesc};
use fixstep::world::Handle;

/// Exact state at t = 10 (kepler_e0.5_reference.csv, row `10`): x, y, vx, vy.
const EXACT_T10: [f64; 4] = [
    -1.42617025159879,
    -0.326583065681721,
    0.257746890538708,
    -0.548216198750389,
];
/// L = √(1 − e²).
const ANGULAR_MOMENTUM: f64 = 0.866025403784439;

/// (method, N steps to t = 10, position error at t = 10) from
/// kepler_e0.5_integrator_convergence_float64.csv.
const CONVERGENCE: [(Integrator, u32, f64); 8] = [
    (Integrator::ExplicitEuler, 400, 1.444405e+00),
    (Integrator::ExplicitEuler, 800, 1.601394e+00),
    (Integrator::SemiImplicitEuler, 400, 7.103926e-02),
    (Integrator::SemiImplicitEuler, 800, 4.535292e-02),
    (Integrator::VelocityVerlet, 400, 2.188052e-02),
    (Integrator::VelocityVerlet, 800, 5.475072e-03),
    (Integrator::Rk4, 400, 1.101897e-05),
    (Integrator::Rk4, 800, 6.042850e-07),
];

/// The same file's `max_abs_energy_error` for velocity Verlet at N = 400 (h = 0.025).
const VELOCITY_VERLET_MAX_ENERGY_ERROR_H0025: f64 = 8.507009e-04;

const BODY: Handle = Handle::new(0, 0);

fn kepler<R: Real>(integrator: Integrator) -> ParticleSystem<R> {
    let desc = ParticlesDesc {
        integrator,
        particles: vec![ParticleDesc {
            position: Vec3::new(R::HALF, R::ZERO, R::ZERO),
            velocity: Vec3::new(R::ZERO, R::from_int(3).sqrt(), R::ZERO),
            mass: R::ONE,
            group: 0,
            lifetime: R::ZERO,
        }],
        forces: vec![ForceDesc::PointGravity {
            centre: Vec3::ZERO,
            gm: R::ONE,
            softening: R::ZERO,
            group: None,
        }],
        ..ParticlesDesc::default()
    };
    ParticleSystem::from_desc(&desc).expect("valid Kepler scene")
}

/// Runs `steps` steps of `h` seconds.
fn run<R: Real>(system: &mut ParticleSystem<R>, h: R, steps: u32) {
    let mut rng = Pcg32::new(7, 7);
    for _ in 0..steps {
        system.step(h, Vec3::ZERO, &mut rng);
    }
}

fn position_error_at_t10<R: Real>(system: &ParticleSystem<R>) -> f64 {
    let [x, y, _] = system.position(BODY).unwrap().to_f64();
    ((x - EXACT_T10[0]).powi(2) + (y - EXACT_T10[1]).powi(2)).sqrt()
}

/// In f64 the engine's schemes are the textbook ones, so their errors at t = 10 must agree
/// with the independently computed table.
#[test]
fn float_errors_match_the_reference_table() {
    for (integrator, steps, reference) in CONVERGENCE {
        let mut system = kepler::<f64>(integrator);
        run(&mut system, 10.0 / f64::from(steps), steps);
        let error = position_error_at_t10(&system);
        println!("{integrator} N = {steps}: error {error:.6e}, table {reference:.6e}");
        assert!(
            (error / reference - 1.0).abs() < 1e-4,
            "{integrator} N = {steps}: error {error}, table {reference}"
        );
    }
}

/// Störmer–Verlet and leapfrog (not in the table) converge with order 2 towards the exact
/// state.
#[test]
fn second_order_schemes_converge_on_kepler() {
    for integrator in [Integrator::StormerVerlet, Integrator::Leapfrog] {
        let errors: Vec<f64> = [800u32, 1600, 3200]
            .iter()
            .map(|&steps| {
                let mut system = kepler::<f64>(integrator);
                run(&mut system, 10.0 / f64::from(steps), steps);
                position_error_at_t10(&system)
            })
            .collect();
        for pair in errors.windows(2) {
            let order = (pair[0] / pair[1]).log2();
            println!(
                "{integrator}: errors {errors:?}, order {order:.3}",
                errors = errors
            );
            assert!((order - 2.0).abs() < 0.2, "{integrator}: order {order}");
        }
    }
}

/// A central force exerts no torque, and the kicks of semi-implicit Euler, velocity Verlet and
/// leapfrog are along q while their drifts are along v, so L = q × v is conserved exactly in
/// exact arithmetic: in I32F32 it may only wander by rounding, at most a few ulps (2⁻³²) per
/// step. Explicit Euler has no such property. (Störmer–Verlet conserves the discrete
/// q_n × (q_{n+1} − q_n)/h instead: its reconstructed velocity is not the conjugate momentum.)
#[test]
fn angular_momentum_is_conserved_to_rounding_in_fixed_point() {
    let h = Fx::from_ratio(1, 128);
    let steps = 1280;
    let ulp = Fx::EPSILON.to_f64();
    let rounding_bound = f64::from(steps) * 8.0 * ulp;
    for integrator in [
        Integrator::SemiImplicitEuler,
        Integrator::VelocityVerlet,
        Integrator::Leapfrog,
    ] {
        let mut system = kepler::<Fx>(integrator);
        let l0 = system.angular_momentum(Vec3::ZERO).z.to_f64();
        assert!((l0 - ANGULAR_MOMENTUM).abs() < 1e-9);
        let mut rng = Pcg32::new(7, 7);
        let mut worst = 0.0f64;
        for _ in 0..steps {
            system.step(h, Vec3::ZERO, &mut rng);
            worst = worst.max((system.angular_momentum(Vec3::ZERO).z.to_f64() - l0).abs());
        }
        println!("{integrator}: max |ΔL| = {worst:.3e} (rounding bound {rounding_bound:.3e})");
        assert!(worst <= rounding_bound, "{integrator}: |ΔL| = {worst}");
    }
    let mut euler = kepler::<Fx>(Integrator::ExplicitEuler);
    run(&mut euler, h, steps);
    let drift = (euler.angular_momentum(Vec3::ZERO).z.to_f64() - ANGULAR_MOMENTUM).abs();
    println!("ExplicitEuler: |ΔL| = {drift:.3e}");
    assert!(
        drift > 1000.0 * rounding_bound,
        "explicit Euler should not conserve L"
    );
}

/// Velocity Verlet's energy error is bounded and scales as h²: at h = 1/128 in I32F32 it stays
/// below the table's maximum at h = 0.025 scaled by (h/0.025)².
#[test]
fn velocity_verlet_energy_error_scales_with_h_squared() {
    let h = 1.0 / 128.0;
    let bound = VELOCITY_VERLET_MAX_ENERGY_ERROR_H0025 * (h / 0.025f64).powi(2);
    let mut system = kepler::<Fx>(Integrator::VelocityVerlet);
    let energy =
        |s: &ParticleSystem<Fx>| (s.kinetic_energy() + s.potential_energy(Vec3::ZERO)).to_f64();
    assert!((energy(&system) + 0.5).abs() < 1e-8, "H0 = −1/(2a) = −0.5");
    let mut rng = Pcg32::new(7, 7);
    let mut worst = 0.0f64;
    for _ in 0..1280 {
        system.step(Fx::from_ratio(1, 128), Vec3::ZERO, &mut rng);
        worst = worst.max((energy(&system) + 0.5).abs());
    }
    println!("VelocityVerlet I32F32: max |ΔH| = {worst:.3e}, scaled table bound {bound:.3e}");
    assert!(worst <= bound * 1.05, "max |ΔH| {worst} above {bound}");
    assert!(
        worst >= bound * 0.5,
        "max |ΔH| {worst} suspiciously far below {bound}"
    );
}
