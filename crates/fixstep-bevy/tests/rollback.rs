//! The plugin under bevy_ggrs: two apps as P2P peers on 127.0.0.1, GGRS's sync test, and
//! run-time spawns and despawns under rollback. Every loop is bounded in iterations and in
//! wall time; sockets bind 127.0.0.1 only.

use std::time::{Duration, Instant};

use bevy::prelude::*;
use bevy_ggrs::SyncTestMismatch;
use fixstep::replay::{Replay, VerifyOutcome, verify};
use fixstep_bevy::box_game::{
    Crate, PairOutcome, headless_app, run_loopback_pair, sync_test_session,
};
use fixstep_bevy::{BodyLink, FixstepWorld};

const TICKS: u64 = 600;
/// At most this many app updates per peer (a 600-tick session takes about 620).
const MAX_UPDATES: u32 = 5_000;
const WALL_LIMIT: Duration = Duration::from_secs(120);

/// Runs two peers to `TICKS` confirmed ticks.
fn run_peers(cycle: Option<u64>) -> PairOutcome {
    run_loopback_pair(TICKS, 7, cycle, MAX_UPDATES, WALL_LIMIT).unwrap_or_else(|e| panic!("{e}"))
}

/// The replay through its file format, verified as `fixstep verify` does.
fn verified_checksum(replay: &Replay) -> u64 {
    let bytes = replay.to_bytes().expect("encode");
    let read = Replay::from_bytes(&bytes, "peer0.replay").expect("decode");
    assert_eq!(read.ticks(), TICKS);
    match verify(&read).expect("verify") {
        VerifyOutcome::Ok { checksum, ticks } => {
            assert_eq!(ticks, TICKS);
            checksum
        }
        other => panic!("the replay does not verify: {other:?}"),
    }
}

#[test]
fn two_peers_on_loopback_agree_with_the_replay() {
    let PairOutcome {
        checksums,
        rollbacks,
        replay,
        ..
    } = run_peers(None);
    assert_eq!(checksums[0], checksums[1], "the peers disagree");
    assert!(
        rollbacks.iter().all(|&r| r > 0),
        "no rollback happened: {rollbacks:?}"
    );
    assert_eq!(verified_checksum(&replay), checksums[0]);
    // Bot inputs arrived: the replay has the players' impulses.
    assert!(replay.inputs().iter().any(|i| !i.players.is_empty()));
}

#[test]
fn spawns_and_despawns_under_rollback_are_deterministic() {
    let PairOutcome {
        checksums,
        rollbacks,
        replay,
        ..
    } = run_peers(Some(30));
    assert_eq!(checksums[0], checksums[1], "the peers disagree");
    assert!(rollbacks.iter().all(|&r| r > 0), "{rollbacks:?}");
    assert_eq!(verified_checksum(&replay), checksums[0]);
    let spawns = replay
        .inputs()
        .iter()
        .flat_map(|i| &i.players)
        .flat_map(|p| &p.commands)
        .filter(|c| matches!(c, fixstep::world::Command::SpawnBody { .. }))
        .count();
    let removals = replay
        .inputs()
        .iter()
        .flat_map(|i| &i.players)
        .flat_map(|p| &p.commands)
        .filter(|c| matches!(c, fixstep::world::Command::Remove { .. }))
        .count();
    // One spawn every 30 ticks, one despawn half a period later.
    assert_eq!(spawns, 20);
    assert_eq!(removals, 20);
}

/// Runs the sync test; returns the final checksum and the number of mismatches.
fn sync_test(cycle: Option<u64>, frames: u32) -> (u64, u32, App) {
    #[derive(Resource, Default)]
    struct Mismatches(u32);
    let mut app = headless_app(sync_test_session(7).unwrap(), 3, u64::from(frames), cycle);
    app.init_resource::<Mismatches>()
        .add_observer(|_: On<SyncTestMismatch>, mut m: ResMut<Mismatches>| m.0 += 1);
    let start = Instant::now();
    for _ in 0..frames {
        app.update();
        assert!(start.elapsed() < WALL_LIMIT, "the sync test took too long");
    }
    let checksum = app.world().resource::<FixstepWorld>().checksum();
    let mismatches = app.world().resource::<Mismatches>().0;
    (checksum, mismatches, app)
}

#[test]
fn sync_test_with_check_distance_7_passes() {
    let (_, mismatches, app) = sync_test(None, 300);
    assert_eq!(mismatches, 0);
    assert!(app.world().resource::<FixstepWorld>().world().tick() >= 290);
}

#[test]
fn sync_test_with_spawns_and_despawns_passes_and_links_stay_true() {
    let (_, mismatches, mut app) = sync_test(Some(10), 300);
    assert_eq!(mismatches, 0);
    // Every crate entity left (not despawned) is linked to a live body, and every live
    // crate body has exactly one entity.
    let links: Vec<BodyLink> = app
        .world_mut()
        .query_filtered::<&BodyLink, With<Crate>>()
        .iter(app.world())
        .copied()
        .collect();
    let world = app.world().resource::<FixstepWorld>().world();
    let rigid = world.rigid().unwrap();
    for link in &links {
        assert!(
            rigid.position(link.0).is_some(),
            "{:?} is not alive",
            link.0
        );
    }
    let mut handles: Vec<_> = links.iter().map(|l| l.0).collect();
    handles.sort_unstable();
    handles.dedup();
    assert_eq!(handles.len(), links.len(), "two entities share a body");
    // floor + 2 players + 4 startup crates + (spawned − despawned) crates
    assert_eq!(rigid.body_count(), 3 + links.len());
}
