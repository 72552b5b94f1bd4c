//! The fused step for I32F32 in AVX2: a bound check per block, then the block in place,
//! four `i64` lanes at a time, without range checks.
//!
//! # Layout
//!
//! Positions, velocities and external forces are slices of `Vec3<Fx>`: runs of `i64` (x, y,
//! z, x, y, z, …; `Vec3` is `repr(C)` and `Fx` a transparent `i64`). Four particles are
//! twelve values, three vectors. Every operation applies to each component alike; only
//! 1/m (one per particle, spread over the lanes of its three components), gravity (a
//! pattern of components that repeats every three vectors) and, for a drag restricted to a
//! group, the drag coefficient (0 in the lanes of particles of other groups: v·0 = 0 and
//! F − 0 = F, as if the drag were skipped) differ from lane to lane.
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
//! in it and its results are the exact rounded values. The kernel computes each of them
//! exactly modulo 2⁶⁴ (wrapping additions, and the products below), and a value in range is
//! determined by its residue, so the kernel's bits are the general path's. Blocks that
//! fail the check (values within a factor of about eight of the range limits, or a huge
//! 1/m) and a last block whose length is not a multiple of four take the portable guarded
//! computation, which falls back to the general path when it must. Pinned and dead slots
//! (1/m = 0) are computed like the others and then given back their old x and v.
//!
//! # Products
//!
//! AVX2 multiplies 32 by 32 bits into 64 (`vpmuldq` signed, `vpmuludq` unsigned), so each
//! product is assembled from halves. The checked `*` is ⌊(a·b + 2³¹)/2³²⌋ (to nearest,
//! ties toward +∞).
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
//!   by 32 is the floor plus 2³⁰, which the kernel takes off gravity beforehand. Each term,
//!   hence the sum, is exact modulo 2⁶⁴.
//!
//! The proptests in `tests/avx2.rs` compare the lane products with the checked `*`, blocks
//! with the general path and steps with the portable path, bit for bit, on values from
//! zero to the range limits, rounding ties and negative values included.

use core::any::Any;
use core::arch::x86_64::{
    __m256i, _mm256_add_epi64, _mm256_and_si256, _mm256_blendv_epi8, _mm256_cmpeq_epi64,
    _mm256_cmpgt_epi64, _mm256_extract_epi64, _mm256_loadu_si256, _mm256_mul_epi32,
    _mm256_mul_epu32, _mm256_or_si256, _mm256_permute4x64_epi64, _mm256_set_epi64x,
    _mm256_set1_epi64x, _mm256_setzero_si256, _mm256_slli_epi64, _mm256_srli_epi64,
    _mm256_storeu_si256, _mm256_sub_epi64, _mm256_xor_si256,
};
use core::mem::{offset_of, size_of};

use super::{Block, Buffers, for_each_block};
use crate::math::{Fraction, Fx, Real, Vec3};
use crate::particles::forces::LinearField;
use crate::particles::storage::{Attributes, Kinematics};

// The layout the loads and stores rely on: `Fx` is one `i64` (`repr(transparent)` over the
// `fixed` crate's `repr(transparent)` `FixedI64`), `Vec3<Fx>` is x, y, z in a row.
const _: () = {
    assert!(size_of::<Fx>() == 8);
    assert!(size_of::<Vec3<Fx>>() == 24);
    assert!(offset_of!(Vec3<Fx>, x) == 0);
    assert!(offset_of!(Vec3<Fx>, y) == 8);
    assert!(offset_of!(Vec3<Fx>, z) == 16);
};

/// The fused step with this kernel, when it applies: `R` is I32F32 and the processor has
/// AVX2. Returns whether it ran.
pub(super) fn step<R: Real>(
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
    if !available() {
        return false;
    }
    let constants = Constants::new(field, h);
    let mut buffers = Buffers::new();
    for_each_block(kinematics, attributes, |mut block| {
        // SAFETY: `available()` above found AVX2 on this processor.
        if !unsafe { step_block(&mut block, &constants) } {
            block.step_portable(&mut buffers, field, h);
        }
    });
    true
}

