//! Rapier's side: the same scenes as fixstep's built-in ones (`crates/fixstep-scenes/src/rigid.rs`),
//! bodies for bodies, with Rapier's defaults otherwise (friction 0.5, restitution 0).

use crate::queries::{
    Answers, BodyShape, MAX_DISTANCE, PlacedBody, Queries, QuerySet, RayAnswer, SETTLE_STEPS, UNIT,
    metres,
};
use crate::scenes::{RigidRun, Scene};
use crate::time_steps;
use rapier3d::prelude::*;
use std::time::Instant;

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
/// `hills` and `hills_mesh`: fixstep's landing (`fixstep_scenes::terrain::landing`) from
/// the same exact numbers: a 64 m square terrain of 256 × 256 samples, as a heightfield
/// (parry's rows run along z and its columns along x, centred, `scale` the whole extent:
/// fixstep's layout, its height matrix being column-major) or as the triangle mesh of
/// fixstep's triangles (two per cell, split along the same diagonal); 1000 hulls of the
/// rock's 12 points and 1000 balls of radius 0.2 m in the same lattices. Sleeping off.
fn hills(world: &mut PhysicsWorld, as_mesh: bool) {
    use fixstep_scenes::terrain::{LANDING_SAMPLES, landing_height, rock_centimetres};
    let n = LANDING_SAMPLES as usize;
    let height = |r: usize, c: usize| {
        let (num, den) = landing_height(r as u32, c as u32);
        num as f32 / den as f32
    };
    let ground = if as_mesh {
        let at = |k: usize| -32.0 + 64.0 * k as f32 / (n - 1) as f32;
        let mut vertices = Vec::with_capacity(n * n);
        for r in 0..n {
            for c in 0..n {
                vertices.push(Vector::new(at(c), height(r, c), at(r)));
            }
        }
        let mut triangles = Vec::with_capacity(2 * (n - 1) * (n - 1));
        for r in 0..n - 1 {
            for c in 0..n - 1 {
                let v = (r * n + c) as u32;
                let (v01, v10, v11) = (v + 1, v + n as u32, v + n as u32 + 1);
                triangles.push([v, v10, v11]);
                triangles.push([v, v11, v01]);
            }
        }
        ColliderBuilder::trimesh(vertices, triangles).expect("a valid mesh")
    } else {
        let mut column_major = vec![0.0; n * n];
        for r in 0..n {
            for c in 0..n {
                column_major[r + c * n] = height(r, c);
            }
        }
        ColliderBuilder::heightfield(
            Array2::new(n, n, column_major),
            Vector::new(64.0, 1.0, 64.0),
        )
    };
    world.insert(RigidBodyBuilder::fixed(), ground);
    let points: Vec<Vector> = rock_centimetres()
        .iter()
        .map(|&(x, y, z)| Vector::new(x as f32 / 100.0, y as f32 / 100.0, z as f32 / 100.0))
        .collect();
    for i in 0..10 {
        for j in 0..10 {
            for k in 0..10 {
                let (x, y, z) = (i as f32 * 1.2, j as f32 * 1.2, k as f32 * 1.2);
                let rock = ColliderBuilder::convex_hull(&points).expect("a hull");
                dynamic(world, [-6.0 + x, 3.0 + y, -6.0 + z], rock, false);
                let ball = ColliderBuilder::ball(0.2);
                dynamic(world, [-5.4 + x, 3.5 + y, -5.4 + z], ball, false);
            }
        }
    }
}

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
        "hills" => hills(&mut world, false),
        "hills_mesh" => hills(&mut world, true),
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

/// Rapier's world of `scene` after [`SETTLE_STEPS`] steps (its default friction, sleeping
/// off), or a copy of fixstep's bodies, with the query set in Rapier's types.
pub struct RapierQueries {
    world: PhysicsWorld,
    rays: Vec<Ray>,
    spheres: Vec<(Pose, Ball)>,
}

fn world() -> PhysicsWorld {
    let mut world = PhysicsWorld {
        gravity: Vector::new(0.0, -9.81, 0.0),
        ..PhysicsWorld::default()
    };
    world.integration_parameters.dt = 1.0 / 60.0;
    world.integration_parameters.num_solver_iterations = 4;
    world
}

