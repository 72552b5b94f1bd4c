//! `fixstep run --record` streams the replay to its file as it runs; the file is byte for
//! byte the one recorded in memory before, so the committed replays record again to
//! themselves, and the run's checksum is the same recorded or not.

use std::path::Path;

use crate::replay_support::{TempPath, fixstep};

#[test]
fn recording_a_builtin_scene_gives_its_committed_replay() {
    for name in ["stack", "shooter", "cradle", "fountain"] {
        let replay = TempPath::new(&format!("{name}.replay"));
        let recorded = fixstep(&["run", name, "--record", replay.str()]);
        assert_eq!(recorded.code, 0, "{recorded:?}");
        let committed = Path::new(env!("CARGO_MANIFEST_DIR"))
            .join("../../replays")
            .join(format!("{name}.replay"));
        assert!(
            std::fs::read(replay.path()).expect("written")
                == std::fs::read(&committed).expect("committed"),
            "{name}: the recorded replay differs from {}",
            committed.display()
        );
        let plain = fixstep(&["run", name]);
        assert_eq!(plain.code, 0, "{plain:?}");
        assert_eq!(
            plain.stdout.lines().last(),
            recorded.stdout.lines().last(),
            "{name}: the checksum"
        );
    }
}
