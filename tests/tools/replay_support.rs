//! Shared helpers for the replay and CLI tests: running the binary, temporary paths, a
//! sample replay with inputs, and the byte layout of a replay file.

use std::path::{Path, PathBuf};
use std::process::Command as Process;
use std::sync::atomic::{AtomicUsize, Ordering};

use fixstep::codec;
use fixstep::math::{Fx, Real, Vec3};
use fixstep::replay::format::PREAMBLE_LEN;
use fixstep::replay::{Checkpoint, Replay, ReplayHeader, content_hash, record};
use fixstep::scene::Scene;
use fixstep::world::{Command, PlayerInput, Target, TickInput};
use fixstep_scenes::builtin_scene;

/// What a run of the `fixstep` binary printed, and how it exited.
#[derive(Debug)]
pub struct Run {
    /// Exit code (-1 if killed by a signal).
    pub code: i32,
    /// Standard output.
    pub stdout: String,
    /// Standard error.
    pub stderr: String,
}

impl Run {
    /// Asserts a single-line `error: ...` on stderr containing every one of `parts`, and
    /// exit code 2.
    pub fn assert_error(&self, parts: &[&str]) {
        assert_eq!(self.code, 2, "exit code, stderr: {}", self.stderr);
        let lines: Vec<&str> = self.stderr.lines().collect();
        assert_eq!(lines.len(), 1, "one line on stderr, got: {:?}", self.stderr);
        assert!(lines[0].starts_with("error: "), "{}", lines[0]);
        for part in parts {
            assert!(lines[0].contains(part), "{:?} not in {:?}", part, lines[0]);
        }
        assert!(!self.stderr.contains("panicked"), "{}", self.stderr);
    }
}

/// Runs the `fixstep` binary with `args`.
pub fn fixstep<S: AsRef<std::ffi::OsStr>>(args: &[S]) -> Run {
    fixstep_with_env(args, &[])
}

/// [`fixstep`] with environment variables set for the run.
pub fn fixstep_with_env<S: AsRef<std::ffi::OsStr>>(args: &[S], vars: &[(&str, &str)]) -> Run {
    let output = Process::new(env!("CARGO_BIN_EXE_fixstep"))
        .args(args)
        .envs(vars.iter().copied())
        .output()
        .expect("the fixstep binary runs");
    Run {
        code: output.status.code().unwrap_or(-1),
        stdout: String::from_utf8_lossy(&output.stdout).into_owned(),
        stderr: String::from_utf8_lossy(&output.stderr).into_owned(),
    }
}

/// A unique path under the temporary directory, removed (file or directory) when dropped.
pub struct TempPath(PathBuf);

impl TempPath {
    /// A fresh path ending in `name`; nothing is created.
    pub fn new(name: &str) -> Self {
        static COUNTER: AtomicUsize = AtomicUsize::new(0);
        let n = COUNTER.fetch_add(1, Ordering::Relaxed);
        let unique = format!("fixstep-test-{}-{n}-{name}", std::process::id());
        Self(std::env::temp_dir().join(unique))
    }

    /// A fresh file holding `bytes`.
    pub fn with_bytes(name: &str, bytes: &[u8]) -> Self {
        let path = Self::new(name);
        std::fs::write(&path.0, bytes).expect("write a temporary file");
        path
    }

    /// The path.
    pub fn path(&self) -> &Path {
        &self.0
    }

    /// The path as a string (for command lines and message checks).
    pub fn str(&self) -> &str {
        self.0.to_str().expect("temporary paths are UTF-8")
    }
}

impl Drop for TempPath {
    fn drop(&mut self) {
        if self.0.is_dir() {
            let _ = std::fs::remove_dir_all(&self.0);
        } else {
            let _ = std::fs::remove_file(&self.0);
        }
    }
}

/// `n` as a fixed-point number.
pub fn fx(n: i32) -> Fx {
    Fx::from_int(n)
}

