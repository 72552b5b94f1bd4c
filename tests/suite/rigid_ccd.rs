//! Continuous collision (issue [geometry]): fast bodies do not tunnel through thin static
//! bodies, and bullets not through dynamic ones. The bounds come from the geometry (a
//! wall's faces, a slab's thickness), not from this engine's output.

use std::num::NonZeroU32;

use fixstep::math::{Fx, Real, Vec3};
use fixstep::replay::{VerifyOutcome, record, scene_id, verify};
use fixstep::rigid::{BodyDesc, RigidDesc, Shape};
use fixstep::scene::Scene;
use fixstep::world::snapshot::{decode_snapshot, encode_snapshot};
use fixstep::world::{Handle, TickInput, World};

fn v(x: f64, y: f64, z: f64) -> Vec3<Fx> {
    Vec3::new(Fx::from_f64(x), Fx::from_f64(y), Fx::from_f64(z))
}

fn scene_of(bodies: Vec<BodyDesc<Fx>>, ticks: u64) -> Scene<Fx> {
    let mut scene = Scene::empty("ccd");
    scene.ticks = ticks;
    scene.rigid = Some(RigidDesc {
        bodies,
        ..RigidDesc::default()
    });
    scene
}

fn ball(radius: f64, position: Vec3<Fx>, velocity: Vec3<Fx>) -> BodyDesc<Fx> {
    let mut b = BodyDesc::new(
        Shape::Sphere {
            radius: Fx::from_f64(radius),
        },
        position,
    );
    b.velocity = velocity;
    b
}

fn slab(half: Vec3<Fx>, position: Vec3<Fx>) -> BodyDesc<Fx> {
    BodyDesc::new(Shape::Box { half_extents: half }, position)
}

/// Body `index`'s position after each of `ticks` ticks.
fn track(scene: &Scene<Fx>, index: u32) -> Vec<[f64; 3]> {
    let mut world = scene.build().expect("builds");
    (0..scene.ticks)
        .map(|_| {
            world.step(&TickInput::default());
            position(&world, index)
        })
        .collect()
}

fn position(world: &World<Fx>, index: u32) -> [f64; 3] {
    world
        .rigid()
        .expect("rigid bodies")
        .position(Handle::new(index, 0))
        .expect("alive")
        .to_f64()
}

/// The scene records, and its replay verifies to the recorded checksum.
fn replays(scene: &Scene<Fx>) {
    let replay = record(scene, scene.ticks, NonZeroU32::new(5).expect("nonzero")).expect("records");
    let bytes = replay.to_bytes().expect("encodes");
    let read = fixstep::replay::Replay::from_bytes(&bytes, "ccd").expect("decodes");
    assert_eq!(
        read.scene(),
        replay.scene(),
        "the bullet flags survive the file"
    );
    assert_eq!(
        verify(&read).expect("verifies"),
        VerifyOutcome::Ok {
            ticks: scene.ticks,
            checksum: replay.final_checksum(),
        }
    );
}

/// Checksums of a straight run, and of a run saved at `at` through snapshot bytes and
/// restored into a world built from `host` (the same scene, or one without bullets: the
/// snapshot carries the flags).
fn restored_matches(scene: &Scene<Fx>, host: &Scene<Fx>, at: u64) {
    let empty = TickInput::default();
    let mut world = scene.build().expect("builds");
    let mut straight = Vec::new();
    let mut saved = None;
    for tick in 0..scene.ticks {
        if tick == at {
            let id = scene_id(scene).expect("id");
            saved = Some(encode_snapshot(&world.snapshot(), &id).expect("encodes"));
        }
        world.step(&empty);
        straight.push(world.checksum().total);
    }
    let mut world = host.build().expect("builds");
    world.restore(
        &decode_snapshot(&saved.expect("saved"))
            .expect("decodes")
            .state,
    );
    let resumed: Vec<u64> = (at..scene.ticks)
        .map(|_| {
            world.step(&empty);
            world.checksum().total
        })
        .collect();
    assert_eq!(resumed, straight[at as usize..]);
}