fn point(v: [i32; 3]) -> Vector {
    let [x, y, z] = metres(v);
    Vector::new(x as f32, y as f32, z as f32)
}

fn with_queries(world: PhysicsWorld, set: &QuerySet) -> RapierQueries {
    RapierQueries {
        world,
        rays: set
            .rays
            .iter()
            .map(|r| {
                let origin = point(r.origin);
                Ray::new(origin, (point(r.target) - origin).normalize())
            })
            .collect(),
        spheres: set
            .spheres
            .iter()
            .map(|s| {
                let c = point(s.centre);
                let radius = s.radius as f32 / UNIT as f32;
                (Pose::translation(c.x, c.y, c.z), Ball::new(radius))
            })
            .collect(),
    }
}

/// `scene` settled, ready for the queries of `set`.
pub fn queries(scene: &str, set: &QuerySet) -> RapierQueries {
    let mut world = world();
    match scene {
        "pyramid" => pyramid(&mut world, false),
        "balls" => balls(&mut world, false),
        other => unreachable!("no Rapier version of {other}"),
    }
    for _ in 0..SETTLE_STEPS {
        world.step();
    }
    with_queries(world, set)
}

/// fixstep's `bodies` as Rapier bodies and colliders, in the same order (the ground plane as
/// a 200 m box under its height), the tree built by one collision detection.
pub fn queries_on(bodies: &[PlacedBody], set: &QuerySet) -> RapierQueries {
    let mut world = world();
    for body in bodies {
        let [x, y, z] = body.position.map(|c| c as f32);
        let [w, i, j, k] = body.orientation.map(|c| c as f32);
        let (centre, collider) = match body.shape {
            BodyShape::Ball(r) => (Vector::new(x, y, z), ColliderBuilder::ball(r as f32)),
            BodyShape::Cuboid(h) => (
                Vector::new(x, y, z),
                ColliderBuilder::cuboid(h[0] as f32, h[1] as f32, h[2] as f32),
            ),
            BodyShape::Ground(top) => (
                Vector::new(0.0, top as f32 - 0.5, 0.0),
                ColliderBuilder::cuboid(100.0, 0.5, 100.0),
            ),
        };
        let builder = if body.dynamic {
            RigidBodyBuilder::dynamic()
        } else {
            RigidBodyBuilder::fixed()
        };
        let rotation = Rotation::from_xyzw(i, j, k, w).normalize();
        world.insert(
            builder
                .pose(Pose::from_parts(centre, rotation))
                .can_sleep(false),
            collider,
        );
    }
    world.detect_collisions(&(), &());
    with_queries(world, set)
}

impl Queries for RapierQueries {
    fn rays(&self) -> Answers<RayAnswer> {
        let pipeline = self.world.query_pipeline();
        let max = MAX_DISTANCE as f32;
        let mut hits = Vec::with_capacity(self.rays.len());
        let start = Instant::now();
        for ray in &self.rays {
            hits.push(pipeline.cast_ray_and_get_normal(ray, max, true));
        }
        let seconds = start.elapsed().as_secs_f64();
        Answers {
            seconds,
            answers: hits
                .into_iter()
                .map(|hit| hit.map(|(h, i)| (h.into_raw_parts().0, f64::from(i.time_of_impact))))
                .collect(),
        }
    }

    fn overlaps(&self) -> Answers<Vec<u32>> {
        let pipeline = self.world.query_pipeline();
        let mut found = Vec::with_capacity(self.spheres.len());
        let start = Instant::now();
        for (pose, ball) in &self.spheres {
            found.push(
                pipeline
                    .intersect_shape(*pose, ball)
                    .map(|(h, _)| h)
                    .collect::<Vec<_>>(),
            );
        }
        let seconds = start.elapsed().as_secs_f64();
        Answers {
            seconds,
            answers: found
                .into_iter()
                .map(|handles| {
                    let mut slots: Vec<u32> =
                        handles.iter().map(|h| h.into_raw_parts().0).collect();
                    slots.sort_unstable();
                    slots
                })
                .collect(),
        }
    }
}
