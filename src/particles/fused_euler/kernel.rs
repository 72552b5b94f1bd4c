//! The fused step for I32F32 as a kernel: a bound check per block, then the block in
//! place, eight particles at a time, without range checks. It is written once against
//! [`Wide`] and runs with the backend [`backend`] picks (AVX-512 or AVX2); both give the
//! general path's bits.
//!
//! # Layout
//!
//! Positions, velocities and external forces are slices of `Vec3<Fx>`: runs of `i64` (x, y,
//! z, x, y, z, …; `Vec3` is `repr(C)` and `Fx` a transparent `i64`). A group of eight
//! particles is 24 values, three vectors ([`Wide::load_third`]). Every operation
//! applies to each component alike; only 1/m (one per particle, spread over the lanes of
//! its three components, [`Wide::spread_thirds`]), gravity (a pattern of components that repeats every three lanes) and, for a
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
//! Each product is assembled from products of 32-bit halves into 64 bits, signed
//! ([`Wide::mul_low_halves`]) and unsigned ([`Wide::mul_unsigned_low_halves`]), which every
//! backend has. The checked `*` is
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
//! The proptests in `tests/kernel.rs` compare each kernel's lane products with the checked
//! `*`, its blocks with the general path and its steps with the portable path, bit for bit,
//! on values from zero to the range limits, rounding ties and negative values included.

use core::mem::{offset_of, size_of};

use super::{Block, for_each_block};
use crate::math::over_real::OverReal;
use crate::math::wide::{Backend, LANES, Wide, backend, bit_length, kernel_entry};
use crate::math::{Fraction, Fx, Real, Vec3};
use crate::particles::forces::LinearField;
use crate::particles::storage::{Attributes, Kinematics};

// The layout the kernels' loads and stores rely on: `Fx` is one `i64` (`repr(transparent)`
// over the `fixed` crate's `repr(transparent)` `FixedI64`), `Vec3<Fx>` is x, y, z in a row.
const _: () = {
    assert!(size_of::<Fx>() == 8);
    assert!(size_of::<Vec3<Fx>>() == 24);
    assert!(offset_of!(Vec3<Fx>, x) == 0);
    assert!(offset_of!(Vec3<Fx>, y) == 8);
    assert!(offset_of!(Vec3<Fx>, z) == 16);
};

/// The family of [`LinearField`]s, for [`Real::as_fixed`].
struct LinearFieldOf;

impl OverReal for LinearFieldOf {
    type Of<R: Real> = LinearField<R>;
}

/// The family of [`Fraction`]s, for [`Real::as_fixed`].
struct FractionOf;

impl OverReal for FractionOf {
    type Of<R: Real> = Fraction<R>;
}

/// The family of [`Kinematics`], for [`Real::as_fixed`].
struct KinematicsOf;

impl OverReal for KinematicsOf {
    type Of<R: Real> = Kinematics<R>;
}

/// The family of [`Attributes`], for [`Real::as_fixed`].
struct AttributesOf;

impl OverReal for AttributesOf {
    type Of<R: Real> = Attributes<R>;
}

/// The fused step with the kernel, when one applies: `R` is I32F32 and the processor has
/// a backend ([`backend`]). Returns whether it ran.
pub(super) fn step<R: Real>(
    field: &LinearField<R>,
    h: Fraction<R>,
    kinematics: &mut Kinematics<R>,
    attributes: &Attributes<R>,
) -> bool {
    backend().is_some_and(|backend| step_with(backend, field, h, kinematics, attributes))
}

/// The fused step with the kernel on `backend`, when `R` is I32F32; returns whether it
/// ran.
pub(super) fn step_with<R: Real>(
    backend: Backend,
    field: &LinearField<R>,
    h: Fraction<R>,
    kinematics: &mut Kinematics<R>,
    attributes: &Attributes<R>,
) -> bool {
    let (Some(field), Some(&h), Some(kinematics), Some(attributes)) = (
        R::as_fixed::<LinearFieldOf>(field),
        R::as_fixed::<FractionOf>(&h),
        R::as_fixed_mut::<KinematicsOf>(kinematics),
        R::as_fixed::<AttributesOf>(attributes),
    ) else {
        return false;
    };
    let constants = Constants::new(field, h);
    for_each_block(kinematics, attributes, |mut block, buffers| {
        if !step_block_on(backend, &mut block, &constants) {
            block.step_portable(buffers, field, h);
        }
    });
    true
}

