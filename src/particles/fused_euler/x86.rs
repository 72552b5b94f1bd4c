//! The fused step for I32F32 in x86-64 vector code: a bound check per block, then the block
//! in place, four (AVX2, [`avx2`]) or eight (AVX-512, [`avx512`]) `i64` lanes at a time,
//! without range checks. The kernel is chosen at run time, the widest the processor has;
//! both give the general path's bits.
//!
//! # Layout
//!
//! Positions, velocities and external forces are slices of `Vec3<Fx>`: runs of `i64` (x, y,
//! z, x, y, z, …; `Vec3` is `repr(C)` and `Fx` a transparent `i64`). A group of n particles
//! (n = 4 or 8, the lane count) is 3n values, three vectors. Every operation applies to each
//! component alike; only 1/m (one per particle, spread over the lanes of its three
//! components), gravity (a pattern of components that repeats every three lanes) and, for a
//! drag restricted to a group, the drag coefficient (0 in the lanes of particles of other
//! groups: v·0 = 0 and F − 0 = F, as if the drag were skipped) differ from lane to lane.
//!
//! # Bounds
//!
//! Before a block is computed, one pass over it takes the bit length of the largest
//! magnitude among its positions (b_x: every |x| ≤ 2^b_x), velocities (b_v), external
//! forces (b_F) and inverse masses (b_m; a negative 1/m counts as 64 bits). With b_g that
//! of gravity, every drag coefficient and h below 2³¹ (½) and at most four drags, the
//! values of the module's equations, as exact integers (raw bits), satisfy:
//!
//! | value | bound |
//! |---|---|
//! | v·kⱼ, a·h, v'·h (rounded) | at most half the first factor's bound plus one: that bound |
//! | F = F_ext − Σ v·kⱼ, every partial sum | ≤ 2^b_F + 4·2^b_v ≤ 2^e_F, e_F = max(b_F, b_v) + 3 |
//! | F·(1/m) (rounded) | ≤ 2^(e_F + b_m − 32) + 1 ≤ 2^e_P, e_P = max(e_F + b_m − 32, 0) + 1 |
//! | a = g + F·(1/m) | ≤ 2^e_a, e_a = max(b_g, e_P) + 1 |
//! | v' = v + a·h | ≤ 2^e_v, e_v = max(b_v, e_a) + 1 |
//! | x' = x + v'·h | ≤ 2^e_x, e_x = max(b_x, e_v) + 1 |
//!
//! When b_m ≤ 62, e_F ≤ 62 and e_x ≤ 62, every value of the table lies within 2⁶² of
//! zero: no operation of the block leaves the range, so the general path saturates nowhere
//! in it and its results are the exact rounded values. The kernels compute each of them
//! exactly modulo 2⁶⁴ (wrapping additions, and the products below), and a value in range is
//! determined by its residue, so the kernels' bits are the general path's. Blocks that
//! fail the check (magnitudes within a factor of 4 to 32 of the range limits, depending on
//! the quantity, or 1/m ≥ 2³⁰ kg⁻¹) and a last block whose length is not a multiple of the
//! lane count take the portable guarded computation, which falls back to the general path
//! when it must. Pinned and dead
//! slots (1/m = 0) are computed like the others and then given back their old x and v.
//!
//! # Products
//!
//! Both instruction sets multiply 32 by 32 bits into 64 (`vpmuldq` signed, `vpmuludq`
//! unsigned), so each product is assembled from halves. The checked `*` is
//! ⌊(a·b + 2³¹)/2³²⌋ (to nearest, ties toward +∞).
//!
//! * By a fraction c ∈ [0, 2³¹) (v·kⱼ, a·h, v'·h), for every a: with a = a_h·2³² + a_l,
//!   a_h = ⌊a/2³²⌋ (the high half, signed) and 0 ≤ a_l < 2³² (the low half, unsigned),
//!   ⌊(a·c + 2³¹)/2³²⌋ = a_h·c + ⌊(a_l·c + 2³¹)/2³²⌋, since a_h·c·2³² is a multiple of
//!   2³²: one signed product, and one unsigned product plus 2³¹ (below 2⁶³) shifted right.
//! * By 1/m = m, for |a| ≤ 2⁶² and 0 ≤ m < 2⁶²: with both split around their low half
//!   read as signed, a = a_h·2³² + a_l with a_l ∈ [−2³¹, 2³¹) and a_h = ⌊(a + 2³¹)/2³²⌋
//!   (which fits in 32 signed bits), m likewise,
//!   ⌊(a·m + 2³¹)/2³²⌋ = a_h·m_h·2³² + a_h·m_l + a_l·m_h + ⌊(a_l·m_l + 2³¹)/2³²⌋: four
//!   signed products. a_l·m_l + 2³¹ + 2⁶² lies in [2³², 2⁶³ + 2³¹], so its logical shift
//!   by 32 is the floor plus 2³⁰, which the kernels take off gravity beforehand. Each term,
//!   hence the sum, is exact modulo 2⁶⁴.
//!
//! The proptests in `tests/x86.rs` compare each kernel's lane products with the checked
//! `*`, its blocks with the general path and its steps with the portable path, bit for bit,
//! on values from zero to the range limits, rounding ties and negative values included.

