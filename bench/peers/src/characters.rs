//! `characters`: 1000 kinematic characters walking among 10,000 static boxes, fixstep's
//! characters (`fixstep::character`) beside Rapier's `KinematicCharacterController` on the
//! same layout and the same inputs, the time per tick of each (issue [character]).
//!
//! The layout: a 100 × 100 grid of boxes 4 m apart on a floor (fixstep's a plane, Rapier's
//! a 400 m box whose top is y = 0), 1 m square, every third one 0.25 m tall (a step) and
//! the others 1.5 m (walls); 1000 capsules (radius 0.3 m, 1.6 m tall) standing between the
//! boxes, 8 m apart, each walking at 3 m/s in its own direction (k × the golden angle),
//! turned by 90° every second, so that they slide along walls, climb steps and meet
//! one another. Both controllers: 45° slope limit, 0.3 m step height, 0.3 m snap, 1 cm
//! skin (Rapier's offset), gravity −9.81 m/s², dt = 1/60 s. Rapier's characters are
//! kinematic position-based bodies with capsule colliders, so that they see one another;
//! a tick moves each with `move_shape` against the query pipeline (its own body
//! excluded), sets its next kinematic position and steps the world (which updates the
//! broad phase). Sleeping is on in both (nothing dynamic).
//!
//! The quality figure is the mean horizontal distance the characters covered (the same
//! walk for both: their work is comparable) and how many stand on ground at the end.

use crate::{median, time_steps};
use fixstep::character::{CharacterDesc, CharacterSettings};
use fixstep::math::{Fx, Real, Vec3};
use fixstep::rigid::{BodyDesc, RigidDesc, Shape};
use fixstep::world::{Command, Handle, PlayerInput, TickInput};
use rapier3d::control::{CharacterAutostep, CharacterLength, KinematicCharacterController};
use rapier3d::prelude::*;

/// Ticks per run.
const STEPS: u32 = 180;
const BOXES_PER_SIDE: usize = 100;
const CHARACTERS: usize = 1000;
const SPEED: f64 = 3.0;
const DT: f64 = 1.0 / 60.0;

/// Centre and half extents of box k (m).
fn static_box(k: usize) -> ([f64; 3], [f64; 3]) {
    let (i, j) = (k % BOXES_PER_SIDE, k / BOXES_PER_SIDE);
    let height = if (i + j) % 3 == 0 { 0.25 } else { 1.5 };
    let at = |n: usize| -198.0 + 4.0 * n as f64;
    ([at(i), height / 2.0, at(j)], [0.5, height / 2.0, 0.5])
}

/// Where character k starts: its centre, feet 1 cm above the floor (m).
fn start(k: usize) -> [f64; 3] {
    let (col, row) = (k % 50, k / 50);
    [-196.0 + 8.0 * col as f64, 0.81, -196.0 + 8.0 * row as f64]
}

/// Character k's walking velocity at `tick` (m/s, horizontal).
fn walking(k: usize, tick: u32) -> [f64; 3] {
    let golden = std::f64::consts::PI * (3.0 - 5f64.sqrt());
    let a = k as f64 * golden + f64::from(tick / 60) * std::f64::consts::FRAC_PI_2;
    [SPEED * a.cos(), 0.0, SPEED * a.sin()]
}

/// One run: ms per tick, mean horizontal distance covered (m), characters grounded.
pub struct CharacterRun {
    pub ms: f64,
    pub covered: f64,
    pub grounded: usize,
}

fn covered(ends: impl Iterator<Item = [f64; 3]>) -> f64 {
    let total: f64 = ends
        .enumerate()
        .map(|(k, e)| {
            let s = start(k);
            (e[0] - s[0]).hypot(e[2] - s[2])
        })
        .sum();
    total / CHARACTERS as f64
}

/// fixstep: a scene of the boxes and the characters; each tick one `MoveCharacter` per
/// character.
pub fn run_fixstep() -> CharacterRun {
    let v = |a: [f64; 3]| Vec3::<Fx>::from_f64(a[0], a[1], a[2]);
    let mut bodies = vec![
        BodyDesc::new(
            Shape::Plane {
                normal: Vec3::Y,
                offset: Fx::ZERO,
            },
            Vec3::ZERO,
        )
        .fixed(),
    ];
    for k in 0..BOXES_PER_SIDE * BOXES_PER_SIDE {
        let (centre, half) = static_box(k);
        bodies.push(
            BodyDesc::new(
                Shape::Box {
                    half_extents: v(half),
                },
                v(centre),
            )
            .fixed(),
        );
    }
    let settings = CharacterSettings::<Fx> {
        max_slope: Fx::from_f64(45f64.to_radians()),
        step_height: Fx::from_f64(0.3),
        snap_distance: Fx::from_f64(0.3),
        skin: Fx::from_f64(0.01),
        ..CharacterSettings::default()
    };
    let capsule = Shape::Capsule {
        radius: Fx::from_f64(0.3),
        half_height: Fx::from_f64(0.5),
    };
    let mut scene = fixstep::scene::Scene::empty("characters-bench");
    let mut rigid = RigidDesc {
        bodies,
        ..RigidDesc::default()
    };
    rigid.solver.sleeping = true;
    scene.rigid = Some(rigid);
    scene.characters = (0..CHARACTERS)
        .map(|k| {
            let mut c = CharacterDesc::new(capsule.clone(), v(start(k)));
            c.settings = settings;
            c
        })
        .collect();
    let mut world = scene.build().expect("the bench scene builds");
    let mut tick = 0;
    let ms = time_steps(STEPS, || {
        let commands = (0..CHARACTERS)
            .map(|k| Command::MoveCharacter {
                target: Handle::new(k as u32, 0),
                desired_velocity: v(walking(k, tick)),
                jump: false,
            })
            .collect();
        world.step(&TickInput {
            tick: world.tick(),
            players: vec![PlayerInput {
                player: 0,
                commands,
            }],
        });
        tick += 1;
    });
    let characters = world.characters().expect("characters").characters();
    CharacterRun {
        ms,
        covered: covered(characters.iter().map(|c| c.position.to_f64())),
        grounded: characters.iter().filter(|c| c.grounded).count(),
    }
}

