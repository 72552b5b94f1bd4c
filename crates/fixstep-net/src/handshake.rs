//! The handshake before a session: every peer checks that the others run the same scene,
//! expect the same number of players and hold the player index its `--remote` order gives
//! them, and refuses a remote that is its own address.
//!
//! Each peer sends its [`Hello`] to every remote it is not done with, every
//! [`RESEND_EVERY`], until the session's deadline. It is done with a remote once it has
//! that remote's hello and the remote has heard its own ([`Heard::You`]). A peer that is
//! done answers a remote's further hellos with [`Heard::Answer`], which nobody answers,
//! and keeps answering them from its session socket ([`PeerSocket`](super::PeerSocket)),
//! so the last remote to finish always hears it. A hello that disagrees ends the
//! handshake with an error saying what differs, after one last hello to that remote so
//! that it finds the same disagreement.

use core::fmt;
use std::net::{SocketAddr, UdpSocket};
use std::time::{Duration, Instant};

use super::hello::{Heard, Hello};

/// Pause between two rounds of hellos to the remotes not done yet.
pub const RESEND_EVERY: Duration = Duration::from_millis(50);

/// Pause between two polls of the socket.
const POLL_EVERY: Duration = Duration::from_millis(2);

/// Whether `a` and `b` name the same endpoint, counting 127.0.0.1, `localhost`'s address
/// and 0.0.0.0 (any address of this machine) as one.
pub fn same_endpoint(a: SocketAddr, b: SocketAddr) -> bool {
    a.port() == b.port() && (a.ip() == b.ip() || (on_this_machine(a) && on_this_machine(b)))
}

/// Whether `address` is this machine whatever its interfaces: loopback or 0.0.0.0 (`::`).
fn on_this_machine(address: SocketAddr) -> bool {
    address.ip().is_loopback() || address.ip().is_unspecified()
}

/// Refuses a remote that is this peer's own address (port `local_port` on this machine)
/// and a remote given twice.
pub fn check_remotes(local_port: u16, remotes: &[SocketAddr]) -> Result<(), String> {
    for (i, remote) in remotes.iter().enumerate() {
        if local_port != 0 && remote.port() == local_port && on_this_machine(*remote) {
            return Err(format!(
                "--remote {remote}: this peer's own address (--local-port {local_port}); \
                 give the other peers' addresses"
            ));
        }
        if let Some(other) = remotes[..i].iter().find(|r| same_endpoint(**r, *remote)) {
            return Err(format!(
                "--remote {remote}: the same peer as --remote {other}; give each other peer \
                 once"
            ));
        }
    }
    Ok(())
}

/// What this peer says about itself.
#[derive(Clone, Debug)]
pub struct Introduction {
    /// The scene's hash.
    pub scene_hash: u64,
    /// The scene's name, for messages.
    pub scene_name: String,
    /// The number of players (1 + the remotes).
    pub players: u8,
    /// This peer's player index.
    pub player: u8,
}

impl Introduction {
    /// The hello that says `heard` to its receiver.
    pub fn hello(&self, heard: Heard) -> Hello {
        Hello::new(
            self.scene_hash,
            self.players,
            self.player,
            heard,
            &self.scene_name,
        )
    }
}

/// Where the handshake stands with one remote.
#[derive(Clone, Copy, Debug, Default)]
struct Progress {
    /// Its hello arrived (and agreed).
    heard: bool,
    /// It has heard ours.
    acknowledged: bool,
}

/// Why a handshake failed.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum HandshakeError {
    /// A remote disagrees; the text says about what.
    Disagreement(String),
    /// The deadline passed; `silent` are the remotes never heard (empty when every remote
    /// was heard but some did not hear this peer).
    TimedOut {
        /// The remotes never heard.
        silent: Vec<SocketAddr>,
    },
}

impl fmt::Display for HandshakeError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::Disagreement(why) => f.write_str(why),
            Self::TimedOut { silent } if silent.is_empty() => {
                f.write_str("the handshake: the remote peers did not hear this peer")
            }
            Self::TimedOut { silent } => {
                let silent: Vec<String> = silent.iter().map(ToString::to_string).collect();
                write!(f, "the handshake: no answer from {}", silent.join(", "))
            }
        }
    }
}

