//! A non-blocking UDP socket for GGRS that binds the address it is told to.
//!
//! GGRS's own `UdpNonBlockingSocket` always binds 0.0.0.0; a peer whose remotes are all on
//! loopback binds 127.0.0.1 instead, so that a local session is not reachable from the
//! network. The same socket carries the [handshake](mod@super::handshake) before the session,
//! and answers a late remote's handshake messages during it.

use std::io::ErrorKind;
use std::net::{IpAddr, Ipv4Addr, SocketAddr, UdpSocket};

use ggrs::{Message, NonBlockingSocket};

use super::hello::{HELLO_MAGIC, Heard, Hello};

/// Largest datagram accepted; GGRS messages are far smaller.
const RECEIVE_BUFFER_LEN: usize = 4096;

/// A UDP socket in non-blocking mode that (de)serialises GGRS messages with bincode 1, as
/// GGRS's own socket does.
#[derive(Debug)]
pub struct PeerSocket {
    socket: UdpSocket,
    buffer: Box<[u8; RECEIVE_BUFFER_LEN]>,
    /// This peer's handshake answer ([`Heard::Answer`]), sent back to every handshake
    /// message that asks for one during the session.
    hello_answer: Vec<u8>,
}

impl PeerSocket {
    /// Binds `port` on 127.0.0.1 when every remote is a loopback address, on 0.0.0.0
    /// otherwise.
    pub fn bind(port: u16, remotes: &[SocketAddr]) -> std::io::Result<Self> {
        let ip = if remotes.iter().all(|r| r.ip().is_loopback()) {
            IpAddr::V4(Ipv4Addr::LOCALHOST)
        } else {
            IpAddr::V4(Ipv4Addr::UNSPECIFIED)
        };
        let socket = UdpSocket::bind(SocketAddr::new(ip, port))?;
        socket.set_nonblocking(true)?;
        Ok(Self {
            socket,
            buffer: Box::new([0; RECEIVE_BUFFER_LEN]),
            hello_answer: Vec::new(),
        })
    }

    /// The socket itself, for the handshake before the session.
    pub(crate) fn udp(&self) -> &UdpSocket {
        &self.socket
    }

    /// From now on, answers a remote's handshake message (one that is not itself an
    /// answer) with `answer`, the bytes of this peer's [`Heard::Answer`] hello.
    pub(crate) fn answer_hellos_with(&mut self, answer: Vec<u8>) {
        self.hello_answer = answer;
    }

    /// The address the socket is bound to.
    pub fn local_addr(&self) -> std::io::Result<SocketAddr> {
        self.socket.local_addr()
    }
}

impl NonBlockingSocket<SocketAddr> for PeerSocket {
    /// Sends one message; a failed send is a lost packet, which GGRS recovers from by
    /// resending.
    fn send_to(&mut self, msg: &Message, addr: &SocketAddr) {
        if let Ok(bytes) = bincode1::serialize(msg) {
            let _ = self.socket.send_to(&bytes, addr);
        }
    }

    /// Every datagram waiting; undecodable ones are dropped, handshake messages answered.
    fn receive_all_messages(&mut self) -> Vec<(SocketAddr, Message)> {
        let mut messages = Vec::new();
        loop {
            match self.socket.recv_from(&mut self.buffer[..]) {
                Ok((len, from)) => {
                    let bytes = &self.buffer[..len];
                    if bytes.starts_with(&HELLO_MAGIC) {
                        let asks = Hello::decode(bytes).is_ok_and(|h| h.heard != Heard::Answer);
                        if asks && !self.hello_answer.is_empty() {
                            let _ = self.socket.send_to(&self.hello_answer, from);
                        }
                    } else if let Ok(message) = bincode1::deserialize(bytes) {
                        messages.push((from, message));
                    }
                }
                // WouldBlock: nothing more now. ConnectionReset (Windows reports an ICMP
                // "port unreachable" this way) and other errors end this poll; GGRS polls
                // again and times out a peer that never answers.
                Err(e) if e.kind() == ErrorKind::Interrupted => {}
                Err(_) => return messages,
            }
        }
    }
}
