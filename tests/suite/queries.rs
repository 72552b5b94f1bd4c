//! Scene queries on random scenes of random shapes and poses: `cast_ray` is the nearest of
//! the per-body answers (each body asked alone), `overlap` is the set of bodies that
//! overlap when asked alone, and every answer is the same with the tree (after steps) and
//! by brute force (a world made from a snapshot, whose tree is not built yet), and after a
//! snapshot is restored.

use fixstep::math::{Fx, Quat, Real, Vec3};
use fixstep::rigid::convex::ConvexHull;
use fixstep::rigid::{
    BodyDesc, BodyKind, CollisionFilter, Part, QueryFilter, RayHit, RigidDesc, Shape,
};
use fixstep::scene::Scene;
use fixstep::world::{Handle, TickInput, World};
use proptest::prelude::*;

/// One body: shape kind, three sizes (eighths of a metre), position (quarters), rotation
/// axis (integers) and angle (twentieths of a radian), kind, sensor, layers.
type BodySpec = (u8, [i32; 3], [i32; 3], [i32; 3], i32, u8, bool, u32);

fn body_spec() -> impl Strategy<Value = BodySpec> {
    (
        0u8..8,
        [1i32..9, 1i32..9, 1i32..9],
        [-32i32..32, -8i32..40, -32i32..32],
        [-3i32..4, -3i32..4, -3i32..4],
        0i32..63,
        0u8..3,
        prop::bool::weighted(0.15),
        1u32..4,
    )
}

/// A ray, shape cast or point: origin (quarters) and direction (integers).
type QuerySpec = ([i32; 3], [i32; 3], u8);

fn query_spec() -> impl Strategy<Value = QuerySpec> {
    (
        [-48i32..48, -16i32..48, -48i32..48],
        [-4i32..5, -4i32..5, -4i32..5],
        0u8..3,
    )
}

fn eighth(n: i32) -> Fx {
    Fx::from_ratio(i64::from(n), 8)
}

fn quarter(v: [i32; 3]) -> Vec3<Fx> {
    let q = |n: i32| Fx::from_ratio(i64::from(n), 4);
    Vec3::new(q(v[0]), q(v[1]), q(v[2]))
}

fn integer(v: [i32; 3]) -> Vec3<Fx> {
    Vec3::new(Fx::from_int(v[0]), Fx::from_int(v[1]), Fx::from_int(v[2]))
}

fn rotation(axis: [i32; 3], angle: i32) -> Quat<Fx> {
    match integer(axis).try_normalize() {
        Some((axis, _)) => Quat::from_axis_angle(axis, Fx::from_ratio(i64::from(angle), 20)),
        None => Quat::IDENTITY,
    }
}

fn shape_of(kind: u8, s: [i32; 3]) -> Shape<Fx> {
    match kind {
        0 => Shape::Sphere {
            radius: eighth(s[0]),
        },
        1 => Shape::Box {
            half_extents: Vec3::new(eighth(s[0]), eighth(s[1]), eighth(s[2])),
        },
        2 => Shape::Capsule {
            radius: eighth(s[0]),
            half_height: eighth(s[1]),
        },
        3 => Shape::Compound {
            parts: vec![
                Part {
                    rotation: Quat::IDENTITY,
                    translation: Vec3::new(eighth(s[2]), Fx::ZERO, Fx::ZERO),
                    shape: Shape::Sphere {
                        radius: eighth(s[0]),
                    },
                },
                Part {
                    rotation: rotation([0, 0, 1], 10),
                    translation: Vec3::new(-eighth(s[2]), Fx::ZERO, Fx::ZERO),
                    shape: Shape::Capsule {
                        radius: eighth(s[1]),
                        half_height: eighth(s[0]),
                    },
                },
            ],
        },
        5 => Shape::Cylinder {
            radius: eighth(s[0]),
            half_height: eighth(s[1]),
        },
        6 => Shape::Cone {
            radius: eighth(s[0]),
            half_height: eighth(s[1]),
        },
        7 => {
            let (a, b, c) = (eighth(s[0]), eighth(s[1]), eighth(s[2]));
            let points = [
                Vec3::new(a, Fx::ZERO, Fx::ZERO),
                Vec3::new(-a, Fx::ZERO, Fx::ZERO),
                Vec3::new(Fx::ZERO, b, Fx::ZERO),
                Vec3::new(Fx::ZERO, -b, Fx::ZERO),
                Vec3::new(Fx::ZERO, Fx::ZERO, c),
                Vec3::new(Fx::ZERO, Fx::ZERO, -c),
            ];
            Shape::ConvexHull {
                hull: ConvexHull::new(&points).expect("an octahedron"),
            }
        }
        _ => Shape::Box {
            half_extents: Vec3::new(eighth(4 * s[0]), eighth(s[1]), eighth(s[2])),
        },
    }
}