/// A 5 cm ball at 300 m/s (5 m per tick) and a 5 cm thick static wall across its path at
/// x ∈ [−0.025, 0.025].
fn ball_and_wall() -> Scene<Fx> {
    let wall = slab(v(0.025, 1.0, 1.0), v(0.0, 0.0, 0.0)).fixed();
    let shot = ball(0.05, v(-12.0, 0.0, 0.0), v(300.0, 0.0, 0.0));
    scene_of(vec![wall, shot], 30)
}

#[test]
fn a_fast_ball_never_passes_a_thin_static_wall() {
    let scene = ball_and_wall();
    let path = track(&scene, 1);
    for (tick, p) in path.iter().enumerate() {
        assert!(
            p[0] < -0.025,
            "tick {tick}: the ball's centre at x = {}",
            p[0]
        );
    }
    // It stopped at the wall: its surface within a centimetre of the near face.
    let last = path.last().expect("ticks");
    assert!(last[0] > -0.025 - 0.05 - 0.01, "{last:?}");
    replays(&scene);
    restored_matches(&scene, &scene, 2);
}

/// A 2 cm box at 100 m/s (1.7 m per tick) straight down at `ground`, whose top is y = 0.
fn box_onto(ground: BodyDesc<Fx>) -> Scene<Fx> {
    let mut cube = slab(v(0.01, 0.01, 0.01), v(0.0, 5.0, 0.0));
    cube.velocity = v(0.0, -100.0, 0.0);
    scene_of(vec![ground, cube], 30)
}

#[test]
fn a_fast_small_box_never_passes_a_thin_static_slab() {
    // A 1 cm thick slab: y ∈ [−0.01, 0].
    let scene = box_onto(slab(v(2.0, 0.005, 2.0), v(0.0, -0.005, 0.0)).fixed());
    for (tick, p) in track(&scene, 1).iter().enumerate() {
        assert!(p[1] > 0.0, "tick {tick}: the box's centre at y = {}", p[1]);
    }
    replays(&scene);
    restored_matches(&scene, &scene, 1);
}

#[test]
fn a_fast_small_box_stops_on_a_plane_without_sinking() {
    let plane = BodyDesc::new(
        Shape::Plane {
            normal: v(0.0, 1.0, 0.0),
            offset: Fx::ZERO,
        },
        Vec3::ZERO,
    )
    .fixed();
    let scene = box_onto(plane);
    // Its centre never goes below the surface (a shallower end pose is left to the
    // contact); without the sweep it ends a tick up to 1.7 m below the surface.
    for (tick, p) in track(&scene, 1).iter().enumerate() {
        assert!(p[1] > 0.0, "tick {tick}: the box's centre at y = {}", p[1]);
    }
    replays(&scene);
}

/// A 5 cm ball at 300 m/s at a free (dynamic) plank 5 cm thick, 1 m square, without
/// gravity; the ball is a bullet or not.
fn ball_and_plank(bullet: bool) -> Scene<Fx> {
    let plank = slab(v(0.025, 0.5, 0.5), v(0.0, 0.0, 0.0));
    let mut shot = ball(0.05, v(-12.0, 0.0, 0.0), v(300.0, 0.0, 0.0));
    shot.bullet = bullet;
    let mut scene = scene_of(vec![plank, shot], 20);
    scene.gravity = Vec3::ZERO;
    scene
}

/// Whether the ball's centre ever gets past the plank's centre.
fn passes(scene: &Scene<Fx>) -> bool {
    let mut world = scene.build().expect("builds");
    (0..scene.ticks).any(|_| {
        world.step(&TickInput::default());
        position(&world, 1)[0] > position(&world, 0)[0]
    })
}

