//! `fixstep run` holds O(bodies) in memory, not O(ticks): a run a hundred times longer
//! peaks at the same resident size, recorded (the replay is streamed to its file) or not.
//!
//! The check is `run balls --ticks 100000` under 64 MiB, but balls runs about 70
//! ticks a second in a debug build, so 100,000 ticks would take the test run half an hour.
//! This test runs a scene that is cheap to step but heavy to checkpoint instead: 4096
//! pinned particles, each with its digest in every checkpoint (about 48 KiB a checkpoint,
//! one a second at 60 Hz). A run that kept its checkpoints would grow by about 24 MiB from
//! 300 to 30,000 ticks; the bound on growth is 6 MiB, far from both, and the peak must stay
//! under 64 MiB. The peak is the child's own (`wait4`'s maximum resident set size), so other
//! tests running at the same time do not count.

use std::ffi::OsStr;
use std::process::{Command, Stdio};

use crate::replay_support::TempPath;

/// Pinned particles in the scene: each has a digest in every checkpoint.
const PARTICLES: usize = 4096;

/// Largest growth of the peak resident size from a short to a long run, KiB.
const MAX_GROWTH_KIB: i64 = 6 * 1024;

/// Largest peak resident size of a run, KiB.
const MAX_PEAK_KIB: i64 = 64 * 1024;

/// The scene: [`PARTICLES`] massless (pinned) particles, no gravity.
fn pinned_particles_scene() -> TempPath {
    let particles: Vec<String> = (0..PARTICLES)
        .map(|i| {
            format!(
                "(position: (x: {}.0, y: {}.0, z: 0.0), mass: 0.0)",
                i % 64,
                i / 64
            )
        })
        .collect();
    let text = format!(
        "(name: \"pins\", gravity: (x: 0.0, y: 0.0, z: 0.0), particles: (capacity: {PARTICLES}, \
         particles: [{}]))",
        particles.join(",")
    );
    TempPath::with_bytes("pins.ron", text.as_bytes())
}

/// Runs `fixstep` with `args` to its end; its peak resident set size in KiB.
#[expect(
    clippy::zombie_processes,
    reason = "the child is waited for with wait4, which also reports its peak memory"
)]
fn peak_kib<S: AsRef<OsStr>>(args: &[S]) -> i64 {
    let child = Command::new(env!("CARGO_BIN_EXE_fixstep"))
        .args(args)
        .stdout(Stdio::null())
        .stderr(Stdio::null())
        .spawn()
        .expect("the fixstep binary starts");
    let pid = libc::pid_t::try_from(child.id()).expect("a process id");
    let mut status = 0;
    // SAFETY: an all-zero `rusage` is a valid value of the plain C struct.
    let mut usage: libc::rusage = unsafe { std::mem::zeroed() };
    // SAFETY: `pid` is our own child, not yet waited for (`child` is never waited on), and
    // both pointers are to live locals of the right types.
    let waited = unsafe { libc::wait4(pid, &mut status, 0, &mut usage) };
    assert_eq!(waited, pid, "wait4: {}", std::io::Error::last_os_error());
    assert!(
        libc::WIFEXITED(status) && libc::WEXITSTATUS(status) == 0,
        "{:?} ended with status {status:#x}",
        args.iter().map(AsRef::as_ref).collect::<Vec<_>>()
    );
    // Linux reports the maximum resident set size in KiB.
    usage.ru_maxrss
}

/// The peak growth from 300 to 30,000 ticks of the pinned scene, with `extra` arguments.
fn growth_kib(extra: &[&str]) -> (i64, i64) {
    let scene = pinned_particles_scene();
    let run = |ticks: &str| {
        let mut args = vec!["run", scene.str(), "--ticks", ticks];
        args.extend_from_slice(extra);
        peak_kib(&args)
    };
    let short = run("300");
    let long = run("30000");
    (long - short, long)
}

#[test]
#[ignore = "ru_maxrss of a child spawned with CLONE_VM counts the test process's own resident memory at the spawn, which other tests running beside it raise (131 MB measured); scripts/test.sh runs them alone with --ignored"]
fn a_long_run_peaks_where_a_short_one_does() {
    let (growth, peak) = growth_kib(&[]);
    assert!(growth < MAX_GROWTH_KIB, "grew by {growth} KiB");
    assert!(peak < MAX_PEAK_KIB, "peaked at {peak} KiB");
}

#[test]
#[ignore = "ru_maxrss of a child spawned with CLONE_VM counts the test process's own resident memory at the spawn, which other tests running beside it raise (131 MB measured); scripts/test.sh runs them alone with --ignored"]
fn a_long_recorded_run_peaks_where_a_short_one_does() {
    let replay = TempPath::new("pins.replay");
    let (growth, peak) = growth_kib(&["--record", replay.str()]);
    assert!(growth < MAX_GROWTH_KIB, "grew by {growth} KiB");
    assert!(peak < MAX_PEAK_KIB, "peaked at {peak} KiB");
    assert!(replay.path().exists(), "the replay is written");
}
