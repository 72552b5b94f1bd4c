//! Bodies on triangle meshes and heightfields: smooth floors (no bumps at the seams
//! between triangles, thanks to internal-edge removal), resting stacks that sleep, and the
//! meshes' own tables (active edges) and written forms. Tolerances come from the physics:
//! a body on a flat floor has no vertical motion, so any vertical speed is an artefact.

use fixstep::math::{Fx, Real, Vec3};
use fixstep::rigid::convex::ConvexHull;
use fixstep::rigid::{
    BodyDesc, BodyKind, HeightField, Material, MeshError, RigidDesc, Shape, SolverSettings, TriMesh,
};
use fixstep::scene::{Scene, parse_scene};
use fixstep::world::{Handle, TickInput, World};

fn fx(v: f64) -> Fx {
    Fx::from_f64(v)
}

/// A flat square floor at y = 0, `cells` × `cells` squares of `spacing` m, two triangles
/// each, centred on the origin and facing +y.
fn flat_grid(cells: u32, spacing: f64) -> TriMesh<Fx> {
    let n = cells + 1;
    let half = f64::from(cells) * spacing / 2.0;
    let mut vertices = Vec::new();
    for r in 0..n {
        for c in 0..n {
            vertices.push(Vec3::new(
                fx(f64::from(c) * spacing - half),
                Fx::ZERO,
                fx(f64::from(r) * spacing - half),
            ));
        }
    }
    let mut triangles = Vec::new();
    for r in 0..cells {
        for c in 0..cells {
            let v = r * n + c;
            triangles.push([v, v + n, v + n + 1]);
            triangles.push([v, v + n + 1, v + 1]);
        }
    }
    TriMesh::new(vertices, triangles).expect("a flat grid is a valid mesh")
}

/// A static body of `shape` at the origin with friction `mu`.
fn floor(shape: Shape<Fx>, mu: f64) -> BodyDesc<Fx> {
    let mut body = BodyDesc::new(shape, Vec3::ZERO);
    body.kind = BodyKind::Static;
    body.material = Material {
        friction: fx(mu),
        restitution: Fx::ZERO,
    };
    body
}

/// A world of `bodies` (the first a floor) under g = 10 m/s² down; the handles of the
/// dynamic bodies, in order.
fn world_of(bodies: Vec<BodyDesc<Fx>>, sleeping: bool) -> (World<Fx>, Vec<Handle>) {
    let mut scene = Scene::empty("mesh floor");
    scene.gravity = Vec3::new(Fx::ZERO, fx(-10.0), Fx::ZERO);
    scene.rigid = Some(RigidDesc {
        bodies,
        solver: SolverSettings {
            sleeping,
            ..SolverSettings::default()
        },
        ..RigidDesc::default()
    });
    let world = scene.build().expect("the scene builds");
    let r = world.rigid().expect("rigid bodies");
    let dynamic = r
        .handles()
        .filter(|&h| r.mass(h).expect("live") > Fx::ZERO)
        .collect();
    (world, dynamic)
}

/// The largest |v_y| (m/s) of `body` over `ticks` steps after the first `settle`.
fn largest_vertical_speed(world: &mut World<Fx>, body: Handle, settle: u64, ticks: u64) -> f64 {
    let mut largest: f64 = 0.0;
    for tick in 0..settle + ticks {
        world.step(&TickInput::default());
        if tick >= settle {
            let v = world.rigid().unwrap().linear_velocity(body).unwrap();
            largest = largest.max(v.y.to_f64().abs());
        }
    }
    largest
}

/// A 0.5 m box slides at 4 m/s with μ = 0.1 across a flat mesh of 0.25 m squares (51 200
/// triangles; it crosses about 20 seams a second): its vertical speed stays below 1 mm/s
/// once it has settled on the floor. Without internal-edge removal the seams tilt contact
/// normals and bump it by centimetres per second.
#[test]
fn a_box_slides_across_a_many_triangle_mesh_without_bumps() {
    let mesh = flat_grid(160, 0.25);
    let mut body = BodyDesc::new(
        Shape::Box {
            half_extents: Vec3::splat(fx(0.25)),
        },
        Vec3::new(fx(-8.0), fx(0.25), fx(0.1)),
    );
    body.velocity = Vec3::new(fx(4.0), Fx::ZERO, Fx::ZERO);
    body.material.friction = fx(0.1);
    let (mut world, dynamic) = world_of(vec![floor(Shape::TriMesh { mesh }, 0.1), body], false);
    let vy = largest_vertical_speed(&mut world, dynamic[0], 10, 110);
    let x = world
        .rigid()
        .unwrap()
        .position(dynamic[0])
        .unwrap()
        .x
        .to_f64();
    assert!(x > -4.0, "the box slid (x = {x} m)");
    assert!(vy < 1e-3, "largest vertical speed {vy} m/s");
}