/// Whether the processor running this has AVX2.
pub(super) fn available() -> bool {
    std::arch::is_x86_feature_detected!("avx2")
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

/// Steps the block in place when its length is a multiple of four and its bounds keep
/// every value in range; returns whether it did (if not, the block is untouched).
#[target_feature(enable = "avx2")]
pub(super) fn step_block(block: &mut Block<'_, Fx>, constants: &Constants) -> bool {
    if !block.positions.len().is_multiple_of(4) {
        return false;
    }
    let bits = block_bits(block);
    if !constants.in_range(bits) {
        return false;
    }
    if bits.pinned || constants.restricted {
        step_in_place_with::<true>(block, constants);
    } else {
        step_in_place_with::<false>(block, constants);
    }
    true
}

/// The bit lengths of the block's largest magnitudes (its length a multiple of four).
#[target_feature(enable = "avx2")]
fn block_bits(block: &Block<'_, Fx>) -> BlockBits {
    let zero = _mm256_setzero_si256();
    // v ^ (v >> 63) per lane, the arithmetic shift being a comparison with zero.
    let magnitude = |v: __m256i| _mm256_xor_si256(v, _mm256_cmpgt_epi64(zero, v));
    let [mut x, mut v, mut f, mut m, mut pinned] = [zero; 5];
    let (positions, _) = block.positions.as_chunks::<4>();
    let (velocities, _) = block.velocities.as_chunks::<4>();
    let (forces, _) = block.external_forces.as_chunks::<4>();
    let (inv_masses, _) = block.inv_masses.as_chunks::<4>();
    for (((x4, v4), f4), m4) in positions.iter().zip(velocities).zip(forces).zip(inv_masses) {
        for lanes in load(x4) {
            x = _mm256_or_si256(x, magnitude(lanes));
        }
        for lanes in load(v4) {
            v = _mm256_or_si256(v, magnitude(lanes));
        }
        for lanes in load(f4) {
            f = _mm256_or_si256(f, magnitude(lanes));
        }
        // A negative m sets the sign bit: 64 bits.
        let masses = load_masses(m4);
        m = _mm256_or_si256(m, masses);
        pinned = _mm256_or_si256(pinned, _mm256_cmpeq_epi64(masses, zero));
    }
    let bits = |lanes: __m256i| {
        let all = _mm256_extract_epi64::<0>(lanes)
            | _mm256_extract_epi64::<1>(lanes)
            | _mm256_extract_epi64::<2>(lanes)
            | _mm256_extract_epi64::<3>(lanes);
        bit_length(all as u64)
    };
    BlockBits {
        positions: bits(x),
        velocities: bits(v),
        forces: bits(f),
        inv_masses: bits(m),
        pinned: bits(pinned) != 0,
    }
}

/// [`step_in_place`] for the block's drag count.
#[inline]
#[target_feature(enable = "avx2")]
fn step_in_place_with<const MIXED: bool>(block: &mut Block<'_, Fx>, constants: &Constants) {
    // One instance per drag count, so that the drag loop unrolls.
    match constants.drag_count {
        0 => step_in_place::<0, MIXED>(block, constants),
        1 => step_in_place::<1, MIXED>(block, constants),
        2 => step_in_place::<2, MIXED>(block, constants),
        3 => step_in_place::<3, MIXED>(block, constants),
        _ => step_in_place::<4, MIXED>(block, constants),
    }
}

/// The step of a block that stays in range, in place, for `DRAGS` drags. `MIXED` when the
/// lanes do not all take the same path: some slot of the block is pinned or dead (its
/// lanes keep x and v) or some drag is restricted to a group (its coefficient is 0 in the
/// lanes of other groups: v·0 = 0 and F − 0 = F, the same as leaving F alone).
#[inline]
#[target_feature(enable = "avx2")]
fn step_in_place<const DRAGS: usize, const MIXED: bool>(
    block: &mut Block<'_, Fx>,
    constants: &Constants,
) {
    // g − 2³⁰, which `mul_mass_biased`'s 2³⁰ completes.
    let [gx, gy, gz] = constants.gravity.map(|g| g.wrapping_sub(1 << 30));
    let mut drags = [(_mm256_setzero_si256(), None); DRAGS];
    for (lanes, &(k, group)) in drags.iter_mut().zip(&constants.drags) {
        *lanes = (_mm256_set1_epi64x(k), group);
    }
    let step = Step::<DRAGS, MIXED> {
        // The components' lane pattern over three vectors: (x y z x) (y z x y) (z x y z).
        gravity_biased: [
            _mm256_set_epi64x(gx, gz, gy, gx),
            _mm256_set_epi64x(gy, gx, gz, gy),
            _mm256_set_epi64x(gz, gy, gx, gz),
        ],
        drags,
        h: _mm256_set1_epi64x(constants.h),
    };
    let (positions, _) = block.positions.as_chunks_mut::<4>();
    let (velocities, _) = block.velocities.as_chunks_mut::<4>();
    let (forces, _) = block.external_forces.as_chunks::<4>();
    let (inv_masses, _) = block.inv_masses.as_chunks::<4>();
    let (groups, _) = block.groups.as_chunks::<4>();
    let kinematics = positions.iter_mut().zip(velocities.iter_mut());
    let attributes = forces.iter().zip(inv_masses).zip(groups);
    for ((x4, v4), ((f4, m4), g4)) in kinematics.zip(attributes) {
        let [m0, m1, m2] = spread(load_masses(m4)).map(|m| MassLanes::new(m));
        let [k0, k1, k2] = step.coefficients(g4);
        let ([x0, x1, x2], [v0, v1, v2], [f0, f1, f2]) = (load(x4), load(v4), load(f4));
        let (x0, v0) = step.lanes(0, x0, v0, f0, &m0, k0);
        let (x1, v1) = step.lanes(1, x1, v1, f1, &m1, k1);
        let (x2, v2) = step.lanes(2, x2, v2, f2, &m2, k2);
        store(x4, [x0, x1, x2]);
        store(v4, [v0, v1, v2]);
    }
}

/// The step's constants in lanes.
struct Step<const DRAGS: usize, const MIXED: bool> {
    /// g − 2³⁰ in the lane pattern of each of the three vectors.
    gravity_biased: [__m256i; 3],
    /// kⱼ in every lane, with the group it is restricted to.
    drags: [(__m256i, Option<u16>); DRAGS],
    h: __m256i,
}

impl<const DRAGS: usize, const MIXED: bool> Step<DRAGS, MIXED> {
    /// The drag coefficients in each lane of the three vectors of four particles of
    /// `groups`: kⱼ, or 0 in the lanes of particles a restricted drag does not act on.
    #[inline]
    #[target_feature(enable = "avx2")]
    fn coefficients(&self, groups: &[u16; 4]) -> [[__m256i; DRAGS]; 3] {
        let mut lanes = [[_mm256_setzero_si256(); DRAGS]; 3];
        let groups = _mm256_set_epi64x(
            i64::from(groups[3]),
            i64::from(groups[2]),
            i64::from(groups[1]),
            i64::from(groups[0]),
        );
        for (i, &(k, restriction)) in self.drags.iter().enumerate() {
            match restriction {
                Some(group) if MIXED => {
                    let acts = _mm256_cmpeq_epi64(groups, _mm256_set1_epi64x(i64::from(group)));
                    for (vector, acts) in lanes.iter_mut().zip(spread(acts)) {
                        vector[i] = _mm256_and_si256(acts, k);
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

    /// The new (x, v) of the lanes of vector `j` (0, 1 or 2 in the pattern) from x, v, the
    /// external force, 1/m and the drag coefficients. Every operation wraps; the block's
    /// bounds keep each exact result in range, so each is the checked operator's.
    #[inline]
    #[target_feature(enable = "avx2")]
    fn lanes(
        &self,
        j: usize,
        x: __m256i,
        v: __m256i,
        external: __m256i,
        m: &MassLanes,
        drags: [__m256i; DRAGS],
    ) -> (__m256i, __m256i) {
        let mut force = external;
        for k in drags {
            force = _mm256_sub_epi64(force, mul_fraction(v, k));
        }
        let a = _mm256_add_epi64(self.gravity_biased[j], mul_mass_biased(force, m));
        let kicked = _mm256_add_epi64(v, mul_fraction(a, self.h));
        let drifted = _mm256_add_epi64(x, mul_fraction(kicked, self.h));
        if MIXED {
            (
                _mm256_blendv_epi8(drifted, x, m.zero),
                _mm256_blendv_epi8(kicked, v, m.zero),
            )
        } else {
            (drifted, kicked)
        }
    }
}

/// 1/m for the four lanes of one vector, with the halves [`mul_mass_biased`] uses.
struct MassLanes {
    /// m; its low half read as signed is m_l.
    m: __m256i,
    /// m_h = ⌊(m + 2³¹)/2³²⌋.
    high: __m256i,
    /// All ones where m = 0 (pinned or dead slot).
    zero: __m256i,
}

impl MassLanes {
    /// The halves of the masses in `m`, each in [0, 2⁶²).
    #[inline]
    #[target_feature(enable = "avx2")]
    fn new(m: __m256i) -> Self {
        Self {
            m,
            high: _mm256_srli_epi64::<32>(_mm256_add_epi64(m, half())),
            zero: _mm256_cmpeq_epi64(m, _mm256_setzero_si256()),
        }
    }
}

/// (a₀, a₁, a₂, a₃), one per particle, spread over the lane pattern of their components:
/// (a₀ a₀ a₀ a₁) (a₁ a₁ a₂ a₂) (a₂ a₃ a₃ a₃).
#[inline]
#[target_feature(enable = "avx2")]
fn spread(a: __m256i) -> [__m256i; 3] {
    [
        _mm256_permute4x64_epi64::<0b01_00_00_00>(a),
        _mm256_permute4x64_epi64::<0b10_10_01_01>(a),
        _mm256_permute4x64_epi64::<0b11_11_11_10>(a),
    ]
}

/// 2³¹ in every lane.
#[inline]
#[target_feature(enable = "avx2")]
fn half() -> __m256i {
    _mm256_set1_epi64x(1 << 31)
}

/// ⌊(a·c + 2³¹)/2³²⌋ per lane, for any a and 0 ≤ c < 2³¹: `mul_fraction`, the checked `*`
/// by a [`Fraction`].
#[inline]
#[target_feature(enable = "avx2")]
fn mul_fraction(a: __m256i, c: __m256i) -> __m256i {
    let high = _mm256_mul_epi32(_mm256_srli_epi64::<32>(a), c);
    let low = _mm256_srli_epi64::<32>(_mm256_add_epi64(_mm256_mul_epu32(a, c), half()));
    _mm256_add_epi64(high, low)
}

/// ⌊(a·m + 2³¹)/2³²⌋ + 2³⁰ per lane (the checked `*` by 1/m, plus 2³⁰), modulo 2⁶⁴, for
/// |a| ≤ 2⁶² and 0 ≤ m < 2⁶² (module documentation, "Products").
#[inline]
#[target_feature(enable = "avx2")]
fn mul_mass_biased(a: __m256i, m: &MassLanes) -> __m256i {
    // a_h = ⌊(a + 2³¹)/2³²⌋ in the low half; `vpmuldq` reads a_l from the low half of a.
    let a_high = _mm256_srli_epi64::<32>(_mm256_add_epi64(a, half()));
    let high_high = _mm256_slli_epi64::<32>(_mm256_mul_epi32(a_high, m.high));
    let high_low = _mm256_mul_epi32(a_high, m.m);
    let low_high = _mm256_mul_epi32(a, m.high);
    // a_l·m_l + 2³¹ + 2⁶² ∈ [2³², 2⁶³ + 2³¹]: its logical shift is the floor plus 2³⁰.
    let low_low = _mm256_srli_epi64::<32>(_mm256_add_epi64(
        _mm256_mul_epi32(a, m.m),
        _mm256_set1_epi64x((1 << 62) | (1 << 31)),
    ));
    _mm256_add_epi64(
        _mm256_add_epi64(high_high, high_low),
        _mm256_add_epi64(low_high, low_low),
    )
}

/// The twelve components of four vectors, as three vectors of lanes.
#[inline]
#[target_feature(enable = "avx2")]
fn load(values: &[Vec3<Fx>; 4]) -> [__m256i; 3] {
    let p = values.as_ptr().cast::<__m256i>();
    // SAFETY: `values` is 96 bytes of `i64` (layout asserted above); the three unaligned
    // 32-byte reads at byte 0, 32 and 64 stay inside it.
    unsafe {
        [
            _mm256_loadu_si256(p),
            _mm256_loadu_si256(p.add(1)),
            _mm256_loadu_si256(p.add(2)),
        ]
    }
}

/// Four inverse masses, one per lane.
#[inline]
#[target_feature(enable = "avx2")]
fn load_masses(values: &[Fx; 4]) -> __m256i {
    // SAFETY: `values` is 32 bytes of `i64` (layout asserted above); the read is unaligned.
    unsafe { _mm256_loadu_si256(values.as_ptr().cast::<__m256i>()) }
}

/// Writes three vectors of lanes back as four vectors.
#[inline]
#[target_feature(enable = "avx2")]
fn store(values: &mut [Vec3<Fx>; 4], lanes: [__m256i; 3]) {
    let p = values.as_mut_ptr().cast::<__m256i>();
    // SAFETY: `values` is 96 bytes of `i64` (layout asserted above), borrowed mutably; the
    // three unaligned 32-byte writes at byte 0, 32 and 64 stay inside it, and every bit
    // pattern is a valid `Fx`.
    unsafe {
        _mm256_storeu_si256(p, lanes[0]);
        _mm256_storeu_si256(p.add(1), lanes[1]);
        _mm256_storeu_si256(p.add(2), lanes[2]);
    }
}

/// The lane operations on arrays, for the tests.
#[cfg(test)]
pub(super) mod on_arrays {
    use super::{__m256i, _mm256_extract_epi64, _mm256_set_epi64x, MassLanes};

    #[target_feature(enable = "avx2")]
    fn lanes(values: [i64; 4]) -> __m256i {
        _mm256_set_epi64x(values[3], values[2], values[1], values[0])
    }

    #[target_feature(enable = "avx2")]
    fn values(lanes: __m256i) -> [i64; 4] {
        [
            _mm256_extract_epi64::<0>(lanes),
            _mm256_extract_epi64::<1>(lanes),
            _mm256_extract_epi64::<2>(lanes),
            _mm256_extract_epi64::<3>(lanes),
        ]
    }

    /// [`super::mul_fraction`] on four lanes.
    #[target_feature(enable = "avx2")]
    pub(in super::super) fn mul_fraction(a: [i64; 4], c: [i64; 4]) -> [i64; 4] {
        values(super::mul_fraction(lanes(a), lanes(c)))
    }

    /// [`super::mul_mass_biased`] on four lanes.
    #[target_feature(enable = "avx2")]
    pub(in super::super) fn mul_mass_biased(a: [i64; 4], m: [i64; 4]) -> [i64; 4] {
        values(super::mul_mass_biased(lanes(a), &MassLanes::new(lanes(m))))
    }
}
