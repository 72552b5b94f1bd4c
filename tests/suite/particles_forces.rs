//! Force generators against closed-form physics.
//!
//! Reference data, copied below with their provenance:
//! * `/work/shared/reference/damped_oscillator_reference.csv`: exact x(t) of
//!   x'' + 2ζω₀x' + ω₀²x = 0, ω₀ = 1, x(0) = 1, v(0) = 0 (mpmath);
//! * `/work/shared/reference/projectile_linear_drag_reference.csv`: exact trajectory of
//!   m dv/dt = m g − b v with g = 9.81, m = 1 kg, b = 0.5 kg/s, |v0| = 20 m/s at 45°
//!   (mpmath, 30 digits).

use fixstep::math::rng::Pcg32;
use fixstep::math::{Fx, Real, Vec3};
use fixstep::particles::{
    ForceDesc, Integrator, ParticleDesc, ParticleForce, ParticleSystem, ParticleView,
    ParticlesDesc, SpringDesc,
};
use fixstep::world::Handle;

const FIRST: Handle = Handle::new(0, 0);
const SECOND: Handle = Handle::new(1, 0);

fn particle<R: Real>(position: Vec3<R>, velocity: Vec3<R>, mass: R, group: u16) -> ParticleDesc<R> {
    ParticleDesc {
        position,
        velocity,
        mass,
        group,
        lifetime: R::ZERO,
    }
}

fn system<R: Real>(
    integrator: Integrator,
    particles: Vec<ParticleDesc<R>>,
    forces: Vec<ForceDesc<R>>,
) -> ParticleSystem<R> {
    ParticleSystem::from_desc(&ParticlesDesc {
        integrator,
        particles,
        forces,
        ..ParticlesDesc::default()
    })
    .expect("valid test scene")
}

fn run<R: Real>(system: &mut ParticleSystem<R>, h: R, gravity: Vec3<R>, steps: u32) {
    let mut rng = Pcg32::new(3, 3);
    for _ in 0..steps {
        system.step(h, gravity, &mut rng);
    }
}

/// v ← v·d^Δt is frame-rate independent: with d = 1/2 per second, 60 steps of 1/60 s and
/// 120 steps of 1/120 s both halve the velocity, up to the rounding of d^Δt and of each
/// product (≤ 1 ulp each, so ≲ (n₁ + n₂)·|v|·2⁻³² in all).
#[test]
fn damping_is_frame_rate_independent() {
    let speed_after_one_second = |rate: i32| {
        let mut s = system::<Fx>(
            Integrator::SemiImplicitEuler,
            vec![particle(
                Vec3::ZERO,
                Vec3::new(Fx::from_int(10), Fx::ZERO, Fx::ZERO),
                Fx::ONE,
                0,
            )],
            vec![ForceDesc::Damping {
                kept_per_second: Fx::HALF,
                group: None,
            }],
        );
        run(
            &mut s,
            Fx::from_ratio(1, i64::from(rate)),
            Vec3::ZERO,
            rate as u32,
        );
        s.velocity(FIRST).unwrap().x.to_f64()
    };
    let (at_60, at_120) = (speed_after_one_second(60), speed_after_one_second(120));
    let tolerance = 180.0 * 11.0 * Fx::EPSILON.to_f64();
    println!("after 1 s: {at_60:.12} at 60 Hz, {at_120:.12} at 120 Hz (tolerance {tolerance:.2e})");
    assert!((at_60 - at_120).abs() <= tolerance);
    assert!((at_60 - 5.0).abs() <= tolerance);
    assert!((at_120 - 5.0).abs() <= tolerance);
}

