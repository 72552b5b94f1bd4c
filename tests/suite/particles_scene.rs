//! Scene descriptions (validation, RON), snapshots (serde, `restore_from`) and state
//! comparison (`hash_state`, `first_difference`).

use fixstep::math::rng::Pcg32;
use fixstep::math::state_hash::StateHasher;
use fixstep::math::{Fx, Real, Vec3};
use fixstep::particles::{
    EmitterDesc, ForceDesc, Integrator, Interval, ParticleDesc, ParticleForce, ParticleSystem,
    ParticleTemplate, ParticleView, ParticlesDesc, Spread, SpringDesc,
};
use fixstep::scene::Scene;
use fixstep::world::Handle;
use fixstep::world::Target;
use fixstep_scenes::particles as presets;

fn hash(system: &ParticleSystem<Fx>) -> u64 {
    let mut h = StateHasher::new();
    system.hash_state(&mut h);
    h.finish()
}

fn valid() -> ParticlesDesc<Fx> {
    let emitter = EmitterDesc {
        position: Vec3::ZERO,
        rate: Fx::ONE,
        spread: Spread::Cone {
            axis: Vec3::Y,
            half_angle: Fx::HALF,
        },
        speed: Interval::new(Fx::ONE, Fx::TWO),
        lifetime: Interval::new(Fx::ONE, Fx::TWO),
        mass: Fx::ONE,
        group: 0,
        on: true,
    };
    let spring = SpringDesc {
        stiffness: Fx::ONE,
        damping: Fx::ZERO,
        rest_length: Fx::ONE,
    };
    ParticlesDesc {
        integrator: Integrator::Leapfrog,
        capacity: 16,
        particles: vec![
            ParticleDesc {
                position: Vec3::ZERO,
                velocity: Vec3::ZERO,
                mass: Fx::ONE,
                group: 0,
                lifetime: Fx::ZERO,
            };
            2
        ],
        templates: vec![ParticleTemplate::default()],
        emitters: vec![emitter.clone(), emitter.clone(), emitter],
        forces: vec![
            ForceDesc::Spring {
                first: 0,
                second: 1,
                spring,
            },
            ForceDesc::AnchoredSpring {
                particle: 1,
                anchor: Vec3::Y,
                spring,
            },
            ForceDesc::Damping {
                kept_per_second: Fx::HALF,
                group: None,
            },
        ],
        collisions: Vec::new(),
        contacts: None,
    }
}

/// Each invalid field is reported by its path.
#[test]
fn validation_names_the_field() {
    ParticleSystem::from_desc(&valid()).expect("the base description is valid");
    type Edit = fn(&mut ParticlesDesc<Fx>);
    let cases: [(&str, Edit); 17] = [
        ("capacity", |d| d.capacity = 0),
        ("particles", |d| d.capacity = 1),
        ("particles[1].mass", |d| d.particles[1].mass = -Fx::ONE),
        ("particles[0].lifetime", |d| {
            d.particles[0].lifetime = -Fx::ONE
        }),
        ("particles[1].velocity", |d| {
            d.particles[1].mass = Fx::ZERO;
            d.particles[1].velocity = Vec3::X;
        }),
        ("templates[0].mass", |d| {
            d.templates[0].mass = Fx::from_bits(1)
        }),
        ("emitters[2].rate", |d| d.emitters[2].rate = -Fx::ONE),
        ("emitters[0].spread.axis", |d| {
            d.emitters[0].spread = Spread::Cone {
                axis: Vec3::ZERO,
                half_angle: Fx::ONE,
            }
        }),
        ("emitters[1].spread.half_angle", |d| {
            d.emitters[1].spread = Spread::Cone {
                axis: Vec3::X,
                half_angle: Fx::from_int(4),
            }
        }),
        ("emitters[0].spread.half_extents.z", |d| {
            d.emitters[0].spread = Spread::Box {
                half_extents: Vec3::new(Fx::ONE, Fx::ONE, -Fx::ONE),
                direction: Vec3::Y,
            }
        }),
        ("emitters[0].speed.max", |d| {
            d.emitters[0].speed = Interval::new(Fx::TWO, Fx::ONE)
        }),
        ("emitters[1].lifetime.min", |d| {
            d.emitters[1].lifetime = Interval::new(Fx::ZERO, Fx::ONE)
        }),
        ("forces[0].second", |d| {
            d.forces[0] = ForceDesc::Spring {
                first: 1,
                second: 1,
                spring: SpringDesc {
                    stiffness: Fx::ONE,
                    damping: Fx::ZERO,
                    rest_length: Fx::ONE,
                },
            }
        }),
        ("forces[1].particle", |d| {
            if let ForceDesc::AnchoredSpring { particle, .. } = &mut d.forces[1] {
                *particle = 2;
            }
        }),
        ("forces[1].spring.stiffness", |d| {
            if let ForceDesc::AnchoredSpring { spring, .. } = &mut d.forces[1] {
                spring.stiffness = -Fx::ONE;
            }
        }),
        ("forces[2].kept_per_second", |d| {
            d.forces[2] = ForceDesc::Damping {
                kept_per_second: Fx::ZERO,
                group: None,
            }
        }),
        ("forces[2].coefficient", |d| {
            d.forces[2] = ForceDesc::QuadraticDrag {
                coefficient: -Fx::ONE,
                group: None,
            }
        }),
    ];
    for (field, edit) in cases {
        let mut desc = valid();
        edit(&mut desc);
        let error = ParticleSystem::from_desc(&desc).expect_err(field);
        println!("{error}");
        assert_eq!(error.field, field, "{error}");
    }
}

