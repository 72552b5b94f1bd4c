//! Particle contacts, rods and cables (Millington's mass-aggregate engine): a rod keeps its
//! length under load, a cable never stretches past its length and goes slack when pushed,
//! a particle dropped on a plane rebounds to e²h (Newton's restitution: the rebound speed
//! is e times the impact speed, and h = v²/2g), two particles colliding head-on keep their
//! momentum and part with e times their closing speed, and bad fields are named.

use fixstep::math::rng::Pcg32;
use fixstep::math::{Fx, Real, Vec3};
use fixstep::particles::{
    ContactPlaneDesc, ContactsDesc, ForceDesc, Integrator, LinkDesc, ParticleDesc, ParticleSystem,
    ParticlesDesc,
};
use fixstep::scene::{Scene, parse_scene};
use fixstep::world::{Handle, Target};

fn v(x: f64, y: f64, z: f64) -> Vec3<Fx> {
    Vec3::from_f64(x, y, z)
}

fn particle(position: Vec3<Fx>, mass: f64) -> ParticleDesc<Fx> {
    ParticleDesc {
        position,
        velocity: Vec3::ZERO,
        mass: Fx::from_f64(mass),
        group: 0,
        lifetime: Fx::ZERO,
    }
}

fn gravity() -> ForceDesc<Fx> {
    ForceDesc::Gravity {
        scale: Fx::ONE,
        group: None,
    }
}

const G: f64 = 9.81;

fn run(system: &mut ParticleSystem<Fx>, ticks: u32, mut each: impl FnMut(&ParticleSystem<Fx>)) {
    let mut rng = Pcg32::new(1, 1);
    for _ in 0..ticks {
        system.step(Fx::from_ratio(1, 60), v(0.0, -G, 0.0), &mut rng);
        system.end_tick();
        each(system);
    }
}

fn distance(system: &ParticleSystem<Fx>, a: u32, b: u32) -> f64 {
    let pa = system.position(Handle::new(a, 0)).unwrap();
    let pb = system.position(Handle::new(b, 0)).unwrap();
    (pa - pb).length().to_f64()
}

/// A double pendulum of rods from a pinned particle: a 1 kg particle 1 m out horizontally,
/// a 20 kg one 0.5 m further, released from rest; for 10 s at 60 Hz both rods keep their
/// length within 1 mm at every tick.
#[test]
fn a_rod_keeps_its_length_under_load() {
    let mut system = ParticleSystem::from_desc(&ParticlesDesc {
        particles: vec![
            particle(v(0.0, 0.0, 0.0), 0.0),
            particle(v(1.0, 0.0, 0.0), 1.0),
            particle(v(1.5, 0.0, 0.0), 20.0),
        ],
        forces: vec![gravity()],
        contacts: Some(ContactsDesc {
            links: vec![
                LinkDesc::Rod {
                    a: 0,
                    b: 1,
                    length: Fx::ONE,
                },
                LinkDesc::Rod {
                    a: 1,
                    b: 2,
                    length: Fx::HALF,
                },
            ],
            ..ContactsDesc::default()
        }),
        ..ParticlesDesc::default()
    })
    .unwrap();
    let mut worst: f64 = 0.0;
    let mut lowest: f64 = 0.0;
    run(&mut system, 600, |s| {
        worst = worst
            .max((distance(s, 0, 1) - 1.0).abs())
            .max((distance(s, 1, 2) - 0.5).abs());
        lowest = lowest.min(s.position(Handle::new(2, 0)).unwrap().y.to_f64());
    });
    println!("worst rod error {worst:.2e} m, lowest point {lowest:.3} m");
    assert!(worst <= 1e-3, "a rod's length was off by {worst} m");
    assert!(
        lowest < -1.0,
        "the pendulum did not swing: lowest {lowest} m"
    );
}