/// The anchored spring's damping c (v·û) reproduces the damped oscillator with c = 2ζ
/// (k = 1, m = 1), integrated with RK4 at h = 1/64 s: x(t) within 10⁻⁶ m of the exact
/// solution for ζ = 0.1, 0.5 and 1 (critical), in f64 and I32F32.
#[test]
fn damped_spring_matches_the_damped_oscillator() {
    // (t, x for ζ = 0.1, x for ζ = 0.5, x for ζ = 1) from damped_oscillator_reference.csv.
    const ROWS: [(u32, [f64; 3]); 4] = [
        (1, [0.5689718909461, 0.659700153391702, 0.735758882342885]),
        (
            2,
            [-0.258070263439546, 0.150574365145888, 0.406005849709838],
        ),
        (
            5,
            [0.098550667618586, -0.0745905665950333, 0.0404276819945128],
        ),
        (
            10,
            [
                -0.336851680590413,
                -0.00217011673932621,
                0.000499399227387333,
            ],
        ),
    ];
    fn check<R: Real>() {
        for (column, zeta) in [(1, 10), (5, 10), (1, 1)].iter().enumerate() {
            let damping = R::from_ratio(2 * zeta.0, zeta.1);
            let mut s = system(
                Integrator::Rk4,
                vec![particle(
                    Vec3::new(R::from_int(3), R::ZERO, R::ZERO),
                    Vec3::ZERO,
                    R::ONE,
                    0,
                )],
                vec![ForceDesc::AnchoredSpring {
                    particle: 0,
                    anchor: Vec3::ZERO,
                    spring: SpringDesc {
                        stiffness: R::ONE,
                        damping,
                        rest_length: R::TWO,
                    },
                }],
            );
            let mut elapsed = 0;
            for (t, expected) in ROWS {
                run(&mut s, R::from_ratio(1, 64), Vec3::ZERO, (t - elapsed) * 64);
                elapsed = t;
                let x = s.position(FIRST).unwrap().x.to_f64() - 2.0;
                let error = (x - expected[column]).abs();
                println!(
                    "{} c = {damping}: t = {t}: x = {x:.12}, error {error:.2e}",
                    R::NAME
                );
                assert!(
                    error < 1e-6,
                    "{} ζ column {column}, t = {t}: {x} vs {}",
                    R::NAME,
                    expected[column]
                );
            }
        }
    }
    check::<f64>();
    check::<Fx>();
}

/// World gravity through a `Gravity` entry plus linear drag F = −b v reproduce the exact
/// projectile (RK4, h = 1/64 s) within 10⁻⁶ m at t = 0.5, 1, 1.5 and 2 s.
#[test]
fn linear_drag_projectile_matches_the_closed_form() {
    // (t, x, y) from projectile_linear_drag_reference.csv.
    const ROWS: [(u32, f64, f64); 4] = [
        (32, 6.25645865133455, 5.12631592361262),
        (64, 11.1289935482478, 6.94873046112403),
        (96, 14.9237275415065, 6.19806401194911),
        (128, 17.8790693470041, 3.44348007543673),
    ];
    const V0: f64 = 14.142135623731;
    fn check<R: Real>() {
        let mut s = system(
            Integrator::Rk4,
            vec![particle(Vec3::ZERO, Vec3::from_f64(V0, V0, 0.0), R::ONE, 0)],
            vec![
                ForceDesc::Gravity {
                    scale: R::ONE,
                    group: None,
                },
                ForceDesc::LinearDrag {
                    coefficient: R::HALF,
                    group: None,
                },
            ],
        );
        let gravity = Vec3::new(R::ZERO, -R::from_ratio(981, 100), R::ZERO);
        let mut elapsed = 0;
        for (steps, x, y) in ROWS {
            run(&mut s, R::from_ratio(1, 64), gravity, steps - elapsed);
            elapsed = steps;
            let [px, py, _] = s.position(FIRST).unwrap().to_f64();
            let error = ((px - x).powi(2) + (py - y).powi(2)).sqrt();
            println!(
                "{} t = {}: ({px:.9}, {py:.9}), error {error:.2e}",
                R::NAME,
                f64::from(steps) / 64.0
            );
            assert!(
                error < 1e-6,
                "{}: at step {steps} ({px}, {py}) vs ({x}, {y})",
                R::NAME
            );
        }
    }
    check::<f64>();
    check::<Fx>();
}

