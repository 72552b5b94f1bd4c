//! Restitution through touching bodies (issue [energy]): a Newton's cradle whose balls touch
//! must pass the striker's impulse along the row, as the notes' iterative resolver does
//! (each contact resolved in turn, the largest closing speed first). The gates are the
//! issue's: with e = 1 and no friction, the balls that leave do so at ≥ 0.98 v, the others
//! move at ≤ 0.02 v, and the kinetic energy stays within 2 % (elastic collisions keep it).

use fixstep::math::{Fx, Real, Vec3};
use fixstep::rigid::{BodyDesc, Material, RigidDesc, Shape};
use fixstep::scene::Scene;
use fixstep::world::{Handle, TickInput, World};
use fixstep_scenes::builtin_scene;
use fixstep_scenes::rigid::{cradle_row, ground};

/// The strikers' speed in every scene here, m/s.
const V: f64 = 2.0;

fn run(world: &mut World<Fx>, ticks: u64) {
    let empty = TickInput::default();
    for _ in 0..ticks {
        world.step(&empty);
    }
}

/// The dynamic bodies, in creation order (strikers first, then the row from the left).
fn balls(world: &World<Fx>) -> Vec<Handle> {
    let r = world.rigid().expect("rigid bodies");
    r.handles()
        .filter(|&h| r.mass(h).expect("live") > Fx::ZERO)
        .collect()
}

fn velocity(world: &World<Fx>, h: Handle) -> [f64; 3] {
    world
        .rigid()
        .expect("rigid bodies")
        .linear_velocity(h)
        .expect("live")
        .to_f64()
}