/// The fountain scene with a script: inputs from two players at three ticks.
pub fn scripted_scene() -> Scene<Fx> {
    let mut scene = builtin_scene::<Fx>("fountain").expect("fountain is built in");
    scene.name = "scripted".to_owned();
    scene.ticks = 130;
    scene.script = vec![
        TickInput {
            tick: 5,
            players: vec![
                PlayerInput {
                    player: 0,
                    commands: vec![Command::SetGravity {
                        gravity: Vec3::new(fx(0), fx(-3), fx(1)),
                    }],
                },
                PlayerInput {
                    player: 1,
                    commands: vec![Command::Payload(7)],
                },
            ],
        },
        TickInput {
            tick: 61,
            players: vec![PlayerInput {
                player: 2,
                commands: vec![
                    Command::ApplyImpulse {
                        target: Target::ParticleGroup(0),
                        impulse: Vec3::new(fx(1), fx(2), fx(0)),
                        point: None,
                    },
                    Command::Payload(9),
                ],
            }],
        },
        TickInput {
            tick: 100,
            players: vec![PlayerInput {
                player: 0,
                commands: vec![Command::SetEmitter {
                    emitter: 0,
                    on: false,
                }],
            }],
        },
    ];
    scene
}

/// The sample replay: [`scripted_scene`] for 130 ticks, checkpoints every 60.
pub fn sample_replay() -> Replay {
    let scene = scripted_scene();
    record(&scene, scene.ticks, 60.try_into().expect("non-zero")).expect("the scene builds")
}

/// The sample replay's bytes.
pub fn sample_bytes() -> Vec<u8> {
    sample_replay().to_bytes().expect("encodes")
}

/// Where the parts of a replay file are.
#[derive(Clone, Debug)]
pub struct Layout {
    /// The decoded header.
    pub header: ReplayHeader,
    /// End of the header (start of the header hash).
    pub header_end: usize,
    /// Start of the scene section.
    pub scene: usize,
    /// Start of the inputs section.
    pub inputs: usize,
    /// Start of the checksums section.
    pub checksums: usize,
    /// Start of each checkpoint in the checksums section.
    pub checkpoints: Vec<usize>,
}

impl Layout {
    /// The layout of a valid replay file.
    pub fn of(bytes: &[u8]) -> Self {
        let (header, used) =
            codec::decode_prefix::<ReplayHeader>(&bytes[PREAMBLE_LEN..]).expect("header");
        let header_end = PREAMBLE_LEN + used;
        let scene = header_end + 8;
        let inputs = scene + header.scene_len as usize;
        let checksums = inputs + header.inputs_len as usize;
        let list: Vec<Checkpoint> = codec::decode_exact(&bytes[checksums..]).expect("checksums");
        let mut at = checksums + 8;
        let mut checkpoints = Vec::new();
        for checkpoint in &list {
            checkpoints.push(at);
            at += codec::encode(checkpoint).expect("encodes").len();
        }
        Self {
            header,
            header_end,
            scene,
            inputs,
            checksums,
            checkpoints,
        }
    }
}

/// Writes `header` over the file's header and recomputes the header hash, so that a
/// changed field is not caught by the hash first. The header must keep its length.
pub fn rewrite_header(bytes: &mut [u8], header: &ReplayHeader) {
    let encoded = codec::encode(header).expect("encodes");
    let end = PREAMBLE_LEN + encoded.len();
    bytes[PREAMBLE_LEN..end].copy_from_slice(&encoded);
    let hash = content_hash(&bytes[..end]);
    bytes[end..end + 8].copy_from_slice(&hash.to_le_bytes());
}

/// The names in `folder`, sorted.
pub fn names_in(folder: &Path) -> Vec<String> {
    let mut names: Vec<String> = std::fs::read_dir(folder)
        .expect("readable")
        .map(|e| e.expect("entry").file_name().to_string_lossy().into_owned())
        .collect();
    names.sort();
    names
}
