//! Emitters: determinism, fractional rates, lifetimes, capacity, spread shapes and the
//! documented random-draw order.

use fixstep::math::rng::Pcg32;
use fixstep::math::state_hash::StateHasher;
use fixstep::math::{Fx, Real, Vec3};
use fixstep::particles::{
    EmitterDesc, Integrator, Interval, ParticleDesc, ParticleSystem, ParticlesDesc, Spread,
};
use fixstep_scenes::particles as presets;

fn hash(system: &ParticleSystem<Fx>) -> u64 {
    let mut h = StateHasher::new();
    system.hash_state(&mut h);
    h.finish()
}

fn emitter(rate: Fx, spread: Spread<Fx>, lifetime: Interval<Fx>) -> EmitterDesc<Fx> {
    EmitterDesc {
        position: Vec3::ZERO,
        rate,
        spread,
        speed: Interval::new(Fx::ONE, Fx::TWO),
        lifetime,
        mass: Fx::ONE,
        group: 0,
        on: true,
    }
}

fn up_cone(half_angle: Fx) -> Spread<Fx> {
    Spread::Cone {
        axis: Vec3::new(Fx::ZERO, Fx::from_int(3), Fx::ZERO),
        half_angle,
    }
}

fn with_emitters(capacity: u32, emitters: Vec<EmitterDesc<Fx>>) -> ParticleSystem<Fx> {
    ParticleSystem::from_desc(&ParticlesDesc {
        capacity,
        emitters,
        ..ParticlesDesc::default()
    })
    .expect("valid emitter scene")
}

const H: i64 = 64;

fn dt() -> Fx {
    Fx::from_ratio(1, H)
}

/// Two systems fed the same seed stay bit-identical; a different seed diverges.
#[test]
fn same_seed_same_state() {
    let gravity = Vec3::new(Fx::ZERO, -Fx::from_ratio(981, 100), Fx::ZERO);
    let (mut a, mut b, mut c) = (
        ParticleSystem::<Fx>::from_desc(&presets::fountain()).unwrap(),
        ParticleSystem::<Fx>::from_desc(&presets::fountain()).unwrap(),
        ParticleSystem::<Fx>::from_desc(&presets::fountain()).unwrap(),
    );
    let (mut rng_a, mut rng_b, mut rng_c) = (Pcg32::new(9, 1), Pcg32::new(9, 1), Pcg32::new(10, 1));
    for tick in 0..300 {
        a.step(Fx::from_ratio(1, 60), gravity, &mut rng_a);
        b.step(Fx::from_ratio(1, 60), gravity, &mut rng_b);
        c.step(Fx::from_ratio(1, 60), gravity, &mut rng_c);
        for s in [&mut a, &mut b, &mut c] {
            s.end_tick();
        }
        assert_eq!(hash(&a), hash(&b), "diverged at tick {tick}");
        assert_eq!(a.first_difference(&b), None);
    }
    assert_eq!(a, b);
    assert!(
        a.live_count() > 300,
        "the fountain should be running: {}",
        a.live_count()
    );
    assert_ne!(hash(&a), hash(&c));
    assert!(a.first_difference(&c).is_some());
}

/// A rate of 2.5/s at 64 steps/s accumulates 0.0390625 exactly per step: 5 particles after
/// 128 steps (2 s), 4 after 127.
#[test]
fn fractional_rates_accumulate_exactly() {
    let mut s = with_emitters(
        64,
        vec![emitter(
            Fx::from_ratio(5, 2),
            up_cone(Fx::ZERO),
            Interval::default(),
        )],
    );
    let mut rng = Pcg32::new(1, 2);
    let mut emitted = 0;
    for step in 1..=128 {
        emitted += s.step(dt(), Vec3::ZERO, &mut rng).emitted;
        if step == 127 {
            assert_eq!(emitted, 4);
        }
    }
    assert_eq!(emitted, 5);
    assert_eq!(s.live_count(), 5);
}