fn speed(v: [f64; 3]) -> f64 {
    (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt()
}

/// Σ ½ m |v|² + ½ ω·Iω over the dynamic bodies, J (the spheres' inertia is isotropic).
fn kinetic_energy(world: &World<Fx>) -> f64 {
    let r = world.rigid().expect("rigid bodies");
    balls(world)
        .into_iter()
        .map(|h| {
            let m = r.mass(h).expect("live").to_f64();
            let v = speed(r.linear_velocity(h).expect("live").to_f64());
            let w = speed(r.angular_velocity(h).expect("live").to_f64());
            // A solid sphere of radius ½ m: I = 2/5 m r².
            0.5 * m * v * v + 0.5 * (0.4 * m * 0.25) * w * w
        })
        .sum()
}

/// Σ m v_x over the dynamic bodies, kg·m/s.
fn momentum_x(world: &World<Fx>) -> f64 {
    let r = world.rigid().expect("rigid bodies");
    balls(world)
        .into_iter()
        .map(|h| r.mass(h).expect("live").to_f64() * velocity(world, h)[0])
        .sum()
}

/// Runs a cradle of `strikers` then `row` balls (creation order) until the impulse has
/// passed (2 s; the strikers reach the row at 0.5 s), then checks the gates: the
/// last `strikers` balls leave along +x at ≥ 0.98 v, every other ball moves at ≤ 0.02 v,
/// and the kinetic energy is within 2 % of the start's.
fn check_cradle(name: &str, mut world: World<Fx>, strikers: usize) {
    let all = balls(&world);
    let energy = kinetic_energy(&world);
    run(&mut world, 120);
    let speeds: Vec<[f64; 3]> = all.iter().map(|&h| velocity(&world, h)).collect();
    let after = kinetic_energy(&world);
    eprintln!(
        "{name}: x speeds {:?} m/s, kinetic energy {energy:.4} → {after:.4} J",
        speeds.iter().map(|v| v[0]).collect::<Vec<_>>()
    );
    let leaving = all.len() - strikers;
    for (k, v) in speeds.iter().enumerate() {
        if k >= leaving {
            assert!(
                v[0] >= 0.98 * V && speed(*v) <= 1.02 * V,
                "{name}: ball {k} leaves at {v:?} m/s, not ≥ 0.98 v along x"
            );
        } else {
            assert!(
                speed(*v) <= 0.02 * V,
                "{name}: ball {k} still moves at {v:?} m/s (≤ 0.02 v wanted)"
            );
        }
    }
    assert!(
        (after - energy).abs() <= 0.02 * energy,
        "{name}: kinetic energy {energy} J became {after} J"
    );
}

fn zero_gravity(rigid: RigidDesc<Fx>) -> World<Fx> {
    let mut scene = Scene::empty("cradle");
    scene.gravity = Vec3::ZERO;
    scene.rigid = Some(rigid);
    scene.build().expect("the scene builds")
}

/// The same cradle standing on a frictionless ground under gravity: the balls' resting
/// contacts with the ground must neither bounce nor take the row's impulse.
fn on_the_ground(mut rigid: RigidDesc<Fx>) -> World<Fx> {
    let lift = Vec3::new(Fx::ZERO, Fx::HALF, Fx::ZERO);
    for body in &mut rigid.bodies {
        body.position += lift;
    }
    let mut floor = ground();
    floor.material = Material {
        friction: Fx::ZERO,
        restitution: Fx::ZERO,
    };
    rigid.bodies.insert(0, floor);
    let mut scene = Scene::empty("cradle on the ground");
    scene.rigid = Some(rigid);
    scene.build().expect("the scene builds")
}

/// The built-in `cradle_touching`: one ball strikes five touching balls, the last leaves.
#[test]
fn one_ball_into_five_touching_sends_the_last_away() {
    let scene = builtin_scene::<Fx>("cradle_touching").expect("cradle_touching");
    let world = scene.build().expect("the scene builds");
    assert_eq!(balls(&world).len(), 6);
    check_cradle("cradle_touching", world, 1);
}

/// Two touching balls strike three touching balls: two leave.
#[test]
fn two_balls_into_three_touching_send_two_away() {
    check_cradle("2 into 3", zero_gravity(cradle_row(2, 3, Fx::ZERO)), 2);
}

/// The touching cradle resting on a frictionless ground under gravity.
#[test]
fn a_touching_cradle_on_the_ground_sends_the_last_away() {
    check_cradle(
        "1 into 5, on the ground",
        on_the_ground(cradle_row(1, 5, Fx::ZERO)),
        1,
    );
    check_cradle(
        "2 into 3, on the ground",
        on_the_ground(cradle_row(2, 3, Fx::ZERO)),
        2,
    );
}

/// The cradle with gaps (each collision a two-body one) still works as it did.
#[test]
fn the_cradle_with_gaps_still_sends_the_last_away() {
    let scene = builtin_scene::<Fx>("cradle").expect("cradle");
    check_cradle("cradle", scene.build().expect("the scene builds"), 1);
}

/// A pool break in zero gravity: a cue ball at 4 m/s strikes the apex of a rack of 15
/// touching frictionless elastic balls (rows 1 to 5, centres 1 m apart). Elastic collisions
/// keep the kinetic energy (within 2 %, and never more than 0.1 % above the start) and the
/// momentum (within 0.1 %), and the impulse reaches the back row.
#[test]
fn a_pool_break_keeps_energy_and_momentum() {
    let elastic = Material {
        friction: Fx::ZERO,
        restitution: Fx::ONE,
    };
    let ball = |x: f64, z: f64| {
        let mut b = BodyDesc::new(
            Shape::Sphere { radius: Fx::HALF },
            Vec3::new(Fx::from_f64(x), Fx::ZERO, Fx::from_f64(z)),
        );
        b.material = elastic;
        b
    };
    let mut cue = ball(-3.0, 0.0);
    cue.velocity = Vec3::new(Fx::from_int(4), Fx::ZERO, Fx::ZERO);
    let mut bodies = vec![cue];
    let row_step = 3f64.sqrt() / 2.0;
    for row in 0..5 {
        for k in 0..=row {
            bodies.push(ball(row as f64 * row_step, k as f64 - row as f64 / 2.0));
        }
    }
    let mut world = zero_gravity(RigidDesc {
        bodies,
        ..RigidDesc::default()
    });
    let all = balls(&world);
    let (energy, momentum) = (kinetic_energy(&world), momentum_x(&world));
    let mut highest = energy;
    for _ in 0..90 {
        run(&mut world, 1);
        highest = highest.max(kinetic_energy(&world));
    }
    let (after, momentum_after) = (kinetic_energy(&world), momentum_x(&world));
    let back_row: f64 = all[11..].iter().map(|&h| speed(velocity(&world, h))).sum();
    eprintln!(
        "pool break: kinetic energy {energy:.4} → {after:.4} J (highest {highest:.4}), \
         momentum {momentum:.4} → {momentum_after:.4}, back row speeds sum {back_row:.3} m/s"
    );
    assert!(
        (after - energy).abs() <= 0.02 * energy,
        "kinetic energy {energy} J became {after} J"
    );
    assert!(
        highest <= 1.001 * energy,
        "kinetic energy rose to {highest} J from {energy} J"
    );
    assert!(
        (momentum_after - momentum).abs() <= 1e-3 * momentum,
        "momentum {momentum} became {momentum_after}"
    );
    assert!(
        back_row > 0.1 * V,
        "the back row barely moved: {back_row} m/s"
    );
}