#[test]
fn a_bullet_does_not_pass_a_dynamic_plank_and_a_plain_ball_does() {
    // Without the flag the ball is swept only against static and kinematic bodies: it
    // jumps from 3 m before the plank to 2 m past it in one tick, as without any sweep.
    assert!(passes(&ball_and_plank(false)));
    // A bullet is swept against the plank too: it stops at it and pushes it.
    let scene = ball_and_plank(true);
    assert!(!passes(&scene));
    let mut world = scene.build().expect("builds");
    for _ in 0..scene.ticks {
        world.step(&TickInput::default());
    }
    let plank = world
        .rigid()
        .expect("rigid bodies")
        .linear_velocity(Handle::new(0, 0))
        .expect("alive");
    assert!(plank.x > Fx::ONE, "the plank was pushed: {plank:?}");
    replays(&scene);
    restored_matches(&scene, &scene, 1);
    // The snapshot carries the flag: restored into the world of the scene without it, the
    // run goes on as a bullet's.
    restored_matches(&scene, &ball_and_plank(false), 1);
}

#[test]
fn a_box_sliding_fast_on_the_ground_is_not_held_back() {
    // A 20 cm box at 30 m/s along a static floor it rests on: fast (0.5 m per tick against
    // a 0.1 m core), but it starts within the slop of the floor, so only its core is swept,
    // which never meets the floor. Friction (μ g ≈ 6 m/s²) takes about 1 m/s in the 10
    // ticks: it covers about 4.9 m.
    let floor = slab(v(20.0, 0.5, 2.0), v(0.0, -0.5, 0.0)).fixed();
    let mut sled = slab(v(0.1, 0.1, 0.1), v(0.0, 0.1, 0.0));
    sled.velocity = v(30.0, 0.0, 0.0);
    let scene = scene_of(vec![floor, sled], 10);
    let last = *track(&scene, 1).last().expect("ticks");
    assert!(last[0] > 4.5, "{last:?}");
    assert!(last[1] > 0.09 && last[1] < 0.11, "{last:?}");
}

/// A 4 m × 4 m heightfield of 0.25 m cells with gentle bumps (up to 2 cm, so the box meets
/// faces, edges and corners), its surface at y = h(x, z) ∈ [0, 0.02] m.
fn bumpy_heightfield() -> BodyDesc<Fx> {
    let n = 17u32;
    let heights = (0..n * n)
        .map(|k| Fx::from_ratio(i64::from((k * 7) % 5), 200))
        .collect();
    let field =
        fixstep::rigid::HeightField::new(n, n, v(4.0, 1.0, 4.0), heights).expect("a valid grid");
    BodyDesc::new(Shape::HeightField { field }, Vec3::ZERO).fixed()
}

#[test]
fn a_fast_small_box_never_passes_a_heightfield() {
    let scene = box_onto(bumpy_heightfield());
    // The surface is at least 0 everywhere: the centre of a 2 cm box resting on it is at
    // y ≥ 0.01 − (rounding), and without the sweep it ends a tick up to 1.7 m below.
    for (tick, p) in track(&scene, 1).iter().enumerate() {
        assert!(p[1] > 0.0, "tick {tick}: the box's centre at y = {}", p[1]);
    }
    replays(&scene);
    restored_matches(&scene, &scene, 1);
}

#[test]
fn a_fast_ball_never_passes_a_thin_triangle_mesh_wall() {
    // A wall of two triangles across x = 0, 4 m square, facing −x (towards the ball).
    let corner = |y: f64, z: f64| v(0.0, y, z);
    let mesh = fixstep::rigid::TriMesh::new(
        vec![
            corner(-2.0, -2.0),
            corner(-2.0, 2.0),
            corner(2.0, 2.0),
            corner(2.0, -2.0),
        ],
        vec![[0, 1, 2], [0, 2, 3]],
    )
    .expect("a valid mesh");
    let wall = BodyDesc::new(Shape::TriMesh { mesh }, v(0.0, 1.0, 0.0)).fixed();
    let mut scene = scene_of(
        vec![wall, ball(0.05, v(-3.0, 1.2, 0.1), v(300.0, 0.0, 0.0))],
        20,
    );
    scene.gravity = Vec3::ZERO;
    for (tick, p) in track(&scene, 1).iter().enumerate() {
        assert!(p[0] < 0.0, "tick {tick}: the ball's centre at x = {}", p[0]);
    }
    replays(&scene);
}
