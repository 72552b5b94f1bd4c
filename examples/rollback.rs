//! Rollback, as a networked game does it: run ahead on guessed inputs, and when the real
//! inputs arrive, restore the last confirmed snapshot and simulate again.
//!
//! Run it: `cargo run --example rollback`
//!
//! Because the world is deterministic and a snapshot holds its complete state, the world
//! that rolled back ends on exactly the checksum of a world that was given the real inputs
//! from the start; the example asserts it.

use fixstep::math::{Fx, Real, Vec3};
use fixstep::replay::scene_id;
use fixstep::scene::parse_scene;
use fixstep::world::{
    Command, Handle, PlayerInput, Target, TickInput, World, decode_snapshot, encode_snapshot,
};

/// Two players, each with a ball on the ground.
const ARENA: &str = r#"(
    name: "rollback",
    rigid: (
        bodies: [
            (kind: Static, shape: Plane(normal: (x: 0.0, y: 1.0, z: 0.0), offset: 0.0)),
            (shape: Sphere(radius: 0.5), position: (x: -2.0, y: 0.5, z: 0.0)),
            (shape: Sphere(radius: 0.5), position: (x: 2.0, y: 0.5, z: 0.0)),
        ],
    ),
)"#;

const TICKS: u64 = 120;

/// Player `player`'s real input at `tick`: both kick their ball now and then, in different
/// directions. In a game these arrive over the network, late.
fn real_input(player: u8, tick: u64, ball: Handle) -> Vec<Command<Fx>> {
    let kick = match (player, tick % 40) {
        (0, 10) => Some(Vec3::new(Fx::from_int(300), Fx::from_int(200), Fx::ZERO)),
        (1, 25) => Some(Vec3::new(-Fx::from_int(300), Fx::ZERO, Fx::from_int(100))),
        _ => None,
    };
    kick.map(|impulse| Command::ApplyImpulse {
        target: Target::Body(ball),
        impulse,
        point: None,
    })
    .into_iter()
    .collect()
}

/// A tick's input from both players' commands.
fn tick_input(tick: u64, commands: [Vec<Command<Fx>>; 2]) -> TickInput<Fx> {
    let [first, second] = commands;
    TickInput {
        tick,
        players: vec![
            PlayerInput {
                player: 0,
                commands: first,
            },
            PlayerInput {
                player: 1,
                commands: second,
            },
        ],
    }
}

fn main() {
    let scene = parse_scene::<Fx>(ARENA, "rollback arena").expect("the arena parses");
    let balls: Vec<Handle> = {
        let world = scene.build().expect("the arena builds");
        world
            .rigid()
            .expect("rigid bodies")
            .handles()
            .skip(1)
            .collect()
    };
    let real = |tick: u64| {
        tick_input(
            tick,
            [real_input(0, tick, balls[0]), real_input(1, tick, balls[1])],
        )
    };

    // The reference: one world given every real input on time.
    let mut straight: World<Fx> = scene.build().expect("the arena builds");
    for tick in 0..TICKS {
        straight.step(&real(tick));
    }

    // Player 0's machine. It knows its own input at once; player 1's input reaches it
    // `DELAY` ticks late, so it predicts it (here: "no command", the usual guess is "the
    // same as last tick") and corrects itself when the real one comes.
    const DELAY: u64 = 6;
    let mut world: World<Fx> = scene.build().expect("the arena builds");
    let mut confirmed = world.snapshot(); // the state at the last tick with every real input
    let mut confirmed_tick = 0;
    let mut rollbacks = 0;

    for tick in 0..TICKS {
        // Player 1's inputs up to `tick - DELAY` have arrived. If any of them differs from
        // what was predicted, roll back: restore the confirmed state and simulate again
        // with the real inputs, up to the newest confirmed tick.
        let arrived_up_to = (tick + 1).saturating_sub(DELAY);
        if arrived_up_to > confirmed_tick {
            let mispredicted =
                (confirmed_tick..arrived_up_to).any(|t| !real_input(1, t, balls[1]).is_empty());
            if mispredicted {
                rollbacks += 1;
            }
            // Either way the state at `arrived_up_to` is now final: rebuild it from the last
            // confirmed snapshot with real inputs only. (A game skips this when every
            // prediction was right; it is done always here to keep the example short.)
            world.restore(&confirmed);
            for t in confirmed_tick..arrived_up_to {
                world.step(&real(t));
            }
            confirmed = world.snapshot();
            confirmed_tick = arrived_up_to;
            // Then predict again from there up to the present.
            for t in confirmed_tick..tick {
                world.step(&tick_input(t, [real_input(0, t, balls[0]), Vec::new()]));
            }
        }
        // This tick: own input known, the other player's guessed.
        world.step(&tick_input(
            tick,
            [real_input(0, tick, balls[0]), Vec::new()],
        ));
    }

    // The last inputs arrive after the game ends: settle the remaining ticks.
    world.restore(&confirmed);
    for t in confirmed_tick..TICKS {
        world.step(&real(t));
    }

    // A snapshot can also leave the process (save games, late joiners, bug reports): encode
    // it to bytes, decode it, and it restores the same state.
    // The file names its scene, so that it is never restored into another one.
    let id = scene_id(&scene).expect("the arena encodes");
    let bytes = encode_snapshot(&world.snapshot(), &id).expect("the state encodes");
    let decoded = decode_snapshot::<Fx>(&bytes).expect("the bytes decode");
    decoded
        .scene
        .check_same(&id)
        .expect("the arena's own snapshot");
    let mut copy = scene.build().expect("the arena builds");
    copy.restore(&decoded.state);

    let expected = straight.checksum().total;
    let got = world.checksum().total;
    println!("{rollbacks} rollbacks over {TICKS} ticks");
    println!("straight run:      {expected:016x}");
    println!("with rollbacks:    {got:016x}");
    println!(
        "snapshot restored: {:016x} ({} bytes)",
        copy.checksum().total,
        bytes.len()
    );
    assert_eq!(
        got, expected,
        "rollback must end on the straight run's bits"
    );
    assert_eq!(copy.checksum().total, expected);
}
