//! GGRS's determinism test on every built-in scene: a `SyncTestSession` rolls back
//! `CHECK_DISTANCE` frames on every frame, re-simulates them with the same (random bot)
//! inputs and compares the checksums of both simulations of every frame.
#![cfg(feature = "net")]

use fixstep_net::{Bot, NetInput, build_world, sync_test, tick_input};
use fixstep_scenes::{BUILTIN_SCENES, builtin_scene};

/// Frames rolled back and re-simulated on every frame.
const CHECK_DISTANCE: usize = 7;

/// Frames run per scene, unless its test names fewer.
const FRAMES: u32 = 300;

/// Bot players, each with its own input stream.
const PLAYERS: usize = 2;

/// Seed of the bots.
const BOT_SEED: u64 = 0x05ee_db07;

/// Runs the sync test on `name` for `frames` frames, then checks that its final state, after all the rollbacks,
/// is the state of a straight run with the same inputs.
fn sync_test_scene(name: &str, frames: u32) {
    let scene = builtin_scene(name).expect("a built-in scene");
    let checksum = sync_test(&scene, frames, CHECK_DISTANCE, PLAYERS, BOT_SEED)
        .unwrap_or_else(|message| panic!("{message}"));
    let mut world = build_world(&scene).expect("the scene builds");
    let bot = Bot::new(BOT_SEED, &world);
    for tick in 0..u64::from(frames) {
        let inputs: Vec<NetInput> = (0..PLAYERS as u8).map(|p| bot.input(p, tick)).collect();
        world.step(&tick_input(&scene, tick, &inputs));
    }
    assert_eq!(checksum, world.checksum().total, "{name}");
}

/// A scene's frame count: its test's own, or [`FRAMES`].
macro_rules! frames {
    () => {
        FRAMES
    };
    ($frames:expr) => {
        $frames
    };
}

macro_rules! sync_tests {
    ($($(#[$attribute:meta])* $name:ident $(: $frames:expr)?),* $(,)?) => {
        $(
            #[test]
            $(#[$attribute])*
            fn $name() {
                sync_test_scene(stringify!($name), frames!($($frames)?));
            }
        )*

        /// The scenes with a test above.
        const TESTED: &[&str] = &[$(stringify!($name)),*];
    };
}

sync_tests!(
    showcase,
    fountain,
    orbits,
    pyramid,
    stack,
    shooter,
    parkour,
    bullets,
    terrain,
    debris,
    flag,
    // 2.5 cm water and seven bodies at the fluid's substep rate, ~15 ms a step in release:
    // half a second (the crate sinking, the paddle's first stroke), re-simulated 8 times.
    harbour: 30,
    pond,
    // 4096 colliding balls: 300 frames × 8 simulations are 2400 steps of ~13 ms in release
    // (about a minute), several times that in the test profile. The release test run checks
    // it; the debug run skips it to keep the whole test command within its time budget.
    #[cfg_attr(debug_assertions, ignore = "heavy: checked by the release test run")]
    balls,
    falling,
    cradle,
    cradle_touching,
    incline,
    spinner,
    chain,
    bridge,
    ragdolls,
    top,
    wrecking_ball,
    falling_hinges,
    dam_break,
    tank,
    pour,
    cloth,
    curtain,
    rope,
    bridge_particles,
    jelly,
);

#[test]
fn every_builtin_scene_has_a_sync_test() {
    let builtin: Vec<&str> = BUILTIN_SCENES.iter().map(|(name, _)| *name).collect();
    assert_eq!(TESTED, builtin.as_slice());
}

/// The test has teeth: when every load leaves the state one ulp off, re-simulation gives
/// other checksums and GGRS reports the mismatch.
#[test]
fn an_inexact_restore_is_caught() {
    use fixstep_net::{FixstepConfig, fulfil, nudge_first_body};
    use ggrs::{GgrsError, GgrsRequest, SessionBuilder};

    let scene = builtin_scene("stack").expect("a built-in scene");
    let mut world = build_world(&scene).expect("the scene builds");
    let bot = Bot::new(BOT_SEED, &world);
    let mut session = SessionBuilder::<FixstepConfig>::new()
        .with_num_players(PLAYERS)
        .expect("players")
        .with_check_distance(CHECK_DISTANCE)
        .with_max_prediction_window(CHECK_DISTANCE + 1)
        .start_synctest_session()
        .expect("a sync test session");
    for frame in 0..FRAMES {
        for player in 0..PLAYERS {
            let input = bot.input(player as u8, u64::from(frame));
            session.add_local_input(player, input).expect("input");
        }
        let requests = match session.advance_frame() {
            Ok(requests) => requests,
            Err(GgrsError::MismatchedChecksum { .. }) => return,
            Err(other) => panic!("{other}"),
        };
        for request in requests {
            if let GgrsRequest::LoadGameState { cell, .. } = &request {
                world.restore(&cell.load().expect("a saved state"));
                assert!(nudge_first_body(&mut world));
            } else {
                fulfil(&scene, &mut world, vec![request], |_, _| Ok(()), |_| {})
                    .expect("the request is fulfilled");
            }
        }
    }
    panic!("{FRAMES} frames of inexact restores went unnoticed");
}