use core::any::Any;
use core::mem::{offset_of, size_of};

use super::{Block, Buffers, for_each_block};
use crate::math::{Fraction, Fx, Real, Vec3};
use crate::particles::forces::LinearField;
use crate::particles::storage::{Attributes, Kinematics};

mod avx2;
mod avx512;

// The layout the kernels' loads and stores rely on: `Fx` is one `i64` (`repr(transparent)`
// over the `fixed` crate's `repr(transparent)` `FixedI64`), `Vec3<Fx>` is x, y, z in a row.
const _: () = {
    assert!(size_of::<Fx>() == 8);
    assert!(size_of::<Vec3<Fx>>() == 24);
    assert!(offset_of!(Vec3<Fx>, x) == 0);
    assert!(offset_of!(Vec3<Fx>, y) == 8);
    assert!(offset_of!(Vec3<Fx>, z) == 16);
};

/// The fused step with the widest kernel the processor has, when one applies: `R` is
/// I32F32 and the processor has AVX2 or AVX-512. Returns whether it ran.
pub(super) fn step<R: Real>(
    field: &LinearField<R>,
    h: Fraction<R>,
    kinematics: &mut Kinematics<R>,
    attributes: &Attributes<R>,
) -> bool {
    Kernel::detect().is_some_and(|kernel| step_with(kernel, field, h, kinematics, attributes))
}

/// The fused step with `kernel`, when `R` is I32F32; returns whether it ran.
pub(super) fn step_with<R: Real>(
    kernel: Kernel,
    field: &LinearField<R>,
    h: Fraction<R>,
    kinematics: &mut Kinematics<R>,
    attributes: &Attributes<R>,
) -> bool {
    let (Some(field), Some(&h), Some(kinematics), Some(attributes)) = (
        (field as &dyn Any).downcast_ref::<LinearField<Fx>>(),
        (&h as &dyn Any).downcast_ref::<Fraction<Fx>>(),
        (kinematics as &mut dyn Any).downcast_mut::<Kinematics<Fx>>(),
        (attributes as &dyn Any).downcast_ref::<Attributes<Fx>>(),
    ) else {
        return false;
    };
    let constants = Constants::new(field, h);
    let mut buffers = Buffers::new();
    for_each_block(kinematics, attributes, |mut block| {
        if !kernel.step_block(&mut block, &constants) {
            block.step_portable(&mut buffers, field, h);
        }
    });
    true
}

/// A vector kernel that the processor running this has: a value exists only once the
/// instruction set has been detected.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) struct Kernel(Isa);

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Isa {
    Avx2,
    Avx512,
}

impl Kernel {
    /// The widest kernel the processor has, if any.
    pub(super) fn detect() -> Option<Self> {
        Self::avx512().or_else(Self::avx2)
    }

    /// The AVX2 kernel (four lanes), if the processor has AVX2.
    pub(super) fn avx2() -> Option<Self> {
        crate::math::cpu::avx2().then_some(Self(Isa::Avx2))
    }

    /// The AVX-512 kernel (eight lanes), if the processor has AVX-512F.
    pub(super) fn avx512() -> Option<Self> {
        crate::math::cpu::avx512f().then_some(Self(Isa::Avx512))
    }

    /// Steps the block in place when its length is a multiple of the lane count and its
    /// bounds keep every value in range; returns whether it did (if not, the block is
    /// untouched).
    pub(super) fn step_block(self, block: &mut Block<'_, Fx>, constants: &Constants) -> bool {
        match self.0 {
            // SAFETY: a `Kernel` of `Isa::Avx2` comes only from `Kernel::avx2`, which found
            // AVX2 on this processor.
            Isa::Avx2 => unsafe { avx2::step_block(block, constants) },
            // SAFETY: a `Kernel` of `Isa::Avx512` comes only from `Kernel::avx512`, which
            // found AVX-512F on this processor.
            Isa::Avx512 => unsafe { avx512::step_block(block, constants) },
        }
    }
}