kernel_entry! {
    /// Steps the block in place with the instructions of `backend` when its length is a
    /// multiple of eight and its bounds keep every value in range; returns whether it did
    /// (if not, the block is untouched).
    pub(super) fn step_block_on(block: &mut Block<'_, Fx>, constants: &Constants) -> bool = step_block;
}

/// [`step_block_on`]'s kernel.
#[inline(always)]
fn step_block<W: Wide>(w: W, block: &mut Block<'_, Fx>, constants: &Constants) -> bool {
    if !block.positions.len().is_multiple_of(LANES) {
        return false;
    }
    let bits = block_bits(w, block);
    if !constants.in_range(bits) {
        return false;
    }
    // One instance per drag count, so that the drag loop unrolls.
    match (bits.pinned || constants.restricted, constants.drag_count) {
        (false, 0) => step_in_place::<W, 0, false>(w, block, constants),
        (false, 1) => step_in_place::<W, 1, false>(w, block, constants),
        (false, 2) => step_in_place::<W, 2, false>(w, block, constants),
        (false, 3) => step_in_place::<W, 3, false>(w, block, constants),
        (false, _) => step_in_place::<W, 4, false>(w, block, constants),
        (true, 0) => step_in_place::<W, 0, true>(w, block, constants),
        (true, 1) => step_in_place::<W, 1, true>(w, block, constants),
        (true, 2) => step_in_place::<W, 2, true>(w, block, constants),
        (true, 3) => step_in_place::<W, 3, true>(w, block, constants),
        (true, _) => step_in_place::<W, 4, true>(w, block, constants),
    }
    true
}

/// The bit lengths of the block's largest magnitudes (its length a multiple of eight).
#[inline(always)]
fn block_bits<W: Wide>(w: W, block: &Block<'_, Fx>) -> BlockBits {
    let zero = w.zero();
    let [mut x, mut v, mut f, mut m] = [zero; 4];
    let mut pinned = 0u8;
    let (positions, _) = block.positions.as_chunks::<LANES>();
    let (velocities, _) = block.velocities.as_chunks::<LANES>();
    let (forces, _) = block.external_forces.as_chunks::<LANES>();
    let (inv_masses, _) = block.inv_masses.as_chunks::<LANES>();
    for i in 0..positions.len() {
        for k in 0..3 {
            x = w.or(x, w.magnitude(w.load_third(&positions[i], k)));
            v = w.or(v, w.magnitude(w.load_third(&velocities[i], k)));
            f = w.or(f, w.magnitude(w.load_third(&forces[i], k)));
        }
        // A negative m sets the sign bit: 64 bits.
        let masses = w.load(&inv_masses[i]);
        m = w.or(m, masses);
        pinned |= w.equal(masses, zero);
    }
    BlockBits {
        positions: bit_length(w.or_lanes(x)),
        velocities: bit_length(w.or_lanes(v)),
        forces: bit_length(w.or_lanes(f)),
        inv_masses: bit_length(w.or_lanes(m)),
        pinned: pinned != 0,
    }
}

/// The step of a block that stays in range, in place, for `DRAGS` drags. `MIXED` when the
/// lanes do not all take the same path: some slot of the block is pinned or dead (its
/// lanes keep x and v) or some drag is restricted to a group (its coefficient is 0 in the
/// lanes of other groups: v·0 = 0 and F − 0 = F, the same as leaving F alone).
#[inline(always)]
fn step_in_place<W: Wide, const DRAGS: usize, const MIXED: bool>(
    w: W,
    block: &mut Block<'_, Fx>,
    constants: &Constants,
) {
    let gravity = constants.gravity_biased();
    // The components' lane pattern over three vectors: (x y z x y z x y) (z x y z x y z x)
    // (y z x y z x y z).
    let mut pattern = [[0; LANES]; 3];
    for (k, lanes) in pattern.iter_mut().enumerate() {
        for (j, lane) in lanes.iter_mut().enumerate() {
            *lane = gravity[(LANES * k + j) % 3];
        }
    }
    let mut drags = [(w.zero(), None); DRAGS];
    for (lanes, &(k, group)) in drags.iter_mut().zip(&constants.drags) {
        *lanes = (w.splat(k), group);
    }
    let step = Step::<W, DRAGS, MIXED> {
        w,
        gravity_biased: [
            w.load_words(pattern[0]),
            w.load_words(pattern[1]),
            w.load_words(pattern[2]),
        ],
        drags,
        h: w.splat(constants.h),
    };
    let (positions, _) = block.positions.as_chunks_mut::<LANES>();
    let (velocities, _) = block.velocities.as_chunks_mut::<LANES>();
    let (forces, _) = block.external_forces.as_chunks::<LANES>();
    let (inv_masses, _) = block.inv_masses.as_chunks::<LANES>();
    let (groups, _) = block.groups.as_chunks::<LANES>();
    for i in 0..positions.len() {
        let [m0, m1, m2] = w.spread_thirds(w.load(&inv_masses[i]));
        let [k0, k1, k2] = step.coefficients(&groups[i]);
        let (x, v, f) = (&mut positions[i], &mut velocities[i], &forces[i]);
        // Three calls, not a loop over the thirds: a loop kept the spread masses on the
        // stack (1.46× the time per step on AVX2).
        step.third(0, x, v, f, m0, k0);
        step.third(1, x, v, f, m1, k1);
        step.third(2, x, v, f, m2, k2);
    }
}

/// The step's constants in lanes.
struct Step<W: Wide, const DRAGS: usize, const MIXED: bool> {
    w: W,
    /// g − 2³⁰ in the lane pattern of each of the three vectors.
    gravity_biased: [W::V; 3],
    /// kⱼ in every lane, with the group it is restricted to.
    drags: [(W::V, Option<u16>); DRAGS],
    h: W::V,
}

impl<W: Wide, const DRAGS: usize, const MIXED: bool> Step<W, DRAGS, MIXED> {
    /// The drag coefficients in each lane of the three vectors of eight particles of
    /// `groups`: kⱼ, or 0 in the lanes of particles a restricted drag does not act on.
    #[inline(always)]
    fn coefficients(&self, groups: &[u16; LANES]) -> [[W::V; DRAGS]; 3] {
        let w = self.w;
        let mut lanes = [[w.zero(); DRAGS]; 3];
        let mut words = [0; LANES];
        for (word, &group) in words.iter_mut().zip(groups) {
            *word = i64::from(group);
        }
        let groups = w.load_words(words);
        for i in 0..DRAGS {
            let (k, restriction) = self.drags[i];
            // `step_block` makes every step with a restricted drag `MIXED`.
            match restriction {
                Some(group) if MIXED => {
                    let acts = w.equal(groups, w.splat(i64::from(group)));
                    let spread = w.spread_thirds(w.select(acts, k, w.zero()));
                    for j in 0..3 {
                        lanes[j][i] = spread[j];
                    }
                }
                _ => {
                    for vector in &mut lanes {
                        vector[i] = k;
                    }
                }
            }
        }
        lanes
    }

    /// Steps third `j` of eight particles' words in place ([`Wide::load_third`]), whose
    /// inverse masses are `masses` and drag coefficients `drags`.
    #[inline(always)]
    fn third(
        &self,
        j: usize,
        positions: &mut [Vec3<Fx>; LANES],
        velocities: &mut [Vec3<Fx>; LANES],
        forces: &[Vec3<Fx>; LANES],
        masses: W::V,
        drags: [W::V; DRAGS],
    ) {
        let w = self.w;
        let x = w.load_third(positions, j);
        let v = w.load_third(velocities, j);
        let f = w.load_third(forces, j);
        let (moved, kicked) = self.lanes(j, x, v, f, &MassLanes::new(w, masses), drags);
        w.store_third(positions, j, moved);
        w.store_third(velocities, j, kicked);
    }

    /// The new (x, v) of the lanes of vector `j` (0, 1 or 2 in the pattern) from x, v, the
    /// external force, 1/m and the drag coefficients. Every operation wraps; the block's
    /// bounds keep each exact result in range, so each is the checked operator's.
    #[inline(always)]
    fn lanes(
        &self,
        j: usize,
        x: W::V,
        v: W::V,
        external: W::V,
        m: &MassLanes<W>,
        drags: [W::V; DRAGS],
    ) -> (W::V, W::V) {
        let w = self.w;
        let mut force = external;
        for k in drags {
            force = w.sub(force, mul_fraction(w, v, k));
        }
        let a = w.add(self.gravity_biased[j], mul_mass_biased(w, force, m));
        let kicked = w.add(v, mul_fraction(w, a, self.h));
        let drifted = w.add(x, mul_fraction(w, kicked, self.h));
        if MIXED {
            (w.select(m.zero, x, drifted), w.select(m.zero, v, kicked))
        } else {
            (drifted, kicked)
        }
    }
}

/// 1/m for the lanes of one vector, with the halves [`mul_mass_biased`] uses.
struct MassLanes<W: Wide> {
    /// m; its low half read as signed is m_l.
    m: W::V,
    /// m_h = ⌊(m + 2³¹)/2³²⌋.
    high: W::V,
    /// The lanes where m = 0 (pinned or dead slot).
    zero: u8,
}

impl<W: Wide> MassLanes<W> {
    /// The halves of the masses in `m`, each in [0, 2⁶²).
    #[inline(always)]
    fn new(w: W, m: W::V) -> Self {
        Self {
            m,
            high: w.shift_right_unsigned(w.add(m, w.splat(1 << 31)), 32),
            zero: w.equal(m, w.zero()),
        }
    }
}

/// ⌊(a·c + 2³¹)/2³²⌋ per lane, for any a and 0 ≤ c < 2³¹: `mul_fraction`, the checked `*`
/// by a [`Fraction`].
#[inline(always)]
fn mul_fraction<W: Wide>(w: W, a: W::V, c: W::V) -> W::V {
    let high = w.mul_low_halves(w.shift_right_unsigned(a, 32), c);
    let low = w.mul_unsigned_low_halves(a, c);
    w.add(
        high,
        w.shift_right_unsigned(w.add(low, w.splat(1 << 31)), 32),
    )
}

/// ⌊(a·m + 2³¹)/2³²⌋ + 2³⁰ per lane (the checked `*` by 1/m, plus 2³⁰), modulo 2⁶⁴, for
/// |a| ≤ 2⁶² and 0 ≤ m < 2⁶² (module documentation, "Products").
#[inline(always)]
fn mul_mass_biased<W: Wide>(w: W, a: W::V, m: &MassLanes<W>) -> W::V {
    // a_h = ⌊(a + 2³¹)/2³²⌋ in the low half; the signed product reads a_l from the low
    // half of a.
    let a_high = w.shift_right_unsigned(w.add(a, w.splat(1 << 31)), 32);
    let high_high = w.shift_left(w.mul_low_halves(a_high, m.high), 32);
    let high_low = w.mul_low_halves(a_high, m.m);
    let low_high = w.mul_low_halves(a, m.high);
    // a_l·m_l + 2³¹ + 2⁶² ∈ [2³², 2⁶³ + 2³¹]: its logical shift is the floor plus 2³⁰.
    let low_low = w.shift_right_unsigned(
        w.add(w.mul_low_halves(a, m.m), w.splat((1 << 62) | (1 << 31))),
        32,
    );
    w.add(w.add(high_high, high_low), w.add(low_high, low_low))
}

/// The lane products, for the tests: eight pairs at a time.
#[cfg(test)]
pub(super) mod products {
    use super::{MassLanes, mul_fraction, mul_mass_biased};
    use crate::math::wide::{Wide, kernel_entry};

    kernel_entry! {
        /// `mul_fraction` of each pair aᵢ, cᵢ (0 ≤ cᵢ < 2³¹).
        pub(in crate::particles::fused_euler) fn mul_fraction_on(a: [i64; 8], c: [i64; 8]) -> [i64; 8] = fraction;
    }

    kernel_entry! {
        /// `mul_mass_biased` of each pair aᵢ, mᵢ (|aᵢ| ≤ 2⁶², 0 ≤ mᵢ < 2⁶²).
        pub(in crate::particles::fused_euler) fn mul_mass_biased_on(a: [i64; 8], m: [i64; 8]) -> [i64; 8] = mass;
    }

    #[inline(always)]
    fn fraction<W: Wide>(w: W, a: [i64; 8], c: [i64; 8]) -> [i64; 8] {
        w.store_words(mul_fraction(w, w.load_words(a), w.load_words(c)))
    }

    #[inline(always)]
    fn mass<W: Wide>(w: W, a: [i64; 8], m: [i64; 8]) -> [i64; 8] {
        let m = MassLanes::new(w, w.load_words(m));
        w.store_words(mul_mass_biased(w, w.load_words(a), &m))
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