/// A 0.3 m ball rolls at 3 m/s across a flat 64 × 64 heightfield of 0.25 m cells: its
/// vertical speed stays below 1 mm/s.
#[test]
fn a_ball_rolls_over_a_flat_heightfield_without_bumps() {
    let field = HeightField::new(
        65,
        65,
        Vec3::new(fx(16.0), fx(1.0), fx(16.0)),
        vec![Fx::ZERO; 65 * 65],
    )
    .expect("a flat grid");
    let mut body = BodyDesc::new(
        Shape::Sphere { radius: fx(0.3) },
        Vec3::new(fx(-6.0), fx(0.3), fx(0.05)),
    );
    body.velocity = Vec3::new(fx(3.0), Fx::ZERO, Fx::ZERO);
    body.angular_velocity = Vec3::new(Fx::ZERO, Fx::ZERO, fx(-10.0));
    body.material.friction = fx(0.5);
    let (mut world, dynamic) =
        world_of(vec![floor(Shape::HeightField { field }, 0.5), body], false);
    let vy = largest_vertical_speed(&mut world, dynamic[0], 10, 170);
    let x = world
        .rigid()
        .unwrap()
        .position(dynamic[0])
        .unwrap()
        .x
        .to_f64();
    assert!(x > 0.0, "the ball rolled (x = {x} m)");
    assert!(vy < 1e-3, "largest vertical speed {vy} m/s");
}

/// A stack of 10 hull cubes (0.5 m) on a flat mesh floor falls asleep within 5 s.
#[test]
fn a_stack_of_ten_hull_boxes_on_a_mesh_floor_sleeps_within_five_seconds() {
    let h = 0.25;
    let corners: Vec<Vec3<Fx>> = (0..8)
        .map(|k| {
            let s = |bit: i32| if k & bit != 0 { fx(h) } else { fx(-h) };
            Vec3::new(s(1), s(2), s(4))
        })
        .collect();
    let hull = ConvexHull::new(&corners).expect("a cube");
    let mut bodies = vec![floor(
        Shape::TriMesh {
            mesh: flat_grid(16, 0.5),
        },
        0.6,
    )];
    for level in 0..10 {
        let mut body = BodyDesc::new(
            Shape::ConvexHull { hull: hull.clone() },
            Vec3::new(fx(0.1), fx(h + 2.0 * h * f64::from(level)), fx(0.1)),
        );
        body.material.friction = fx(0.6);
        bodies.push(body);
    }
    let (mut world, dynamic) = world_of(bodies, true);
    let asleep = |world: &World<Fx>| {
        dynamic
            .iter()
            .all(|&b| world.rigid().unwrap().is_sleeping(b).unwrap())
    };
    let mut tick = 0;
    while tick < 300 && !asleep(&world) {
        world.step(&TickInput::default());
        tick += 1;
    }
    assert!(asleep(&world), "the stack is still awake after 5 s");
    let top = world.rigid().unwrap().position(dynamic[9]).unwrap();
    assert!(
        (top.y.to_f64() - 4.75).abs() < 0.02 && top.x.to_f64().abs() < 0.2,
        "the stack stood: top at {top:?}"
    );
}

/// A flat grid's only active edges are on its boundary; folding it into a ridge makes the
/// fold's edges active.
#[test]
fn active_edges_are_the_boundary_of_a_flat_grid_and_the_crest_of_a_ridge() {
    let flat = flat_grid(4, 1.0);
    assert_eq!(
        flat.active_edge_count(),
        16,
        "4 cells along each of 4 sides"
    );
    // The same grid with the middle column raised by 0.5 m: a convex crest along z.
    let vertices: Vec<Vec3<Fx>> = flat
        .vertices()
        .iter()
        .map(|v| {
            let y = if v.x == Fx::ZERO { fx(0.5) } else { Fx::ZERO };
            Vec3::new(v.x, y, v.z)
        })
        .collect();
    let ridge = TriMesh::new(vertices, flat.triangles().to_vec()).expect("a ridge");
    // The crest (4 edges, each counted by its 2 triangles), and the valleys at x = ±1 are
    // concave, hence inactive; the diagonals on each slope are flat, hence inactive.
    assert_eq!(ridge.active_edge_count(), 16 + 8);
}

/// Meshes refuse bad data with the index of the culprit.
#[test]
fn meshes_refuse_bad_data() {
    let v = |x: f64, z: f64| Vec3::new(fx(x), Fx::ZERO, fx(z));
    let square = vec![v(0.0, 0.0), v(0.0, 1.0), v(1.0, 1.0), v(1.0, 0.0)];
    assert_eq!(TriMesh::new(square.clone(), vec![]), Err(MeshError::Empty));
    assert_eq!(
        TriMesh::new(square.clone(), vec![[0, 1, 2], [0, 2, 7]]).unwrap_err(),
        MeshError::IndexOutOfRange {
            triangle: 1,
            index: 7,
            vertices: 4
        }
    );
    assert_eq!(
        TriMesh::new(square.clone(), vec![[0, 1, 1]]).unwrap_err(),
        MeshError::Degenerate { triangle: 0 }
    );
    let mut fin = square.clone();
    fin.push(Vec3::new(fx(0.5), fx(1.0), fx(0.5)));
    assert_eq!(
        TriMesh::new(fin, vec![[0, 1, 2], [0, 2, 3], [0, 4, 2]]).unwrap_err(),
        MeshError::NonManifold { triangle: 2 }
    );
    assert!(matches!(
        HeightField::new(1, 4, Vec3::splat(Fx::ONE), vec![Fx::ZERO; 4]),
        Err(MeshError::GridSize { .. })
    ));
    assert_eq!(
        HeightField::new(2, 2, Vec3::splat(Fx::ONE), vec![Fx::ZERO; 3]).unwrap_err(),
        MeshError::HeightCount {
            expected: 4,
            got: 3
        }
    );
}

