//! Snapshot files: a saved world continues bit for bit, on the API and from `fixstep run`,
//! and bytes that are not a valid snapshot of this build are refused with the byte offset,
//! never a panic.

use crate::replay_support::{TempPath, fixstep};
use fixstep::math::{Fx, FxI48F16};
use fixstep::replay::{InputFeed, scene_id};
use fixstep::world::snapshot::{SNAPSHOT_FORMAT_VERSION, SNAPSHOT_MAGIC};
use fixstep::world::{STATE_VERSION, SceneId, World, WorldState, decode_snapshot, encode_snapshot};
use fixstep_scenes::builtin_scene;

/// The `fountain` world after `ticks` ticks of its script.
fn fountain_after(ticks: u64) -> World<Fx> {
    let scene = builtin_scene("fountain").expect("built in");
    let mut world = scene.build().expect("valid");
    let mut feed = InputFeed::new(&scene.script);
    for tick in 0..ticks {
        world.step(feed.at(tick));
    }
    world
}

/// The `fountain` scene's name and hash.
fn fountain_id() -> SceneId {
    scene_id(&builtin_scene("fountain").expect("built in")).expect("encodes")
}

fn snapshot_bytes(ticks: u64) -> Vec<u8> {
    encode_snapshot(&fountain_after(ticks).snapshot(), &fountain_id()).expect("encodes")
}

fn decode(bytes: &[u8]) -> Result<WorldState<Fx>, String> {
    decode_snapshot::<Fx>(bytes)
        .map(|snapshot| snapshot.state)
        .map_err(|e| e.to_string())
}

/// Replaces the trailing hash so that the rest of the checks run.
fn rehash(bytes: &mut [u8]) {
    let at = bytes.len() - 8;
    let mut hasher = fixstep::math::state_hash::StateHasher::new();
    hasher.write_bytes(&bytes[..at]);
    let hash = hasher.finish();
    bytes[at..].copy_from_slice(&hash.to_le_bytes());
}

#[test]
fn a_decoded_snapshot_continues_exactly_like_the_uninterrupted_world() {
    let scene = builtin_scene("fountain").expect("built in");
    let mut uninterrupted = fountain_after(90);
    let mut resumed = scene.build().expect("valid");
    resumed.restore(&decode(&snapshot_bytes(90)).expect("decodes"));
    assert_eq!(resumed.checksum(), uninterrupted.checksum());
    let mut feed_a = InputFeed::new(&scene.script);
    let mut feed_b = InputFeed::new(&scene.script);
    for tick in 90..180 {
        uninterrupted.step(feed_a.at(tick));
        resumed.step(feed_b.at(tick));
    }
    assert_eq!(resumed.checksum(), uninterrupted.checksum());
}

#[test]
fn encode_decode_encode_is_byte_identical() {
    let bytes = snapshot_bytes(75);
    let again =
        encode_snapshot(&decode(&bytes).expect("decodes"), &fountain_id()).expect("encodes");
    assert_eq!(bytes, again);
}

#[test]
fn the_header_is_as_documented() {
    let bytes = snapshot_bytes(1);
    assert_eq!(bytes[..8], SNAPSHOT_MAGIC);
    assert_eq!(bytes[8..12], SNAPSHOT_FORMAT_VERSION.to_le_bytes());
    assert_eq!(bytes[12..16], STATE_VERSION.to_le_bytes());
    assert_eq!(bytes[16..24], 6u64.to_le_bytes());
    assert_eq!(&bytes[24..30], b"I32F32");
    assert_eq!(bytes[30..38], 8u64.to_le_bytes());
    assert_eq!(&bytes[38..46], b"fountain");
    assert_eq!(bytes[46..54], fountain_id().hash.to_le_bytes());
    let snapshot = decode_snapshot::<Fx>(&bytes).expect("decodes");
    assert_eq!(snapshot.scene, fountain_id());
}

#[test]
fn an_older_format_version_is_refused_naming_both_versions() {
    let mut bytes = snapshot_bytes(1);
    let older = SNAPSHOT_FORMAT_VERSION - 1;
    bytes[8..12].copy_from_slice(&older.to_le_bytes());
    rehash(&mut bytes);
    let error = decode(&bytes).expect_err("older format");
    assert_eq!(
        error,
        format!(
            "at byte 8: snapshot format version {older}; this build reads version \
             {SNAPSHOT_FORMAT_VERSION}"
        )
    );
}

#[test]
fn every_prefix_is_refused_without_a_panic() {
    let bytes = snapshot_bytes(20);
    for len in 0..bytes.len() {
        let error = decode(&bytes[..len]).expect_err("a prefix is not a snapshot");
        assert!(error.starts_with("at byte "), "{error}");
    }
}

#[test]
fn a_flipped_bit_anywhere_is_refused() {
    let bytes = snapshot_bytes(20);
    for at in (0..bytes.len()).step_by(7) {
        let mut damaged = bytes.clone();
        damaged[at] ^= 0x10;
        assert!(decode(&damaged).is_err(), "bit flip at {at} accepted");
    }
}

#[test]
fn damage_is_reported_at_the_hash() {
    let mut bytes = snapshot_bytes(20);
    let middle = bytes.len() / 2;
    bytes[middle] ^= 1;
    let error = decode(&bytes).expect_err("damaged");
    assert!(
        error.contains(&format!("at byte {}", bytes.len() - 8)) && error.contains("damaged"),
        "{error}"
    );
}