/// Under gravity and quadratic drag F = −k|v|v a falling body tends to the terminal speed
/// √(mg/k), which is also the fixed point of every integrator's map.
#[test]
fn quadratic_drag_gives_the_terminal_speed() {
    let (mass, k, g) = (Fx::TWO, Fx::from_ratio(1, 10), Fx::from_ratio(981, 100));
    let terminal = (mass.to_f64() * g.to_f64() / k.to_f64()).sqrt();
    for integrator in Integrator::ALL {
        let mut s = system(
            integrator,
            vec![particle(Vec3::ZERO, Vec3::ZERO, mass, 0)],
            vec![
                ForceDesc::Gravity {
                    scale: Fx::ONE,
                    group: None,
                },
                ForceDesc::QuadraticDrag {
                    coefficient: k,
                    group: None,
                },
            ],
        );
        run(
            &mut s,
            Fx::from_ratio(1, 64),
            Vec3::new(Fx::ZERO, -g, Fx::ZERO),
            64 * 30,
        );
        let speed = -s.velocity(FIRST).unwrap().y.to_f64();
        println!("{integrator}: {speed:.9} m/s vs √(mg/k) = {terminal:.9}");
        assert!(
            (speed - terminal).abs() < 1e-6,
            "{integrator}: {speed} vs {terminal}"
        );
    }
}

/// Softened point gravity a = −GM r (r² + ε²)^{−3/2} holds a circular orbit at the speed
/// v² = GM r² (r² + ε²)^{−3/2}, and conserves E = ½mv² − GMm/√(r² + ε²) on an eccentric
/// one (RK4, h = 1/128 s, 8 s).
#[test]
fn softened_point_gravity_orbits() {
    let (gm, softening, radius) = (Fx::ONE, Fx::HALF, Fx::ONE);
    let s2 = radius * radius + softening * softening;
    let circular = (gm * radius * radius * s2.rsqrt() * s2.rsqrt() * s2.rsqrt()).sqrt();
    for (speed, check_radius) in [(circular, true), (Fx::from_ratio(6, 10), false)] {
        let mut s = system(
            Integrator::Rk4,
            vec![particle(
                Vec3::new(radius, Fx::ZERO, Fx::ZERO),
                Vec3::new(Fx::ZERO, speed, Fx::ZERO),
                Fx::ONE,
                0,
            )],
            vec![ForceDesc::PointGravity {
                centre: Vec3::ZERO,
                gm,
                softening,
                group: None,
            }],
        );
        let energy =
            |s: &ParticleSystem<Fx>| (s.kinetic_energy() + s.potential_energy(Vec3::ZERO)).to_f64();
        let e0 = energy(&s);
        let mut rng = Pcg32::new(3, 3);
        let (mut radius_error, mut energy_error) = (0.0f64, 0.0f64);
        for _ in 0..8 * 128 {
            s.step(Fx::from_ratio(1, 128), Vec3::ZERO, &mut rng);
            let r = s.position(FIRST).unwrap().length().to_f64();
            radius_error = radius_error.max((r - 1.0).abs());
            energy_error = energy_error.max((energy(&s) - e0).abs());
        }
        println!("v0 = {speed}: max |r − 1| = {radius_error:.2e}, max |ΔE| = {energy_error:.2e}");
        if check_radius {
            assert!(
                radius_error < 1e-6,
                "circular orbit radius drifted by {radius_error}"
            );
        }
        assert!(energy_error < 1e-6, "energy changed by {energy_error}");
    }
}

