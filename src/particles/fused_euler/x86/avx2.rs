//! The AVX2 kernel: four `i64` lanes, four particles (three vectors) at a time. The
//! arithmetic and why it gives the general path's bits are in the parent module.

use core::arch::x86_64::{
    __m256i, _mm256_add_epi64, _mm256_and_si256, _mm256_blendv_epi8, _mm256_cmpeq_epi64,
    _mm256_cmpgt_epi64, _mm256_extract_epi64, _mm256_loadu_si256, _mm256_mul_epi32,
    _mm256_mul_epu32, _mm256_or_si256, _mm256_permute4x64_epi64, _mm256_set_epi64x,
    _mm256_set1_epi64x, _mm256_setzero_si256, _mm256_slli_epi64, _mm256_srli_epi64,
    _mm256_storeu_si256, _mm256_sub_epi64, _mm256_xor_si256,
};

use super::super::Block;
use super::{BlockBits, Constants, bit_length};
use crate::math::{Fx, Vec3};

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
    let [gx, gy, gz] = constants.gravity_biased();
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
            // `step_block` makes every step with a restricted drag `MIXED`.
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
/// by a [`Fraction`](crate::math::Fraction).
#[inline]
#[target_feature(enable = "avx2")]
fn mul_fraction(a: __m256i, c: __m256i) -> __m256i {
    let high = _mm256_mul_epi32(_mm256_srli_epi64::<32>(a), c);
    let low = _mm256_srli_epi64::<32>(_mm256_add_epi64(_mm256_mul_epu32(a, c), half()));
    _mm256_add_epi64(high, low)
}

/// ⌊(a·m + 2³¹)/2³²⌋ + 2³⁰ per lane (the checked `*` by 1/m, plus 2³⁰), modulo 2⁶⁴, for
/// |a| ≤ 2⁶² and 0 ≤ m < 2⁶² (the parent module's documentation, "Products").
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

/// The components of four vectors, as three vectors of lanes.
#[inline]
#[target_feature(enable = "avx2")]
fn load(values: &[Vec3<Fx>; 4]) -> [__m256i; 3] {
    let p = values.as_ptr().cast::<__m256i>();
    // SAFETY: `values` is 96 bytes of `i64` (layout asserted in the parent module); the
    // three unaligned 32-byte reads at byte 0, 32 and 64 stay inside it.
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
    // SAFETY: `values` is 32 bytes of `i64` (layout asserted in the parent module); the
    // read is unaligned.
    unsafe { _mm256_loadu_si256(values.as_ptr().cast::<__m256i>()) }
}

/// Writes three vectors of lanes back as four vectors.
#[inline]
#[target_feature(enable = "avx2")]
fn store(values: &mut [Vec3<Fx>; 4], lanes: [__m256i; 3]) {
    let p = values.as_mut_ptr().cast::<__m256i>();
    // SAFETY: `values` is 96 bytes of `i64` (layout asserted in the parent module),
    // borrowed mutably; the three unaligned 32-byte writes at byte 0, 32 and 64 stay
    // inside it, and every bit pattern is a valid `Fx`.
    unsafe {
        _mm256_storeu_si256(p, lanes[0]);
        _mm256_storeu_si256(p.add(1), lanes[1]);
        _mm256_storeu_si256(p.add(2), lanes[2]);
    }
}

/// [`mul_fraction`] of each pair, for the tests.
#[cfg(test)]
#[target_feature(enable = "avx2")]
pub(super) fn mul_fraction_on(a: &[i64], c: &[i64]) -> Vec<i64> {
    let (a, c) = (a.as_chunks::<4>().0, c.as_chunks::<4>().0);
    a.iter()
        .zip(c)
        .flat_map(|(a, c)| values(mul_fraction(lanes(a), lanes(c))))
        .collect()
}

/// [`mul_mass_biased`] of each pair, for the tests.
#[cfg(test)]
#[target_feature(enable = "avx2")]
pub(super) fn mul_mass_biased_on(a: &[i64], m: &[i64]) -> Vec<i64> {
    let (a, m) = (a.as_chunks::<4>().0, m.as_chunks::<4>().0);
    a.iter()
        .zip(m)
        .flat_map(|(a, m)| values(mul_mass_biased(lanes(a), &MassLanes::new(lanes(m)))))
        .collect()
}

#[cfg(test)]
#[target_feature(enable = "avx2")]
fn lanes(values: &[i64; 4]) -> __m256i {
    _mm256_set_epi64x(values[3], values[2], values[1], values[0])
}

#[cfg(test)]
#[target_feature(enable = "avx2")]
fn values(lanes: __m256i) -> [i64; 4] {
    [
        _mm256_extract_epi64::<0>(lanes),
        _mm256_extract_epi64::<1>(lanes),
        _mm256_extract_epi64::<2>(lanes),
        _mm256_extract_epi64::<3>(lanes),
    ]
}
