//! Implicit Euler (`Integrator::ImplicitEuler`, Baraff & Witkin 1998) on springs: its energy
//! decay against theory, its stability where semi-implicit Euler diverges, the
//! conjugate-gradient solve of networks against the same scheme in `f64`, and spring-mass
//! bodies.
//!
//! Theory: on x'' = −ω² x backward Euler's one-step map is (I − hJ)⁻¹, whose eigenvalues
//! 1/(1 ∓ iθ), θ = ωh, have |λ|² = 1/(1 + θ²): the energy ½v² + ½ω²x² falls by exactly that
//! factor every step (derived; `harmonic_oscillator_discrete_amplification.csv` tabulates
//! the explicit schemes only).

use fixstep::math::rng::Pcg32;
use fixstep::math::{Fx, Real, Vec3};
use fixstep::particles::{
    ForceDesc, Integrator, ParticleDesc, ParticleSystem, ParticlesDesc, SpringDesc,
};
use fixstep::scene::Scene;
use fixstep::soft::SoftModel;
use fixstep::world::{Handle, TickInput, World};
use fixstep_scenes::builtin_scene;

/// A particle of mass `mass` on an anchored spring of stiffness `stiffness` and rest length
/// 2 m, displaced 1 m along x.
fn oscillator<R: Real>(integrator: Integrator, stiffness: R, mass: R) -> ParticlesDesc<R> {
    ParticlesDesc {
        integrator,
        particles: vec![ParticleDesc {
            position: Vec3::new(R::from_int(3), R::ZERO, R::ZERO),
            velocity: Vec3::ZERO,
            mass,
            group: 0,
            lifetime: R::ZERO,
        }],
        forces: vec![ForceDesc::AnchoredSpring {
            particle: 0,
            anchor: Vec3::ZERO,
            spring: SpringDesc {
                stiffness,
                damping: R::ZERO,
                rest_length: R::TWO,
            },
        }],
        ..ParticlesDesc::default()
    }
}

/// ½ m v² + ½ k u² of the oscillator (k = ω² for m = 1), u the stretch.
fn energy<R: Real>(system: &ParticleSystem<R>, stiffness: f64) -> f64 {
    let bob = Handle::new(0, 0);
    let u = system.position(bob).unwrap().x.to_f64() - 2.0;
    let v = system.velocity(bob).unwrap().x.to_f64();
    0.5 * v * v + 0.5 * stiffness * u * u
}

fn energy_decay<R: Real>() {
    for theta in [0.1, 0.5, 1.0, 10.0] {
        let h = R::from_f64(theta);
        let mut system =
            ParticleSystem::from_desc(&oscillator(Integrator::ImplicitEuler, R::ONE, R::ONE))
                .unwrap();
        let mut rng = Pcg32::new(1, 1);
        let expected = 1.0 / (1.0 + theta * theta);
        // Steps until the energy is down to about 1%, at least one.
        let steps = ((0.01f64).ln() / expected.ln()).ceil().max(1.0) as u32;
        let e0 = energy(&system, 1.0);
        for _ in 0..steps {
            system.step(h, Vec3::ZERO, &mut rng);
        }
        let measured = (energy(&system, 1.0) / e0).powf(1.0 / f64::from(steps));
        let error = (measured / expected - 1.0).abs();
        println!(
            "{} θ = {theta}: per-step energy factor {measured:.6}, theory {expected:.6} over {steps} steps",
            R::NAME
        );
        assert!(
            error < 0.01,
            "{} θ = {theta}: energy factor {measured}, theory {expected}",
            R::NAME
        );
    }
}

#[test]
fn energy_decays_by_one_over_one_plus_theta_squared_in_f64() {
    energy_decay::<f64>();
}

#[test]
fn energy_decays_by_one_over_one_plus_theta_squared_in_fixed_point() {
    energy_decay::<Fx>();
}

/// A world of the oscillator at 60 Hz with k dt²/m = 100 (k = 360,000 N/m, m = 1 kg).
fn stiff_world(integrator: Integrator) -> World<Fx> {
    let mut scene = Scene::empty("stiff");
    scene.tick_rate = 60;
    scene.particles = Some(oscillator(integrator, Fx::from_int(360_000), Fx::ONE));
    scene.build().unwrap()
}

fn idle(tick: u64) -> TickInput<Fx> {
    TickInput {
        tick,
        players: Vec::new(),
    }
}

