//! Snapshot files: a complete [`WorldState`] as bytes, to save a world and continue it later,
//! on this machine or another.
//!
//! All integers are little-endian; "codec" is [`crate::codec`] (fixed-width bincode).
//!
//! | offset | size | content |
//! |---|---|---|
//! | 0 | 8 | magic: the ASCII bytes `FXSTEPSN` |
//! | 8 | 4 | format version, `u32` = 15 ([`SNAPSHOT_FORMAT_VERSION`]) |
//! | 12 | 4 | state version, `u32` ([`STATE_VERSION`] when written) |
//! | 16 | 8 + n | scalar format name: `u64` length n, then its ASCII bytes (`"I32F32"`) |
//! | 24 + n | 16 + m | the scene it was taken in: codec-encoded [`SceneId`] (`u64` name length m, the name's UTF-8 bytes, the `u64` scene hash) |
//! | 40 + n + m | S | the state: codec-encoded [`WorldState`] |
//! | 40 + n + m + S | 8 | XXH3-64 of every byte before it |
//!
//! A snapshot file is at most [`MAX_SNAPSHOT_LEN`] bytes, the limit of every input file.
//!
//! Readers check, in order: the length, the magic, the format version, the trailing hash,
//! the state version, the scalar, the scene's name and hash, the decoding (which must use
//! every byte), and then the state's own invariants ([`WorldState::validate`]), so that a
//! restored world can never index out of its arrays, however the bytes were made. Whether
//! the snapshot belongs to the scene it is restored into is the caller's check
//! ([`SceneId::check_same`]): the engine's world does not know its scene.

use core::fmt;

use super::pipeline::{STATE_VERSION, WorldState};
use super::scene_id::SceneId;
use crate::codec;
use crate::math::Real;
use crate::math::state_hash::StateHasher;
use crate::types::MAX_INPUT_FILE_LEN;

/// The first eight bytes of every snapshot.
pub const SNAPSHOT_MAGIC: [u8; 8] = *b"FXSTEPSN";

/// The layout version this build reads and writes. Version 2 added the rigid bodies to
/// [`WorldState`], version 3 the fluid and the soft bodies, version 4 the rigid bodies'
/// joints, version 5 the fluid's CFL number (adaptive substeps), version 6 the rigid
/// bodies' collision filters, sensor flags and sensor overlaps, version 7 the bodies' and
/// templates' bullet flags, version 8 the triangle meshes and heightfields and contact
/// keys whose parts are 32-bit (a mesh's triangle), version 9 the particle groups'
/// collisions, version 10 the soft bodies' ties to and contacts with rigid bodies, version
/// 11 the layers of the rigid bodies a fluid meets, version 12 the scene the snapshot was
/// taken in ([`SceneId`]), version 13 the kinematic characters, version 14 the water
/// surface, version 15 the particles' contacts, rods and cables; older files are refused
/// with a message naming both versions.
pub const SNAPSHOT_FORMAT_VERSION: u32 = 15;

/// The largest snapshot written or read: [`MAX_INPUT_FILE_LEN`], as every input file.
pub const MAX_SNAPSHOT_LEN: u64 = MAX_INPUT_FILE_LEN;

/// Magic, format version and state version.
const FIXED_PREFIX: usize = 16;

/// Length of the trailing hash.
const HASH_LEN: usize = 8;

/// Why bytes are not a snapshot this build can restore. `offset` is the byte where the
/// problem was found.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct SnapshotError {
    /// Byte offset of the offending part.
    pub offset: usize,
    /// What is wrong there.
    pub message: String,
}

impl SnapshotError {
    fn at(offset: usize, message: impl Into<String>) -> Self {
        Self {
            offset,
            message: message.into(),
        }
    }
}

impl fmt::Display for SnapshotError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "at byte {}: {}", self.offset, self.message)
    }
}

impl std::error::Error for SnapshotError {}

/// A decoded snapshot: the state, and the scene it was taken in.
#[derive(Clone, Debug, PartialEq)]
pub struct Snapshot<R: Real> {
    /// The scene the state belongs to.
    pub scene: SceneId,
    /// The world's state.
    pub state: WorldState<R>,
}

/// XXH3-64 of `bytes`, as the trailing hash.
fn trailing_hash(bytes: &[u8]) -> u64 {
    let mut hasher = StateHasher::new();
    hasher.write_bytes(bytes);
    hasher.finish()
}

