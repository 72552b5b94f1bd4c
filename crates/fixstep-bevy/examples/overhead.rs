//! The plugin's overhead against the raw engine on the built-in scene `balls` (4096 balls in
//! a box): one world stepped by `World::step`, the same world built from entities and
//! stepped by `FixstepPlugin` in Bevy's `FixedUpdate` (queue, step, link, pose copy into
//! `FixedTransform` and `RenderPose` for 4096 entities). Both advance in lockstep, in
//! alternating blocks of ticks, and must end on the same checksum.
//!
//! ```sh
//! cargo run --release -p fixstep-bevy --example overhead -- --ticks 200
//! ```

use std::process::ExitCode;
use std::time::{Duration, Instant};

use bevy::prelude::*;
use fixstep::math::{Fx, Real, Vec3 as FxVec3};
use fixstep::world::TickInput;
use fixstep_bevy::{Collider, FixedTransform, FixstepPlugin, FixstepWorld, RigidBody};

const BLOCK: u64 = 10;

fn main() -> ExitCode {
    let mut ticks = 200u64;
    let mut args = std::env::args().skip(1);
    while let Some(arg) = args.next() {
        match (arg.as_str(), args.next().map(|v| v.parse::<u64>())) {
            ("--ticks", Some(Ok(n))) if (BLOCK..=100_000).contains(&n) => ticks = n,
            _ => {
                eprintln!("usage: overhead [--ticks N]  (N from {BLOCK} to 100000)");
                return ExitCode::from(2);
            }
        }
    }
    let scene = fixstep_scenes::builtin_scene::<Fx>("balls").expect("balls is built in");
    let mut raw = scene.build().expect("balls builds");

    // The same scene for the plugin: the walls stay in the scene, every ball of the grid
    // becomes an entity, in the grid's order (x fastest, then y, then z).
    let mut base = scene.clone();
    let rigid = base.rigid.as_mut().expect("balls has bodies");
    let grid_body = rigid.bodies.pop().expect("the grid of balls");
    let grid = grid_body.grid.expect("balls are a grid");
    let mut app = App::new();
    app.add_plugins(MinimalPlugins)
        .add_plugins(FixstepPlugin::new(base));
    let (nx, ny, nz) = grid.count;
    let mut balls = Vec::new();
    for k in 0..nz {
        for j in 0..ny {
            for i in 0..nx {
                // As the engine expands a grid: spacing × index, per axis.
                let at = |n: u32, s: Fx| s * Fx::from_int(n as i32);
                let position = grid_body.position
                    + FxVec3::new(
                        at(i, grid.spacing.x),
                        at(j, grid.spacing.y),
                        at(k, grid.spacing.z),
                    );
                let body = RigidBody {
                    kind: grid_body.kind,
                    density: grid_body.density,
                    material: grid_body.material,
                    linear_damping: grid_body.linear_damping,
                    angular_damping: grid_body.angular_damping,
                    filter: grid_body.filter,
                    sensor: grid_body.sensor,
                    bullet: grid_body.bullet,
                };
                balls.push((
                    body,
                    Collider(grid_body.shape.clone()),
                    FixedTransform {
                        position,
                        orientation: grid_body.orientation,
                    },
                ));
            }
        }
    }
    app.world_mut().spawn_batch(balls);
    // Startup and PostStartup (the world is built); no fixed tick has run yet.
    app.update();
    assert_eq!(app.world().resource::<FixstepWorld>().world().tick(), 0);

    let input = TickInput::default();
    let (mut raw_time, mut plugin_time) = (Duration::ZERO, Duration::ZERO);
    let mut done = 0;
    while done < ticks {
        let start = Instant::now();
        for _ in 0..BLOCK {
            raw.step(&input);
        }
        raw_time += start.elapsed();
        let start = Instant::now();
        for _ in 0..BLOCK {
            app.world_mut().run_schedule(FixedUpdate);
        }
        plugin_time += start.elapsed();
        done += BLOCK;
    }
    let plugin_world = app.world().resource::<FixstepWorld>();
    let (a, b) = (raw.checksum().total, plugin_world.checksum());
    let per_tick = |d: Duration| d.as_secs_f64() * 1e3 / done as f64;
    println!(
        "balls, {done} ticks, {} bodies",
        raw.rigid().map_or(0, |r| r.body_count())
    );
    println!("raw engine:  {:.3} ms/tick", per_tick(raw_time));
    println!("with plugin: {:.3} ms/tick", per_tick(plugin_time));
    println!(
        "overhead:    {:+.2} %",
        100.0 * (plugin_time.as_secs_f64() / raw_time.as_secs_f64() - 1.0)
    );
    if a != b {
        eprintln!(
            "overhead: the plugin's world differs: {} vs {}",
            fixstep::world::checksum::hex(a),
            fixstep::world::checksum::hex(b)
        );
        return ExitCode::FAILURE;
    }
    println!("same checksum: {}", fixstep::world::checksum::hex(a));
    ExitCode::SUCCESS
}