/// A 5 kg particle on a 1 m cable from a pinned particle, released 0.5 m below it: it falls
/// freely until the cable is taut, then never hangs more than 1 mm past 1 m. Pushed up
/// towards the anchor, the slack cable does not act: the particle rises as in free flight.
#[test]
fn a_cable_never_stretches_and_goes_slack_when_pushed() {
    let desc = ParticlesDesc {
        particles: vec![
            particle(v(0.0, 0.0, 0.0), 0.0),
            particle(v(0.3, -0.4, 0.0), 5.0),
        ],
        forces: vec![gravity()],
        contacts: Some(ContactsDesc {
            links: vec![LinkDesc::Cable {
                a: 0,
                b: 1,
                max_length: Fx::ONE,
                restitution: Fx::from_ratio(1, 5),
            }],
            ..ContactsDesc::default()
        }),
        ..ParticlesDesc::default()
    };
    let mut system = ParticleSystem::from_desc(&desc).unwrap();
    let mut longest: f64 = 0.0;
    let mut taut = 0;
    run(&mut system, 600, |s| {
        let length = distance(s, 0, 1);
        longest = longest.max(length);
        if length > 0.999 {
            taut += 1;
        }
    });
    println!("longest {longest:.6} m, taut at {taut} ticks");
    assert!(longest <= 1.001, "the cable stretched to {longest} m");
    assert!(taut > 300, "the cable was taut at only {taut} ticks");

    // Pushed: 3 m/s up from the hanging position, the cable slack all the way.
    let bob = Handle::new(1, 0);
    let start = system.position(bob).unwrap();
    assert!(system.set_velocity(Target::Particle(bob), v(0.0, 3.0, 0.0)));
    let mut free = ParticleSystem::from_desc(&ParticlesDesc {
        particles: vec![particle(start, 5.0)],
        forces: vec![gravity()],
        ..ParticlesDesc::default()
    })
    .unwrap();
    assert!(free.set_velocity(Target::Particle(Handle::new(0, 0)), v(0.0, 3.0, 0.0)));
    for _ in 0..10 {
        run(&mut system, 1, |_| {});
        run(&mut free, 1, |_| {});
        assert!(distance(&system, 0, 1) < 1.0, "the cable pulled");
        assert_eq!(system.position(bob), free.position(Handle::new(0, 0)));
    }
}

/// The highest point a particle dropped from `h` on the plane y = 0 with restitution `e`
/// reaches after its first bounce, m.
fn rebound_height(h: f64, e: f64, integrator: Integrator, radius: f64) -> f64 {
    let mut system = ParticleSystem::from_desc(&ParticlesDesc {
        integrator,
        particles: vec![particle(v(0.1, h + radius, 0.2), 1.0)],
        forces: vec![gravity()],
        contacts: Some(ContactsDesc {
            radius: Fx::from_f64(radius),
            planes: vec![ContactPlaneDesc {
                normal: v(0.0, 1.0, 0.0),
                offset: Fx::ZERO,
                restitution: Fx::from_f64(e),
            }],
            ..ContactsDesc::default()
        }),
        ..ParticlesDesc::default()
    })
    .unwrap();
    let bob = Handle::new(0, 0);
    let (mut bounced, mut done) = (false, false);
    let mut highest = f64::NEG_INFINITY;
    run(&mut system, 240, |s| {
        let y = s.position(bob).unwrap().y.to_f64() - radius;
        let vy = s.velocity(bob).unwrap().y;
        assert!(y >= -1e-9, "the particle passed into the plane: {y}");
        if vy > Fx::ZERO {
            bounced = true;
        }
        if bounced && !done {
            highest = highest.max(y);
            done = vy < Fx::ZERO && y < highest - 0.05;
        }
    });
    assert!(bounced, "the particle never bounced");
    highest
}

#[test]
fn a_particle_dropped_on_a_plane_rebounds_to_e_squared_h() {
    let h = 1.0;
    for e in [0.25, 0.5, 0.8, 1.0] {
        // Second- and fourth-order schemes follow the parabola exactly, so what is
        // measured is the bounce; a first-order scheme's apex lags by v Δt/2 on its own.
        for integrator in [Integrator::VelocityVerlet, Integrator::Rk4] {
            for radius in [0.0, 0.1] {
                let got = rebound_height(h, e, integrator, radius);
                let want = e * e * h;
                println!("e = {e}, {integrator}, r = {radius}: rebound {got:.5} m, e²h {want} m");
                assert!(
                    (got - want).abs() <= 0.02 * want,
                    "e = {e}, {integrator}, r = {radius}: rebound {got} m, e²h = {want} m"
                );
            }
        }
    }
}

/// A particle dropped with e = 0 comes to rest on the plane and stays there without
/// jitter: its velocity is exactly 0 once settled.
#[test]
fn a_resting_particle_does_not_jitter() {
    let mut system = ParticleSystem::from_desc(&ParticlesDesc {
        particles: vec![particle(v(0.0, 0.5, 0.0), 1.0)],
        forces: vec![gravity()],
        contacts: Some(ContactsDesc {
            planes: vec![ContactPlaneDesc {
                normal: v(0.0, 1.0, 0.0),
                offset: Fx::ZERO,
                restitution: Fx::HALF,
            }],
            ..ContactsDesc::default()
        }),
        ..ParticlesDesc::default()
    })
    .unwrap();
    run(&mut system, 300, |_| {});
    let bob = Handle::new(0, 0);
    let mut heights = Vec::new();
    run(&mut system, 60, |s| {
        heights.push(s.position(bob).unwrap().y.to_f64());
        assert!(s.velocity(bob).unwrap().y.to_f64().abs() < 1e-6);
    });
    let spread = heights.iter().cloned().fold(f64::MIN, f64::max)
        - heights.iter().cloned().fold(f64::MAX, f64::min);
    assert!(spread < 1e-6, "the resting particle moved {spread} m");
}

