//! Replays: record a run, write it to a file, read it back and verify it bit for bit.
//!
//! A replay file holds a scene, the inputs fed to it and the world checksums at regular
//! checkpoints (layout in [`format`](mod@format)). [`verify`](fn@verify) simulates the scene and inputs again and
//! compares every checkpoint; [`rerecord`] records them again after a deliberate change to
//! the engine.

mod atomic;
mod decode;
mod encode;
mod error;
mod feed;
mod file;
pub mod format;
mod record;
mod scene_id;
pub mod scene_section;
mod stream;
mod verify;

pub use atomic::{AtomicFile, folder_of, temporary_path_for, write_atomic};
pub use decode::{MAX_FILE_LEN, StateVersionCheck};
pub use error::{ReplayError, ReplayErrorKind};
pub use feed::InputFeed;
pub use file::Replay;
pub use format::{Checkpoint, ReplayHeader, Section, content_hash};
pub use record::{DEFAULT_CHECKSUM_EVERY, Recorder, record, rerecord};
pub use scene_id::scene_id;
pub use stream::StreamingRecorder;
pub use verify::{
    VerifyOutcome, verify, verify_on_threads, verify_reporting, verify_with_progress,
};