/// Runs the handshake on `socket` with `remotes` (in ascending player index, this peer's
/// own skipped) until every remote agrees, one disagrees (the error says how) or
/// `deadline` passes.
pub fn handshake(
    socket: &UdpSocket,
    me: &Introduction,
    remotes: &[SocketAddr],
    deadline: Instant,
) -> Result<(), HandshakeError> {
    let mut progress = vec![Progress::default(); remotes.len()];
    let mut next_round = Instant::now(); // ok-det: network handshake timing, never simulated state
    let mut buffer = [0u8; 512];
    loop {
        let now = Instant::now(); // ok-det: network handshake timing, never simulated state
        if progress.iter().all(|p| p.heard && p.acknowledged) {
            return Ok(());
        }
        if now >= deadline {
            let silent = remotes.iter().zip(&progress).filter(|(_, p)| !p.heard);
            return Err(HandshakeError::TimedOut {
                silent: silent.map(|(r, _)| *r).collect(),
            });
        }
        if now >= next_round {
            for (remote, p) in remotes.iter().zip(&progress) {
                if !(p.heard && p.acknowledged) {
                    send(socket, me, *remote, heard_of(p));
                }
            }
            next_round = now + RESEND_EVERY;
        }
        let (len, from) = match socket.recv_from(&mut buffer) {
            Ok(received) => received,
            // Nothing waiting (WouldBlock), or an error such as Windows' ConnectionReset for
            // an ICMP "port unreachable" (the remote has not started yet): the next round
            // asks again.
            Err(_) => {
                std::thread::sleep(POLL_EVERY);
                continue;
            }
        };
        let Ok(hello) = Hello::decode(&buffer[..len]) else {
            continue; // A GGRS packet from a remote already in its session, or noise.
        };
        let Some(index) = remotes.iter().position(|r| same_endpoint(*r, from)) else {
            continue; // Not one of this peer's remotes.
        };
        if let Err(why) = agree(me, &hello, index, from) {
            send(socket, me, remotes[index], Heard::You);
            return Err(HandshakeError::Disagreement(why));
        }
        let p = &mut progress[index];
        let was_heard = p.heard;
        p.heard = true;
        p.acknowledged |= hello.heard != Heard::Nothing;
        if p.acknowledged && hello.heard != Heard::Answer {
            // Done with this remote: answer, so it can finish too.
            send(socket, me, remotes[index], Heard::Answer);
        } else if !was_heard {
            // Tell it at once that its hello arrived.
            send(socket, me, remotes[index], Heard::You);
        }
    }
}

/// What a hello to a remote at `progress` says.
fn heard_of(progress: &Progress) -> Heard {
    if progress.heard {
        Heard::You
    } else {
        Heard::Nothing
    }
}

/// Sends this peer's hello; a lost or refused datagram is sent again next round.
fn send(socket: &UdpSocket, me: &Introduction, to: SocketAddr, heard: Heard) {
    let _ = socket.send_to(&me.hello(heard).encode(), to);
}

