//! A game loop around a fixstep world: a fixed-timestep accumulator, player inputs turned
//! into commands once per tick, and rendering that interpolates between the last two ticks.
//!
//! Run it: `cargo run --example step_loop`
//!
//! The simulation only ever advances in whole ticks (1/60 s here). The frame time of the
//! game goes into the accumulator ([`FixedTimestep`]), never into the world, so every
//! machine that is fed the same inputs runs the same ticks and ends on the same checksum.

use std::time::Duration;

use fixstep::math::{Fx, Real, Vec3};
use fixstep::scene::parse_scene;
use fixstep::world::{Command, FixedTimestep, Handle, PlayerInput, Target, TickInput, World};

/// The level: a ground plane, the player's box (body 1) and a stack of three crates to
/// push into. A game would load this from a file with `fixstep::scene::load_scene_file`.
const LEVEL: &str = r#"(
    name: "step_loop",
    tick_rate: 60,
    rigid: (
        bodies: [
            (kind: Static, shape: Plane(normal: (x: 0.0, y: 1.0, z: 0.0), offset: 0.0)),
            (shape: Box(half_extents: (x: 0.5, y: 0.5, z: 0.5)), position: (x: -4.0, y: 0.5, z: 0.0)),
            (
                shape: Box(half_extents: (x: 0.5, y: 0.5, z: 0.5)),
                position: (x: 0.0, y: 0.5, z: 0.0),
                grid: (count: (1, 3, 1), spacing: (x: 0.0, y: 1.0, z: 0.0)),
            ),
        ],
    ),
)"#;

/// What the keyboard said during one frame (a stand-in for a real input system).
#[derive(Clone, Copy, Default)]
struct Keys {
    right: bool,
    jump: bool,
}

/// Turns the keys held during a tick into that tick's commands for player 0. Inputs are
/// sampled per tick, not per frame: a frame that runs two ticks sends the keys twice.
fn commands_for(keys: Keys, player_box: Handle) -> TickInput<Fx> {
    let mut commands = Vec::new();
    if keys.right {
        // 12 000 N to the right for this tick only (a force lasts one tick). The box weighs
        // 1000 kg and friction holds it with up to 0.6 · 9.81 · 1000 ≈ 5900 N.
        commands.push(Command::ApplyForce {
            target: Target::Body(player_box),
            force: Vec3::new(Fx::from_int(12_000), Fx::ZERO, Fx::ZERO),
            point: None,
        });
    }
    if keys.jump {
        // An impulse changes the velocity at once: 5000 N·s on a 1000 kg box is 5 m/s up.
        commands.push(Command::ApplyImpulse {
            target: Target::Body(player_box),
            impulse: Vec3::new(Fx::ZERO, Fx::from_int(5000), Fx::ZERO),
            point: None,
        });
    }
    TickInput {
        tick: 0, // filled in by the loop with the world's tick
        players: vec![PlayerInput {
            player: 0,
            commands,
        }],
    }
}

/// A body's position as floats, for drawing only (never fed back into the world).
fn position_f64(world: &World<Fx>, body: Handle) -> [f64; 3] {
    world
        .rigid()
        .and_then(|rigid| rigid.position(body))
        .map(|p| p.to_f64())
        .unwrap_or([0.0; 3])
}

fn main() {
    let scene = parse_scene::<Fx>(LEVEL, "step_loop level").expect("the level parses");
    let mut world = scene.build().expect("the level builds");

    // Bodies get handles in scene order: the plane is the first, the player's box the second.
    let player_box = world
        .rigid()
        .and_then(|rigid| rigid.handles().nth(1))
        .expect("the level has a player box");

    // 60 ticks a second; after a long stall run at most 5 ticks in one frame and drop the rest.
    let mut clock = FixedTimestep::new(scene.tick_rate, 5);

    // The renderer keeps the player box's pose at the last two ticks.
    let mut previous = position_f64(&world, player_box);
    let mut current = previous;

    // Frame times a real game would measure with `Instant::now()`: a 144 Hz, a 60 Hz and a
    // 30 Hz stretch, and one 200 ms hitch. They are fixed here so the example always prints
    // the same lines.
    let mut frames = Vec::new();
    frames.extend([Duration::from_micros(6_944); 90]);
    frames.extend([Duration::from_micros(16_667); 60]);
    frames.push(Duration::from_millis(200));
    frames.extend([Duration::from_micros(33_333); 30]);

    for (frame, frame_time) in frames.into_iter().enumerate() {
        // Input for this frame: hold right for the first second, jump at frame 100.
        let keys = Keys {
            right: world.tick() < 60,
            jump: frame == 100,
        };

        // Run as many whole ticks as the accumulated time allows.
        let ticks = clock.advance(frame_time);
        for _ in 0..ticks {
            let mut input = commands_for(keys, player_box);
            input.tick = world.tick();
            let report = world.step(&input);
            assert_eq!(report.ignored_commands, 0, "the player box exists");
            previous = current;
            current = position_f64(&world, player_box);
        }

        // Draw the state `alpha` of the way from the previous tick to the current one, so
        // motion looks smooth whatever the frame rate.
        let alpha = clock.alpha();
        let drawn: Vec<f64> = (0..3)
            .map(|i| previous[i] + (current[i] - previous[i]) * alpha)
            .collect();
        if frame % 30 == 0 || ticks > 2 {
            println!(
                "frame {frame:3}: {ticks} tick(s), world tick {:3}, alpha {alpha:.2}, player box drawn at ({:6.3}, {:6.3}, {:6.3})",
                world.tick(),
                drawn[0],
                drawn[1],
                drawn[2],
            );
        }
    }

    // The checksum is what peers compare and replays record: the same inputs on the same
    // ticks give these bits on every machine.
    println!(
        "after {} ticks: checksum {:016x}",
        world.tick(),
        world.checksum().total
    );
}