/// A scene writes a mesh and a heightfield as their source data and reads them back equal;
/// a bad mesh in a scene file is refused with the reason.
#[test]
fn meshes_are_written_and_read_as_source_data() {
    let text = r#"(
        name: "meshes",
        rigid: (
            bodies: [
                (kind: Static, shape: TriMesh(
                    vertices: [(x: 0, y: 0, z: 0), (x: 0, y: 0, z: 1), (x: 1, y: 0, z: 0)],
                    triangles: [(0, 1, 2)],
                ), position: (x: 0, y: 0, z: 0)),
                (kind: Static, shape: HeightField(
                    rows: 2, columns: 3, scale: (x: 2, y: 1, z: 1),
                    heights: [0, 0.5, 0, 0, 0.25, 0],
                ), position: (x: 0, y: -1, z: 0)),
            ],
        ),
    )"#;
    let scene = parse_scene::<Fx>(text, "inline").expect("the scene reads");
    let bodies = &scene.rigid.as_ref().unwrap().bodies;
    let Shape::HeightField { field } = &bodies[1].shape else {
        panic!("a heightfield");
    };
    assert_eq!(field.mesh().triangles().len(), 4);
    assert_eq!(field.mesh().vertices()[1].y, fx(0.5));
    let written = ron::Options::default()
        .to_string_pretty(&scene, ron::ser::PrettyConfig::new())
        .expect("writes");
    assert!(
        !written.contains("file"),
        "no file field in text: {written}"
    );
    let again = parse_scene::<Fx>(&written, "again").expect("reads back");
    assert_eq!(again, scene);
    let bad = text.replace("(0, 1, 2)", "(0, 1, 3)");
    let error = parse_scene::<Fx>(&bad, "bad").unwrap_err().to_string();
    assert!(
        error.contains("triangles[0]") && error.contains("out of range"),
        "{error}"
    );
}

/// Every convex shape dropped on a flat mesh settles where it settles on a plane (its
/// centre of mass within 1 mm of the same height, with no vertical motion above 1 mm/s:
/// round shapes may still roll), dropped at a slant so that corners, edges and faces meet
/// the triangles' seams.
#[test]
fn every_convex_shape_rests_on_a_mesh_as_on_a_plane() {
    let q =
        fixstep::math::Quat::<Fx>::from_axis_angle(Vec3::new(fx(0.6), Fx::ZERO, fx(0.8)), fx(0.3));
    let corners: Vec<Vec3<Fx>> = (0..8)
        .map(|k| {
            let s = |bit: i32, h: f64| if k & bit != 0 { fx(h) } else { fx(-h) };
            Vec3::new(s(1, 0.3), s(2, 0.2), s(4, 0.25))
        })
        .collect();
    let shapes = [
        Shape::Sphere { radius: fx(0.3) },
        Shape::Box {
            half_extents: Vec3::new(fx(0.3), fx(0.2), fx(0.25)),
        },
        Shape::Capsule {
            radius: fx(0.2),
            half_height: fx(0.3),
        },
        Shape::Cylinder {
            radius: fx(0.3),
            half_height: fx(0.2),
        },
        Shape::Cone {
            radius: fx(0.3),
            half_height: fx(0.3),
        },
        Shape::ConvexHull {
            hull: ConvexHull::new(&corners).expect("a box"),
        },
    ];
    for shape in shapes {
        let rest = |floor_shape: Shape<Fx>| {
            let mut body = BodyDesc::new(shape.clone(), Vec3::new(fx(0.11), fx(1.0), fx(0.07)));
            body.orientation = q;
            let (mut world, dynamic) = world_of(vec![floor(floor_shape, 0.6), body], false);
            for _ in 0..240 {
                world.step(&TickInput::default());
            }
            let r = world.rigid().unwrap();
            (
                r.position(dynamic[0]).unwrap().y.to_f64(),
                r.linear_velocity(dynamic[0]).unwrap().y.to_f64().abs(),
            )
        };
        let (on_mesh, speed) = rest(Shape::TriMesh {
            mesh: flat_grid(8, 0.25),
        });
        let (on_plane, _) = rest(Shape::Plane {
            normal: Vec3::Y,
            offset: Fx::ZERO,
        });
        assert!(
            (on_mesh - on_plane).abs() < 1e-3 && speed < 1e-3,
            "{shape:?}: at {on_mesh} m on the mesh, {on_plane} m on a plane, |v_y| {speed} m/s"
        );
    }
}
