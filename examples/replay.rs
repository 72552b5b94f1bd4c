//! Record a replay, write it to a file, read it back and verify it bit for bit.
//!
//! Run it: `cargo run --example replay`
//!
//! A replay holds the scene, the inputs of every tick and checksums at checkpoints. Verifying
//! one simulates the scene again with those inputs and compares every checkpoint, so a
//! replay recorded on one machine checks the engine on any other. The file goes to the
//! system's temporary directory and is removed at the end.

use core::num::NonZeroU32;

use fixstep::math::{Fx, Real, Vec3};
use fixstep::replay::{Recorder, Replay, VerifyOutcome, verify, write_atomic};
use fixstep::scene::parse_scene;
use fixstep::world::{Command, PlayerInput, Target, TickInput};

/// Ten boxes stacked on the ground.
const STACK: &str = r#"(
    name: "replay_example",
    rigid: (
        bodies: [
            (kind: Static, shape: Plane(normal: (x: 0.0, y: 1.0, z: 0.0), offset: 0.0)),
            (
                shape: Box(half_extents: (x: 0.5, y: 0.5, z: 0.5)),
                position: (x: 0.0, y: 0.5, z: 0.0),
                grid: (count: (1, 10, 1), spacing: (x: 0.0, y: 1.0, z: 0.0)),
            ),
        ],
    ),
)"#;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let scene = parse_scene::<Fx>(STACK, "replay example")?;

    // Record 300 ticks with a checkpoint every 60 ticks (plus tick 0 and the last tick).
    let mut recorder = Recorder::new(&scene, NonZeroU32::new(60).expect("not zero"))?;
    let top_box = recorder
        .world()
        .rigid()
        .and_then(|rigid| rigid.handles().last())
        .expect("the stack has boxes");
    for tick in 0..300 {
        // At tick 120 a player knocks the top box sideways. Ticks without commands are
        // not stored: the recorder keeps only the inputs that did something.
        let mut input = TickInput::default();
        if tick == 120 {
            input.players.push(PlayerInput {
                player: 0,
                commands: vec![Command::ApplyImpulse {
                    target: Target::Body(top_box),
                    impulse: Vec3::new(Fx::from_int(3000), Fx::ZERO, Fx::ZERO),
                    point: None,
                }],
            });
        }
        recorder.step(&input);
    }
    let recorded = recorder.finish();
    println!(
        "recorded {} ticks, {} checkpoints, final checksum {:016x}",
        recorded.ticks(),
        recorded.checkpoints().len(),
        recorded.final_checksum()
    );

    // Write it. `write_atomic` writes a temporary file and renames it, so a crash never
    // leaves half a replay behind.
    let path = std::env::temp_dir().join(format!("fixstep-example-{}.replay", std::process::id()));
    let bytes = recorded.to_bytes()?;
    write_atomic(&path, &bytes)?;
    println!("wrote {} ({} bytes)", path.display(), bytes.len());

    // Read it back: the header, the content hashes, the format and the state version are
    // checked; a damaged or foreign file is an error naming the byte offset.
    let read = Replay::read(&path)?;
    std::fs::remove_file(&path)?;

    // Verify: simulate again and compare every checkpoint.
    match verify(&read)? {
        VerifyOutcome::Ok { ticks, checksum } => {
            println!("ok: {ticks} ticks, checksum {checksum:016x}");
            assert_eq!(checksum, recorded.final_checksum());
        }
        VerifyOutcome::Desync {
            tick,
            expected,
            got,
            part,
            first_differing_id,
        } => {
            // What a desync looks like: the tick, both checksums, the subsystem and the
            // first object that differs.
            return Err(format!(
                "desync at tick {tick}: expected {expected:016x}, got {got:016x} \
                 (part {part:?}, first differing object {first_differing_id:?})"
            )
            .into());
        }
    }
    Ok(())
}
