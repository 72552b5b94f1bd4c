//! A command stopped by SIGINT or SIGTERM removes its temporary files and writes no output:
//! exit 130 or 143, the destination folder as it was.

use std::path::Path;
use std::process::{Child, Command, Stdio};
use std::time::{Duration, Instant};

use crate::replay_support::{TempPath, names_in};

/// Waits until `folder` holds a temporary file (the command is running and writing), or
/// 20 s have passed.
fn wait_for_a_temporary_file(folder: &Path) {
    let started = Instant::now();
    while started.elapsed() < Duration::from_secs(20) {
        if names_in(folder).iter().any(|n| n.contains(".tmp-")) {
            // Let it get well into its run.
            std::thread::sleep(Duration::from_millis(300));
            return;
        }
        std::thread::sleep(Duration::from_millis(20));
    }
    panic!("no temporary file appeared in {}", folder.display());
}

/// Waits at most 20 s for `child` to end; its exit code.
fn exit_code_within_20_s(child: &mut Child) -> Option<i32> {
    let started = Instant::now();
    while started.elapsed() < Duration::from_secs(20) {
        if let Some(status) = child.try_wait().expect("wait") {
            return status.code();
        }
        std::thread::sleep(Duration::from_millis(20));
    }
    let _ = child.kill();
    let _ = child.wait();
    panic!("fixstep did not end within 20 s of the signal");
}

/// Starts a long recorded run writing into `folder`, sends it `signal` while it runs, and
/// checks it ends with `code`, leaving `folder` empty.
fn stop_a_recorded_run(signal: &str, code: i32) {
    let folder = TempPath::new("interrupted");
    std::fs::create_dir(folder.path()).expect("create the folder");
    let mut child = Command::new(env!("CARGO_BIN_EXE_fixstep"))
        .args([
            "run",
            "stack",
            "--ticks",
            "100000000",
            "--record",
            "out.replay",
            "--metrics",
            "out.csv",
        ])
        .current_dir(folder.path())
        .stdout(Stdio::null())
        .stderr(Stdio::null())
        .spawn()
        .expect("the fixstep binary starts");
    wait_for_a_temporary_file(folder.path());
    let sent = Command::new("kill")
        .args([signal, &child.id().to_string()])
        .status()
        .expect("kill runs");
    assert!(sent.success(), "kill {signal}");
    assert_eq!(exit_code_within_20_s(&mut child), Some(code), "{signal}");
    assert_eq!(
        names_in(folder.path()),
        Vec::<String>::new(),
        "{signal}: no temporary file, no output"
    );
}

#[cfg(unix)]
#[test]
fn sigint_on_a_recorded_run_leaves_nothing() {
    stop_a_recorded_run("-INT", 130);
}

#[cfg(unix)]
#[test]
fn sigterm_on_a_recorded_run_leaves_nothing() {
    stop_a_recorded_run("-TERM", 143);
}
