//! `energy`: how much energy joints and touching contacts make or lose, fixstep beside
//! Rapier on the same mechanical systems (issue [energy]). No timing: each run steps a
//! fresh world at dt = 1/60 s with each engine's default solver (fixstep's 5 substeps,
//! Rapier's 4 solver iterations; Rapier's gyroscopic forces at its default, on) and
//! prints the energy drift, (E_end − E₀) and the
//! largest |E − E₀| over the run, as a percentage of the case's energy scale:
//!
//! - **pendulum 90° and 150°**: a ball of radius 0.1 m on a massless arm of 1.5 m from a
//!   fixed pivot, released from rest, 10 s. The arm is a ball joint whose anchor on the bob
//!   is the pivot (Rapier's spherical joint with that local anchor; the bob turns with the
//!   arm, a compound pendulum), and for fixstep also its `Rod` joint (a distance between
//!   the pivot and the bob's centre; the bob does not turn). Scale: m g L.
//! - **hinge wheel**: a solid cylinder (radius 0.3 m, half thickness 0.05 m, 1000 kg/m³)
//!   on a hinge through its centre about the horizontal x axis, spinning at 100 rad/s
//!   under gravity, 10 s. No torque acts about the axis: ω and the energy are constant.
//!   Scale: the kinetic energy at the start.
//! - **touching cradle**: one ball at 2 m/s strikes five touching balls (radius 0.5 m,
//!   restitution 1, friction 0, zero gravity; fixstep's `cradle_touching`), 2 s. The last
//!   ball should leave at 2 m/s and the rest stop. Scale: the kinetic energy at the start.
//!
//! E = Σ ½ m v² + ½ ω·Iω + m g y over the dynamic bodies, computed here from each
//! engine's positions, velocities and orientations with the bodies' exact moments.

use fixstep::math::{Fx, Quat, Real, Vec3};
use fixstep::rigid::{BodyDesc, JointDesc, JointKind, JointsDesc, RigidDesc, Shape};
use fixstep::world::{Handle, TickInput, World};
use fixstep_scenes::builtin_scene;
use rapier3d::prelude::*;

const G: f64 = 9.81;
const DT: f64 = 1.0 / 60.0;
const ARM: f64 = 1.5;
const BOB_RADIUS: f64 = 0.1;
const DENSITY: f64 = 1000.0;
const WHEEL_RADIUS: f64 = 0.3;
const WHEEL_HALF: f64 = 0.05;
const WHEEL_SPIN: f64 = 100.0;
const CRADLE_SPEED: f64 = 2.0;

/// One body's state in `f64`: mass (kg), position (m), velocity (m/s), angular velocity
/// (rad/s, world), its symmetry axis in the world and its moments about that axis and
/// across it (kg·m²).
struct BodyState {
    mass: f64,
    position: [f64; 3],
    velocity: [f64; 3],
    omega: [f64; 3],
    axis: [f64; 3],
    moments: (f64, f64),
}

fn dot(a: [f64; 3], b: [f64; 3]) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

/// ½ m v² + ½ (I_axial ω_a² + I_across |ω⊥|²) + m g y, J.
fn energy(bodies: &[BodyState], gravity: bool) -> f64 {
    bodies
        .iter()
        .map(|b| {
            let along = dot(b.omega, b.axis);
            let across = (dot(b.omega, b.omega) - along * along).max(0.0);
            let g = if gravity { G } else { 0.0 };
            0.5 * b.mass * dot(b.velocity, b.velocity)
                + 0.5 * (b.moments.0 * along * along + b.moments.1 * across)
                + b.mass * g * b.position[1]
        })
        .sum()
}

/// The cases, by name.
#[derive(Clone, Copy)]
enum Case {
    Pendulum { release_deg: f64, rod: bool },
    Wheel,
    Cradle,
}

