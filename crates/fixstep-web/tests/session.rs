//! The web package's session on the host: the checksums `fixstep run` prints, snapshots,
//! the replays it writes and the verdicts on replay bytes.

use core::num::NonZeroU32;

use fixstep::math::Fx;
use fixstep::replay::{DEFAULT_CHECKSUM_EVERY, Replay, record};
use fixstep::world::checksum::hex;
use fixstep_web::session::Session;
use fixstep_web::verdict::verify_bytes;

/// The checksum `fixstep run NAME --ticks N` prints: the world after N ticks of a recorded
/// run of the scene's script.
fn native_checksum(name: &str, ticks: u64) -> String {
    let scene = fixstep_scenes::builtin_scene::<Fx>(name).expect("built-in scene");
    let every = NonZeroU32::new(1000).expect("non-zero");
    hex(record(&scene, ticks, every)
        .expect("records")
        .final_checksum())
}

fn committed(name: &str) -> Vec<u8> {
    let path = format!("{}/../../replays/{name}", env!("CARGO_MANIFEST_DIR"));
    std::fs::read(&path).unwrap_or_else(|e| panic!("{path}: {e}"))
}

#[test]
fn the_checksum_after_n_ticks_is_the_native_run_s() {
    for (name, ticks) in [
        ("pyramid", 12),
        ("cloth", 6),
        ("dam_break", 2),
        ("shooter", 40),
    ] {
        let mut session = Session::builtin(name).expect("loads");
        for _ in 0..ticks {
            session.step();
        }
        assert_eq!(session.checksum(), native_checksum(name, ticks), "{name}");
        assert_eq!(session.checksum().len(), 16);
    }
}

#[test]
fn an_unknown_scene_and_bad_ron_are_errors() {
    let unknown = Session::builtin("nope").expect_err("no such scene");
    assert!(unknown.contains("nope"), "{unknown}");
    let ron = Session::from_ron("(name: \"x\", gravity: oops)", "my.ron").expect_err("bad RON");
    assert!(ron.starts_with("my.ron"), "{ron}");
}

#[test]
fn a_pushed_run_s_replay_verifies_and_holds_the_push() {
    let mut session = Session::builtin("stack").expect("loads");
    session.step();
    let poses = session.body_poses().to_vec();
    let handles = session.body_handles().to_vec();
    let dynamic = (0..handles.len())
        .find(|&i| session.body(i).is_some_and(|(_, kind, _)| kind == 2))
        .expect("a dynamic box");
    let at = [0, 1, 2].map(|k| f64::from(poses[7 * dynamic + k]));
    assert!(session.queue_push(handles[dynamic], [1.0, 0.0, 0.0], at, 3.0));
    session
        .queue_ron("[SetGravity(gravity: (x: 0, y: -9, z: 0))]")
        .expect("commands in RON");
    for _ in 0..30 {
        session.step();
    }
    assert_eq!(session.page_ticks(), &[1]);
    let bytes = session.replay().expect("a replay");
    let replay = Replay::from_bytes(&bytes, "pushed.replay").expect("reads");
    assert_eq!(replay.ticks(), 31);
    assert_eq!(replay.inputs().len(), 1);
    assert_eq!(replay.checksum_every(), DEFAULT_CHECKSUM_EVERY);
    let verdict = verify_bytes(&bytes, "pushed.replay").expect("verifies");
    assert_eq!(verdict.verdict, "ok");
    assert_eq!(verdict.expected, session.checksum());
}

#[test]
fn a_restored_snapshot_runs_on_to_the_same_checksum() {
    let mut session = Session::builtin("stack").expect("loads");
    for _ in 0..10 {
        session.step();
    }
    let snapshot = session.snapshot().expect("a snapshot");
    for _ in 0..10 {
        session.step();
    }
    let later = session.checksum();
    session.restore(&snapshot).expect("restores");
    assert_eq!(session.world().tick(), 10);
    for _ in 0..10 {
        session.step();
    }
    assert_eq!(session.checksum(), later);
    let other = Session::builtin("pyramid").expect("loads");
    let refused = Session::builtin("stack")
        .expect("loads")
        .restore(&other.snapshot().expect("a snapshot"))
        .expect_err("another scene's snapshot");
    assert!(refused.starts_with("snapshot:"), "{refused}");
}

#[test]
fn a_committed_replay_verifies_and_bad_bytes_name_the_section_and_offset() {
    let bytes = committed("stack.replay");
    let verdict = verify_bytes(&bytes, "stack.replay").expect("verifies");
    assert_eq!(verdict.verdict, "ok", "{}", verdict.line);
    assert!(verdict.line.starts_with("ok stack.replay "));

    let truncated = verify_bytes(&bytes[..bytes.len() / 2], "cut.replay").expect_err("cut");
    assert!(
        truncated.starts_with("cut.replay: truncated in the ") && truncated.contains("offset"),
        "{truncated}"
    );
    let garbage = verify_bytes(b"not a replay at all", "junk.replay").expect_err("junk");
    assert!(garbage.contains("not a fixstep replay"), "{garbage}");
}

#[test]
fn a_replay_played_in_a_session_ends_at_its_final_checksum() {
    let bytes = committed("parkour.replay");
    let replay = Replay::from_bytes(&bytes, "parkour.replay").expect("decodes");
    let mut session = Session::from_replay(&bytes, "parkour.replay").expect("loads");
    assert_eq!(
        session.recorded(),
        Some((replay.ticks(), replay.final_checksum()))
    );
    for _ in 0..replay.ticks() {
        session.step();
    }
    assert_eq!(session.checksum(), hex(replay.final_checksum()));
    let cut = Session::from_replay(&bytes[..bytes.len() / 2], "cut.replay").expect_err("cut");
    assert!(cut.starts_with("cut.replay: truncated in the "), "{cut}");
    assert_eq!(Session::builtin("parkour").expect("loads").recorded(), None);
}

#[test]
fn characters_and_water_are_read_for_drawing() {
    let mut parkour = Session::builtin("parkour").expect("loads");
    assert_eq!(parkour.character_count(), 3);
    parkour.step();
    let centres = parkour.character_positions().to_vec();
    assert_eq!(centres.len(), 9);
    let world = parkour.world().characters().expect("characters");
    for (c, centre) in world.characters().iter().zip(centres.chunks(3)) {
        let p = c.position.to_f64();
        assert!((0..3).all(|k| (f64::from(centre[k]) - p[k]).abs() < 1e-5));
    }
    let mesh = parkour.character_mesh(0).expect("a shape");
    assert!(!mesh.indices.is_empty() && mesh.indices.len().is_multiple_of(3));
    assert!(parkour.character_mesh(3).is_none());
    assert!(parkour.water_grid().is_none() && parkour.water_heights().is_empty());

    let mut pond = Session::builtin("pond").expect("loads");
    let grid = pond.water_grid().expect("water");
    assert_eq!(
        pond.water_heights().len(),
        (grid.columns * grid.rows) as usize
    );
    assert_eq!(pond.character_count(), 0);
}
