//! Rapier's side: the same scenes as fixstep's built-in ones (`src/rigid/presets.rs`),
//! bodies for bodies, with Rapier's defaults otherwise (friction 0.5, restitution 0).

use crate::{Scene, time_steps};
use rapier3d::prelude::*;

/// Whether this build has Rapier's enhanced-determinism mode.
pub const ENHANCED_DETERMINISM: bool = cfg!(feature = "enhanced-determinism");

fn fixed_box(world: &mut PhysicsWorld, centre: [f32; 3], half: [f32; 3]) {
    world.insert(
        RigidBodyBuilder::fixed().translation(Vector::new(centre[0], centre[1], centre[2])),
        ColliderBuilder::cuboid(half[0], half[1], half[2]),
    );
}

fn dynamic(world: &mut PhysicsWorld, at: [f32; 3], shape: ColliderBuilder) {
    world.insert(
        RigidBodyBuilder::dynamic()
            .translation(Vector::new(at[0], at[1], at[2]))
            .can_sleep(false),
        shape,
    );
}

/// `pyramid`: base 20, unit cubes 1 m apart in x resting exactly on each other, on the
/// ground (fixstep's ground is a plane; here a 200 m box whose top is y = 0).
fn pyramid(world: &mut PhysicsWorld) {
    fixed_box(world, [0.0, -0.5, 0.0], [100.0, 0.5, 100.0]);
    for row in 0..20 {
        let count = 20 - row;
        for i in 0..count {
            let x = -(count as f32 - 1.0) / 2.0 + i as f32;
            dynamic(
                world,
                [x, 0.5 + row as f32, 0.0],
                ColliderBuilder::cuboid(0.5, 0.5, 0.5),
            );
        }
    }
}

/// `balls`: 16³ spheres of radius ½ m, 1.1 m apart, from y = 1 m, into a 20 × 20 m box of
/// five static boxes.
fn balls(world: &mut PhysicsWorld) {
    fixed_box(world, [0.0, -0.5, 0.0], [11.0, 0.5, 11.0]);
    fixed_box(world, [-10.5, 10.0, 0.0], [0.5, 10.0, 11.0]);
    fixed_box(world, [10.5, 10.0, 0.0], [0.5, 10.0, 11.0]);
    fixed_box(world, [0.0, 10.0, -10.5], [10.0, 10.0, 0.5]);
    fixed_box(world, [0.0, 10.0, 10.5], [10.0, 10.0, 0.5]);
    let (n, spacing) = (16, 1.1f32);
    let start = -(spacing * (n as f32 - 1.0)) * 0.5;
    for i in 0..n {
        for j in 0..n {
            for k in 0..n {
                let at = [
                    start + i as f32 * spacing,
                    1.0 + j as f32 * spacing,
                    start + k as f32 * spacing,
                ];
                dynamic(world, at, ColliderBuilder::ball(0.5));
            }
        }
    }
}

/// `falling`: 1000 spheres of radius ½ m, 2 m apart in a row, falling freely.
fn falling(world: &mut PhysicsWorld) {
    for i in 0..1000 {
        dynamic(
            world,
            [2.0 * i as f32, 0.0, 0.0],
            ColliderBuilder::ball(0.5),
        );
    }
}

/// Mean ms per step of `scene` in Rapier.
pub fn run(scene: Scene) -> f64 {
    let mut world = PhysicsWorld {
        gravity: Vector::new(0.0, -9.81, 0.0),
        ..PhysicsWorld::default()
    };
    world.integration_parameters.dt = 1.0 / 60.0;
    world.integration_parameters.num_solver_iterations = 4;
    match scene.name {
        "pyramid" => pyramid(&mut world),
        "balls" => balls(&mut world),
        "falling" => falling(&mut world),
        other => unreachable!("no Rapier version of {other}"),
    }
    time_steps(scene.steps, || world.step())
}
