//! `fixstep render`: outputs and errors.

use crate::replay_support::{TempPath, fixstep};

/// Asserts exit code 2 and an error naming every one of `parts`, without a panic.
fn assert_refused(args: &[&str], parts: &[&str]) {
    let run = fixstep(args);
    assert_eq!(run.code, 2, "{args:?}: {run:?}");
    for part in parts {
        assert!(
            run.stderr.contains(part),
            "{part:?} not in {:?}",
            run.stderr
        );
    }
    assert!(!run.stderr.contains("panicked"), "{}", run.stderr);
}

#[test]
fn render_writes_frames_a_gif_and_the_player() {
    let out = TempPath::new("render-out");
    let run = fixstep(&[
        "render",
        "cradle",
        "--ticks",
        "10",
        "--every",
        "5",
        "--size",
        "96x64",
        "--view",
        "front",
        "--out",
        out.str(),
    ]);
    assert_eq!(run.code, 0, "{run:?}");
    assert!(
        run.stdout
            .lines()
            .last()
            .is_some_and(|l| l.starts_with("checksum: "))
    );
    for name in [
        "tick-000000.png",
        "tick-000005.png",
        "tick-000010.png",
        "animation.gif",
    ] {
        let bytes = std::fs::read(out.path().join(name)).expect(name);
        assert!(bytes.len() > 32, "{name}");
    }
    let gif = std::fs::read(out.path().join("animation.gif")).expect("the GIF");
    let mut decoder = gif::DecodeOptions::new()
        .read_info(std::io::Cursor::new(gif))
        .expect("a GIF");
    assert_eq!((decoder.width(), decoder.height()), (96, 64));
    let mut frames = 0;
    while decoder.read_next_frame().expect("a frame").is_some() {
        frames += 1;
    }
    assert_eq!(frames, 3, "ticks 0, 5 and 10");
    let page = std::fs::read_to_string(out.path().join("index.html")).expect("index.html");
    assert!(page.contains("<canvas") && page.contains("\"tick\":10"));
    assert!(
        !page.contains("http://") && !page.contains("https://"),
        "no network"
    );
}

#[test]
fn render_replays_a_replay_to_its_recorded_checksum() {
    let out = TempPath::new("render-replay");
    let replay = concat!(
        concat!(env!("CARGO_MANIFEST_DIR"), "/../.."),
        "/replays/stack.replay"
    );
    let verified = fixstep(&["verify", replay]);
    assert_eq!(verified.code, 0, "{verified:?}");
    let recorded = verified
        .stdout
        .split_whitespace()
        .last()
        .expect("a checksum");
    let run = fixstep(&[
        "render",
        replay,
        "--every",
        "1000",
        "--size",
        "64x48",
        "--out",
        out.str(),
    ]);
    assert_eq!(run.code, 0, "{run:?}");
    assert_eq!(
        run.stdout.lines().last(),
        Some(format!("checksum: {recorded}").as_str())
    );
    assert!(
        out.path().join("tick-000420.png").exists(),
        "the replay's last tick"
    );
}

#[test]
fn render_refuses_bad_arguments() {
    assert_refused(
        &["render", "stack", "--size", "640"],
        &["640", "WIDTHxHEIGHT"],
    );
    assert_refused(
        &["render", "stack", "--size", "0x10"],
        &["width 0", "16 to 4096"],
    );
    assert_refused(&["render", "stack", "--size", "64xq"], &["height `q`"]);
    assert_refused(
        &["render", "stack", "--view", "side"],
        &["side", "iso, front or top"],
    );
    assert_refused(&["render", "stack", "--every", "0"], &["--every"]);
    assert_refused(
        &["render", "stack", "--ticks", "1000000000"],
        &["--ticks 1000000000", "--every 1", "frames, more than 20000"],
    );
    assert_refused(&["render", "no-such.replay"], &["no-such.replay"]);
    assert_refused(
        &["render", "no-such-scene"],
        &["unknown scene `no-such-scene`"],
    );
}
