//! Verification: simulate a replay again and compare every checkpoint.

use super::feed::InputFeed;
use super::file::Replay;
use super::format::Checkpoint;
use super::record::build_world;
use crate::scene::SceneError;
use crate::world::{Checksum, ObjectDigests, Part, World};

/// The result of re-simulating a replay.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum VerifyOutcome {
    /// Every checkpoint matched.
    Ok {
        /// Ticks simulated.
        ticks: u64,
        /// The final world checksum.
        checksum: u64,
    },
    /// The first checkpoint that did not match.
    Desync {
        /// The checkpoint's tick.
        tick: u64,
        /// The recorded world checksum.
        expected: u64,
        /// The world checksum this build computed.
        got: u64,
        /// The first part whose sub-checksum differs, when one does.
        part: Option<Part>,
        /// The first object whose recorded digest differs, such as `2v0` (slot 2,
        /// generation 0); `None` when every object matches and the difference lies in
        /// shared state (settings, RNG, emitters) or in the recorded checksums themselves.
        first_differing_id: Option<String>,
    },
}

/// Simulates the replay's scene with its inputs and compares the world's checksum (total
/// and every part) at each checkpoint; stops at the first difference.
pub fn verify(replay: &Replay) -> Result<VerifyOutcome, SceneError> {
    verify_with_progress(replay, |_| {})
}

/// [`verify`](fn@verify), calling `on_tick` with the number of ticks simulated after each
/// tick (to show progress; it cannot change the outcome).
pub fn verify_with_progress(
    replay: &Replay,
    mut on_tick: impl FnMut(u64),
) -> Result<VerifyOutcome, SceneError> {
    let mut world = build_world(replay.scene())?;
    Ok(verify_world(replay, &mut world, &mut on_tick))
}

/// [`verify`](fn@verify) with the world stepping on `threads` threads
/// ([`World::set_threads`]; 0: every core): the outcome is the same at any count.
pub fn verify_on_threads(replay: &Replay, threads: usize) -> Result<VerifyOutcome, SceneError> {
    let mut world = build_world(replay.scene())?;
    world.set_threads(threads);
    Ok(verify_world(replay, &mut world, &mut |_| {}))
}

/// [`verify_with_progress`] with the divergence check on (sampled every
/// `divergence_every` ticks), returning the world as it stopped as well, so that a driver
/// can report what it has to warn about, as it would for a run ([`World::warnings`],
/// [`World::health`]).
pub fn verify_reporting(
    replay: &Replay,
    divergence_every: u64,
    mut on_tick: impl FnMut(u64),
) -> Result<(VerifyOutcome, World), SceneError> {
    let mut world = build_world(replay.scene())?;
    world.enable_divergence_check(divergence_every);
    let outcome = verify_world(replay, &mut world, &mut on_tick);
    Ok((outcome, world))
}

/// Steps `world` (built from the replay's scene) through the replay's inputs, comparing
/// each checkpoint and calling `on_tick` with the ticks simulated after each tick.
fn verify_world(
    replay: &Replay,
    world: &mut World,
    on_tick: &mut impl FnMut(u64),
) -> VerifyOutcome {
    let mut feed = InputFeed::new(replay.inputs());
    for checkpoint in replay.checkpoints() {
        while world.tick() < checkpoint.tick {
            let tick = world.tick();
            world.step(feed.at(tick));
            on_tick(world.tick());
        }
        let got = world.checksum();
        let objects = world.object_digests();
        if !matches(checkpoint, &got, &objects) {
            return desync(checkpoint, &got, &objects);
        }
    }
    VerifyOutcome::Ok {
        ticks: world.tick(),
        checksum: world.checksum().total,
    }
}

fn matches(expected: &Checkpoint, got: &Checksum, objects: &ObjectDigests) -> bool {
    expected.tick == got.tick
        && expected.total == got.total
        && expected.parts == got.parts
        && expected.objects == *objects
}

fn desync(expected: &Checkpoint, got: &Checksum, objects: &ObjectDigests) -> VerifyOutcome {
    let recorded = Checksum {
        tick: expected.tick,
        total: expected.total,
        parts: expected.parts.clone(),
    };
    VerifyOutcome::Desync {
        tick: expected.tick,
        expected: expected.total,
        got: got.total,
        part: recorded.first_differing_part(got),
        first_differing_id: expected
            .first_differing_object(objects)
            .map(|(_, id)| id.to_string()),
    }
}