/// The world prefixes the particle section's path.
#[test]
fn scene_errors_are_prefixed() {
    let mut scene = Scene::<Fx>::empty("bad");
    let mut desc = valid();
    desc.emitters[2].rate = -Fx::ONE;
    scene.particles = Some(desc);
    let error = scene.build().expect_err("negative rate");
    assert_eq!(error.field, "particles.emitters[2].rate");
}

/// Scene files may leave out every field with a default.
#[test]
fn ron_scene_text_with_defaults() {
    let text = r#"(
        integrator: VelocityVerlet,
        capacity: 256,
        particles: [(position: (x: 1.0, y: 0.0, z: 0.0), velocity: (x: 0.0, y: 1.0, z: 0.0))],
        emitters: [(
            position: (x: 0.0, y: 0.0, z: 0.0),
            rate: 30.0,
            spread: Cone(axis: (x: 0.0, y: 1.0, z: 0.0), half_angle: 0.3),
            speed: (min: 4.0, max: 6.0),
            lifetime: (min: 1.0, max: 2.0),
        )],
        forces: [Gravity(), QuadraticDrag(coefficient: 0.01), PointGravity(centre: (x: 0.0, y: 0.0, z: 0.0), gm: 2.0, group: Some(1))],
    )"#;
    let desc: ParticlesDesc<Fx> = ron::from_str(text).expect("valid RON");
    assert_eq!(desc.particles[0].mass, Fx::ONE);
    assert!(desc.emitters[0].on);
    assert_eq!(
        desc.forces[0],
        ForceDesc::Gravity {
            scale: Fx::ONE,
            group: None
        }
    );
    assert!(desc.templates.is_empty());
    ParticleSystem::from_desc(&desc).expect("valid description");

    let unknown = text.replace("capacity", "capacty");
    assert!(
        ron::from_str::<ParticlesDesc<Fx>>(&unknown).is_err(),
        "unknown fields are rejected"
    );
}

/// A user force that pulls group 0 towards the origin.
struct Tether;

impl ParticleForce<Fx> for Tether {
    fn accumulate(&self, particles: &ParticleView<'_, Fx>, forces: &mut [Vec3<Fx>]) {
        for (i, force) in forces.iter_mut().enumerate() {
            if particles.alive[i] {
                *force -= particles.positions[i];
            }
        }
    }
}

/// A snapshot serialised with bincode restores the exact state; `restore_from` keeps the
/// registered user forces, and the restored run continues bit-identically.
#[test]
fn snapshots_restore_exactly_and_keep_user_forces() {
    let mut desc = presets::showcase_particles::<Fx>();
    desc.forces.push(ForceDesc::User {
        name: "tether".into(),
    });
    let mut live = ParticleSystem::from_desc(&desc).unwrap();
    live.register_user_force("tether", Box::new(Tether));
    live.check_user_forces().unwrap();
    let gravity = Vec3::new(Fx::ZERO, -Fx::from_ratio(981, 100), Fx::ZERO);
    let mut rng = Pcg32::new(4, 4);
    let tick = |s: &mut ParticleSystem<Fx>, rng: &mut Pcg32| {
        s.step(Fx::from_ratio(1, 120), gravity, rng);
        s.step(Fx::from_ratio(1, 120), gravity, rng);
        s.end_tick();
    };
    for _ in 0..90 {
        tick(&mut live, &mut rng);
    }
    live.apply_force(Target::ParticleGroup(1), Vec3::X);

    let config = bincode::config::standard();
    let bytes = bincode::serde::encode_to_vec(&live, config).unwrap();
    let (snapshot, _): (ParticleSystem<Fx>, usize) =
        bincode::serde::decode_from_slice(&bytes, config).unwrap();
    assert_eq!(snapshot, live);
    assert_eq!(hash(&snapshot), hash(&live));
    assert_eq!(
        snapshot.missing_user_forces(),
        vec!["tether".to_owned()],
        "the registry is not serialised"
    );

    let saved_rng = rng.clone();
    for _ in 0..60 {
        tick(&mut live, &mut rng);
    }
    let expected = hash(&live);

    // Restore into a system that has the user force registered, then replay.
    let mut restored = ParticleSystem::from_desc(&desc).unwrap();
    restored.register_user_force("tether", Box::new(Tether));
    restored.restore_from(snapshot);
    restored.check_user_forces().unwrap();
    let mut rng = saved_rng;
    for _ in 0..60 {
        tick(&mut restored, &mut rng);
    }
    assert_eq!(hash(&restored), expected);
    assert_eq!(restored.first_difference(&live), None);
    assert_eq!(restored, live);
}

/// `first_difference` names the lowest slot that differs, with its handle.
#[test]
fn first_difference_finds_the_lowest_differing_slot() {
    let desc = presets::orbits::<Fx>();
    let a = ParticleSystem::from_desc(&desc).unwrap();
    let mut b = a.clone();
    assert_eq!(a.first_difference(&b), None);
    assert_eq!(hash(&a), hash(&b));
    b.set_velocity(Target::Particle(Handle::new(3, 0)), Vec3::X);
    b.set_velocity(Target::Particle(Handle::new(4, 0)), Vec3::X);
    assert_eq!(a.first_difference(&b), Some(Handle::new(3, 0)));
    assert_ne!(hash(&a), hash(&b));

    let mut c = a.clone();
    let spawned = c.spawn(0, Vec3::ZERO, Vec3::ZERO).unwrap();
    assert_eq!(
        a.first_difference(&c),
        Some(spawned),
        "a slot only one side has"
    );
    assert_eq!(c.first_difference(&a), Some(spawned));
    c.remove(Target::Particle(spawned));
    assert_eq!(a.first_difference(&c), Some(Handle::new(spawned.index, 1)));
}
