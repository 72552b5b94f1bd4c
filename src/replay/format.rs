//! The replay file format, version 1, byte by byte.
//!
//! A replay is a scene, the inputs fed to it, and the checksums the engine produced. All
//! integers are little-endian. "codec" means [`crate::codec`]: bincode 2 with fixed-width
//! little-endian integers, every length a `u64`, every enum variant index a `u32`, an
//! `Option` a `u8` tag (0 = none, 1 = some) followed by the value, a `String` its `u64` byte
//! length followed by its UTF-8 bytes, a `Vec` its `u64` element count followed by the
//! elements, a struct its fields in declaration order with nothing between them, and a
//! fixed-point number its raw `i64` bits. "hash" means [`content_hash`]: XXH3-64 (seed 0,
//! default secret) of exactly those bytes, with no length prefix, as computed by
//! [`StateHasher::write_bytes`].
//!
//! | offset | size | content |
//! |---|---|---|
//! | 0 | 8 | magic: the ASCII bytes `FXSTEPRP` |
//! | 8 | 4 | format version, `u32` = 1 ([`FORMAT_VERSION`]) |
//! | 12 | H | header: codec-encoded [`ReplayHeader`] (below) |
//! | 12 + H | 8 | `header_hash`, `u64`: hash of bytes `0 .. 12 + H` |
//! | 20 + H | `scene_len` | scene section: the scene with an empty `script`, laid out as in [`scene_section`](super::scene_section) |
//! | 20 + H + `scene_len` | `inputs_len` | inputs section: codec-encoded `Vec<TickInput<Fx>>` |
//! | 20 + H + `scene_len` + `inputs_len` | to end of file | checksums section: codec-encoded `Vec<`[`Checkpoint`]`>` |
//!
//! The header, in order (with `scalar` = `"I32F32"`, H = 74 and the scene starts at byte 94):
//!
//! | header offset | size | field | meaning |
//! |---|---|---|---|
//! | 0 | 4 | `state_version: u32` | the engine's [`STATE_VERSION`] when recorded |
//! | 4 | 8 + n | `scalar: String` | the scalar format, `"I32F32"` (n = 6) |
//! | 12 + n | 4 | `tick_rate: u32` | ticks per second (repeats the scene's) |
//! | 16 + n | 8 | `seed: u64` | the world's seed (repeats the scene's) |
//! | 24 + n | 8 | `ticks: u64` | ticks simulated |
//! | 32 + n | 4 | `checksum_every: u32` | checkpoint interval in ticks, at least 1 |
//! | 36 + n | 8 | `scene_len: u64` | length of the scene section |
//! | 44 + n | 8 | `scene_hash: u64` | hash of the scene section |
//! | 52 + n | 8 | `inputs_len: u64` | length of the inputs section |
//! | 60 + n | 8 | `inputs_hash: u64` | hash of the inputs section |
//!
//! The inputs section lists only ticks that have at least one command, in strictly
//! ascending tick order, each below `ticks`; within a tick the players are in strictly
//! ascending index and each has at least one command. Each `TickInput` is its `tick: u64`
//! then its players, each a `player: u8` then its commands (a `u32` variant index then the
//! command's fields).
//!
//! The checksums section holds one [`Checkpoint`] at tick 0, one at every multiple of
//! `checksum_every`, and one at `ticks` (never two at the same tick). Each is `tick: u64`,
//! `total: u64`, then `parts` as a `u64` count of (`u32` [`Part`] variant index, `u64`
//! sub-checksum) pairs, then `objects` as a `u64` count of (`u32` [`Part`] variant index,
//! `u64` count of (`u32` slot index, `u32` generation, `u32` digest)) entries: one 32-bit
//! digest per object slot, in ascending slot index, so that a desync names the first
//! differing object. This section has no hash on purpose: a changed checksum must show
//! as a desync, not as a damaged file. The header, scene and inputs are covered by their
//! hashes, so damage there is reported as such.
//!
//! Readers check, in order: the magic and the format version (read raw, before anything
//! else), the header, `header_hash`, the scalar, the state version, then each section's
//! length against the bytes left in the file, its hash, and its decoding. Each section is
//! at most [`SIZE_LIMIT`] bytes.
//!
//! [`STATE_VERSION`]: crate::world::STATE_VERSION
//! [`SIZE_LIMIT`]: crate::codec::SIZE_LIMIT