/// Whether the hello of remote number `index` (the player index this peer's remote order
/// gives it: `index`, or `index + 1` from this peer's own on) agrees with this peer.
fn agree(me: &Introduction, hello: &Hello, index: usize, from: SocketAddr) -> Result<(), String> {
    if hello.scene_hash != me.scene_hash {
        return Err(format!(
            "peer {from} runs scene {:?} (scene hash {:016x}), this peer runs scene {:?} \
             (scene hash {:016x}); every peer must run the same scene",
            hello.scene_name, hello.scene_hash, me.scene_name, me.scene_hash
        ));
    }
    if hello.players != me.players {
        return Err(format!(
            "peer {from} expects {} players, this peer {} (1 + its remotes); every peer must \
             name every other one with --remote",
            hello.players, me.players
        ));
    }
    if hello.player == me.player {
        return Err(format!(
            "peer {from} also has --player-index {}; each peer needs its own index",
            me.player
        ));
    }
    let expected = if index < usize::from(me.player) {
        index
    } else {
        index + 1
    };
    if usize::from(hello.player) != expected {
        return Err(format!(
            "peer {from} has --player-index {}, but this peer's --remote order makes it \
             player {expected}; give the remotes in ascending player index",
            hello.player
        ));
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn address(text: &str) -> SocketAddr {
        text.parse().expect("an address")
    }

    #[test]
    fn loopback_and_any_address_on_one_port_are_one_endpoint() {
        assert!(same_endpoint(
            address("127.0.0.1:7122"),
            address("0.0.0.0:7122")
        ));
        assert!(same_endpoint(
            address("[::1]:7122"),
            address("127.0.0.1:7122")
        ));
        assert!(!same_endpoint(
            address("127.0.0.1:7122"),
            address("127.0.0.1:7123")
        ));
        assert!(!same_endpoint(
            address("10.0.0.1:7122"),
            address("127.0.0.1:7122")
        ));
    }

    #[test]
    fn a_remote_at_the_local_port_or_given_twice_is_refused() {
        for own in ["127.0.0.1:7122", "0.0.0.0:7122", "[::1]:7122"] {
            let error = check_remotes(7122, &[address(own)]).expect_err("own address");
            assert!(error.contains("this peer's own address"), "{error}");
        }
        assert!(check_remotes(7122, &[address("10.0.0.1:7122")]).is_ok());
        assert!(check_remotes(0, &[address("127.0.0.1:7122")]).is_ok());
        let twice = [address("127.0.0.1:7123"), address("0.0.0.0:7123")];
        let error = check_remotes(7122, &twice).expect_err("twice");
        assert!(error.contains("the same peer"), "{error}");
    }

    /// Two handshakes on loopback sockets this test binds, in two threads.
    fn pair(a: Introduction, b: Introduction) -> [Result<(), HandshakeError>; 2] {
        let sockets = [(); 2].map(|()| {
            let socket = UdpSocket::bind("127.0.0.1:0").expect("bind");
            socket.set_nonblocking(true).expect("non-blocking");
            socket
        });
        let addresses = [0, 1].map(|i| sockets[i].local_addr().expect("address"));
        let deadline = Instant::now() + Duration::from_secs(10);
        let [first, second] = sockets;
        let other = std::thread::spawn(move || handshake(&second, &b, &[addresses[0]], deadline));
        let mine = handshake(&first, &a, &[addresses[1]], deadline);
        [mine, other.join().expect("the other peer")]
    }

    fn introduction(scene_hash: u64, players: u8, player: u8) -> Introduction {
        Introduction {
            scene_hash,
            scene_name: format!("scene{scene_hash}"),
            players,
            player,
        }
    }

    #[test]
    fn agreeing_peers_finish_the_handshake() {
        let [a, b] = pair(introduction(7, 2, 0), introduction(7, 2, 1));
        assert_eq!(a, Ok(()));
        assert_eq!(b, Ok(()));
    }

    #[test]
    fn both_peers_name_what_disagrees() {
        let [a, b] = pair(introduction(7, 2, 1), introduction(7, 2, 1));
        for error in [a, b] {
            let error = error.expect_err("one index").to_string();
            assert!(error.contains("also has --player-index 1"), "{error}");
        }
        let [a, b] = pair(introduction(7, 2, 0), introduction(8, 2, 1));
        for error in [a, b] {
            let error = error.expect_err("two scenes").to_string();
            assert!(
                error.contains("every peer must run the same scene"),
                "{error}"
            );
        }
        let [a, _] = pair(introduction(7, 2, 0), introduction(7, 3, 1));
        let error = a.expect_err("counts").to_string();
        assert!(error.contains("expects 3 players, this peer 2"), "{error}");
    }

    #[test]
    fn a_silent_remote_times_out_naming_it() {
        let socket = UdpSocket::bind("127.0.0.1:0").expect("bind");
        socket.set_nonblocking(true).expect("non-blocking");
        let silent = UdpSocket::bind("127.0.0.1:0").expect("bind");
        let remote = silent.local_addr().expect("address");
        let deadline = Instant::now() + Duration::from_millis(300);
        let error = handshake(&socket, &introduction(1, 2, 0), &[remote], deadline)
            .expect_err("nobody answers");
        assert_eq!(
            error,
            HandshakeError::TimedOut {
                silent: vec![remote]
            }
        );
    }
}
