//! Particle sections of the built-in scenes. Every constant is an exact ratio or an
//! integer-backed function of one, so the presets are the same bits on every machine.

use fixstep::math::{Real, Vec3};
use fixstep::particles::Integrator;
use fixstep::particles::{
    EmitterDesc, ForceDesc, Interval, ParticleDesc, ParticleTemplate, ParticlesDesc, Spread,
    SpringDesc,
};

/// `num/den` in the scalar format.
fn ratio<R: Real>(num: i64, den: i64) -> R {
    R::from_ratio(num, den)
}

/// The vector (x, y, z) from integers.
fn ivec<R: Real>(x: i32, y: i32, z: i32) -> Vec3<R> {
    Vec3::new(R::from_int(x), R::from_int(y), R::from_int(z))
}

/// Three cone emitters spraying 0.1 kg droplets upward (the outer two tilted inward) against
/// gravity and quadratic drag (k = 0.01 kg/m, terminal speed √(mg/k) ≈ 9.9 m/s). There is no
/// ground: droplets die after 1.5–2.5 s, so about 450 are alive at once. Template 0 spawns a
/// 3 s droplet in group 3.
pub fn fountain<R: Real>() -> ParticlesDesc<R> {
    let droplet_mass = ratio::<R>(1, 10);
    let emitter = |x: i32, tilt: R, group: u16| EmitterDesc {
        position: ivec(x, 0, 0),
        rate: R::from_int(60),
        spread: Spread::Cone {
            axis: Vec3::new(tilt, R::ONE, R::ZERO),
            half_angle: ratio(15, 100),
        },
        speed: Interval::new(R::from_int(7), R::from_int(9)),
        lifetime: Interval::new(ratio(3, 2), ratio(5, 2)),
        mass: droplet_mass,
        group,
        on: true,
    };
    ParticlesDesc {
        integrator: Integrator::SemiImplicitEuler,
        capacity: 1024,
        particles: Vec::new(),
        templates: vec![ParticleTemplate {
            mass: droplet_mass,
            group: 3,
            lifetime: R::from_int(3),
        }],
        emitters: vec![
            emitter(-2, ratio(1, 5), 0),
            emitter(0, R::ZERO, 1),
            emitter(2, -ratio::<R>(1, 5), 2),
        ],
        forces: vec![
            ForceDesc::Gravity {
                scale: R::ONE,
                group: None,
            },
            ForceDesc::QuadraticDrag {
                coefficient: ratio(1, 100),
                group: None,
            },
        ],
        collisions: Vec::new(),
        contacts: None,
    }
}

/// Four 1 kg bodies around a fixed centre with GM = 40 m³/s² and softening ε = 0.05 m,
/// integrated with velocity Verlet (meant for zero world gravity):
///
/// * a circular orbit, r = 2 m, v = √(GM/r) (period 2π√(r³/GM) ≈ 2.8 s);
/// * an e = 0.5 ellipse, a = 3 m, starting at periapsis r = a(1 − e) = 1.5 m with
///   v = √(GM(1 + e)/(a(1 − e)));
/// * an e = 0.2 ellipse, a = 4 m, in the x–z plane;
/// * a retrograde circular orbit, r = 5 m.
///
/// Particle 0 is a pinned marker at the centre (it feels nothing and weighs nothing).
pub fn orbits<R: Real>() -> ParticlesDesc<R> {
    let gm = R::from_int(40);
    let body = |position: Vec3<R>, velocity: Vec3<R>| ParticleDesc {
        position,
        velocity,
        mass: R::ONE,
        group: 0,
        lifetime: R::ZERO,
    };
    // Starting speeds from the vis-viva equation v² = GM (2/r − 1/a).
    let circular_speed = |r: i32| (gm / R::from_int(r)).sqrt();
    let periapsis_speed = |a: R, e: R| (gm * (R::ONE + e) / (a * (R::ONE - e))).sqrt();
    let half = R::HALF;
    let fifth = ratio::<R>(1, 5);
    ParticlesDesc {
        integrator: Integrator::VelocityVerlet,
        capacity: 64,
        particles: vec![
            ParticleDesc {
                position: Vec3::ZERO,
                velocity: Vec3::ZERO,
                mass: R::ZERO,
                group: 1,
                lifetime: R::ZERO,
            },
            body(
                ivec(2, 0, 0),
                Vec3::new(R::ZERO, circular_speed(2), R::ZERO),
            ),
            body(
                Vec3::new(-ratio::<R>(3, 2), R::ZERO, R::ZERO),
                Vec3::new(R::ZERO, -periapsis_speed(R::from_int(3), half), R::ZERO),
            ),
            body(
                Vec3::new(R::ZERO, R::ZERO, ratio(16, 5)),
                Vec3::new(periapsis_speed(R::from_int(4), fifth), R::ZERO, R::ZERO),
            ),
            body(
                ivec(0, 5, 0),
                Vec3::new(circular_speed(5), R::ZERO, R::ZERO),
            ),
        ],
        templates: vec![ParticleTemplate::default()],
        emitters: Vec::new(),
        forces: vec![ForceDesc::PointGravity {
            centre: Vec3::ZERO,
            gm,
            softening: ratio(1, 20),
            group: None,
        }],
        collisions: Vec::new(),
        contacts: None,
    }
}

