//! Dynamics of cylinders, cones and hulls through their contact manifolds: a solid cylinder
//! rolls down a slope without slipping at a = (2/3) g sin θ, a hull cube slides at
//! g (sin θ − μ cos θ), and resting shapes fall asleep. The slope is the ground plane with
//! gravity turned by θ, which is the same physics. Tolerances come from the physics.

use fixstep::math::{Fx, Quat, Real, Vec3};
use fixstep::rigid::convex::ConvexHull;
use fixstep::rigid::{BodyDesc, Material, Part, RigidDesc, Shape, SolverSettings};
use fixstep::scene::Scene;
use fixstep::world::{Handle, TickInput, World};

/// Gravity, m/s².
const G: f64 = 10.0;
/// Ticks per second (the scene default).
const TICK_RATE: f64 = 60.0;

/// `body` on the ground plane (both with friction `mu`), gravity g turned by `slope`
/// degrees towards +x, sleeping on or off.
fn on_slope(mut body: BodyDesc<Fx>, slope: f64, mu: f64, sleeping: bool) -> (World<Fx>, Handle) {
    let material = Material {
        friction: Fx::from_f64(mu),
        restitution: Fx::ZERO,
    };
    let mut ground = fixstep_scenes::rigid::ground::<Fx>();
    ground.material = material;
    body.material = material;
    let theta = slope.to_radians();
    let mut scene = Scene::empty("convex shapes");
    scene.gravity = Vec3::new(
        Fx::from_f64(G * theta.sin()),
        -Fx::from_f64(G * theta.cos()),
        Fx::ZERO,
    );
    scene.rigid = Some(RigidDesc {
        bodies: vec![ground, body],
        solver: SolverSettings {
            sleeping,
            ..SolverSettings::default()
        },
        ..RigidDesc::default()
    });
    let world = scene.build().expect("the scene builds");
    let r = world.rigid().expect("rigid bodies");
    let handle = r
        .handles()
        .find(|&h| r.mass(h).expect("live") > Fx::ZERO)
        .expect("the body");
    (world, handle)
}

fn x_at(world: &World<Fx>, body: Handle) -> f64 {
    world.rigid().unwrap().position(body).unwrap().x.to_f64()
}

/// The acceleration along x from three positions Δ = `gap` ticks apart, starting at tick
/// `skip`: a = (x₃ − 2 x₂ + x₁) / Δt² (exact for constant acceleration).
fn acceleration(world: &mut World<Fx>, body: Handle, skip: u64, gap: u64) -> f64 {
    let mut samples = Vec::new();
    for tick in 0..=skip + 2 * gap {
        if tick >= skip && (tick - skip).is_multiple_of(gap) {
            samples.push(x_at(world, body));
        }
        world.step(&TickInput::default());
    }
    let dt = gap as f64 / TICK_RATE;
    (samples[2] - 2.0 * samples[1] + samples[0]) / (dt * dt)
}

/// A solid cylinder (r 0.3 m, half length 0.4 m) lying across a 20° slope with μ = 0.8
/// (rolling needs μ ≥ tan θ / 3 = 0.12) rolls without slipping: a = (2/3) g sin θ within
/// 2%, measured over 1 s after the first 10 ticks.
#[test]
fn solid_cylinder_rolls_down_a_slope_at_two_thirds_g_sin_theta() {
    let mut body = BodyDesc::new(
        Shape::Cylinder {
            radius: Fx::from_f64(0.3),
            half_height: Fx::from_f64(0.4),
        },
        Vec3::new(Fx::ZERO, Fx::from_f64(0.3), Fx::ZERO),
    );
    body.orientation = Quat::from_axis_angle(Vec3::X, Fx::FRAC_PI_2);
    let (mut world, cylinder) = on_slope(body, 20.0, 0.8, false);
    let a = acceleration(&mut world, cylinder, 10, 30);
    let expected = 2.0 / 3.0 * G * 20f64.to_radians().sin();
    println!("rolling cylinder: a = {a} m/s², expected {expected}");
    assert!(
        (a - expected).abs() <= 0.02 * expected,
        "a = {a}, expected {expected}"
    );
    // Rolling without slipping: ω r = v.
    let r = world.rigid().unwrap();
    let v = r.linear_velocity(cylinder).unwrap().x.to_f64();
    let w = r.angular_velocity(cylinder).unwrap().z.to_f64();
    assert!((v + w * 0.3).abs() <= 0.02 * v.abs(), "v {v}, ω {w}");
}

