//! Two `fixstep peer` processes on 127.0.0.1: in lockstep and in rollback mode both report
//! the same final checksum and write replays that verify; when one peer nudges a body by
//! one ulp, both report the desync within one detection interval.
//!
//! Every wait is bounded: the peers get `--timeout`, and the test kills them at
//! [`DEADLINE`] whatever happens.
#![cfg(feature = "net")]

use std::fs;
use std::net::UdpSocket;
use std::path::{Path, PathBuf};
use std::process::{Child, Command, Stdio};
use std::time::{Duration, Instant};

const FIXSTEP: &str = env!("CARGO_BIN_EXE_fixstep");

/// The test kills both peers after this long.
const DEADLINE: Duration = Duration::from_secs(120);

/// The peers give up after this many seconds (before [`DEADLINE`]).
const PEER_TIMEOUT: &str = "90";

/// The scene: particles and rigid bodies.
const SCENE: &str = "showcase";

const TICKS: &str = "240";

/// Ticks between desync checks.
const DESYNC_EVERY: u64 = 10;

/// The nudging peer moves a body by one ulp once its world has run this many ticks.
const NUDGE_AT: u64 = 95;

/// What a peer process left behind.
#[derive(Debug)]
struct Finished {
    code: Option<i32>,
    stdout: String,
    stderr: String,
}

/// `N` distinct free UDP ports on 127.0.0.1 (bound together, read, released).
fn free_ports<const N: usize>() -> [u16; N] {
    let sockets = [(); N].map(|()| UdpSocket::bind("127.0.0.1:0").expect("bind a free port"));
    sockets.map(|s| s.local_addr().expect("address").port())
}

/// A fresh directory for one test's files.
fn scratch(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("fixstep-net-{}-{name}", std::process::id()));
    let _ = fs::remove_dir_all(&dir);
    fs::create_dir_all(&dir).expect("create a scratch directory");
    dir
}

/// Starts peer `player` of `ports.len()`, writing its output to files in `dir`.
fn spawn_peer(dir: &Path, ports: &[u16], player: usize, mode: &str, extra: &[&str]) -> Child {
    let out = fs::File::create(dir.join(format!("peer{player}.out"))).expect("stdout file");
    let err = fs::File::create(dir.join(format!("peer{player}.err"))).expect("stderr file");
    let replay = dir.join(format!("peer{player}.replay"));
    let remotes = (0..ports.len())
        .filter(|&p| p != player)
        .flat_map(|p| ["--remote".to_owned(), format!("127.0.0.1:{}", ports[p])]);
    Command::new(FIXSTEP)
        .args(["peer", "--local-port", &ports[player].to_string()])
        .args(remotes)
        .args(["--player-index", &player.to_string()])
        .args(["--scene", SCENE, "--ticks", TICKS, mode])
        .args(["--desync-every", &DESYNC_EVERY.to_string()])
        .args(["--timeout", PEER_TIMEOUT])
        .arg("--record")
        .arg(&replay)
        .args(extra)
        .stdin(Stdio::null())
        .stdout(out)
        .stderr(err)
        .spawn()
        .expect("start fixstep peer")
}

/// Runs two peers (peer 0 with `extra` arguments) until both exit or the deadline passes.
fn run_pair(name: &str, mode: &str, extra: &[&str]) -> (PathBuf, [Finished; 2]) {
    run_peers(name, mode, extra)
}

/// Runs `N` peers (peer 0 with `extra` arguments) until all exit or the deadline passes.
fn run_peers<const N: usize>(name: &str, mode: &str, extra: &[&str]) -> (PathBuf, [Finished; N]) {
    let dir = scratch(name);
    let ports = free_ports::<N>();
    let mut children: [Child; N] = std::array::from_fn(|player| {
        let extra = if player == 0 { extra } else { &[] };
        spawn_peer(&dir, &ports, player, mode, extra)
    });
    let started = Instant::now();
    let mut codes = [None; N];
    while codes.iter().any(Option::is_none) && started.elapsed() < DEADLINE {
        for (child, code) in children.iter_mut().zip(codes.iter_mut()) {
            if code.is_none()
                && let Some(status) = child.try_wait().expect("wait for a peer")
            {
                *code = Some(status.code());
            }
        }
        std::thread::sleep(Duration::from_millis(20));
    }
    for (child, code) in children.iter_mut().zip(&codes) {
        if code.is_none() {
            let _ = child.kill();
            let _ = child.wait();
        }
    }
    let finished = std::array::from_fn(|player| Finished {
        code: codes[player].flatten(),
        stdout: fs::read_to_string(dir.join(format!("peer{player}.out"))).unwrap_or_default(),
        stderr: fs::read_to_string(dir.join(format!("peer{player}.err"))).unwrap_or_default(),
    });
    (dir, finished)
}

