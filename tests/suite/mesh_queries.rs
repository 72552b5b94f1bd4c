//! Scene queries on meshes and heightfields: rays, closest points, overlaps and shape
//! casts against the triangles, checked against the geometry (a tilted plane's analytic
//! answers), with ties between triangles resolved by index.

use fixstep::math::{Fx, Quat, Real, Vec3};
use fixstep::rigid::{BodyDesc, HeightField, QueryFilter, RigidDesc, Shape, TriMesh};
use fixstep::scene::Scene;
use fixstep::world::{TickInput, World};

fn fx(v: f64) -> Fx {
    Fx::from_f64(v)
}

fn v(x: f64, y: f64, z: f64) -> Vec3<Fx> {
    Vec3::new(fx(x), fx(y), fx(z))
}

/// A world holding one static `shape` at `position`, stepped once (so the query tree is
/// built).
fn world_with(shape: Shape<Fx>, position: Vec3<Fx>) -> World<Fx> {
    let mut scene = Scene::empty("mesh queries");
    scene.rigid = Some(RigidDesc {
        bodies: vec![BodyDesc::new(shape, position).fixed()],
        ..RigidDesc::default()
    });
    let mut world = scene.build().expect("builds");
    world.step(&TickInput::default());
    world
}

/// A 16 × 16 heightfield over 8 m × 8 m of the plane y = 0.25 x (heights h = 0.25 x
/// with s_y = 1), so that rays and points have analytic answers.
fn ramp() -> Shape<Fx> {
    let n = 17u32;
    let heights = (0..n * n)
        .map(|k| {
            let c = i64::from(k % n);
            // x = 8 c / 16 − 4 m, h = x / 4.
            Fx::from_ratio(8 * c - 64, 64)
        })
        .collect();
    Shape::HeightField {
        field: HeightField::new(n, n, v(8.0, 1.0, 8.0), heights).expect("a valid grid"),
    }
}

/// The unit normal of the plane y = x / 4 (facing up): (−1, 4, 0) / √17.
fn ramp_normal() -> [f64; 3] {
    let s = 17f64.sqrt();
    [-1.0 / s, 4.0 / s, 0.0]
}

#[test]
fn a_ray_hits_a_heightfield_where_the_plane_is() {
    let world = world_with(ramp(), Vec3::ZERO);
    let r = world.rigid().unwrap();
    let filter = QueryFilter::new();
    // Straight down at x = 1.3 m, z = 0.7 m: the surface is at y = 0.325 m.
    let hit = r
        .cast_ray(v(1.3, 5.0, 0.7), v(0.0, -1.0, 0.0), fx(10.0), &filter)
        .expect("hits");
    assert!(
        (hit.distance.to_f64() - (5.0 - 0.325)).abs() < 1e-6,
        "{hit:?}"
    );
    let n = hit.normal.to_f64();
    for k in 0..3 {
        assert!((n[k] - ramp_normal()[k]).abs() < 1e-6, "normal {n:?}");
    }
    // From below, the normal faces down (towards the origin).
    let below = r
        .cast_ray(v(1.3, -5.0, 0.7), v(0.0, 1.0, 0.0), fx(10.0), &filter)
        .expect("hits from below");
    assert!((below.distance.to_f64() - 5.325).abs() < 1e-6);
    assert!(below.normal.y < Fx::ZERO);
    // Beyond the grid, or too short, or parallel above it: no hit.
    assert!(
        r.cast_ray(v(4.5, 5.0, 0.0), v(0.0, -1.0, 0.0), fx(10.0), &filter)
            .is_none()
    );
    assert!(
        r.cast_ray(v(1.3, 5.0, 0.7), v(0.0, -1.0, 0.0), fx(4.0), &filter)
            .is_none()
    );
}

#[test]
fn a_ray_down_a_shared_edge_hits_once() {
    // Two triangles of a unit square at y = 0 sharing the diagonal (0,0,0)–(1,0,1).
    let mesh = TriMesh::new(
        vec![
            v(0.0, 0.0, 0.0),
            v(0.0, 0.0, 1.0),
            v(1.0, 0.0, 1.0),
            v(1.0, 0.0, 0.0),
        ],
        vec![[0, 1, 2], [0, 2, 3]],
    )
    .expect("a square");
    let world = world_with(Shape::TriMesh { mesh }, Vec3::ZERO);
    let r = world.rigid().unwrap();
    let filter = QueryFilter::new();
    let all = r.cast_ray_all(v(0.5, 1.0, 0.5), v(0.0, -1.0, 0.0), fx(5.0), &filter);
    assert_eq!(all.len(), 1, "one body, one hit: {all:?}");
    assert!((all[0].distance.to_f64() - 1.0).abs() < 1e-9);
}

