//! Input files that are not regular files or are too large (`/dev/zero`, a named pipe with
//! no writer, a 300 MiB sparse file) are refused at once, as scenes, meshes, replays,
//! snapshots and peer scripts alike: exit code 2 and one `error:` line naming the file.
//!
//! Every run is bounded: a command that has not exited after [`LIMIT`] is killed and the
//! test fails, so a read that blocks or never ends cannot hang the test suite.
#![cfg(unix)]

use std::io::Read;
use std::path::Path;
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

use crate::replay_support::{Run, TempPath};

/// The longest a refusal may take; each is immediate, so this only bounds a failure.
const LIMIT: Duration = Duration::from_secs(20);

/// Runs `fixstep ARGS`, killing it after [`LIMIT`] (a failure).
fn fixstep_within_limit(args: &[&str]) -> Run {
    let mut child = Command::new(env!("CARGO_BIN_EXE_fixstep"))
        .args(args)
        .stdin(Stdio::null())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("the fixstep binary runs");
    let started = Instant::now();
    let status = loop {
        if let Some(status) = child.try_wait().expect("wait for fixstep") {
            break status;
        }
        if started.elapsed() > LIMIT {
            let _ = child.kill();
            let _ = child.wait();
            panic!("fixstep {args:?} still ran after {LIMIT:?}");
        }
        std::thread::sleep(Duration::from_millis(10));
    };
    let mut stdout = String::new();
    let mut stderr = String::new();
    let _ = child
        .stdout
        .take()
        .expect("stdout")
        .read_to_string(&mut stdout);
    let _ = child
        .stderr
        .take()
        .expect("stderr")
        .read_to_string(&mut stderr);
    Run {
        code: status.code().unwrap_or(-1),
        stdout,
        stderr,
    }
}

/// A named pipe nobody writes to.
fn fifo(name: &str) -> TempPath {
    let path = TempPath::new(name);
    let made = Command::new("mkfifo")
        .arg(path.path())
        .status()
        .expect("mkfifo runs");
    assert!(made.success(), "mkfifo {}", path.str());
    path
}

/// A sparse file of 300 MiB, over the 256 MiB limit (and the replay limit's 1 GiB is
/// checked with a sparse file of its own).
fn sparse(name: &str, len: u64) -> TempPath {
    let path = TempPath::new(name);
    std::fs::File::create(path.path())
        .and_then(|file| file.set_len(len))
        .expect("a sparse file");
    path
}

const MIB: u64 = 1 << 20;

/// The command lines that read `path` as each kind of input file, with the words their
/// refusal must hold.
fn readers(path: &str) -> Vec<(Vec<String>, &'static str)> {
    let own = |args: &[&str]| args.iter().map(|a| (*a).to_owned()).collect::<Vec<_>>();
    vec![
        (own(&["run", path]), "scene file"),
        (own(&["verify", path]), "replay file"),
        (
            own(&["run", "stack", "--from-snapshot", path]),
            "snapshot file",
        ),
        (
            own(&[
                "peer",
                "--local-port",
                "0",
                "--remote",
                "127.0.0.1:9",
                "--inputs",
                path,
            ]),
            "script file",
        ),
    ]
}

fn assert_all_refused(path: &Path, what: &str) {
    let text = path.to_str().expect("UTF-8 path");
    for (args, expected) in readers(text) {
        let args: Vec<&str> = args.iter().map(String::as_str).collect();
        let run = fixstep_within_limit(&args);
        run.assert_error(&[text, what, expected]);
    }
}

#[test]
fn a_character_device_is_refused_as_every_input() {
    assert_all_refused(Path::new("/dev/zero"), "is a character device, not a");
}

#[test]
fn a_named_pipe_without_a_writer_is_refused_without_blocking() {
    let pipe = fifo("input.fifo");
    assert_all_refused(pipe.path(), "is a named pipe (FIFO), not a");
}

#[test]
fn a_file_over_the_limit_is_refused_before_it_is_read() {
    let large = sparse("large.input", 300 * MIB);
    for args in [
        vec!["run", large.str()],
        vec!["run", "stack", "--from-snapshot", large.str()],
    ] {
        let run = fixstep_within_limit(&args);
        run.assert_error(&[
            large.str(),
            "is 314572800 bytes, over the 268435456-byte limit",
        ]);
    }
    let replay = sparse("large.replay", 1025 * MIB);
    let run = fixstep_within_limit(&["verify", replay.str()]);
    run.assert_error(&[replay.str(), "larger than any replay"]);
}

#[test]
fn a_mesh_file_that_is_a_device_or_a_pipe_is_refused() {
    let pipe = fifo("mesh.fifo");
    for (mesh, what) in [
        ("/dev/zero", "is a character device, not an OBJ file"),
        (pipe.str(), "is a named pipe (FIFO), not an OBJ file"),
    ] {
        let scene = TempPath::with_bytes(
            "mesh.ron",
            format!(
                "(name: \"mesh\", rigid: (bodies: [(kind: Static, shape: TriMesh(file: \
                 {mesh:?}))]))"
            )
            .as_bytes(),
        );
        let run = fixstep_within_limit(&["run", scene.str()]);
        run.assert_error(&[mesh, what]);
    }
}