/// The snapshot file of `state`, a state of the scene `scene` (layout in the [module
/// documentation](self)); refused when it would be over [`MAX_SNAPSHOT_LEN`] bytes.
pub fn encode_snapshot<R: Real>(
    state: &WorldState<R>,
    scene: &SceneId,
) -> Result<Vec<u8>, SnapshotError> {
    let mut bytes = Vec::new();
    bytes.extend_from_slice(&SNAPSHOT_MAGIC);
    bytes.extend_from_slice(&SNAPSHOT_FORMAT_VERSION.to_le_bytes());
    bytes.extend_from_slice(&STATE_VERSION.to_le_bytes());
    let scalar = codec::encode(R::NAME).map_err(|e| SnapshotError::at(FIXED_PREFIX, e.0))?;
    bytes.extend_from_slice(&scalar);
    let scene = codec::encode(scene).map_err(|e| SnapshotError::at(bytes.len(), e.0))?;
    bytes.extend_from_slice(&scene);
    let body = codec::encode(state).map_err(|e| SnapshotError::at(bytes.len(), e.0))?;
    bytes.extend_from_slice(&body);
    let len = (bytes.len() + HASH_LEN) as u64;
    if len > MAX_SNAPSHOT_LEN {
        return Err(SnapshotError::at(
            0,
            format!("the snapshot would be {len} bytes, over the {MAX_SNAPSHOT_LEN}-byte limit"),
        ));
    }
    let hash = trailing_hash(&bytes);
    bytes.extend_from_slice(&hash.to_le_bytes());
    Ok(bytes)
}

/// Reads a snapshot written by [`encode_snapshot`] with the same scalar and state version,
/// and checks that the state is one a world can run.
pub fn decode_snapshot<R: Real>(bytes: &[u8]) -> Result<Snapshot<R>, SnapshotError> {
    if bytes.len() < FIXED_PREFIX + HASH_LEN {
        return Err(SnapshotError::at(
            bytes.len(),
            format!(
                "too short for a snapshot ({} bytes; at least {} needed)",
                bytes.len(),
                FIXED_PREFIX + HASH_LEN
            ),
        ));
    }
    if bytes[..8] != SNAPSHOT_MAGIC {
        return Err(SnapshotError::at(
            0,
            "not a fixstep snapshot (the file does not start with FXSTEPSN)",
        ));
    }
    let format_version = read_u32(bytes, 8);
    if format_version != SNAPSHOT_FORMAT_VERSION {
        return Err(SnapshotError::at(
            8,
            format!(
                "snapshot format version {format_version}; this build reads version \
                 {SNAPSHOT_FORMAT_VERSION}"
            ),
        ));
    }
    let hash_at = bytes.len() - HASH_LEN;
    let stored = u64::from_le_bytes(bytes[hash_at..].try_into().expect("8 bytes"));
    if stored != trailing_hash(&bytes[..hash_at]) {
        return Err(SnapshotError::at(
            hash_at,
            "the snapshot is damaged (its content hash does not match)",
        ));
    }
    let state_version = read_u32(bytes, 12);
    if state_version != STATE_VERSION {
        return Err(SnapshotError::at(
            12,
            format!(
                "written with state version {state_version}; this build simulates state \
                 version {STATE_VERSION}, so the snapshot cannot continue here"
            ),
        ));
    }
    let body = &bytes[FIXED_PREFIX..hash_at];
    let (scalar, used) = codec::decode_prefix::<String>(body)
        .map_err(|e| SnapshotError::at(FIXED_PREFIX, format!("scalar name: {e}")))?;
    if scalar != R::NAME {
        return Err(SnapshotError::at(
            FIXED_PREFIX,
            format!("scalar format {scalar:?}; this world uses {:?}", R::NAME),
        ));
    }
    let scene_at = FIXED_PREFIX + used;
    let (scene, scene_len) = codec::decode_prefix::<SceneId>(&body[used..])
        .map_err(|e| SnapshotError::at(scene_at, format!("scene name and hash: {e}")))?;
    let state_at = scene_at + scene_len;
    let state: WorldState<R> = codec::decode_exact(&body[used + scene_len..])
        .map_err(|e| SnapshotError::at(state_at, format!("state: {e}")))?;
    state
        .validate()
        .map_err(|e| SnapshotError::at(state_at, format!("state: {e}")))?;
    Ok(Snapshot { scene, state })
}

/// The little-endian `u32` at `at` (the caller checked the length).
fn read_u32(bytes: &[u8], at: usize) -> u32 {
    u32::from_le_bytes(bytes[at..at + 4].try_into().expect("4 bytes"))
}