impl Case {
    fn label(self) -> String {
        match self {
            Case::Pendulum { release_deg, .. } => format!("pendulum released at {release_deg}°"),
            Case::Wheel => "hinge wheel, 100 rad/s about a horizontal axle".into(),
            Case::Cradle => "touching cradle, 1 ball into 5".into(),
        }
    }

    fn seconds(self) -> f64 {
        match self {
            Case::Cradle => 2.0,
            _ => 10.0,
        }
    }

    fn gravity(self) -> bool {
        !matches!(self, Case::Cradle)
    }
}

/// The drift over a run: (E_end − E₀)/scale and max |E − E₀|/scale, and a note.
struct Drift {
    end: f64,
    worst: f64,
    note: String,
}

/// Steps `step` for the case's time, reading the bodies with `state`.
fn measure(case: Case, mut step: impl FnMut(), state: impl Fn() -> Vec<BodyState>) -> Drift {
    let start = state();
    let e0 = energy(&start, case.gravity());
    let scale = match case {
        Case::Pendulum { .. } => start[0].mass * G * ARM,
        _ => e0,
    };
    let mut worst = 0.0f64;
    for _ in 0..(case.seconds() / DT).round() as usize {
        step();
        worst = worst.max((energy(&state(), case.gravity()) - e0).abs());
    }
    let end = state();
    let note = match case {
        Case::Cradle => {
            let speeds: Vec<String> = end
                .iter()
                .map(|b| format!("{:.2}", b.velocity[0]))
                .collect();
            format!("x speeds {} m/s", speeds.join(", "))
        }
        Case::Wheel => format!("spin {:.3} rad/s", dot(end[0].omega, end[0].axis)),
        Case::Pendulum { .. } => String::new(),
    };
    Drift {
        end: (energy(&end, case.gravity()) - e0) / scale,
        worst: worst / scale,
        note,
    }
}

// ---------------------------------------------------------------------------------------
// fixstep.

fn fx(x: f64) -> Fx {
    Fx::from_f64(x)
}

fn v3(a: [f64; 3]) -> Vec3<Fx> {
    Vec3::from_f64(a[0], a[1], a[2])
}

fn f3(v: Vec3<Fx>) -> [f64; 3] {
    [v.x.to_f64(), v.y.to_f64(), v.z.to_f64()]
}

/// Where the bob starts: `release_deg` from straight below the pivot at the origin.
fn bob_start(release_deg: f64) -> [f64; 3] {
    let a = release_deg.to_radians();
    [ARM * a.sin(), -ARM * a.cos(), 0.0]
}

/// The moments (axial, across) of the case's moving bodies about their centres.
fn moments(case: Case, mass: f64) -> (f64, f64) {
    match case {
        Case::Pendulum { .. } => (
            0.4 * mass * BOB_RADIUS * BOB_RADIUS,
            0.4 * mass * BOB_RADIUS * BOB_RADIUS,
        ),
        Case::Wheel => (
            0.5 * mass * WHEEL_RADIUS * WHEEL_RADIUS,
            mass * (WHEEL_RADIUS * WHEEL_RADIUS / 4.0 + WHEEL_HALF * WHEEL_HALF / 3.0),
        ),
        Case::Cradle => (0.1 * mass, 0.1 * mass),
    }
}

