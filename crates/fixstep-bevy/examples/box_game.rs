//! Two players push crates, over bevy_ggrs on 127.0.0.1.
//!
//! ```sh
//! # Both peers in this process, bots playing, no window: prints each peer's checksum.
//! cargo run --release -p fixstep-bevy --example box_game -- --headless --ticks 600 --record box.replay
//! fixstep verify box.replay
//! # GGRS's sync test (roll back 7 frames every frame):
//! cargo run --release -p fixstep-bevy --example box_game -- --headless --ticks 300 --synctest
//! ```
//!
//! With `--features render` and without `--headless`, the same in-process pair runs in a
//! window showing peer 0's world (boxes and balls, interpolated).

use std::process::ExitCode;
use std::time::Duration;

use fixstep::world::checksum::hex;
use fixstep_bevy::FixstepWorld;
use fixstep_bevy::box_game::{headless_app, run_loopback_pair, sync_test_session};

struct Args {
    headless: bool,
    ticks: u64,
    record: Option<String>,
    synctest: bool,
    cycle: Option<u64>,
    seed: u64,
}

const USAGE: &str = "usage: box_game [--headless] [--ticks N] [--record FILE] [--synctest] \
                     [--cycle EVERY] [--seed S]";

fn parse_args() -> Result<Args, String> {
    let mut args = Args {
        headless: false,
        ticks: 600,
        record: None,
        synctest: false,
        cycle: None,
        seed: 7,
    };
    let mut it = std::env::args().skip(1);
    while let Some(arg) = it.next() {
        let mut value = |name: &str| it.next().ok_or_else(|| format!("{name} needs a value"));
        let number = |name: &str, v: String| {
            v.parse::<u64>()
                .map_err(|_| format!("{name}: `{v}` is not a whole number"))
        };
        match arg.as_str() {
            "--headless" => args.headless = true,
            "--synctest" => args.synctest = true,
            "--ticks" => args.ticks = number("--ticks", value("--ticks")?)?,
            "--seed" => args.seed = number("--seed", value("--seed")?)?,
            "--cycle" => args.cycle = Some(number("--cycle", value("--cycle")?)?.max(2)),
            "--record" => args.record = Some(value("--record")?),
            other => return Err(format!("unknown argument `{other}`")),
        }
    }
    if args.ticks == 0 || args.ticks > 1_000_000 {
        return Err(format!(
            "--ticks: {} is not within 1 to 1000000",
            args.ticks
        ));
    }
    Ok(args)
}

fn main() -> ExitCode {
    let args = match parse_args() {
        Ok(a) => a,
        Err(e) => {
            eprintln!("box_game: {e}\n{USAGE}");
            return ExitCode::from(2);
        }
    };
    if !args.headless {
        return window(&args);
    }
    let result = if args.synctest {
        sync_test(&args)
    } else {
        pair(&args)
    };
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("box_game: {e}");
            ExitCode::FAILURE
        }
    }
}

fn pair(args: &Args) -> Result<(), String> {
    let updates =
        u32::try_from(args.ticks.saturating_mul(4).saturating_add(600)).unwrap_or(u32::MAX);
    let outcome = run_loopback_pair(
        args.ticks,
        args.seed,
        args.cycle,
        updates,
        Duration::from_secs(600),
    )?;
    println!(
        "peer 0: checksum {} ({} rollbacks)",
        hex(outcome.checksums[0]),
        outcome.rollbacks[0]
    );
    println!(
        "peer 1: checksum {} ({} rollbacks)",
        hex(outcome.checksums[1]),
        outcome.rollbacks[1]
    );
    if let Some(path) = &args.record {
        let bytes = outcome.replay.to_bytes().map_err(|e| e.to_string())?;
        fixstep::replay::write_atomic(std::path::Path::new(path), &bytes)
            .map_err(|e| format!("{path}: {e}"))?;
        println!("recorded {path}");
    }
    if outcome.checksums[0] != outcome.checksums[1] {
        return Err("the peers disagree".to_owned());
    }
    println!("checksum: {}", hex(outcome.checksums[0]));
    Ok(())
}

fn sync_test(args: &Args) -> Result<(), String> {
    use bevy::prelude::*;
    #[derive(Resource, Default)]
    struct Mismatches(Vec<String>);
    let session = sync_test_session(7).map_err(|e| e.to_string())?;
    let mut app = headless_app(session, args.seed, args.ticks, args.cycle);
    app.init_resource::<Mismatches>().add_observer(
        |m: On<bevy_ggrs::SyncTestMismatch>, mut all: ResMut<Mismatches>| {
            all.0.push(format!(
                "frame {}: frames {:?}",
                m.event().current_frame,
                m.event().mismatched_frames
            ));
        },
    );
    for _ in 0..args.ticks {
        app.update();
    }
    let mismatches = &app.world().resource::<Mismatches>().0;
    if let Some(first) = mismatches.first() {
        return Err(format!("the sync test failed at {first}"));
    }
    let world = app.world().resource::<FixstepWorld>();
    println!(
        "sync test passed: {} ticks, check distance 7",
        world.world().tick()
    );
    println!("checksum: {}", hex(world.checksum()));
    Ok(())
}

