//! The committed replays in `replays/`: there is one per built-in scene, and every one
//! simulates again to exactly its recorded checkpoints.

use std::path::{Path, PathBuf};

use fixstep::math::Fx;
use fixstep::replay::{Replay, VerifyOutcome, verify};
use fixstep_scenes::{BUILTIN_SCENES, builtin_scene};

fn replays_dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("replays")
}

fn committed_replays() -> Vec<PathBuf> {
    let mut files: Vec<PathBuf> = std::fs::read_dir(replays_dir())
        .expect("replays/ exists")
        .map(|entry| entry.expect("readable entry").path())
        .filter(|path| path.extension().is_some_and(|e| e == "replay"))
        .collect();
    files.sort();
    files
}

#[test]
fn every_builtin_scene_has_a_replay() {
    for (name, _) in BUILTIN_SCENES {
        let path = replays_dir().join(format!("{name}.replay"));
        let replay = Replay::read(&path).unwrap_or_else(|e| panic!("{e}"));
        let mut builtin = builtin_scene::<Fx>(name).expect("built in");
        // A replay keeps the scene without its script; the script is its inputs.
        let script = std::mem::take(&mut builtin.script);
        assert_eq!(
            replay.scene(),
            &builtin,
            "{name}.replay records another scene than the built-in; re-record it \
             (scripts/rerecord.sh)"
        );
        assert_eq!(
            replay.inputs(),
            script.as_slice(),
            "{name}.replay's inputs are not the built-in scene's script"
        );
        assert_eq!(replay.ticks(), builtin.ticks, "{name}");
    }
}

#[test]
fn every_committed_replay_verifies() {
    let files = committed_replays();
    assert!(files.len() >= BUILTIN_SCENES.len(), "{files:?}");
    for path in files {
        let replay = Replay::read(&path).unwrap_or_else(|e| panic!("{e}"));
        let outcome = verify(&replay).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
        assert_eq!(
            outcome,
            VerifyOutcome::Ok {
                ticks: replay.ticks(),
                checksum: replay.final_checksum(),
            },
            "{}",
            path.display()
        );
    }
}

#[test]
fn committed_replays_are_canonical() {
    for path in committed_replays() {
        let bytes = std::fs::read(&path).expect("readable");
        let replay = Replay::from_bytes(&bytes, &path.display().to_string())
            .unwrap_or_else(|e| panic!("{e}"));
        assert_eq!(
            replay.to_bytes().expect("encodes"),
            bytes,
            "{}",
            path.display()
        );
    }
}