/// A bit of everything: a box emitter of short-lived sparks under gravity and linear drag
/// (group 0), a bob hanging from a damped anchored spring with a second bob on a spring below
/// it (group 1, under gravity), and a ring of eight particles spiralling into a softened
/// point mass under damping (group 2, no gravity). Template 0 spawns a 1 kg, 5 s particle in
/// group 1.
pub fn showcase_particles<R: Real>() -> ParticlesDesc<R> {
    let cluster_centre = ivec::<R>(-3, 3, 0);
    let mut particles = vec![
        ParticleDesc {
            position: Vec3::new(R::from_int(3), ratio(3, 2), R::ZERO),
            velocity: ivec(0, 0, 2),
            mass: R::ONE,
            group: 1,
            lifetime: R::ZERO,
        },
        ParticleDesc {
            position: ivec(3, 0, 0),
            velocity: Vec3::ZERO,
            mass: R::HALF,
            group: 1,
            lifetime: R::ZERO,
        },
    ];
    for k in 0..8 {
        let (sin, cos) = (R::TAU * ratio(k, 8)).sin_cos();
        let radial = Vec3::new(cos, sin, R::ZERO);
        let tangential = Vec3::new(-sin, cos, R::ZERO);
        particles.push(ParticleDesc {
            position: cluster_centre + radial,
            velocity: tangential * R::TWO + Vec3::new(R::ZERO, R::ZERO, ratio(k - 4, 4)),
            mass: ratio(1, 2),
            group: 2,
            lifetime: R::ZERO,
        });
    }
    ParticlesDesc {
        integrator: Integrator::SemiImplicitEuler,
        capacity: 512,
        particles,
        templates: vec![ParticleTemplate {
            mass: R::ONE,
            group: 1,
            lifetime: R::from_int(5),
        }],
        emitters: vec![EmitterDesc {
            position: Vec3::ZERO,
            rate: R::from_int(20),
            spread: Spread::Box {
                half_extents: Vec3::new(R::HALF, R::ZERO, R::HALF),
                direction: ivec(0, 1, 0),
            },
            speed: Interval::new(R::from_int(4), R::from_int(6)),
            lifetime: Interval::new(ratio(3, 2), ratio(5, 2)),
            mass: ratio(1, 5),
            group: 0,
            on: true,
        }],
        forces: vec![
            ForceDesc::Gravity {
                scale: R::ONE,
                group: Some(0),
            },
            ForceDesc::Gravity {
                scale: R::ONE,
                group: Some(1),
            },
            ForceDesc::LinearDrag {
                coefficient: ratio(1, 20),
                group: Some(0),
            },
            ForceDesc::AnchoredSpring {
                particle: 0,
                anchor: ivec(3, 4, 0),
                spring: SpringDesc {
                    stiffness: R::from_int(30),
                    damping: R::HALF,
                    rest_length: ratio(3, 2),
                },
            },
            ForceDesc::Spring {
                first: 0,
                second: 1,
                spring: SpringDesc {
                    stiffness: R::from_int(20),
                    damping: ratio(1, 5),
                    rest_length: R::ONE,
                },
            },
            ForceDesc::PointGravity {
                centre: cluster_centre,
                gm: R::from_int(4),
                softening: ratio(1, 5),
                group: Some(2),
            },
            ForceDesc::Damping {
                kept_per_second: ratio(7, 10),
                group: Some(2),
            },
        ],
        collisions: Vec::new(),
        contacts: None,
    }
}