fn fixstep_world(case: Case) -> World<Fx> {
    if let Case::Cradle = case {
        return builtin_scene::<Fx>("cradle_touching")
            .expect("cradle_touching")
            .build()
            .expect("builds");
    }
    // The pivot: a static ball far from anything that moves (joint anchors are world points).
    let pivot = BodyDesc::new(Shape::Sphere { radius: fx(0.05) }, v3([0.0, 50.0, 0.0])).fixed();
    let (body, joint) = match case {
        Case::Pendulum { release_deg, rod } => {
            let at = bob_start(release_deg);
            let mut bob = BodyDesc::new(
                Shape::Sphere {
                    radius: fx(BOB_RADIUS),
                },
                v3(at),
            );
            bob.density = fx(DENSITY);
            let joint = if rod {
                JointDesc::new(JointKind::Rod { length: None }, 0, 1, Vec3::ZERO)
                    .with_anchor_b(v3(at))
            } else {
                JointDesc::new(JointKind::Ball, 0, 1, Vec3::ZERO)
            };
            (bob, joint)
        }
        _ => {
            let mut wheel = BodyDesc::new(
                Shape::Cylinder {
                    radius: fx(WHEEL_RADIUS),
                    half_height: fx(WHEEL_HALF),
                },
                Vec3::ZERO,
            );
            // Body y (the cylinder's axis) onto world x.
            wheel.orientation = Quat::from_axis_angle(Vec3::Z, fx(-std::f64::consts::FRAC_PI_2));
            wheel.density = fx(DENSITY);
            wheel.angular_velocity = v3([WHEEL_SPIN, 0.0, 0.0]);
            let hinge = JointDesc::new(
                JointKind::Hinge {
                    limits: None,
                    motor: None,
                    spring: None,
                },
                0,
                1,
                Vec3::ZERO,
            )
            .with_axis(Vec3::X);
            (wheel, hinge)
        }
    };
    let mut scene = fixstep::scene::Scene::empty("energy");
    let mut rigid = RigidDesc {
        bodies: vec![pivot, body],
        ..RigidDesc::default()
    };
    rigid.solver.sleeping = false;
    scene.rigid = Some(rigid);
    scene.joints = Some(JointsDesc::new(vec![joint]));
    scene.build().expect("builds")
}

fn fixstep_drift(case: Case) -> Drift {
    let world = std::cell::RefCell::new(fixstep_world(case));
    let moving: Vec<Handle> = {
        let w = world.borrow();
        let rigid = w.rigid().expect("rigid");
        rigid
            .handles()
            .filter(|&h| rigid.mass(h).expect("live") > Fx::ZERO)
            .collect()
    };
    let input = TickInput::default();
    let state = || {
        let w = world.borrow();
        let rigid = w.rigid().expect("rigid");
        moving
            .iter()
            .map(|&h| {
                let mass = rigid.mass(h).expect("live").to_f64();
                let q = rigid.orientation(h).expect("live");
                BodyState {
                    mass,
                    position: f3(rigid.position(h).expect("live")),
                    velocity: f3(rigid.linear_velocity(h).expect("live")),
                    omega: f3(rigid.angular_velocity(h).expect("live")),
                    axis: f3(q.rotate(Vec3::Y)),
                    moments: moments(case, mass),
                }
            })
            .collect()
    };
    measure(
        case,
        || {
            world.borrow_mut().step(&input);
        },
        state,
    )
}

// ---------------------------------------------------------------------------------------
// Rapier.

fn vector(a: [f64; 3]) -> Vector {
    Vector::new(a[0] as f32, a[1] as f32, a[2] as f32)
}