/// A lifetime of L seconds lasts round(L/dt) steps: a particle with L = 1 s at dt = 1/64 s is
/// alive after 63 steps and gone after 64.
#[test]
fn lifetimes_count_simulated_seconds() {
    let mut s = ParticleSystem::<Fx>::from_desc(&ParticlesDesc {
        particles: vec![ParticleDesc {
            position: Vec3::ZERO,
            velocity: Vec3::ZERO,
            mass: Fx::ONE,
            group: 0,
            lifetime: Fx::ONE,
        }],
        ..ParticlesDesc::default()
    })
    .unwrap();
    let mut rng = Pcg32::new(1, 2);
    let mut expired = 0;
    for _ in 0..63 {
        expired += s.step(dt(), Vec3::ZERO, &mut rng).expired;
    }
    assert_eq!((s.live_count(), expired), (1, 0));
    expired += s.step(dt(), Vec3::ZERO, &mut rng).expired;
    assert_eq!((s.live_count(), expired), (0, 1));
}

/// A full system drops what emitters owe, and reports it.
#[test]
fn capacity_limits_emission() {
    // 5 particles per step.
    let mut s = with_emitters(
        12,
        vec![emitter(
            Fx::from_int(5 * H as i32),
            up_cone(Fx::ZERO),
            Interval::default(),
        )],
    );
    let mut rng = Pcg32::new(1, 2);
    let reports: Vec<_> = (0..3).map(|_| s.step(dt(), Vec3::ZERO, &mut rng)).collect();
    assert_eq!(
        reports
            .iter()
            .map(|r| (r.emitted, r.dropped))
            .collect::<Vec<_>>(),
        vec![(5, 0), (5, 0), (2, 3)]
    );
    assert_eq!(s.live_count(), 12);
}

