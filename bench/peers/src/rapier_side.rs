//! Rapier's side: the same scenes as fixstep's built-in ones (`crates/fixstep-scenes/src/rigid.rs`),
//! bodies for bodies, with Rapier's defaults otherwise (friction 0.5, restitution 0).

use crate::scenes::{RigidRun, Scene};
use crate::time_steps;
use rapier3d::prelude::*;

/// Whether this build has Rapier's enhanced-determinism mode.
pub const ENHANCED_DETERMINISM: bool = cfg!(feature = "enhanced-determinism");

fn fixed_box(world: &mut PhysicsWorld, centre: [f32; 3], half: [f32; 3]) {
    world.insert(
        RigidBodyBuilder::fixed().translation(Vector::new(centre[0], centre[1], centre[2])),
        ColliderBuilder::cuboid(half[0], half[1], half[2]),
    );
}

fn dynamic(world: &mut PhysicsWorld, at: [f32; 3], shape: ColliderBuilder, sleeping: bool) {
    world.insert(
        RigidBodyBuilder::dynamic()
            .translation(Vector::new(at[0], at[1], at[2]))
            .can_sleep(sleeping),
        shape,
    );
}

/// `pyramid`: base 20, unit cubes 1 m apart in x resting exactly on each other, on the
/// ground (fixstep's ground is a plane; here a 200 m box whose top is y = 0).
fn pyramid(world: &mut PhysicsWorld, sleeping: bool) {
    fixed_box(world, [0.0, -0.5, 0.0], [100.0, 0.5, 100.0]);
    for row in 0..20 {
        let count = 20 - row;
        for i in 0..count {
            let x = -(count as f32 - 1.0) / 2.0 + i as f32;
            dynamic(
                world,
                [x, 0.5 + row as f32, 0.0],
                ColliderBuilder::cuboid(0.5, 0.5, 0.5),
                sleeping,
            );
        }
    }
}

/// `balls`: 16³ spheres of radius ½ m, 1.1 m apart, from y = 1 m, into a 20 × 20 m box of
/// five static boxes.
fn balls(world: &mut PhysicsWorld, sleeping: bool) {
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
                dynamic(world, at, ColliderBuilder::ball(0.5), sleeping);
            }
        }
    }
}

/// `falling`: 1000 spheres of radius ½ m, 2 m apart in a row, falling freely.
fn falling(world: &mut PhysicsWorld, sleeping: bool) {
    for i in 0..1000 {
        dynamic(
            world,
            [2.0 * i as f32, 0.0, 0.0],
            ColliderBuilder::ball(0.5),
            sleeping,
        );
    }
}

/// The positions of the dynamic bodies, in the order they were created.
fn positions(world: &PhysicsWorld) -> Vec<[f64; 3]> {
    world
        .bodies
        .iter()
        .filter(|(_, body)| body.is_dynamic())
        .map(|(_, body)| {
            let t = body.translation();
            [f64::from(t.x), f64::from(t.y), f64::from(t.z)]
        })
        .collect()
}

/// Runs `scene` in Rapier with the friction model `friction`: mean ms per step and the
/// bodies' positions before and after.
pub fn run(scene: Scene, friction: FrictionModel) -> RigidRun {
    let mut world = PhysicsWorld {
        gravity: Vector::new(0.0, -9.81, 0.0),
        ..PhysicsWorld::default()
    };
    world.integration_parameters.dt = 1.0 / 60.0;
    world.integration_parameters.num_solver_iterations = 4;
    world.integration_parameters.friction_model = friction;
    match scene.name {
        "pyramid" => pyramid(&mut world, scene.sleeping),
        "balls" => balls(&mut world, scene.sleeping),
        "falling" => falling(&mut world, scene.sleeping),
        other => unreachable!("no Rapier version of {other}"),
    }
    let start = positions(&world);
    let ms = time_steps(scene.steps, || world.step());
    RigidRun {
        ms,
        start,
        end: positions(&world),
    }
}

/// Rapier's default friction model: one friction constraint per manifold at its centre
/// (two tangent rows) and a twist row.
pub fn run_simplified(scene: Scene) -> RigidRun {
    run(scene, FrictionModel::Simplified)
}

/// Coulomb friction at each contact point, two tangent rows per point, as fixstep solves
/// friction.
pub fn run_coulomb(scene: Scene) -> RigidRun {
    run(scene, FrictionModel::Coulomb)
}