/// A cylinder lying on the floor and one standing on its cap come to rest and sleep.
#[test]
fn cylinders_resting_on_the_floor_sleep() {
    for lying in [true, false] {
        let mut body = BodyDesc::new(
            Shape::Cylinder {
                radius: Fx::from_f64(0.3),
                half_height: Fx::from_f64(0.4),
            },
            Vec3::new(
                Fx::ZERO,
                Fx::from_f64(if lying { 0.31 } else { 0.41 }),
                Fx::ZERO,
            ),
        );
        if lying {
            body.orientation = Quat::from_axis_angle(Vec3::X, Fx::FRAC_PI_2);
        }
        let (mut world, cylinder) = on_slope(body, 0.0, 0.5, true);
        for _ in 0..600 {
            world.step(&TickInput::default());
        }
        let r = world.rigid().unwrap();
        assert_eq!(r.is_sleeping(cylinder), Some(true), "lying {lying}");
        let y = r.position(cylinder).unwrap().y.to_f64();
        let rest = if lying { 0.3 } else { 0.4 };
        assert!((y - rest).abs() <= 0.01, "lying {lying}: y {y}");
    }
}

/// A hull cube (1 m) with μ = 0.3 on a 30° slope slides at g (sin θ − μ cos θ) within 1%.
#[test]
fn hull_cube_slides_down_a_slope_at_the_coulomb_rate() {
    let points: Vec<Vec3<Fx>> = (0..8)
        .map(|i| {
            let s = |bit: usize| if i & bit != 0 { Fx::HALF } else { -Fx::HALF };
            Vec3::new(s(1), s(2), s(4))
        })
        .collect();
    let hull = ConvexHull::new(&points).expect("a cube");
    let body = BodyDesc::new(
        Shape::ConvexHull { hull },
        Vec3::new(Fx::ZERO, Fx::HALF, Fx::ZERO),
    );
    let (mut world, cube) = on_slope(body, 30.0, 0.3, false);
    let a = acceleration(&mut world, cube, 10, 30);
    let theta = 30f64.to_radians();
    let expected = G * (theta.sin() - 0.3 * theta.cos());
    println!("sliding hull cube: a = {a} m/s², expected {expected}");
    assert!(
        (a - expected).abs() <= 0.01 * expected,
        "a = {a}, expected {expected}"
    );
}

/// A compound of a cylinder (lying along z) and a hull cube side by side, dropped on the
/// floor: the parts collide one by one and the body comes to rest on both at the right
/// height, asleep.
#[test]
fn compound_of_a_cylinder_and_a_hull_rests_on_the_floor() {
    let points: Vec<Vec3<Fx>> = (0..8)
        .map(|i| {
            let s = |bit: usize| {
                if i & bit != 0 {
                    Fx::from_f64(0.3)
                } else {
                    -Fx::from_f64(0.3)
                }
            };
            Vec3::new(s(1), s(2), s(4))
        })
        .collect();
    let parts = vec![
        Part {
            rotation: Quat::from_axis_angle(Vec3::X, Fx::FRAC_PI_2),
            translation: Vec3::new(-Fx::from_f64(0.5), Fx::ZERO, Fx::ZERO),
            shape: Shape::Cylinder {
                radius: Fx::from_f64(0.3),
                half_height: Fx::from_f64(0.3),
            },
        },
        Part {
            rotation: Quat::IDENTITY,
            translation: Vec3::new(Fx::from_f64(0.5), Fx::ZERO, Fx::ZERO),
            shape: Shape::ConvexHull {
                hull: ConvexHull::new(&points).expect("a cube"),
            },
        },
    ];
    let body = BodyDesc::new(
        Shape::Compound { parts },
        Vec3::new(Fx::ZERO, Fx::from_f64(0.5), Fx::ZERO),
    );
    let (mut world, compound) = on_slope(body, 0.0, 0.5, true);
    for _ in 0..600 {
        world.step(&TickInput::default());
    }
    let r = world.rigid().unwrap();
    let y = r.position(compound).unwrap().y.to_f64();
    assert!((y - 0.3).abs() <= 0.01, "y {y}");
    assert_eq!(r.is_sleeping(compound), Some(true));
}