#[cfg(not(feature = "render"))]
fn window(_args: &Args) -> ExitCode {
    eprintln!("box_game: a window needs `--features render`; use --headless without it");
    ExitCode::from(2)
}

#[cfg(feature = "render")]
fn window(args: &Args) -> ExitCode {
    render::run(args.seed)
}

#[cfg(feature = "render")]
mod render {
    //! The windowed game: GGRS's sync test session with two local players, player 0 on the
    //! arrow keys and player 1 the bot, so that every frame is also rolled back.

    use std::process::ExitCode;

    use bevy::prelude::*;
    use bevy_ggrs::{LocalInputs, LocalPlayers};
    use fixstep::math::Real;
    use fixstep::rigid::Shape;
    use fixstep_bevy::box_game::{
        BotFrame, BotSeed, BoxConfig, ChecksumAt, DOWN, LEFT, RIGHT, UP, apply_inputs, bot_input,
        scene, setup, sync_test_session,
    };
    use fixstep_bevy::{Collider, FixstepPlugin, FixstepSystems};

    pub fn run(seed: u64) -> ExitCode {
        let session = match sync_test_session(7) {
            Ok(s) => s,
            Err(e) => {
                eprintln!("box_game: {e}");
                return ExitCode::FAILURE;
            }
        };
        App::new()
            .add_plugins(DefaultPlugins)
            .add_plugins(bevy_ggrs::GgrsPlugin::<BoxConfig>::default())
            .add_plugins(FixstepPlugin::ggrs(scene()))
            .insert_resource(session)
            .insert_resource(BotSeed(seed))
            .init_resource::<BotFrame>()
            .insert_resource(ChecksumAt {
                tick: u64::MAX,
                checksum: None,
            })
            .add_systems(Startup, (setup, camera))
            .add_systems(bevy_ggrs::ReadInputs, read_inputs)
            .add_systems(
                bevy_ggrs::GgrsSchedule,
                apply_inputs.before(FixstepSystems::Step),
            )
            .add_systems(Update, dress)
            .run();
        ExitCode::SUCCESS
    }

    /// Player 0 from the arrow keys, player 1 from the bot.
    fn read_inputs(
        mut commands: Commands,
        keys: Res<ButtonInput<KeyCode>>,
        local: Res<LocalPlayers>,
        seed: Res<BotSeed>,
        mut frame: ResMut<BotFrame>,
    ) {
        let mut keyboard = 0;
        for (key, bit) in [
            (KeyCode::ArrowUp, UP),
            (KeyCode::ArrowDown, DOWN),
            (KeyCode::ArrowLeft, LEFT),
            (KeyCode::ArrowRight, RIGHT),
        ] {
            if keys.pressed(key) {
                keyboard |= bit;
            }
        }
        let inputs = local
            .0
            .iter()
            .map(|&h| {
                let input = if h == 0 {
                    keyboard
                } else {
                    bot_input(seed.0, 1, frame.0)
                };
                (h, input)
            })
            .collect();
        frame.0 += 1;
        commands.insert_resource(LocalInputs::<BoxConfig>(inputs));
    }

    fn camera(mut commands: Commands) {
        commands.spawn((
            Camera3d::default(),
            Transform::from_xyz(0.0, 6.0, 8.0).looking_at(Vec3::ZERO, Vec3::Y),
        ));
        commands.spawn((
            DirectionalLight::default(),
            Transform::from_xyz(3.0, 8.0, 4.0).looking_at(Vec3::ZERO, Vec3::Y),
        ));
    }

    /// Gives every new collider a mesh (render only, floats).
    fn dress(
        mut commands: Commands,
        new: Query<(Entity, &Collider), Without<Mesh3d>>,
        mut meshes: ResMut<Assets<Mesh>>,
        mut materials: ResMut<Assets<StandardMaterial>>,
    ) {
        for (entity, Collider(shape)) in &new {
            let mesh = match shape {
                Shape::Box { half_extents } => {
                    let [x, y, z] = half_extents.to_f64();
                    Mesh::from(Cuboid::new(2.0 * x as f32, 2.0 * y as f32, 2.0 * z as f32))
                }
                Shape::Sphere { radius } => Mesh::from(Sphere::new(radius.to_f64() as f32)),
                _ => Plane3d::default().mesh().size(12.0, 12.0).build(),
            };
            commands.entity(entity).insert((
                Mesh3d(meshes.add(mesh)),
                MeshMaterial3d(materials.add(Color::srgb(0.7, 0.6, 0.4))),
            ));
        }
    }
}