fn rapier_world(case: Case) -> (PhysicsWorld, Vec<RigidBodyHandle>) {
    let mut world = PhysicsWorld {
        gravity: if case.gravity() {
            Vector::new(0.0, -G as f32, 0.0)
        } else {
            Vector::ZERO
        },
        ..PhysicsWorld::default()
    };
    world.integration_parameters.dt = DT as f32;
    world.integration_parameters.num_solver_iterations = 4;
    let mut moving = Vec::new();
    match case {
        Case::Pendulum { release_deg, .. } => {
            let pivot = world.insert_body(RigidBodyBuilder::fixed());
            let at = bob_start(release_deg);
            let (bob, _) = world.insert(
                RigidBodyBuilder::dynamic()
                    .translation(vector(at))
                    .can_sleep(false),
                ColliderBuilder::ball(BOB_RADIUS as f32).density(DENSITY as f32),
            );
            // The bob's anchor is the pivot, in the bob's frame (not turned at the start).
            let joint = SphericalJointBuilder::new()
                .local_anchor1(Vector::ZERO)
                .local_anchor2(vector([-at[0], -at[1], -at[2]]));
            world.insert_impulse_joint(pivot, bob, joint);
            moving.push(bob);
        }
        Case::Wheel => {
            let pivot = world.insert_body(RigidBodyBuilder::fixed());
            // Rapier's cylinder is along the collider's y: the collider is turned onto the
            // body's x, the hinge axis.
            let (wheel, _) = world.insert(
                RigidBodyBuilder::dynamic()
                    .angvel(Vector::new(WHEEL_SPIN as f32, 0.0, 0.0))
                    .can_sleep(false),
                ColliderBuilder::cylinder(WHEEL_HALF as f32, WHEEL_RADIUS as f32)
                    .rotation(Vector::new(0.0, 0.0, -std::f32::consts::FRAC_PI_2))
                    .density(DENSITY as f32),
            );
            world.insert_impulse_joint(pivot, wheel, RevoluteJointBuilder::new(Vector::X));
            moving.push(wheel);
        }
        Case::Cradle => {
            for k in 0..6 {
                let (x, v) = if k == 0 {
                    (-2.0, CRADLE_SPEED)
                } else {
                    (f64::from(k - 1), 0.0)
                };
                let (ball, _) = world.insert(
                    RigidBodyBuilder::dynamic()
                        .translation(vector([x, 0.0, 0.0]))
                        .linvel(vector([v, 0.0, 0.0]))
                        .can_sleep(false),
                    ColliderBuilder::ball(0.5)
                        .density(DENSITY as f32)
                        .friction(0.0)
                        .restitution(1.0),
                );
                moving.push(ball);
            }
        }
    }
    (world, moving)
}

fn rapier_drift(case: Case) -> Drift {
    let (world, moving) = rapier_world(case);
    let world = std::cell::RefCell::new(world);
    let f = |v: Vector| [f64::from(v.x), f64::from(v.y), f64::from(v.z)];
    let state = || {
        let w = world.borrow();
        moving
            .iter()
            .map(|&h| {
                let body = &w.bodies[h];
                let mass = f64::from(body.mass());
                // The wheel's symmetry axis is the body's x; the others are isotropic.
                BodyState {
                    mass,
                    position: f(body.translation()),
                    velocity: f(body.linvel()),
                    omega: f(body.angvel()),
                    axis: f(*body.rotation() * Vector::X),
                    moments: moments(case, mass),
                }
            })
            .collect()
    };
    measure(case, || world.borrow_mut().step(), state)
}

/// Prints the table: per case, fixstep's and Rapier's drift.
pub fn table(rapier: &str) {
    println!();
    println!(
        "| case | time | engine | energy at the end − at the start | largest \\|E − E₀\\| | |"
    );
    println!("|---|---|---|---|---|---|");
    let cases = [
        Case::Pendulum {
            release_deg: 90.0,
            rod: false,
        },
        Case::Pendulum {
            release_deg: 150.0,
            rod: false,
        },
        Case::Wheel,
        Case::Cradle,
    ];
    let unit = |case: Case| match case {
        Case::Pendulum { .. } => "% of m g L",
        _ => "% of E₀",
    };
    for case in cases {
        let mut rows = vec![("fixstep I32F32".to_string(), fixstep_drift(case))];
        if let Case::Pendulum { release_deg, .. } = case {
            rows.push((
                "fixstep I32F32, `Rod` joint (the bob does not turn)".into(),
                fixstep_drift(Case::Pendulum {
                    release_deg,
                    rod: true,
                }),
            ));
        }
        rows.push((rapier.to_string(), rapier_drift(case)));
        for (engine, d) in rows {
            println!(
                "| {} | {} s | {engine} | {:+.3} {} | {:.3} {} | {} |",
                case.label(),
                case.seconds(),
                100.0 * d.end,
                unit(case),
                100.0 * d.worst,
                unit(case),
                d.note
            );
        }
    }
}