/// Rapier: fixed boxes, kinematic capsules moved by one `KinematicCharacterController`.
pub fn run_rapier() -> CharacterRun {
    let mut world = PhysicsWorld {
        gravity: Vector::new(0.0, -9.81, 0.0),
        ..PhysicsWorld::default()
    };
    world.integration_parameters.dt = DT as f32;
    world.insert(
        RigidBodyBuilder::fixed().translation(Vector::new(0.0, -0.5, 0.0)),
        ColliderBuilder::cuboid(200.0, 0.5, 200.0),
    );
    for k in 0..BOXES_PER_SIDE * BOXES_PER_SIDE {
        let (c, h) = static_box(k);
        world.insert(
            RigidBodyBuilder::fixed().translation(Vector::new(
                c[0] as f32,
                c[1] as f32,
                c[2] as f32,
            )),
            ColliderBuilder::cuboid(h[0] as f32, h[1] as f32, h[2] as f32),
        );
    }
    let shape = Capsule::new_y(0.5, 0.3);
    let characters: Vec<RigidBodyHandle> = (0..CHARACTERS)
        .map(|k| {
            let s = start(k);
            let (body, _) = world.insert(
                RigidBodyBuilder::kinematic_position_based().translation(Vector::new(
                    s[0] as f32,
                    s[1] as f32,
                    s[2] as f32,
                )),
                ColliderBuilder::capsule_y(0.5, 0.3),
            );
            body
        })
        .collect();
    world.step();
    let controller = KinematicCharacterController {
        offset: CharacterLength::Absolute(0.01),
        autostep: Some(CharacterAutostep {
            max_height: CharacterLength::Absolute(0.3),
            min_width: CharacterLength::Absolute(0.2),
            include_dynamic_bodies: false,
        }),
        max_slope_climb_angle: 45f32.to_radians(),
        min_slope_slide_angle: 45f32.to_radians(),
        snap_to_ground: Some(CharacterLength::Absolute(0.3)),
        ..KinematicCharacterController::default()
    };
    let dt = DT as f32;
    let mut vertical = vec![0.0f32; CHARACTERS];
    let mut grounded = vec![false; CHARACTERS];
    let mut moves = Vec::with_capacity(CHARACTERS);
    let mut tick = 0;
    let ms = time_steps(STEPS, || {
        moves.clear();
        for (k, &body) in characters.iter().enumerate() {
            let w = walking(k, tick);
            vertical[k] = if grounded[k] {
                0.0
            } else {
                vertical[k] - 9.81 * dt
            };
            let desired = Vector::new(w[0] as f32 * dt, vertical[k] * dt, w[2] as f32 * dt);
            let pose = *world.bodies[body].position();
            let queries =
                world.query_pipeline_with_filter(QueryFilter::default().exclude_rigid_body(body));
            let moved = controller.move_shape(dt, &queries, &shape, &pose, desired, |_| {});
            grounded[k] = moved.grounded;
            moves.push(pose.translation + moved.translation);
        }
        for (&body, &to) in characters.iter().zip(&moves) {
            world.bodies[body].set_next_kinematic_translation(to);
        }
        world.step();
        tick += 1;
    });
    CharacterRun {
        ms,
        covered: covered(characters.iter().map(|&b| {
            let t = world.bodies[b].translation();
            [f64::from(t.x), f64::from(t.y), f64::from(t.z)]
        })),
        grounded: grounded.iter().filter(|&&g| g).count(),
    }
}

/// One engine's run of the bench.
type Runner = fn() -> CharacterRun;

/// The table: each engine's median ms per tick over `rounds` interleaved runs.
pub fn table(rounds: usize, rapier: &str) {
    let engines: [(&str, Runner); 2] = [
        ("fixstep I32F32 characters", run_fixstep),
        ("KinematicCharacterController", run_rapier),
    ];
    let mut times = vec![Vec::new(); engines.len()];
    let mut last = Vec::new();
    for _ in 0..rounds {
        last.clear();
        for ((_, run), times) in engines.iter().zip(&mut times) {
            let r = run();
            times.push(r.ms);
            last.push(r);
        }
    }
    let medians: Vec<f64> = times.iter_mut().map(|t| median(t)).collect();
    println!();
    println!(
        "| scene | ticks | engine | ms/tick (median of {rounds}) | vs fixstep I32F32 | quality |"
    );
    println!("|---|---|---|---|---|---|");
    for (((name, _), m), r) in engines.iter().zip(&medians).zip(&last) {
        let name = if name.starts_with("Kinematic") {
            format!("{rapier} {name}")
        } else {
            (*name).to_string()
        };
        println!(
            "| `characters` ({CHARACTERS} among {} boxes) | {STEPS} | {name} | {m:.3} | {:.2}× | covered {:.2} m, {} grounded |",
            BOXES_PER_SIDE * BOXES_PER_SIDE,
            m / medians[0],
            r.covered,
            r.grounded
        );
    }
}
