//! The handshake's one message, [`Hello`]: what a peer says about itself before the GGRS
//! session starts, and its exact bytes on the wire.
//!
//! | offset | size | content |
//! |---|---|---|
//! | 0 | 8 | magic: the ASCII bytes `FXSTEPHI` |
//! | 8 | 2 | version, `u16` little-endian = 1 ([`HELLO_VERSION`]) |
//! | 10 | 8 | the scene hash, `u64` little-endian ([`fixstep::replay::scene_id`]) |
//! | 18 | 1 | the number of players, 1 to 255 |
//! | 19 | 1 | the sender's player index, below the number of players |
//! | 20 | 1 | what the sender has heard from the receiver ([`Heard`]): 0, 1 or 2 |
//! | 21 | 1 | the scene name's length n, at most [`MAX_NAME_LEN`] |
//! | 22 | n | the scene name, UTF-8 (for messages only) |
//!
//! A message is exactly 22 + n bytes; anything else is refused by [`Hello::decode`].

use core::fmt;

/// The first eight bytes of every handshake message.
pub const HELLO_MAGIC: [u8; 8] = *b"FXSTEPHI";

/// The handshake version this build speaks.
pub const HELLO_VERSION: u16 = 1;

/// The longest scene name a message carries; a longer one is cut at a character boundary.
pub const MAX_NAME_LEN: usize = 64;

/// Bytes before the scene name.
const FIXED_LEN: usize = 22;

/// What the sender of a [`Hello`] has heard from its receiver.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Heard {
    /// Nothing yet: please answer.
    Nothing,
    /// The receiver's hello: the sender is ready, once it hears that the receiver is too.
    You,
    /// An answer from a peer that is done with its receiver; it is never answered, so two
    /// finished peers never echo each other.
    Answer,
}

/// One peer's handshake message.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Hello {
    /// The hash of the scene the sender runs.
    pub scene_hash: u64,
    /// The number of players the sender expects.
    pub players: u8,
    /// The sender's player index.
    pub player: u8,
    /// What the sender has heard from the receiver.
    pub heard: Heard,
    /// The sender's scene name, at most [`MAX_NAME_LEN`] bytes.
    pub scene_name: String,
}

impl Hello {
    /// A message about a peer running scene `name` (cut to [`MAX_NAME_LEN`] bytes).
    pub fn new(scene_hash: u64, players: u8, player: u8, heard: Heard, name: &str) -> Self {
        let mut end = name.len().min(MAX_NAME_LEN);
        while !name.is_char_boundary(end) {
            end -= 1;
        }
        Self {
            scene_hash,
            players,
            player,
            heard,
            scene_name: name[..end].to_owned(),
        }
    }

    /// The message's bytes (layout in the [module documentation](self)).
    pub fn encode(&self) -> Vec<u8> {
        let mut bytes = Vec::with_capacity(FIXED_LEN + self.scene_name.len());
        bytes.extend_from_slice(&HELLO_MAGIC);
        bytes.extend_from_slice(&HELLO_VERSION.to_le_bytes());
        bytes.extend_from_slice(&self.scene_hash.to_le_bytes());
        bytes.push(self.players);
        bytes.push(self.player);
        bytes.push(match self.heard {
            Heard::Nothing => 0,
            Heard::You => 1,
            Heard::Answer => 2,
        });
        let name = &self.scene_name.as_bytes()[..self.scene_name.len().min(MAX_NAME_LEN)];
        bytes.push(name.len() as u8);
        bytes.extend_from_slice(name);
        bytes
    }

    /// Reads a message, refusing anything but the exact bytes [`Hello::encode`] writes.
    pub fn decode(bytes: &[u8]) -> Result<Self, HelloError> {
        let error = |offset: usize, what: String| HelloError { offset, what };
        if bytes.len() < FIXED_LEN {
            return Err(error(
                bytes.len(),
                format!("{} bytes, shorter than a handshake message", bytes.len()),
            ));
        }
        if bytes[..8] != HELLO_MAGIC {
            return Err(error(0, "not a fixstep handshake (magic)".to_owned()));
        }
        let version = u16::from_le_bytes([bytes[8], bytes[9]]);
        if version != HELLO_VERSION {
            return Err(error(
                8,
                format!("handshake version {version}; this build speaks {HELLO_VERSION}"),
            ));
        }
        let mut hash = [0; 8];
        hash.copy_from_slice(&bytes[10..18]);
        let (players, player) = (bytes[18], bytes[19]);
        if players == 0 || player >= players {
            return Err(error(
                18,
                format!("player {player} of {players} players is not a player"),
            ));
        }
        let heard = match bytes[20] {
            0 => Heard::Nothing,
            1 => Heard::You,
            2 => Heard::Answer,
            other => return Err(error(20, format!("heard value {other} (0 to 2)"))),
        };
        let len = usize::from(bytes[21]);
        if len > MAX_NAME_LEN || FIXED_LEN + len != bytes.len() {
            return Err(error(
                21,
                format!(
                    "scene name length {len} (at most {MAX_NAME_LEN}) for {} bytes after it",
                    bytes.len() - FIXED_LEN
                ),
            ));
        }
        let scene_name = std::str::from_utf8(&bytes[FIXED_LEN..])
            .map_err(|_| error(FIXED_LEN, "the scene name is not UTF-8".to_owned()))?
            .to_owned();
        Ok(Self {
            scene_hash: u64::from_le_bytes(hash),
            players,
            player,
            heard,
            scene_name,
        })
    }
}