use core::fmt;

use serde::{Deserialize, Serialize};

use crate::math::Real;
use crate::math::state_hash::StateHasher;
use crate::world::{Checksum, Handle, ObjectDigests, Part, World};

/// The first eight bytes of every replay file.
pub const MAGIC: [u8; 8] = *b"FXSTEPRP";

/// The replay format version this build reads and writes.
pub const FORMAT_VERSION: u32 = 1;

/// Length of the raw preamble: magic and format version.
pub const PREAMBLE_LEN: usize = 12;

/// The header: what was recorded, how, and where the sections are.
#[derive(Clone, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub struct ReplayHeader {
    /// The engine's state version when the replay was recorded.
    pub state_version: u32,
    /// The scalar format's name, e.g. `"I32F32"`.
    pub scalar: String,
    /// Ticks per simulated second (the scene's).
    pub tick_rate: u32,
    /// The world's seed (the scene's).
    pub seed: u64,
    /// Ticks simulated.
    pub ticks: u64,
    /// Interval between checkpoints, in ticks.
    pub checksum_every: u32,
    /// Length of the scene section in bytes.
    pub scene_len: u64,
    /// [`content_hash`] of the scene section.
    pub scene_hash: u64,
    /// Length of the inputs section in bytes.
    pub inputs_len: u64,
    /// [`content_hash`] of the inputs section.
    pub inputs_hash: u64,
}

/// The world's checksum at one recorded tick.
#[derive(Clone, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub struct Checkpoint {
    /// The tick the world was at.
    pub tick: u64,
    /// The world checksum.
    pub total: u64,
    /// Sub-checksums of the parts present, in [`Part`] order.
    pub parts: Vec<(Part, u64)>,
    /// Per-object digests of the parts that have objects, in [`Part`] order (see
    /// [`World::object_digests`]): they let a desync name the first differing object.
    pub objects: ObjectDigests,
}

impl Checkpoint {
    /// The checkpoint of `world` as it is now.
    pub fn capture<R: Real>(world: &World<R>) -> Self {
        let Checksum { tick, total, parts } = world.checksum();
        Self {
            tick,
            total,
            parts,
            objects: world.object_digests(),
        }
    }

    /// The first object whose digest differs from `objects` (recorded here first), in part
    /// order then slot order; an object present on one side only counts as differing.
    pub fn first_differing_object(&self, objects: &ObjectDigests) -> Option<(Part, Handle)> {
        for (part, recorded) in &self.objects {
            let Some((_, current)) = objects.iter().find(|(p, _)| p == part) else {
                return recorded.first().map(|(id, _)| (*part, *id));
            };
            let common = recorded.len().min(current.len());
            if let Some(i) = (0..common).find(|&i| recorded[i] != current[i]) {
                return Some((*part, recorded[i].0));
            }
            if recorded.len() != current.len() {
                let longer = if recorded.len() > current.len() {
                    recorded
                } else {
                    current
                };
                return Some((*part, longer[common].0));
            }
        }
        None
    }
}

/// The parts of a replay file, as named in error messages.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Section {
    /// Magic and format version.
    Preamble,
    /// The header and its hash.
    Header,
    /// The scene section.
    Scene,
    /// The inputs section.
    Inputs,
    /// The checksums section.
    Checksums,
}

impl fmt::Display for Section {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            Section::Preamble => "preamble (magic and format version)",
            Section::Header => "header",
            Section::Scene => "scene section",
            Section::Inputs => "inputs section",
            Section::Checksums => "checksums section",
        })
    }
}

/// The integrity hash of a run of bytes: their XXH3-64 (seed 0), via
/// [`StateHasher::write_bytes`].
pub fn content_hash(bytes: &[u8]) -> u64 {
    let mut hasher = StateHasher::new();
    hasher.write_bytes(bytes);
    hasher.finish()
}
