//! The peers' handshake, through `fixstep peer` on 127.0.0.1: a remote that is the peer's
//! own address is refused before anything is sent; two peers with one player index, or on
//! different scenes, both stop with exit code 2 and one `error:` line that names the cause.
//!
//! Every wait is bounded: the peers get `--timeout`, and the test kills them at
//! [`DEADLINE`] whatever happens.
#![cfg(feature = "net")]

use std::io::Read;
use std::net::UdpSocket;
use std::process::{Child, Command, Stdio};
use std::time::{Duration, Instant};

/// The test kills the peers after this long.
const DEADLINE: Duration = Duration::from_secs(60);

/// The peers give up after this many seconds (before [`DEADLINE`]).
const PEER_TIMEOUT: &str = "30";

/// Two distinct free UDP ports on 127.0.0.1 (bound together, read, released).
fn free_ports() -> [u16; 2] {
    let sockets = [(); 2].map(|()| UdpSocket::bind("127.0.0.1:0").expect("bind a free port"));
    sockets.map(|s| s.local_addr().expect("address").port())
}

/// Starts `fixstep peer` on `port` with one remote, on 127.0.0.1.
fn spawn_peer(port: u16, remote: &str, player: &str, scene: &str) -> Child {
    Command::new(env!("CARGO_BIN_EXE_fixstep"))
        .args([
            "peer",
            "--local-port",
            &port.to_string(),
            "--remote",
            remote,
        ])
        .args(["--player-index", player, "--scene", scene, "--ticks", "60"])
        .args(["--timeout", PEER_TIMEOUT])
        .stdin(Stdio::null())
        .stdout(Stdio::null())
        .stderr(Stdio::piped())
        .spawn()
        .expect("start fixstep peer")
}

/// Waits for `child` until [`DEADLINE`] after `started` (then kills it); its exit code and
/// standard error.
fn finish(mut child: Child, started: Instant) -> (Option<i32>, String) {
    let code = loop {
        if let Some(status) = child.try_wait().expect("wait for the peer") {
            break status.code();
        }
        if started.elapsed() > DEADLINE {
            let _ = child.kill();
            let _ = child.wait();
            break None;
        }
        std::thread::sleep(Duration::from_millis(20));
    };
    let mut stderr = String::new();
    let _ = child
        .stderr
        .take()
        .expect("piped")
        .read_to_string(&mut stderr);
    (code, stderr)
}

/// Asserts exit code 2 and one `error:` line holding `expected`.
fn assert_refused(code: Option<i32>, stderr: &str, expected: &str) {
    assert_eq!(code, Some(2), "{stderr}");
    let lines: Vec<&str> = stderr.lines().collect();
    assert_eq!(lines.len(), 1, "one line on stderr: {stderr:?}");
    assert!(lines[0].starts_with("error: "), "{stderr}");
    assert!(
        lines[0].contains(expected),
        "{expected:?} not in {stderr:?}"
    );
}

/// Two peers on each other's port, with the given player indices and scenes; both must be
/// refused with `expected` in their error.
fn both_refused(players: [&str; 2], scenes: [&str; 2], expected: &str) {
    let ports = free_ports();
    let started = Instant::now();
    let peers = [0, 1].map(|i| {
        let remote = format!("127.0.0.1:{}", ports[1 - i]);
        spawn_peer(ports[i], &remote, players[i], scenes[i])
    });
    for peer in peers {
        let (code, stderr) = finish(peer, started);
        assert_refused(code, &stderr, expected);
    }
    assert!(started.elapsed() < DEADLINE, "the peers were killed");
}

#[test]
fn a_peer_refuses_its_own_address_as_remote() {
    let [port, _] = free_ports();
    for host in ["127.0.0.1", "localhost", "0.0.0.0"] {
        let started = Instant::now();
        let remote = format!("{host}:{port}");
        let (code, stderr) = finish(spawn_peer(port, &remote, "0", "stack"), started);
        assert_refused(code, &stderr, "this peer's own address");
        assert!(started.elapsed() < Duration::from_secs(10), "{stderr}");
    }
}

#[test]
fn two_peers_with_one_player_index_are_refused_naming_it() {
    both_refused(
        ["1", "1"],
        ["stack", "stack"],
        "also has --player-index 1; each peer needs its own index",
    );
}

#[test]
fn peers_on_different_scenes_are_refused_naming_both() {
    both_refused(
        ["0", "1"],
        ["stack", "cradle"],
        "every peer must run the same scene",
    );
}
