//! `StateHasher`: the canonical hash of simulation state, used by world checksums.
//!
//! # What is hashed
//!
//! A byte stream made by the caller's `write_*` calls, in the order the caller documents,
//! with no separators, tags or padding:
//!
//! | call | bytes |
//! |---|---|
//! | [`write_u8`](StateHasher::write_u8) | the byte |
//! | [`write_u32`](StateHasher::write_u32) | 4, little-endian |
//! | [`write_u64`](StateHasher::write_u64) | 8, little-endian |
//! | [`write_i64`](StateHasher::write_i64) | 8, little-endian two's complement |
//! | [`write_len`](StateHasher::write_len) | the length as a `u64`: 8, little-endian, on every target |
//! | [`write_real`](StateHasher::write_real) | [`Real::canonical_bits`] as 8 little-endian bytes: the raw fixed-point bits (the IEEE bits for `f64`) |
//! | [`write_vec3`](StateHasher::write_vec3) | `x`, `y`, `z` as three `write_real` |
//! | [`write_bytes`](StateHasher::write_bytes) | the bytes as given, without a length: write one with `write_len` first when the count varies |
//!
//! The checksum is XXH3-64 with seed 0 and the default secret (Y. Collet, xxHash,
//! <https://github.com/Cyan4973/xxHash>, `XXH3_64bits`) of that stream, computed by the
//! `xxhash-rust` crate. It depends on the bytes alone, not on how they were split into
//! calls. Every multi-byte value is converted with `to_le_bytes`, so the result does not
//! depend on the platform's endianness, word size or struct layout: `std::hash::Hash`,
//! `#[derive(Hash)]` (whose output is unspecified and uses native byte order) and memory
//! images of structs (padding, layout) are never used.
//!
//! # Performance
//!
//! Writes are copied into a 1 KiB buffer inside the hasher (on the stack when the hasher
//! is); each full buffer is fed to the streaming XXH3 in one call, and large
//! [`write_bytes`](StateHasher::write_bytes) slices are fed directly. The hasher does not
//! allocate.

use xxhash_rust::xxh3::Xxh3Default;

use super::real::Real;
use super::vec3::Vec3;

/// Size of the write buffer. Four times XXH3's own 256-byte block buffer, so that the
/// streaming XXH3 consumes a flushed buffer in place instead of copying it first (measured
/// about 25 % faster than 256 bytes when hashing `i64`s and vectors).
const BUFFER_LEN: usize = 1024;

/// A streaming XXH3-64 hasher of canonical little-endian state. See the module documentation.
#[derive(Clone)]
pub struct StateHasher {
    /// Bytes written but not yet fed to `xxh3`: `buffer[..buffered]`.
    buffer: [u8; BUFFER_LEN],
    /// How many bytes of `buffer` are in use.
    buffered: usize,
    /// The streaming XXH3-64 of every byte fed so far.
    xxh3: Xxh3Default,
}

impl StateHasher {
    /// A hasher that has seen no bytes; finishing it gives the XXH3-64 of the empty input,
    /// `0x2D06800538D394C2`.
    pub const fn new() -> Self {
        Self {
            buffer: [0; BUFFER_LEN],
            buffered: 0,
            xxh3: Xxh3Default::new(),
        }
    }

    /// Appends a fixed-size little-endian encoding.
    #[inline(always)]
    fn push<const N: usize>(&mut self, bytes: [u8; N]) {
        let mut at = self.buffered;
        if at > BUFFER_LEN - N {
            self.flush();
            at = 0;
        }
        self.buffer[at..at + N].copy_from_slice(&bytes);
        self.buffered = at + N;
    }

    /// Feeds the buffered bytes to XXH3.
    #[inline(never)]
    fn flush(&mut self) {
        self.xxh3.update(&self.buffer[..self.buffered]);
        self.buffered = 0;
    }

    /// Writes one byte.
    #[inline]
    pub fn write_u8(&mut self, value: u8) {
        self.push([value]);
    }

    /// Writes 4 little-endian bytes.
    #[inline]
    pub fn write_u32(&mut self, value: u32) {
        self.push(value.to_le_bytes());
    }

    /// Writes 8 little-endian bytes.
    #[inline]
    pub fn write_u64(&mut self, value: u64) {
        self.push(value.to_le_bytes());
    }

    /// Writes 8 little-endian bytes of two's complement.
    #[inline]
    pub fn write_i64(&mut self, value: i64) {
        self.push(value.to_le_bytes());
    }

    /// Writes a length or count as a `u64` (8 little-endian bytes), the same on 32- and 64-bit
    /// targets.
    #[inline]
    pub fn write_len(&mut self, len: usize) {
        self.write_u64(len as u64);
    }

    /// Writes a scalar's [`canonical_bits`](Real::canonical_bits) as 8 little-endian bytes.
    #[inline]
    pub fn write_real<R: Real>(&mut self, value: R) {
        self.write_u64(value.canonical_bits());
    }

    /// Writes `x`, `y`, `z`, each with [`write_real`](Self::write_real).
    #[inline]
    pub fn write_vec3<R: Real>(&mut self, v: Vec3<R>) {
        self.write_real(v.x);
        self.write_real(v.y);
        self.write_real(v.z);
    }

    /// Writes the bytes as they are, without a length.
    pub fn write_bytes(&mut self, bytes: &[u8]) {
        if bytes.len() <= BUFFER_LEN - self.buffered {
            self.buffer[self.buffered..self.buffered + bytes.len()].copy_from_slice(bytes);
            self.buffered += bytes.len();
        } else {
            self.flush();
            self.xxh3.update(bytes);
        }
    }

    /// The XXH3-64 (seed 0) of every byte written.
    pub fn finish(mut self) -> u64 {
        self.flush();
        self.xxh3.digest()
    }
}

impl Default for StateHasher {
    fn default() -> Self {
        Self::new()
    }
}