/// A spring between two particles pushes them with opposite forces, so total momentum is
/// conserved to rounding, and (with velocity Verlet) the energy ½m₁v₁² + ½m₂v₂² + ½k(ℓ − ℓ₀)²
/// stays within O(h²).
#[test]
fn two_particle_spring_conserves_momentum_and_energy() {
    let mut s = system(
        Integrator::VelocityVerlet,
        vec![
            particle(
                Vec3::ZERO,
                Vec3::new(Fx::ONE, Fx::HALF, Fx::ZERO),
                Fx::ONE,
                0,
            ),
            particle(
                Vec3::new(Fx::TWO, Fx::ZERO, Fx::ZERO),
                Vec3::ZERO,
                Fx::ONE,
                0,
            ),
        ],
        vec![ForceDesc::Spring {
            first: 0,
            second: 1,
            spring: SpringDesc {
                stiffness: Fx::from_int(4),
                damping: Fx::ZERO,
                rest_length: Fx::ONE,
            },
        }],
    );
    let p0 = s.momentum().to_f64();
    let e0 = (s.kinetic_energy() + s.potential_energy(Vec3::ZERO)).to_f64();
    let mut rng = Pcg32::new(3, 3);
    let steps = 1000;
    let mut energy_error = 0.0f64;
    for _ in 0..steps {
        s.step(Fx::from_ratio(1, 128), Vec3::ZERO, &mut rng);
        let e = (s.kinetic_energy() + s.potential_energy(Vec3::ZERO)).to_f64();
        energy_error = energy_error.max((e - e0).abs() / e0);
    }
    let p = s.momentum().to_f64();
    let momentum_error = (0..3).map(|i| (p[i] - p0[i]).abs()).fold(0.0, f64::max);
    println!("spring pair: |Δp| = {momentum_error:.2e}, max |ΔE|/E = {energy_error:.2e}");
    assert!(momentum_error <= f64::from(steps) * 4.0 * Fx::EPSILON.to_f64());
    // ω² = 2k/m = 8 for the relative motion: (ωh)²/4 = 8/128²/4.
    assert!(energy_error <= 8.0 / (128.0 * 128.0) / 4.0 * 1.5);
    assert!(s.position(SECOND).unwrap().x > Fx::ONE);
}

/// A constant user force on group 1.
struct Push(Vec3<Fx>);

impl ParticleForce<Fx> for Push {
    fn accumulate(&self, particles: &ParticleView<'_, Fx>, forces: &mut [Vec3<Fx>]) {
        for (i, force) in forces.iter_mut().enumerate() {
            if particles.alive[i] && particles.groups[i] == 1 {
                *force += self.0;
            }
        }
    }
}

/// Group restrictions select particles, and a registered user force accelerates by F/m.
#[test]
fn group_restrictions_and_user_forces() {
    let mut s = system(
        Integrator::SemiImplicitEuler,
        vec![
            particle(Vec3::ZERO, Vec3::ZERO, Fx::ONE, 0),
            particle(Vec3::ZERO, Vec3::ZERO, Fx::TWO, 1),
        ],
        vec![
            ForceDesc::Gravity {
                scale: Fx::TWO,
                group: Some(0),
            },
            ForceDesc::User {
                name: "push".into(),
            },
        ],
    );
    assert_eq!(s.missing_user_forces(), vec!["push".to_owned()]);
    let error = s.check_user_forces().unwrap_err();
    assert_eq!(error.field, "forces[1].name");
    s.register_user_force(
        "push",
        Box::new(Push(Vec3::new(Fx::from_int(4), Fx::ZERO, Fx::ZERO))),
    );
    assert!(s.missing_user_forces().is_empty());
    s.check_user_forces().unwrap();

    let g = Vec3::new(Fx::ZERO, -Fx::ONE, Fx::ZERO);
    run(&mut s, Fx::ONE, g, 1);
    // Group 0: a = 2g, no push. Group 1: a = F/m = 2 m/s² along x, no gravity.
    assert_eq!(
        s.velocity(FIRST).unwrap(),
        Vec3::new(Fx::ZERO, -Fx::TWO, Fx::ZERO)
    );
    assert_eq!(
        s.velocity(SECOND).unwrap(),
        Vec3::new(Fx::TWO, Fx::ZERO, Fx::ZERO)
    );
}