/// Head-on collisions of two particles of different groups (radius 0.1 m), masses 1 and
/// m₂ ∈ {1, 10, 100}, e ∈ {0.5, 0.9}, no gravity: momentum is kept within 10⁻⁴ and the
/// separating speed is e times the closing speed within 1%.
#[test]
fn head_on_particle_collisions_follow_newtons_law() {
    for e in [0.5, 0.9] {
        for m2 in [1.0, 10.0, 100.0] {
            let mut a = particle(v(-1.0, 0.0, 0.0), 1.0);
            a.velocity = v(2.0, 0.0, 0.0);
            let mut b = particle(v(0.0, 0.0, 0.0), m2);
            b.group = 1;
            b.velocity = v(-1.0, 0.0, 0.0);
            let mut system = ParticleSystem::from_desc(&ParticlesDesc {
                particles: vec![a, b],
                contacts: Some(ContactsDesc {
                    radius: Fx::from_ratio(1, 10),
                    restitution: Fx::from_f64(e),
                    ..ContactsDesc::default()
                }),
                ..ParticlesDesc::default()
            })
            .unwrap();
            let momentum = |s: &ParticleSystem<Fx>| {
                s.velocity(Handle::new(0, 0)).unwrap().x.to_f64()
                    + m2 * s.velocity(Handle::new(1, 0)).unwrap().x.to_f64()
            };
            let before = momentum(&system);
            let mut rng = Pcg32::new(1, 1);
            for _ in 0..60 {
                system.step(Fx::from_ratio(1, 60), Vec3::ZERO, &mut rng);
            }
            let after = momentum(&system);
            let separating = system.velocity(Handle::new(1, 0)).unwrap().x.to_f64()
                - system.velocity(Handle::new(0, 0)).unwrap().x.to_f64();
            assert!(
                (after - before).abs() <= 1e-4 * before.abs().max(1.0),
                "e = {e}, m₂ = {m2}: momentum {before} → {after}"
            );
            assert!(
                (separating - 3.0 * e).abs() <= 0.01 * 3.0 * e,
                "e = {e}, m₂ = {m2}: separating at {separating} m/s, want {}",
                3.0 * e
            );
        }
    }
}

/// Bad contact fields are refused with the field named.
#[test]
fn bad_contact_fields_are_named() {
    let scene = |contacts: &str| {
        format!(
            "(name: \"x\", particles: Some((particles: [(position: (x: 0.0, y: 0.0, z: 0.0)),
              (position: (x: 1.0, y: 0.0, z: 0.0))], contacts: Some(({contacts})))))"
        )
    };
    let cases = [
        (
            "links: [Rod(a: 0, b: 2, length: 1.0)]",
            "particles.contacts.links[0].Rod.b",
            "does not exist",
        ),
        (
            "links: [Rod(a: 1, b: 1, length: 1.0)]",
            "particles.contacts.links[0].Rod.b",
            "itself",
        ),
        (
            "links: [Cable(a: 0, b: 1, max_length: 0.0)]",
            "particles.contacts.links[0].Cable.max_length",
            "> 0",
        ),
        (
            "links: [Cable(a: 0, b: 1, max_length: 1.0, restitution: 2.0)]",
            "particles.contacts.links[0].Cable.restitution",
            "0 to 1",
        ),
        ("radius: -1.0", "particles.contacts.radius", "≥ 0"),
        (
            "planes: [(normal: (x: 0.0, y: 0.0, z: 0.0))]",
            "particles.contacts.planes[0].normal",
            "zero",
        ),
    ];
    for (contacts, field, message) in cases {
        let text = scene(contacts);
        let error = parse_scene::<Fx>(&text, "x.ron")
            .and_then(|s: Scene<Fx>| s.build().map(|_| ()))
            .expect_err(contacts);
        let shown = error.to_string();
        assert!(
            shown.contains(field) && shown.contains(message),
            "{contacts}: {shown}"
        );
    }
}
