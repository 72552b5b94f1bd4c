//! Checksums of canonical state.
//!
//! Each part of the state is hashed on its own with XXH3-64 over little-endian bytes (see
//! [`StateHasher`](crate::math::state_hash::StateHasher)), giving one sub-checksum per subsystem, so that a desync report can name
//! the part that diverged. The world checksum hashes, in this order: the engine state
//! version (`u32`), then each present part as its one-byte [`Part`] code followed by its
//! sub-checksum (`u64`). Absent subsystems contribute nothing.
//!
//! The core part hashes, in order: the tick (`u64`), gravity (x, y, z), tick rate (`u32`),
//! substeps (`u32`), the RNG state, and the payload digest (`u64`).

use serde::{Deserialize, Serialize};

use crate::types::Part;

/// The checksum of a world at one tick: the total and one sub-checksum per present part.
#[derive(Clone, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub struct Checksum {
    /// The tick the state is at.
    pub tick: u64,
    /// The 64-bit world checksum.
    pub total: u64,
    /// Sub-checksums of the present parts, in [`Part`] order.
    pub parts: Vec<(Part, u64)>,
}

impl Checksum {
    /// The first part whose sub-checksum differs from `other`'s (a part present in only one
    /// of the two counts as different).
    pub fn first_differing_part(&self, other: &Checksum) -> Option<Part> {
        let mut a = self.parts.iter().peekable();
        let mut b = other.parts.iter().peekable();
        loop {
            match (a.peek(), b.peek()) {
                (None, None) => return None,
                (Some(x), Some(y)) if x.0 == y.0 => {
                    if x.1 != y.1 {
                        return Some(x.0);
                    }
                    a.next();
                    b.next();
                }
                (Some(x), Some(y)) => return Some(x.0.min(y.0)),
                (Some(x), None) | (None, Some(x)) => return Some(x.0),
            }
        }
    }
}

/// A checksum as 16 lowercase hex digits.
pub fn hex(checksum: u64) -> String {
    format!("{checksum:016x}")
}