/// At k·dt²/m = 100 (ωh = 10, five times semi-implicit Euler's bound of 2) semi-implicit
/// Euler diverges and the world's divergence check says so; implicit Euler stays bounded,
/// its energy falling, and the check stays quiet.
#[test]
fn stable_at_k_dt2_over_m_of_100_where_semi_implicit_euler_diverges() {
    let mut explicit = stiff_world(Integrator::SemiImplicitEuler);
    explicit.enable_divergence_check(1);
    for _ in 0..60 {
        let tick = explicit.tick();
        explicit.step(&idle(tick));
    }
    let divergence = explicit.divergence().expect("semi-implicit Euler diverges");
    assert!(divergence.tick < 10, "seen at tick {}", divergence.tick);

    let mut implicit = stiff_world(Integrator::ImplicitEuler);
    implicit.enable_divergence_check(1);
    let e0 = energy(implicit.particles().unwrap(), 360_000.0);
    let mut previous = e0;
    for _ in 0..600 {
        let tick = implicit.tick();
        implicit.step(&idle(tick));
        let e = energy(implicit.particles().unwrap(), 360_000.0);
        assert!(
            e <= previous * (1.0 + 1e-6) + 1e-6,
            "tick {tick}: energy {e} > {previous}"
        );
        previous = e;
    }
    assert_eq!(implicit.divergence(), None);
    assert_eq!(implicit.saturations_total(), 0);
    assert!(previous < 1e-3 * e0, "energy {previous} of {e0}");
}

/// A chain of 12 particles hanging from a pinned end (springs between neighbours, gravity,
/// spring damping and linear drag), released stretched: the conjugate-gradient solve in
/// I32F32 follows the same scheme in f64 within 10⁻⁴ m over 2 s at a step past
/// semi-implicit Euler's limit (h² · 4k/m ≈ 22 > 4), and the chain settles.
#[test]
fn networks_solved_by_conjugate_gradients_match_f64() {
    fn chain<R: Real>() -> ParticleSystem<R> {
        let n = 12;
        let particles = (0..n)
            .map(|i| ParticleDesc {
                position: Vec3::new(R::ZERO, -R::from_ratio(i64::from(i), 4), R::ZERO),
                velocity: Vec3::ZERO,
                mass: if i == 0 {
                    R::ZERO
                } else {
                    R::from_ratio(1, 10)
                },
                group: 0,
                lifetime: R::ZERO,
            })
            .collect();
        let mut forces: Vec<ForceDesc<R>> = (1..n)
            .map(|i| ForceDesc::Spring {
                first: i - 1,
                second: i,
                spring: SpringDesc {
                    stiffness: R::from_int(2000),
                    damping: R::from_ratio(1, 2),
                    rest_length: R::from_ratio(1, 5),
                },
            })
            .collect();
        forces.push(ForceDesc::Gravity {
            scale: R::ONE,
            group: None,
        });
        forces.push(ForceDesc::LinearDrag {
            coefficient: R::from_ratio(1, 100),
            group: None,
        });
        ParticleSystem::from_desc(&ParticlesDesc {
            integrator: Integrator::ImplicitEuler,
            particles,
            forces,
            ..ParticlesDesc::default()
        })
        .unwrap()
    }
    let mut fixed = chain::<Fx>();
    let mut float = chain::<f64>();
    let (mut rng_a, mut rng_b) = (Pcg32::new(1, 1), Pcg32::new(1, 1));
    let gravity = Vec3::new(0.0, -9.81, 0.0);
    for _ in 0..120 {
        fixed.step(
            Fx::from_ratio(1, 60),
            Vec3::from_f64(0.0, -9.81, 0.0),
            &mut rng_a,
        );
        float.step(1.0 / 60.0, gravity, &mut rng_b);
    }
    let mut worst = 0.0f64;
    for (a, b) in fixed.positions().iter().zip(float.positions()) {
        let [ax, ay, az] = a.to_f64();
        let d = ((ax - b.x).powi(2) + (ay - b.y).powi(2) + (az - b.z).powi(2)).sqrt();
        worst = worst.max(d);
    }
    assert!(worst < 1e-4, "I32F32 is {worst} m from f64");
    let end = float.positions()[11];
    assert!(end.length() < 4.0, "the chain flew apart: {end:?}");
}

/// The jelly (a spring-mass lattice) with implicit Euler and springs 2,500 times stiffer
/// than its own: no stability warning, no divergence, no saturation, while semi-implicit
/// Euler is warned about and diverges.
#[test]
fn spring_mass_bodies_take_implicit_euler() {
    let stiff = |integrator: Integrator| {
        let mut scene = builtin_scene::<Fx>("jelly").unwrap();
        if let SoftModel::SpringMass {
            integrator: chosen,
            stiffness,
            ..
        } = &mut scene.soft.as_mut().unwrap().bodies[0].model
        {
            *chosen = integrator;
            *stiffness = Fx::from_int(100_000);
        }
        let mut world = scene.build().unwrap();
        world.enable_divergence_check(1);
        world
    };
    let mut explicit = stiff(Integrator::SemiImplicitEuler);
    assert_eq!(explicit.warnings().len(), 1, "{:?}", explicit.warnings());
    let mut implicit = stiff(Integrator::ImplicitEuler);
    assert!(implicit.warnings().is_empty(), "{:?}", implicit.warnings());
    for _ in 0..120 {
        for world in [&mut explicit, &mut implicit] {
            let tick = world.tick();
            world.step(&idle(tick));
        }
    }
    assert!(explicit.divergence().is_some() || explicit.saturations_total() > 0);
    assert_eq!(implicit.divergence(), None);
    assert_eq!(implicit.saturations_total(), 0);
    let m = implicit.metrics();
    assert!(m.max_stretch < 0.05, "max stretch {}", m.max_stretch);
}
