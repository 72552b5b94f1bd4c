//! Friction per contact manifold: the tangent rows at the centre of the points obey
//! Coulomb's limit μ Σλ_n, and the twist row about the normal stops a spinning box at the
//! rate its points' friction predicts. Tolerances come from the physics.

use fixstep::math::{Fx, Real, Vec3};
use fixstep::rigid::{BodyDesc, Material, RigidDesc, Shape, SolverSettings};
use fixstep::scene::Scene;
use fixstep::world::{Handle, TickInput, World};

/// Gravity along −y, m/s².
const G: f64 = 10.0;
/// The friction coefficient of both materials (their mix is the same μ).
const MU: f64 = 0.5;
/// Ticks per second (the scene default).
const TICK_RATE: f64 = 60.0;

/// A unit cube (1 m side, 1000 kg) resting on the ground plane, with gravity
/// (`sideways`, −G, 0) and the cube spinning about the vertical at `spin` rad/s.
fn cube_on_ground(sideways: f64, spin: f64) -> (World<Fx>, Handle) {
    let material = Material {
        friction: Fx::from_f64(MU),
        restitution: Fx::ZERO,
    };
    let mut ground = fixstep_scenes::rigid::ground::<Fx>();
    ground.material = material;
    let mut cube = BodyDesc::new(
        Shape::Box {
            half_extents: Vec3::splat(Fx::HALF),
        },
        Vec3::new(Fx::ZERO, Fx::HALF, Fx::ZERO),
    );
    cube.material = material;
    cube.angular_velocity = Vec3::new(Fx::ZERO, Fx::from_f64(spin), Fx::ZERO);
    let mut scene = Scene::empty("friction");
    scene.gravity = Vec3::new(Fx::from_f64(sideways), -Fx::from_f64(G), Fx::ZERO);
    scene.rigid = Some(RigidDesc {
        bodies: vec![ground, cube],
        solver: SolverSettings {
            sleeping: false,
            ..SolverSettings::default()
        },
        ..RigidDesc::default()
    });
    let world = scene.build().expect("the scene builds");
    let r = world.rigid().expect("rigid bodies");
    let cube = r
        .handles()
        .find(|&h| r.mass(h).expect("live") > Fx::ZERO)
        .expect("the cube");
    (world, cube)
}

fn run(world: &mut World<Fx>, ticks: u64) {
    for _ in 0..ticks {
        world.step(&TickInput::default());
    }
}

fn velocity_x(world: &World<Fx>, cube: Handle) -> f64 {
    world
        .rigid()
        .unwrap()
        .linear_velocity(cube)
        .unwrap()
        .x
        .to_f64()
}

fn spin(world: &World<Fx>, cube: Handle) -> f64 {
    world
        .rigid()
        .unwrap()
        .angular_velocity(cube)
        .unwrap()
        .y
        .to_f64()
}

/// A sideways pull of 0.9 μ m g does not move the cube (static friction holds it: less than
/// 1 mm/s after 2 s); a pull of 1.1 μ m g makes it slide with a = g_x − μ g, the friction
/// force within 1 % of μ m g.
#[test]
fn a_pull_below_mu_m_g_sticks_and_above_slides() {
    let (mut world, cube) = cube_on_ground(0.9 * MU * G, 0.0);
    run(&mut world, 120);
    let speed = velocity_x(&world, cube).abs();
    assert!(
        speed < 1e-3,
        "a pull of 0.9 μ m g moved the cube at {speed} m/s"
    );

    let pull = 1.1 * MU * G;
    let (mut world, cube) = cube_on_ground(pull, 0.0);
    run(&mut world, 30);
    let v0 = velocity_x(&world, cube);
    run(&mut world, 60);
    let v1 = velocity_x(&world, cube);
    let measured = (v1 - v0) * TICK_RATE / 60.0;
    let expected = pull - MU * G;
    eprintln!("sliding at {measured:.4} m/s², expected {expected:.4}");
    assert!(
        (measured - expected).abs() <= 0.01 * MU * G,
        "the cube slides at {measured} m/s², expected {expected}"
    );
}

/// A cube spinning about the vertical on the ground: its contact is the four corners of
/// the bottom face, each √2/2 m from the centre, so the largest friction torque is
/// μ m g √2/2 and the spin falls at α = μ m g (√2/2) / I, I = m/6 (kg·m²), until it stops.
/// The rate must match within 2 % (the normal impulses settle in the first ticks), and
/// the cube must be still after 1 s. The tangent rows alone, at the centre of the face,
/// apply no torque about the normal: without the twist row the cube would spin on.
#[test]
fn the_twist_row_stops_a_spinning_cube_at_the_rate_of_its_friction() {
    let spin0 = 4.0;
    let (mut world, cube) = cube_on_ground(0.0, spin0);
    run(&mut world, 2);
    let w0 = spin(&world, cube);
    run(&mut world, 6);
    let w1 = spin(&world, cube);
    let measured = (w0 - w1) * TICK_RATE / 6.0;
    let expected = MU * G * core::f64::consts::FRAC_1_SQRT_2 * 6.0;
    eprintln!("spin falls at {measured:.3} rad/s², expected {expected:.3}");
    assert!(
        (measured - expected).abs() <= 0.02 * expected,
        "the spin falls at {measured} rad/s², expected {expected}"
    );
    run(&mut world, 52);
    let left = spin(&world, cube).abs();
    assert!(
        left < 1e-3,
        "the cube still spins at {left} rad/s after 1 s"
    );
}