/// Why bytes are not a handshake message: the byte offset and what is wrong there.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct HelloError {
    /// Byte offset of the problem.
    pub offset: usize,
    /// What is wrong.
    pub what: String,
}

impl fmt::Display for HelloError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "handshake message at byte {}: {}",
            self.offset, self.what
        )
    }
}

impl std::error::Error for HelloError {}

/// The fuzz target `handshake_decode` runs every seed and kept crash through this check
/// (`fuzz/fuzz_targets/handshake_decode.rs`); here the seeds run with the unit tests.
#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_message_decodes_to_itself() {
        for heard in [Heard::Nothing, Heard::You, Heard::Answer] {
            let hello = Hello::new(0x0123_4567_89ab_cdef, 3, 2, heard, "stack");
            assert_eq!(Hello::decode(&hello.encode()), Ok(hello));
        }
    }

    #[test]
    fn a_long_name_is_cut_at_a_character_boundary() {
        let name = "é".repeat(40);
        let hello = Hello::new(1, 2, 0, Heard::Nothing, &name);
        assert_eq!(hello.scene_name, "é".repeat(32));
        assert_eq!(Hello::decode(&hello.encode()), Ok(hello));
    }

    #[test]
    fn damaged_messages_are_refused_with_the_offset() {
        let bytes = Hello::new(1, 2, 1, Heard::You, "cradle").encode();
        for len in 0..bytes.len() {
            assert!(
                Hello::decode(&bytes[..len]).is_err(),
                "prefix of {len} bytes"
            );
        }
        let refused = |at: usize, value: u8| {
            let mut damaged = bytes.clone();
            damaged[at] = value;
            Hello::decode(&damaged).expect_err("damaged").to_string()
        };
        assert_eq!(
            refused(19, 2),
            "handshake message at byte 18: player 2 of 2 players is not a player"
        );
        assert_eq!(
            refused(20, 3),
            "handshake message at byte 20: heard value 3 (0 to 2)"
        );
        assert!(refused(0, b'X').contains("magic"));
        assert!(refused(8, 9).contains("handshake version 9"));
        assert!(refused(22, 0xff).contains("not UTF-8"));
    }

    /// Every file of `fuzz/KIND/handshake_decode`, by name.
    fn fuzz_inputs(kind: &str) -> Vec<Vec<u8>> {
        let dir = format!(
            "{}/../../fuzz/{kind}/handshake_decode",
            env!("CARGO_MANIFEST_DIR")
        );
        let Ok(entries) = std::fs::read_dir(dir) else {
            return Vec::new();
        };
        let mut paths: Vec<_> = entries.map(|e| e.expect("an entry").path()).collect();
        paths.sort();
        paths
            .iter()
            .map(|path| std::fs::read(path).expect("readable"))
            .collect()
    }

    /// The fuzz target's check: decoding never panics, and an accepted message encodes
    /// back to its bytes. Returns whether the message was accepted.
    fn fuzz_check(bytes: &[u8]) -> bool {
        let Ok(hello) = Hello::decode(bytes) else {
            return false;
        };
        assert_eq!(hello.encode(), bytes);
        true
    }

    #[test]
    fn every_fuzz_seed_is_accepted_and_every_kept_crash_is_fixed() {
        let seeds = fuzz_inputs("seeds");
        assert!(!seeds.is_empty(), "no seeds for handshake_decode");
        for seed in seeds {
            assert!(fuzz_check(&seed), "a seed is refused: {seed:?}");
        }
        for kept in fuzz_inputs("regressions") {
            fuzz_check(&kept);
        }
    }
}