#[test]
fn the_closest_point_of_a_mesh_lies_on_its_face_edge_or_corner() {
    let mesh = TriMesh::new(
        vec![v(0.0, 0.0, 0.0), v(0.0, 0.0, 2.0), v(2.0, 0.0, 0.0)],
        vec![[0, 1, 2]],
    )
    .expect("a triangle");
    let world = world_with(Shape::TriMesh { mesh }, v(1.0, 0.0, 0.0));
    let r = world.rigid().unwrap();
    let filter = QueryFilter::new();
    let project = |p: Vec3<Fx>| {
        let q = r.project_point(p, fx(100.0), &filter).expect("found");
        assert!(!q.inside, "a surface has no inside");
        (q.point.to_f64(), q.distance.to_f64())
    };
    // Above the face: straight down.
    let (q, d) = project(v(1.5, 3.0, 0.5));
    assert!((q[0] - 1.5).abs() < 1e-9 && q[1].abs() < 1e-9 && (q[2] - 0.5).abs() < 1e-9);
    assert!((d - 3.0).abs() < 1e-6);
    // Past the hypotenuse x + z = 2 (in the body frame): onto the edge.
    let (q, d) = project(v(1.0 + 2.0, 0.0, 2.0));
    assert!(
        (q[0] - 2.0).abs() < 1e-6 && (q[2] - 1.0).abs() < 1e-6,
        "{q:?}"
    );
    assert!((d - 2f64.sqrt()).abs() < 1e-6);
    // Beyond the corner (0, 0, 0) of the body frame: the corner.
    let (q, d) = project(v(0.0, 0.0, -1.0));
    assert!((q[0] - 1.0).abs() < 1e-9 && q[2].abs() < 1e-9, "{q:?}");
    assert!((d - 2f64.sqrt()).abs() < 1e-6);
}

#[test]
fn casts_stop_on_and_overlaps_find_a_heightfield() {
    let world = world_with(ramp(), Vec3::ZERO);
    let r = world.rigid().unwrap();
    let filter = QueryFilter::new();
    // A 0.2 m ball dropped at x = 1 m: it touches the plane y = x/4 when its centre is
    // r √17 / 4 above the surface point below it, y = 0.25 + 0.2 √17 / 4.
    let ball = Shape::Sphere { radius: fx(0.2) };
    let hit = r
        .cast_shape(
            &ball,
            v(1.0, 5.0, 0.3),
            Quat::IDENTITY,
            v(0.0, -1.0, 0.0),
            fx(10.0),
            &filter,
        )
        .expect("lands");
    let expected = 5.0 - (0.25 + 0.2 * 17f64.sqrt() / 4.0);
    assert!(
        (hit.distance.to_f64() - expected).abs() < 1e-5,
        "{hit:?} vs {expected}"
    );
    // A 0.2 m cube: its bottom face's uphill edge (x = 1.2 m) touches first:
    // y_c − 0.2 = 1.2 / 4.
    let cube = Shape::Box {
        half_extents: Vec3::splat(fx(0.2)),
    };
    let hit = r
        .cast_shape(
            &cube,
            v(1.0, 5.0, 0.3),
            Quat::IDENTITY,
            v(0.0, -1.0, 0.0),
            fx(10.0),
            &filter,
        )
        .expect("lands");
    let expected = 5.0 - (0.3 + 0.2);
    assert!(
        (hit.distance.to_f64() - expected).abs() < 1e-5,
        "{hit:?} vs {expected}"
    );
    // Overlaps: a ball sunk into the ramp overlaps it, one above does not.
    assert_eq!(
        r.overlap(&ball, v(1.0, 0.3, 0.3), Quat::IDENTITY, &filter)
            .len(),
        1
    );
    assert!(
        r.overlap(&ball, v(1.0, 0.8, 0.3), Quat::IDENTITY, &filter)
            .is_empty()
    );
}
