//! GGRS's determinism test: roll back and re-simulate every frame, compare checksums.

use ggrs::{GgrsError, SessionBuilder};

use super::bot::Bot;
use super::config::FixstepConfig;
use super::requests::fulfil;
use super::scene_world::build_world;
use fixstep::math::Fx;
use fixstep::scene::Scene;

/// Runs `frames` frames of `scene` in a GGRS `SyncTestSession` with `players` bot players
/// (seed `bot_seed`): every frame, GGRS saves the state, advances, loads the state from
/// `check_distance` frames back, re-simulates to the present and compares the checksums of
/// the first and second simulation of every frame in the window. Returns the final world
/// checksum, or the first mismatch.
pub fn sync_test(
    scene: &Scene<Fx>,
    frames: u32,
    check_distance: usize,
    players: usize,
    bot_seed: u64,
) -> Result<u64, String> {
    if !(1..=usize::from(u8::MAX)).contains(&players) {
        return Err(format!("{players} players: a sync test has 1 to 255"));
    }
    let mut world = build_world(scene)?;
    let bot = Bot::new(bot_seed, &world);
    let mut session = SessionBuilder::<FixstepConfig>::new()
        .with_num_players(players)
        .and_then(|b| {
            b.with_check_distance(check_distance)
                .with_max_prediction_window(check_distance + 1)
                .start_synctest_session()
        })
        .map_err(|e| format!("cannot start the sync test: {e}"))?;
    for frame in 0..frames {
        for player in 0..players {
            let tick = u64::from(frame);
            let input = bot.input(u8::try_from(player).unwrap_or(u8::MAX), tick);
            session
                .add_local_input(player, input)
                .map_err(|e| format!("frame {frame}: {e}"))?;
        }
        let requests = session.advance_frame().map_err(|e| match e {
            GgrsError::MismatchedChecksum {
                current_frame,
                mismatched_frames,
            } => format!(
                "{}: not deterministic: at frame {current_frame}, re-simulating frames \
                 {mismatched_frames:?} gave other checksums",
                scene.name
            ),
            other => format!("frame {frame}: {other}"),
        })?;
        fulfil(scene, &mut world, requests, |_, _| Ok(()), |_| {})?;
    }
    Ok(world.checksum().total)
}