/// Cone directions stay within the half-angle of the axis, fill it, and speeds stay in
/// range. Every particle costs exactly four draws (polar, azimuth, speed, lifetime).
#[test]
fn cone_spread_and_draw_count() {
    let half_angle = Fx::from_ratio(3, 10);
    let mut s = with_emitters(
        1024,
        vec![emitter(
            Fx::from_int(10 * H as i32),
            up_cone(half_angle),
            Interval::new(Fx::ONE, Fx::TWO),
        )],
    );
    let mut rng = Pcg32::new(5, 5);
    let mut shadow = rng.clone();
    let report = s.step(dt(), Vec3::ZERO, &mut rng);
    assert_eq!(report.emitted, 10);
    for _ in 0..4 * report.emitted {
        shadow.next_u32();
    }
    assert_eq!(rng, shadow, "four draws per cone particle");

    let mut s = with_emitters(
        4096,
        vec![emitter(
            Fx::from_int(2000 * H as i32),
            up_cone(half_angle),
            Interval::default(),
        )],
    );
    s.step(dt(), Vec3::ZERO, &mut Pcg32::new(6, 6));
    let cos_limit = half_angle.to_f64().cos();
    let mut widest = 1.0f64;
    for handle in s.handles() {
        let v = s.velocity(handle).unwrap().to_f64();
        let speed = (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt();
        assert!((1.0 - 1e-6..2.0 + 1e-6).contains(&speed), "speed {speed}");
        let cos = v[1] / speed;
        assert!(
            cos >= cos_limit - 1e-6,
            "outside the cone: cos {cos} < {cos_limit}"
        );
        widest = widest.min(cos);
    }
    assert!(
        widest < cos_limit + 0.002,
        "the cone edge is never reached: {widest}"
    );
}

/// Box emitters place particles within the half extents and launch them along the
/// direction; five draws per particle.
#[test]
fn box_spread_and_draw_count() {
    let half = Vec3::new(Fx::ONE, Fx::ZERO, Fx::HALF);
    let spread = Spread::Box {
        half_extents: half,
        direction: Vec3::new(Fx::ZERO, Fx::ZERO, -Fx::TWO),
    };
    let mut s = with_emitters(
        1024,
        vec![emitter(
            Fx::from_int(500 * H as i32),
            spread,
            Interval::default(),
        )],
    );
    let mut rng = Pcg32::new(5, 5);
    let mut shadow = rng.clone();
    let report = s.step(dt(), Vec3::ZERO, &mut rng);
    for _ in 0..5 * report.emitted {
        shadow.next_u32();
    }
    assert_eq!(rng, shadow, "five draws per box particle");
    let (mut min_x, mut max_x) = (0.0f64, 0.0f64);
    for handle in s.handles() {
        // One semi-implicit step moved it by v·dt along −z.
        let v = s.velocity(handle).unwrap();
        let p = s.position(handle).unwrap() - v * dt();
        assert!(
            p.x.abs() <= half.x && p.y == Fx::ZERO && p.z.abs() <= half.z,
            "{p:?}"
        );
        assert!(v.x == Fx::ZERO && v.y == Fx::ZERO && v.z < Fx::ZERO);
        min_x = min_x.min(p.x.to_f64());
        max_x = max_x.max(p.x.to_f64());
    }
    assert!(
        min_x < -0.95 && max_x > 0.95,
        "box not filled: [{min_x}, {max_x}]"
    );
}

/// A switched-off emitter emits nothing and keeps its accumulator.
#[test]
fn switching_emitters() {
    let mut s = with_emitters(
        64,
        vec![emitter(
            Fx::from_int(H as i32 / 2),
            up_cone(Fx::ZERO),
            Interval::default(),
        )],
    );
    let mut rng = Pcg32::new(1, 1);
    s.step(dt(), Vec3::ZERO, &mut rng); // accumulator 0.5
    assert!(s.set_emitter(0, false));
    assert_eq!(s.emitter_is_on(0), Some(false));
    for _ in 0..10 {
        assert_eq!(s.step(dt(), Vec3::ZERO, &mut rng).emitted, 0);
    }
    assert!(s.set_emitter(0, true));
    assert_eq!(s.step(dt(), Vec3::ZERO, &mut rng).emitted, 1);
    assert!(!s.set_emitter(1, true));
}

/// Every preset builds, runs a few seconds in every integrator without saturating, and its
/// RON text reads back to the same description.
#[test]
fn presets_build_run_and_round_trip_through_ron() {
    let gravity = Vec3::new(Fx::ZERO, -Fx::from_ratio(981, 100), Fx::ZERO);
    for (name, desc) in [
        ("fountain", presets::fountain::<Fx>()),
        ("orbits", presets::orbits::<Fx>()),
        ("showcase", presets::showcase_particles::<Fx>()),
    ] {
        let text = ron::ser::to_string_pretty(&desc, ron::ser::PrettyConfig::default()).unwrap();
        let back: ParticlesDesc<Fx> = ron::from_str(&text).unwrap();
        assert_eq!(back, desc, "{name} RON round trip");
        for integrator in Integrator::ALL {
            let mut s = ParticleSystem::from_desc(&ParticlesDesc {
                integrator,
                ..desc.clone()
            })
            .unwrap();
            let mut rng = Pcg32::new(2, 2);
            let (_, saturations) = fixstep::math::saturation::count_saturations(|| {
                for _ in 0..300 {
                    s.step(Fx::from_ratio(1, 60), gravity, &mut rng);
                    s.end_tick();
                }
            });
            assert_eq!(saturations, 0, "{name} with {integrator} saturated");
            assert!(
                s.max_speed() < Fx::from_int(50),
                "{name} with {integrator} blew up"
            );
        }
    }
}

/// The presets are generic: they build and run in the coarser fixed-point formats too.
#[test]
fn presets_run_in_other_formats() {
    fn run<R: Real>() {
        let gravity = Vec3::new(R::ZERO, -R::from_ratio(981, 100), R::ZERO);
        for desc in [
            presets::fountain::<R>(),
            presets::orbits::<R>(),
            presets::showcase_particles::<R>(),
        ] {
            let mut s = ParticleSystem::from_desc(&desc).unwrap();
            let mut rng = Pcg32::new(2, 2);
            let (_, saturations) = fixstep::math::saturation::count_saturations(|| {
                for _ in 0..120 {
                    s.step(R::from_ratio(1, 60), gravity, &mut rng);
                    s.end_tick();
                }
            });
            assert_eq!(saturations, 0, "{} saturated", R::NAME);
            assert!(s.max_speed() < R::from_int(50), "{} blew up", R::NAME);
        }
    }
    run::<fixstep::math::FxI48F16>();
    run::<fixstep::math::FxI40F24>();
    run::<f64>();
}