/// The hex checksum of a successful peer's last line.
fn final_checksum(peer: &Finished) -> &str {
    assert_eq!(
        peer.code,
        Some(0),
        "peer failed:\n{}{}",
        peer.stdout,
        peer.stderr
    );
    let last = peer.stdout.lines().last().unwrap_or_default();
    last.strip_prefix("checksum: ")
        .unwrap_or_else(|| panic!("last line is not a checksum: {peer:?}"))
}

fn peers_agree_and_replays_verify(name: &str, mode: &str) {
    let (dir, peers) = run_pair(name, mode, &[]);
    let checksum = final_checksum(&peers[0]);
    assert_eq!(checksum, final_checksum(&peers[1]), "{peers:?}");
    let replays = [dir.join("peer0.replay"), dir.join("peer1.replay")];
    let verify = Command::new(FIXSTEP)
        .arg("verify")
        .args(&replays)
        .output()
        .expect("run fixstep verify");
    let report = String::from_utf8_lossy(&verify.stdout);
    assert!(verify.status.success(), "{report}");
    for line in report.lines() {
        assert!(line.ends_with(&format!(" {TICKS} {checksum}")), "{line}");
    }
    let bytes = replays.map(|r| fs::read(r).expect("read a replay"));
    assert_eq!(bytes[0], bytes[1], "the peers recorded different replays");
    let _ = fs::remove_dir_all(dir);
}

#[test]
fn lockstep_peers_agree_and_their_replays_verify() {
    peers_agree_and_replays_verify("lockstep", "--lockstep");
}

#[test]
fn rollback_peers_agree_and_their_replays_verify() {
    peers_agree_and_replays_verify("rollback", "--rollback");
}

/// The frame of a peer's desync report, after checking the rest of the line.
fn desync_frame(peer: &Finished) -> u64 {
    assert_eq!(
        peer.code,
        Some(1),
        "peer did not report a desync:\n{}{}",
        peer.stdout,
        peer.stderr
    );
    let line = peer.stdout.lines().last().unwrap_or_default();
    assert!(line.contains("sub-checksum rigid differs"), "{line}");
    let frame = line
        .strip_prefix("desync at frame ")
        .and_then(|rest| rest.split_whitespace().next())
        .and_then(|frame| frame.parse().ok());
    frame.unwrap_or_else(|| panic!("not a desync report: {line}"))
}

fn both_peers_report_the_nudge(name: &str, mode: &str) {
    let nudge = NUDGE_AT.to_string();
    let (dir, peers) = run_pair(name, mode, &["--nudge-at", &nudge]);
    for peer in &peers {
        let frame = desync_frame(peer);
        assert!(
            (NUDGE_AT..=NUDGE_AT + DESYNC_EVERY).contains(&frame),
            "desync reported at frame {frame}, not within one interval after the nudge: {peer:?}"
        );
    }
    let _ = fs::remove_dir_all(dir);
}

#[test]
fn lockstep_peers_detect_a_one_ulp_nudge() {
    both_peers_report_the_nudge("lockstep-nudge", "--lockstep");
}

#[test]
fn rollback_peers_detect_a_one_ulp_nudge() {
    both_peers_report_the_nudge("rollback-nudge", "--rollback");
}

/// Runs `fixstep peer ARGS` alone (its remote never answers) and returns its exit code and
/// standard error, killing it at [`DEADLINE`].
fn lone_peer(args: &[&str]) -> (Option<i32>, String) {
    let [port, remote] = free_ports::<2>();
    let port = port.to_string();
    let remote = format!("127.0.0.1:{remote}");
    let mut child = Command::new(FIXSTEP)
        .args(["peer", "--local-port", &port, "--remote", &remote])
        .args(args)
        .stdin(Stdio::null())
        .stdout(Stdio::null())
        .stderr(Stdio::piped())
        .spawn()
        .expect("start fixstep peer");
    let started = Instant::now();
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
    let output = child.wait_with_output().expect("read the peer's output");
    (code, String::from_utf8_lossy(&output.stderr).into_owned())
}

