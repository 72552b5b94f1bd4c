//! Lattices of copies: a scene entry with a `grid` count stands for nx · ny · nz copies.

/// How many copies a lattice of `count` makes (1 without a lattice), at most `u64::MAX`
/// (three counts of 2³² − 1 would overflow).
pub fn lattice_copies(count: Option<(u32, u32, u32)>) -> u64 {
    count.map_or(1, |(nx, ny, nz)| {
        u64::from(nx)
            .saturating_mul(u64::from(ny))
            .saturating_mul(u64::from(nz))
    })
}
