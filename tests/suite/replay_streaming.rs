//! Streaming a recording to its file ([`StreamingRecorder`]): the bytes are exactly those of
//! an in-memory recording, whatever the run's length against the checkpoint interval.

use core::num::NonZeroU32;
use std::fs::File;
use std::path::PathBuf;

use fixstep::math::Fx;
use fixstep::replay::{InputFeed, Replay, StreamingRecorder, record};
use fixstep::scene::Scene;
use fixstep_scenes::builtin_scene;

/// An empty spool file opened for reading and writing, unlinked at once where the
/// platform allows (it stays usable while open).
fn spool(name: &str) -> File {
    let path: PathBuf =
        std::env::temp_dir().join(format!("fixstep-suite-{}-{name}.spool", std::process::id()));
    let file = File::options()
        .read(true)
        .write(true)
        .create_new(true)
        .open(&path)
        .expect("create a spool file");
    let _ = std::fs::remove_file(&path);
    file
}

/// The replay file of `ticks` ticks of `scene`, streamed.
fn streamed(scene: &Scene<Fx>, ticks: u64, every: NonZeroU32, name: &str) -> (Vec<u8>, u64) {
    let mut recorder = StreamingRecorder::new(scene, every, spool(name)).expect("builds");
    let mut feed = InputFeed::new(&scene.script);
    for tick in 0..ticks {
        recorder.step(feed.at(tick)).expect("spooled");
    }
    let mut bytes = Vec::new();
    let checksum = recorder.finish(&mut bytes).expect("written");
    (bytes, checksum)
}

#[test]
fn a_streamed_recording_has_the_bytes_of_an_in_memory_one() {
    // Ticks that end on a checkpoint, between two, before the first, and none at all; a
    // scene without a script and one with (the shooter fires from tick 0 on).
    for (name, ticks, every) in [
        ("fountain", 120, 60),
        ("fountain", 130, 60),
        ("fountain", 7, 60),
        ("fountain", 0, 60),
        ("shooter", 125, 60),
        ("shooter", 25, 1),
    ] {
        let scene = builtin_scene::<Fx>(name).expect("built in");
        let every = NonZeroU32::new(every).expect("not zero");
        let in_memory = record(&scene, ticks, every).expect("records");
        let (bytes, checksum) = streamed(&scene, ticks, every, &format!("{name}-{ticks}-{every}"));
        assert_eq!(
            bytes,
            in_memory.to_bytes().expect("encodes"),
            "{name}, {ticks} ticks"
        );
        assert_eq!(
            checksum,
            in_memory.final_checksum(),
            "{name}, {ticks} ticks"
        );
        let decoded = Replay::from_bytes(&bytes, "streamed").expect("decodes");
        assert_eq!(decoded, in_memory, "{name}, {ticks} ticks");
    }
}
