//! The 128-bit checksum GGRS compares between peers, and what a mismatch says.
//!
//! GGRS carries one `u128` per checked frame. fixstep packs into it the 64-bit world
//! checksum (high half) and one byte per part of the state (low half): byte `k` (from the
//! least significant) is the XOR of the eight bytes of the sub-checksum of the part with
//! [`Part::code`] `k mod 8`. Two peers whose totals differ can therefore name the part that
//! diverged without another round trip (a differing part keeps the same byte with
//! probability 1/256).

use fixstep::math::Fx;
use fixstep::world::{Checksum, Part, World};

/// The world's checksum for GGRS: `total << 64 | part bytes` (see the module documentation).
pub fn checksum128(world: &World<Fx>) -> u128 {
    pack(&world.checksum())
}

/// Packs a world checksum into 128 bits.
pub fn pack(checksum: &Checksum) -> u128 {
    let mut parts = 0u64;
    for (part, sum) in &checksum.parts {
        let byte = sum.to_le_bytes().iter().fold(0u8, |acc, b| acc ^ b);
        parts ^= u64::from(byte) << (8 * (part.code() % 8));
    }
    (u128::from(checksum.total) << 64) | u128::from(parts)
}

/// The 64-bit world checksum inside a packed checksum.
pub const fn total(packed: u128) -> u64 {
    (packed >> 64) as u64
}

/// The digest byte of `part` inside a packed checksum.
pub const fn part_byte(packed: u128, part: Part) -> u8 {
    (packed >> (8 * (part.code() % 8))) as u8
}

/// The first of `parts` (the parts of the scene, in [`Part`] order) whose digest byte
/// differs between two packed checksums.
pub fn differing_part(parts: &[Part], local: u128, remote: u128) -> Option<Part> {
    parts
        .iter()
        .copied()
        .find(|&part| part_byte(local, part) != part_byte(remote, part))
}