/// The lane products, for the tests.
#[cfg(test)]
impl Kernel {
    /// `mul_fraction` of each pair aᵢ, cᵢ (0 ≤ cᵢ < 2³¹), `a.len()` a multiple of eight.
    pub(super) fn mul_fraction(self, a: &[i64], c: &[i64]) -> Vec<i64> {
        match self.0 {
            // SAFETY: as in `step_block`.
            Isa::Avx2 => unsafe { avx2::mul_fraction_on(a, c) },
            // SAFETY: as in `step_block`.
            Isa::Avx512 => unsafe { avx512::mul_fraction_on(a, c) },
        }
    }

    /// `mul_mass_biased` of each pair aᵢ, mᵢ (|aᵢ| ≤ 2⁶², 0 ≤ mᵢ < 2⁶²), `a.len()` a
    /// multiple of eight.
    pub(super) fn mul_mass_biased(self, a: &[i64], m: &[i64]) -> Vec<i64> {
        match self.0 {
            // SAFETY: as in `step_block`.
            Isa::Avx2 => unsafe { avx2::mul_mass_biased_on(a, m) },
            // SAFETY: as in `step_block`.
            Isa::Avx512 => unsafe { avx512::mul_mass_biased_on(a, m) },
        }
    }
}

/// The step's parameters as raw bits.
pub(super) struct Constants {
    /// g, m/s².
    gravity: [i64; 3],
    /// Bit length of the largest |g| component.
    gravity_bits: u32,
    /// kⱼ (kg/s), each in [0, 2³¹), with the group each is restricted to.
    drags: [(i64, Option<u16>); 4],
    drag_count: usize,
    /// Whether some drag is restricted to a group.
    restricted: bool,
    /// h (s), in [0, 2³¹).
    h: i64,
}

impl Constants {
    /// The parameters of a step of length `h` in `field`.
    pub(super) fn new(field: &LinearField<Fx>, h: Fraction<Fx>) -> Self {
        let g = field.uniform_gravity;
        let gravity = [g.x.to_bits(), g.y.to_bits(), g.z.to_bits()];
        let mut drags = [(0, None); 4];
        for (drag, &(k, group)) in drags.iter_mut().zip(field.drags()) {
            *drag = (k.get().to_bits(), group);
        }
        Self {
            gravity,
            gravity_bits: bit_length(gravity.iter().fold(0, |acc, &g| acc | magnitude(g))),
            drags,
            drag_count: field.drags().len(),
            restricted: field.drags().iter().any(|&(_, group)| group.is_some()),
            h: h.get().to_bits(),
        }
    }

    /// Whether a block whose positions, velocities, external forces and inverse masses
    /// have magnitudes of at most these bit lengths stays in range (module documentation,
    /// "Bounds").
    fn in_range(&self, bits: BlockBits) -> bool {
        let e_force = bits.forces.max(bits.velocities) + 3;
        if bits.inv_masses > 62 || e_force > 62 {
            return false;
        }
        let e_product = (e_force + bits.inv_masses).saturating_sub(32) + 1;
        let e_acceleration = self.gravity_bits.max(e_product) + 1;
        let e_velocity = bits.velocities.max(e_acceleration) + 1;
        let e_position = bits.positions.max(e_velocity) + 1;
        e_position <= 62
    }

    /// g − 2³⁰ per component, which `mul_mass_biased`'s 2³⁰ completes.
    fn gravity_biased(&self) -> [i64; 3] {
        self.gravity.map(|g| g.wrapping_sub(1 << 30))
    }
}

/// Bit lengths of the largest magnitudes in a block (|value| ≤ 2^bits; a negative inverse
/// mass counts as 64).
#[derive(Clone, Copy, Debug)]
struct BlockBits {
    positions: u32,
    velocities: u32,
    forces: u32,
    inv_masses: u32,
    /// Whether some slot has 1/m = 0.
    pinned: bool,
}

/// |v| for v ≥ 0, |v| − 1 for v < 0 (the bits of v with the sign's copies cleared): its bit
/// length b gives |v| ≤ 2^b.
#[inline(always)]
fn magnitude(v: i64) -> u64 {
    (v ^ (v >> 63)) as u64
}

/// The number of significant bits of `bits` (0 for 0).
#[inline(always)]
fn bit_length(bits: u64) -> u32 {
    u64::BITS - bits.leading_zeros()
}
