//! Multiplayer over GGRS (the Rust GGPO): lockstep and rollback sessions between peers
//! that exchange only inputs, with desync detection by checksum and recorded replays.
//!
//! The adapter between a fixstep [`World`](fixstep::world::World) and GGRS:
//! - [`NetInput`]: the fixed-size input a player sends per tick, and the command it maps to;
//! - [`FixstepConfig`]: save and load are world snapshots, restored exactly;
//! - [`checksum128`]: the world checksum with a digest byte per part, for GGRS to compare.
//!
//! [`sync_test`](fn@sync_test) runs GGRS's determinism test on a scene; [`run_peer`] runs one peer of a
//! networked session (`fixstep peer`), after a [`handshake`](fn@handshake) in which the peers
//! compare their scene hash, player count and player indices ([`Hello`]).

// The modules' documentation is for developers and links to private items (read it with
// `cargo doc --document-private-items`, as the test command builds it).
#![allow(rustdoc::private_intra_doc_links)]

mod bot;
mod checksum;
mod config;
mod handshake;
mod hello;
mod input;
mod nudge;
mod peer;
mod requests;
mod scene_world;
mod socket;
mod source;
mod sync_test;

pub use bot::Bot;
pub use checksum::{checksum128, differing_part, pack, part_byte, total};
pub use config::FixstepConfig;
pub use handshake::{HandshakeError, Introduction, check_remotes, handshake, same_endpoint};
pub use hello::{HELLO_MAGIC, HELLO_VERSION, Heard, Hello, HelloError, MAX_NAME_LEN};
pub use input::{Action, IMPULSE_UNITS_PER_NS, NetInput, tick_input};
pub use nudge::nudge_first_body;
pub use peer::{DesyncReport, Mode, PeerOptions, PeerOutcome, ROLLBACK_WINDOW, run_peer};
pub use requests::fulfil;
pub use scene_world::build_world;
pub use socket::PeerSocket;
pub use source::{InputSource, ScriptedInput, read_script};
pub use sync_test::sync_test;