#[test]
fn another_state_version_is_refused_by_name() {
    let mut bytes = snapshot_bytes(5);
    bytes[12..16].copy_from_slice(&(STATE_VERSION + 1).to_le_bytes());
    rehash(&mut bytes);
    let error = decode(&bytes).expect_err("newer state version");
    assert!(
        error.contains("at byte 12") && error.contains("state version"),
        "{error}"
    );
}

#[test]
fn another_scalar_is_refused_by_name() {
    let scene = builtin_scene::<Fx>("fountain").expect("built in");
    let id = scene_id(&scene).expect("encodes");
    let bytes = encode_snapshot(&scene.build().expect("valid").snapshot(), &id).expect("encodes");
    let error = decode_snapshot::<FxI48F16>(&bytes).expect_err("I32F32 snapshot");
    assert!(error.to_string().contains("\"I32F32\""), "{error}");
}

#[test]
fn an_invalid_state_is_refused_with_its_field() {
    let mut state = fountain_after(3).snapshot();
    state.settings.substeps = 0;
    let bytes = encode_snapshot(&state, &fountain_id()).expect("encodes");
    let error = decode(&bytes).expect_err("zero substeps");
    assert!(error.contains("settings.substeps"), "{error}");
}

#[test]
fn trailing_bytes_are_refused() {
    let mut bytes = snapshot_bytes(5);
    bytes.splice(bytes.len() - 8..bytes.len() - 8, [0u8; 3]);
    rehash(&mut bytes);
    let error = decode(&bytes).expect_err("extra bytes");
    assert!(error.contains("unexpected bytes"), "{error}");
}

#[test]
fn run_saves_and_resumes_a_snapshot_with_the_uninterrupted_checksum() {
    let snapshot = TempPath::new("half.snapshot");
    let whole = fixstep(&["run", "fountain", "--ticks", "120"]);
    let first = fixstep(&[
        "run",
        "fountain",
        "--ticks",
        "60",
        "--snapshot",
        snapshot.str(),
    ]);
    assert_eq!(first.code, 0, "{first:?}");
    let second = fixstep(&[
        "run",
        "fountain",
        "--ticks",
        "60",
        "--from-snapshot",
        snapshot.str(),
    ]);
    assert_eq!(second.code, 0, "{second:?}");
    assert_eq!(whole.stdout.lines().last(), second.stdout.lines().last());
    assert_ne!(first.stdout.lines().last(), second.stdout.lines().last());
}

#[test]
fn run_refuses_a_snapshot_of_another_scene_naming_both() {
    let snapshot = TempPath::new("stack.snapshot");
    let saved = fixstep(&["run", "stack", "--ticks", "5", "--snapshot", snapshot.str()]);
    assert_eq!(saved.code, 0, "{saved:?}");
    let run = fixstep(&["run", "cradle", "--from-snapshot", snapshot.str()]);
    run.assert_error(&[
        snapshot.str(),
        "a snapshot of scene \"stack\"",
        "not of scene \"cradle\"",
    ]);
    let reseeded = fixstep(&[
        "run",
        "stack",
        "--seed",
        "7",
        "--from-snapshot",
        snapshot.str(),
    ]);
    reseeded.assert_error(&[snapshot.str(), "the same name, but another seed"]);
}

#[test]
fn run_refuses_a_file_that_is_not_a_snapshot() {
    let bogus = TempPath::with_bytes("bogus.snapshot", b"FXSTEPRP not a snapshot at all");
    let run = fixstep(&["run", "fountain", "--from-snapshot", bogus.str()]);
    run.assert_error(&[bogus.str(), "at byte 0", "FXSTEPSN"]);
}

#[test]
fn run_refuses_a_missing_snapshot() {
    let missing = TempPath::new("missing.snapshot");
    let run = fixstep(&["run", "fountain", "--from-snapshot", missing.str()]);
    run.assert_error(&[missing.str(), "cannot read"]);
}

#[test]
fn run_refuses_to_record_a_resumed_world() {
    let run = fixstep(&[
        "run",
        "fountain",
        "--from-snapshot",
        "a.snapshot",
        "--record",
        "b.replay",
    ]);
    assert_eq!(run.code, 2, "{run:?}");
    assert!(run.stderr.contains("cannot be used with"), "{}", run.stderr);
}

#[test]
fn run_refuses_one_file_for_two_outputs() {
    let out = TempPath::new("same.out");
    let run = fixstep(&[
        "run",
        "fountain",
        "--ticks",
        "2",
        "--snapshot",
        out.str(),
        "--metrics",
        out.str(),
    ]);
    run.assert_error(&[&format!("--snapshot {0} is also --metrics {0}", out.str())]);
    assert!(!out.path().exists());
}

/// A fluid whose substeps adapt keeps its CFL number through a snapshot: the resumed run
/// ends with the uninterrupted checksum (the count would differ without it).
#[test]
fn run_resumes_adaptive_fluid_substeps_from_a_snapshot() {
    let scene = concat!(
        concat!(env!("CARGO_MANIFEST_DIR"), "/../.."),
        "/scenes/dam_break_adaptive.ron"
    );
    let snapshot = TempPath::new("adaptive.snapshot");
    let whole = fixstep(&["run", scene, "--ticks", "12"]);
    let first = fixstep(&["run", scene, "--ticks", "6", "--snapshot", snapshot.str()]);
    assert_eq!(first.code, 0, "{first:?}");
    let second = fixstep(&[
        "run",
        scene,
        "--ticks",
        "6",
        "--from-snapshot",
        snapshot.str(),
    ]);
    assert_eq!(second.code, 0, "{second:?}");
    assert_eq!(whole.stdout.lines().last(), second.stdout.lines().last());
}