/// The world of the specs, over a ground plane at y = −2 m.
fn world_of(specs: &[BodySpec]) -> World<Fx> {
    let mut ground = BodyDesc::new(
        Shape::Plane {
            normal: Vec3::Y,
            offset: Fx::ZERO,
        },
        Vec3::new(Fx::ZERO, -Fx::TWO, Fx::ZERO),
    );
    ground.kind = BodyKind::Static;
    let mut bodies = vec![ground];
    for &(kind, size, position, axis, angle, motion, sensor, layers) in specs {
        let mut b = BodyDesc::new(shape_of(kind, size), quarter(position));
        b.orientation = rotation(axis, angle);
        b.kind = match motion {
            0 => BodyKind::Static,
            1 => BodyKind::Kinematic,
            _ => BodyKind::Dynamic,
        };
        if b.kind == BodyKind::Kinematic {
            b.velocity = Vec3::new(Fx::ONE, Fx::ZERO, Fx::ZERO);
        }
        b.sensor = sensor;
        b.filter = CollisionFilter::new(layers, u32::MAX);
        bodies.push(b);
    }
    let mut scene = Scene::empty("queries");
    scene.gravity = Vec3::new(Fx::ZERO, Fx::from_ratio(-981, 100), Fx::ZERO);
    scene.rigid = Some(RigidDesc {
        bodies,
        ..RigidDesc::default()
    });
    scene.build().expect("the scene builds")
}

fn run(world: &mut World<Fx>, ticks: u32) {
    let input = TickInput::default();
    for _ in 0..ticks {
        world.step(&input);
    }
}

fn handles(world: &World<Fx>) -> Vec<Handle> {
    world.rigid().expect("rigid bodies").handles().collect()
}

/// The filter that sees only `h` (sensors included).
fn only(world: &World<Fx>, h: Handle) -> QueryFilter {
    let mut f = QueryFilter::new().with_sensors();
    f.exclude = handles(world).into_iter().filter(|&o| o != h).collect();
    f
}

fn cast_shape_of(kind: u8) -> Shape<Fx> {
    shape_of(kind % 3, [3, 2, 1])
}

/// Every query of `queries` on `world`, for comparison.
fn answers(world: &World<Fx>, queries: &[QuerySpec]) -> Vec<String> {
    let f = QueryFilter::new();
    let masked = QueryFilter::new().with_mask(0b10).with_sensors();
    let far = Fx::from_int(40);
    let mut out = Vec::new();
    for &(o, d, kind) in queries {
        let (o, d) = (quarter(o), integer(d));
        let q = rotation([1, 1, 0], i32::from(kind) * 7);
        let shape = cast_shape_of(kind);
        out.push(format!("{:?}", world.cast_ray(o, d, far, &f)));
        out.push(format!("{:?}", world.cast_ray_all(o, d, far, &masked)));
        out.push(format!("{:?}", world.cast_shape(&shape, o, q, d, far, &f)));
        out.push(format!("{:?}", world.overlap(&shape, o, q, &masked)));
        out.push(format!("{:?}", world.project_point(o, Fx::from_int(3), &f)));
    }
    out
}