#[test]
fn a_peer_whose_remote_never_answers_gives_up_at_its_timeout() {
    let started = Instant::now();
    let (code, stderr) = lone_peer(&["--scene", "stack", "--timeout", "1"]);
    assert_eq!(code, Some(2), "{stderr}");
    assert!(
        stderr.starts_with("error: timed out after 1.0 s, still synchronising"),
        "{stderr}"
    );
    assert!(started.elapsed() < Duration::from_secs(30));
}

#[test]
fn bad_peer_arguments_are_named() {
    let (code, stderr) = lone_peer(&["--scene", "stack", "--player-index", "2"]);
    assert_eq!(code, Some(2), "{stderr}");
    assert!(
        stderr.contains("--player-index 2: must be below"),
        "{stderr}"
    );

    let (code, stderr) = lone_peer(&["--scene", "fountain", "--nudge-at", "5"]);
    assert_eq!(code, Some(2), "{stderr}");
    assert!(
        stderr.contains("--nudge-at needs a scene with a dynamic rigid body"),
        "{stderr}"
    );
}

#[test]
fn a_peer_binds_loopback_only_when_every_remote_is_on_loopback() {
    use fixstep_net::PeerSocket;
    use std::net::{IpAddr, Ipv4Addr, SocketAddr};

    let loopback: SocketAddr = "127.0.0.1:7000".parse().expect("an address");
    let lan: SocketAddr = "192.168.1.11:7000".parse().expect("an address");
    let local = PeerSocket::bind(0, &[loopback]).expect("bind");
    assert_eq!(
        local.local_addr().expect("address").ip(),
        IpAddr::V4(Ipv4Addr::LOCALHOST)
    );
    let any = PeerSocket::bind(0, &[loopback, lan]).expect("bind");
    assert_eq!(
        any.local_addr().expect("address").ip(),
        IpAddr::V4(Ipv4Addr::UNSPECIFIED)
    );
}

#[test]
fn a_scripted_peer_plays_its_file_and_the_replay_records_it() {
    use fixstep::math::{Fx, Real, Vec3};
    use fixstep::replay::Replay;
    use fixstep::world::{Command, Handle, PlayerInput, Target};

    let script =
        std::env::temp_dir().join(format!("fixstep-net-{}-script.ron", std::process::id()));
    fs::write(
        &script,
        "[(tick: 30, input: (action: ImpulseBody, target: 3, impulse: (0, 160, 0)))]",
    )
    .expect("write the script");
    let inputs = script.to_str().expect("a UTF-8 path");
    let (dir, peers) = run_pair("scripted", "--rollback", &["--inputs", inputs]);
    assert_eq!(final_checksum(&peers[0]), final_checksum(&peers[1]));
    let replay = Replay::read(&dir.join("peer0.replay")).expect("a replay");
    let at_30 = replay
        .inputs()
        .iter()
        .find(|input| input.tick == 30)
        .expect("inputs at tick 30");
    let kick = PlayerInput {
        player: 0,
        commands: vec![Command::ApplyImpulse {
            target: Target::Body(Handle::new(3, 0)),
            impulse: Vec3::new(Fx::ZERO, Fx::from_int(10), Fx::ZERO),
            point: None,
        }],
    };
    assert_eq!(at_30.players.first(), Some(&kick));
    // Player 0 plays nothing but its script.
    let others = replay.inputs().iter().flat_map(|input| &input.players);
    assert_eq!(others.filter(|p| p.player == 0).count(), 1);
    let _ = fs::remove_file(script);
    let _ = fs::remove_dir_all(dir);
}

#[test]
fn three_rollback_peers_agree() {
    let (dir, peers) = run_peers::<3>("three", "--rollback", &[]);
    let checksum = final_checksum(&peers[0]);
    for peer in &peers[1..] {
        assert_eq!(final_checksum(peer), checksum);
    }
    let replays =
        [0, 1, 2].map(|p| fs::read(dir.join(format!("peer{p}.replay"))).expect("a replay"));
    assert!(
        replays.iter().all(|r| *r == replays[0]),
        "the peers recorded different replays"
    );
    let _ = fs::remove_dir_all(dir);
}

#[test]
fn three_lockstep_peers_all_detect_a_nudge() {
    let nudge = NUDGE_AT.to_string();
    let (dir, peers) = run_peers::<3>("three-nudge", "--lockstep", &["--nudge-at", &nudge]);
    for peer in &peers {
        let frame = desync_frame(peer);
        assert!(
            (NUDGE_AT..=NUDGE_AT + DESYNC_EVERY).contains(&frame),
            "{frame}"
        );
    }
    let _ = fs::remove_dir_all(dir);
}