/// Asserts the per-body properties of every query on `world`.
fn check_against_each_body(world: &World<Fx>, queries: &[QuerySpec]) -> Result<(), TestCaseError> {
    let all = QueryFilter::new().with_sensors();
    let far = Fx::from_int(40);
    let bodies = handles(world);
    for &(o, d, kind) in queries {
        let (o, d) = (quarter(o), integer(d));
        let nearest = world.cast_ray(o, d, far, &all);
        let mut each: Vec<RayHit<Fx>> = bodies
            .iter()
            .filter_map(|&h| world.cast_ray(o, d, far, &only(world, h)))
            .collect();
        each.sort_by(|a, b| a.distance.total_cmp(&b.distance).then(a.body.cmp(&b.body)));
        prop_assert_eq!(nearest, each.first().copied());
        prop_assert_eq!(world.cast_ray_all(o, d, far, &all), each);

        let q = rotation([0, 1, 1], i32::from(kind) * 11);
        let shape = cast_shape_of(kind);
        let overlapping: Vec<Handle> = bodies
            .iter()
            .copied()
            .filter(|&h| !world.overlap(&shape, o, q, &only(world, h)).is_empty())
            .collect();
        prop_assert_eq!(world.overlap(&shape, o, q, &all), overlapping);

        let cast = world.cast_shape(&shape, o, q, d, far, &all);
        let first = bodies
            .iter()
            .filter_map(|&h| world.cast_shape(&shape, o, q, d, far, &only(world, h)))
            .min_by(|a, b| a.distance.total_cmp(&b.distance).then(a.body.cmp(&b.body)));
        prop_assert_eq!(cast, first);
    }
    Ok(())
}

proptest! {
    #![proptest_config(crate::property_cases::fixed_cases(48))]

    /// The tree (current after steps) against each body asked alone, and against brute
    /// force (a world made from the snapshot), and the same after a restore.
    #[test]
    fn queries_match_brute_force_and_survive_restore(
        specs in prop::collection::vec(body_spec(), 1..24),
        queries in prop::collection::vec(query_spec(), 1..8),
    ) {
        let mut world = world_of(&specs);
        // Before any step: brute force.
        check_against_each_body(&world, &queries)?;
        run(&mut world, 3);
        check_against_each_body(&world, &queries)?;
        let tree = answers(&world, &queries);
        let snapshot = world.snapshot();
        let brute = World::from_state(snapshot.clone());
        prop_assert_eq!(answers(&brute, &queries), tree.clone());
        run(&mut world, 20);
        check_against_each_body(&world, &queries)?;
        world.restore(&snapshot);
        prop_assert_eq!(answers(&world, &queries), tree.clone());
        run(&mut world, 1);
        let mut again = World::from_state(snapshot);
        run(&mut again, 1);
        prop_assert_eq!(answers(&world, &queries), answers(&again, &queries));
    }
}

#[test]
fn a_world_without_rigid_bodies_answers_nothing() {
    let world = Scene::<Fx>::empty("nothing").build().expect("builds");
    let f = QueryFilter::new();
    let ball = Shape::Sphere { radius: Fx::ONE };
    assert!(world.cast_ray(Vec3::ZERO, Vec3::X, Fx::ONE, &f).is_none());
    assert!(
        world
            .cast_ray_all(Vec3::ZERO, Vec3::X, Fx::ONE, &f)
            .is_empty()
    );
    assert!(
        world
            .cast_shape(&ball, Vec3::ZERO, Quat::IDENTITY, Vec3::X, Fx::ONE, &f)
            .is_none()
    );
    assert!(
        world
            .overlap(&ball, Vec3::ZERO, Quat::IDENTITY, &f)
            .is_empty()
    );
    assert!(world.project_point(Vec3::ZERO, Fx::ONE, &f).is_none());
}

#[test]
fn a_ray_dropped_on_the_balls_scene_lands_on_a_ball_or_the_floor() {
    let mut world = fixstep_scenes::builtin_scene::<Fx>("balls")
        .expect("a built-in scene")
        .build()
        .expect("it builds");
    run(&mut world, 30);
    let f = QueryFilter::new();
    let down = -Vec3::Y;
    for x in -8..=8 {
        let o = Vec3::new(Fx::from_int(x), Fx::from_int(40), Fx::from_ratio(1, 3));
        let hit = world
            .cast_ray(o, down, Fx::from_int(100), &f)
            .expect("the floor at least");
        let brute = World::from_state(world.snapshot());
        assert_eq!(brute.cast_ray(o, down, Fx::from_int(100), &f), Some(hit));
        assert!(hit.normal.y > Fx::ZERO, "{hit:?}");
    }
}
