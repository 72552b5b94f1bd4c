//! The AVX-512 kernel: eight `i64` lanes, eight particles (three vectors) at a time; the
//! AVX2 kernel's operations, twice as wide, with masks for the per-lane choices. The
//! arithmetic and why it gives the general path's bits are in the parent module.

use core::arch::x86_64::{
    __m512i, __mmask8, _mm512_add_epi64, _mm512_cmpeq_epi64_mask, _mm512_loadu_si512,
    _mm512_mask_blend_epi64, _mm512_maskz_mov_epi64, _mm512_mul_epi32, _mm512_mul_epu32,
    _mm512_or_si512, _mm512_permutexvar_epi64, _mm512_reduce_or_epi64, _mm512_set_epi64,
    _mm512_set1_epi64, _mm512_setzero_si512, _mm512_slli_epi64, _mm512_srai_epi64,
    _mm512_srli_epi64, _mm512_storeu_si512, _mm512_sub_epi64, _mm512_xor_si512,
};

use super::super::Block;
use super::{BlockBits, Constants, bit_length};
use crate::math::{Fx, Vec3};

/// Steps the block in place when its length is a multiple of eight and its bounds keep
/// every value in range; returns whether it did (if not, the block is untouched).
#[target_feature(enable = "avx512f")]
pub(super) fn step_block(block: &mut Block<'_, Fx>, constants: &Constants) -> bool {
    if !block.positions.len().is_multiple_of(8) {
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

/// The bit lengths of the block's largest magnitudes (its length a multiple of eight).
#[target_feature(enable = "avx512f")]
fn block_bits(block: &Block<'_, Fx>) -> BlockBits {
    let zero = _mm512_setzero_si512();
    // v ^ (v >> 63) per lane.
    let magnitude = |v: __m512i| _mm512_xor_si512(v, _mm512_srai_epi64::<63>(v));
    let [mut x, mut v, mut f, mut m] = [zero; 4];
    let mut pinned: __mmask8 = 0;
    let (positions, _) = block.positions.as_chunks::<8>();
    let (velocities, _) = block.velocities.as_chunks::<8>();
    let (forces, _) = block.external_forces.as_chunks::<8>();
    let (inv_masses, _) = block.inv_masses.as_chunks::<8>();
    for (((x8, v8), f8), m8) in positions.iter().zip(velocities).zip(forces).zip(inv_masses) {
        for lanes in load(x8) {
            x = _mm512_or_si512(x, magnitude(lanes));
        }
        for lanes in load(v8) {
            v = _mm512_or_si512(v, magnitude(lanes));
        }
        for lanes in load(f8) {
            f = _mm512_or_si512(f, magnitude(lanes));
        }
        // A negative m sets the sign bit: 64 bits.
        let masses = load_masses(m8);
        m = _mm512_or_si512(m, masses);
        pinned |= _mm512_cmpeq_epi64_mask(masses, zero);
    }
    let bits = |lanes: __m512i| bit_length(_mm512_reduce_or_epi64(lanes) as u64);
    BlockBits {
        positions: bits(x),
        velocities: bits(v),
        forces: bits(f),
        inv_masses: bits(m),
        pinned: pinned != 0,
    }
}

/// [`step_in_place`] for the block's drag count.
#[inline]
#[target_feature(enable = "avx512f")]
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
#[target_feature(enable = "avx512f")]
fn step_in_place<const DRAGS: usize, const MIXED: bool>(
    block: &mut Block<'_, Fx>,
    constants: &Constants,
) {
    let [gx, gy, gz] = constants.gravity_biased();
    let mut drags = [(_mm512_setzero_si512(), None); DRAGS];
    for (lanes, &(k, group)) in drags.iter_mut().zip(&constants.drags) {
        *lanes = (_mm512_set1_epi64(k), group);
    }
    let step = Step::<DRAGS, MIXED> {
        // The components' lane pattern over three vectors: (x y z x y z x y)
        // (z x y z x y z x) (y z x y z x y z).
        gravity_biased: [
            _mm512_set_epi64(gy, gx, gz, gy, gx, gz, gy, gx),
            _mm512_set_epi64(gx, gz, gy, gx, gz, gy, gx, gz),
            _mm512_set_epi64(gz, gy, gx, gz, gy, gx, gz, gy),
        ],
        drags,
        h: _mm512_set1_epi64(constants.h),
    };
    let (positions, _) = block.positions.as_chunks_mut::<8>();
    let (velocities, _) = block.velocities.as_chunks_mut::<8>();
    let (forces, _) = block.external_forces.as_chunks::<8>();
    let (inv_masses, _) = block.inv_masses.as_chunks::<8>();
    let (groups, _) = block.groups.as_chunks::<8>();
    let kinematics = positions.iter_mut().zip(velocities.iter_mut());
    let attributes = forces.iter().zip(inv_masses).zip(groups);
    for ((x8, v8), ((f8, m8), g8)) in kinematics.zip(attributes) {
        let [m0, m1, m2] = spread(load_masses(m8)).map(|m| MassLanes::new(m));
        let [k0, k1, k2] = step.coefficients(g8);
        let ([x0, x1, x2], [v0, v1, v2], [f0, f1, f2]) = (load(x8), load(v8), load(f8));
        let (x0, v0) = step.lanes(0, x0, v0, f0, &m0, k0);
        let (x1, v1) = step.lanes(1, x1, v1, f1, &m1, k1);
        let (x2, v2) = step.lanes(2, x2, v2, f2, &m2, k2);
        store(x8, [x0, x1, x2]);
        store(v8, [v0, v1, v2]);
    }
}

/// The step's constants in lanes.
struct Step<const DRAGS: usize, const MIXED: bool> {
    /// g − 2³⁰ in the lane pattern of each of the three vectors.
    gravity_biased: [__m512i; 3],
    /// kⱼ in every lane, with the group it is restricted to.
    drags: [(__m512i, Option<u16>); DRAGS],
    h: __m512i,
}

impl<const DRAGS: usize, const MIXED: bool> Step<DRAGS, MIXED> {
    /// The drag coefficients in each lane of the three vectors of eight particles of
    /// `groups`: kⱼ, or 0 in the lanes of particles a restricted drag does not act on.
    #[inline]
    #[target_feature(enable = "avx512f")]
    fn coefficients(&self, groups: &[u16; 8]) -> [[__m512i; DRAGS]; 3] {
        let mut lanes = [[_mm512_setzero_si512(); DRAGS]; 3];
        let groups = _mm512_set_epi64(
            i64::from(groups[7]),
            i64::from(groups[6]),
            i64::from(groups[5]),
            i64::from(groups[4]),
            i64::from(groups[3]),
            i64::from(groups[2]),
            i64::from(groups[1]),
            i64::from(groups[0]),
        );
        for (i, &(k, restriction)) in self.drags.iter().enumerate() {
            // `step_block` makes every step with a restricted drag `MIXED`.
            match restriction {
                Some(group) if MIXED => {
                    let group = _mm512_set1_epi64(i64::from(group));
                    for (vector, groups) in lanes.iter_mut().zip(spread(groups)) {
                        vector[i] =
                            _mm512_maskz_mov_epi64(_mm512_cmpeq_epi64_mask(groups, group), k);
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
    #[target_feature(enable = "avx512f")]
    fn lanes(
        &self,
        j: usize,
        x: __m512i,
        v: __m512i,
        external: __m512i,
        m: &MassLanes,
        drags: [__m512i; DRAGS],
    ) -> (__m512i, __m512i) {
        let mut force = external;
        for k in drags {
            force = _mm512_sub_epi64(force, mul_fraction(v, k));
        }
        let a = _mm512_add_epi64(self.gravity_biased[j], mul_mass_biased(force, m));
        let kicked = _mm512_add_epi64(v, mul_fraction(a, self.h));
        let drifted = _mm512_add_epi64(x, mul_fraction(kicked, self.h));
        if MIXED {
            (
                _mm512_mask_blend_epi64(m.zero, drifted, x),
                _mm512_mask_blend_epi64(m.zero, kicked, v),
            )
        } else {
            (drifted, kicked)
        }
    }
}

/// 1/m for the eight lanes of one vector, with the halves [`mul_mass_biased`] uses.
struct MassLanes {
    /// m; its low half read as signed is m_l.
    m: __m512i,
    /// m_h = ⌊(m + 2³¹)/2³²⌋.
    high: __m512i,
    /// Set where m = 0 (pinned or dead slot).
    zero: __mmask8,
}

impl MassLanes {
    /// The halves of the masses in `m`, each in [0, 2⁶²).
    #[inline]
    #[target_feature(enable = "avx512f")]
    fn new(m: __m512i) -> Self {
        Self {
            m,
            high: _mm512_srli_epi64::<32>(_mm512_add_epi64(m, half())),
            zero: _mm512_cmpeq_epi64_mask(m, _mm512_setzero_si512()),
        }
    }
}

/// (a₀, …, a₇), one per particle, spread over the lane pattern of their components:
/// (a₀ a₀ a₀ a₁ a₁ a₁ a₂ a₂) (a₂ a₃ a₃ a₃ a₄ a₄ a₄ a₅) (a₅ a₅ a₆ a₆ a₆ a₇ a₇ a₇).
#[inline]
#[target_feature(enable = "avx512f")]
fn spread(a: __m512i) -> [__m512i; 3] {
    [
        _mm512_permutexvar_epi64(_mm512_set_epi64(2, 2, 1, 1, 1, 0, 0, 0), a),
        _mm512_permutexvar_epi64(_mm512_set_epi64(5, 4, 4, 4, 3, 3, 3, 2), a),
        _mm512_permutexvar_epi64(_mm512_set_epi64(7, 7, 7, 6, 6, 6, 5, 5), a),
    ]
}

/// 2³¹ in every lane.
#[inline]
#[target_feature(enable = "avx512f")]
fn half() -> __m512i {
    _mm512_set1_epi64(1 << 31)
}

/// ⌊(a·c + 2³¹)/2³²⌋ per lane, for any a and 0 ≤ c < 2³¹: `mul_fraction`, the checked `*`
/// by a [`Fraction`](crate::math::Fraction).
#[inline]
#[target_feature(enable = "avx512f")]
fn mul_fraction(a: __m512i, c: __m512i) -> __m512i {
    let high = _mm512_mul_epi32(_mm512_srli_epi64::<32>(a), c);
    let low = _mm512_srli_epi64::<32>(_mm512_add_epi64(_mm512_mul_epu32(a, c), half()));
    _mm512_add_epi64(high, low)
}

/// ⌊(a·m + 2³¹)/2³²⌋ + 2³⁰ per lane (the checked `*` by 1/m, plus 2³⁰), modulo 2⁶⁴, for
/// |a| ≤ 2⁶² and 0 ≤ m < 2⁶² (the parent module's documentation, "Products").
#[inline]
#[target_feature(enable = "avx512f")]
fn mul_mass_biased(a: __m512i, m: &MassLanes) -> __m512i {
    // a_h = ⌊(a + 2³¹)/2³²⌋ in the low half; `vpmuldq` reads a_l from the low half of a.
    let a_high = _mm512_srli_epi64::<32>(_mm512_add_epi64(a, half()));
    let high_high = _mm512_slli_epi64::<32>(_mm512_mul_epi32(a_high, m.high));
    let high_low = _mm512_mul_epi32(a_high, m.m);
    let low_high = _mm512_mul_epi32(a, m.high);
    // a_l·m_l + 2³¹ + 2⁶² ∈ [2³², 2⁶³ + 2³¹]: its logical shift is the floor plus 2³⁰.
    let low_low = _mm512_srli_epi64::<32>(_mm512_add_epi64(
        _mm512_mul_epi32(a, m.m),
        _mm512_set1_epi64((1 << 62) | (1 << 31)),
    ));
    _mm512_add_epi64(
        _mm512_add_epi64(high_high, high_low),
        _mm512_add_epi64(low_high, low_low),
    )
}

/// The components of eight vectors, as three vectors of lanes.
#[inline]
#[target_feature(enable = "avx512f")]
fn load(values: &[Vec3<Fx>; 8]) -> [__m512i; 3] {
    let p = values.as_ptr().cast::<__m512i>();
    // SAFETY: `values` is 192 bytes of `i64` (layout asserted in the parent module); the
    // three unaligned 64-byte reads at byte 0, 64 and 128 stay inside it.
    unsafe {
        [
            _mm512_loadu_si512(p),
            _mm512_loadu_si512(p.add(1)),
            _mm512_loadu_si512(p.add(2)),
        ]
    }
}

/// Eight inverse masses, one per lane.
#[inline]
#[target_feature(enable = "avx512f")]
fn load_masses(values: &[Fx; 8]) -> __m512i {
    // SAFETY: `values` is 64 bytes of `i64` (layout asserted in the parent module); the
    // read is unaligned.
    unsafe { _mm512_loadu_si512(values.as_ptr().cast::<__m512i>()) }
}

/// Writes three vectors of lanes back as eight vectors.
#[inline]
#[target_feature(enable = "avx512f")]
fn store(values: &mut [Vec3<Fx>; 8], lanes: [__m512i; 3]) {
    let p = values.as_mut_ptr().cast::<__m512i>();
    // SAFETY: `values` is 192 bytes of `i64` (layout asserted in the parent module),
    // borrowed mutably; the three unaligned 64-byte writes at byte 0, 64 and 128 stay
    // inside it, and every bit pattern is a valid `Fx`.
    unsafe {
        _mm512_storeu_si512(p, lanes[0]);
        _mm512_storeu_si512(p.add(1), lanes[1]);
        _mm512_storeu_si512(p.add(2), lanes[2]);
    }
}

/// [`mul_fraction`] of each pair, for the tests.
#[cfg(test)]
#[target_feature(enable = "avx512f")]
pub(super) fn mul_fraction_on(a: &[i64], c: &[i64]) -> Vec<i64> {
    let (a, c) = (a.as_chunks::<8>().0, c.as_chunks::<8>().0);
    a.iter()
        .zip(c)
        .flat_map(|(a, c)| values(mul_fraction(lanes(a), lanes(c))))
        .collect()
}

/// [`mul_mass_biased`] of each pair, for the tests.
#[cfg(test)]
#[target_feature(enable = "avx512f")]
pub(super) fn mul_mass_biased_on(a: &[i64], m: &[i64]) -> Vec<i64> {
    let (a, m) = (a.as_chunks::<8>().0, m.as_chunks::<8>().0);
    a.iter()
        .zip(m)
        .flat_map(|(a, m)| values(mul_mass_biased(lanes(a), &MassLanes::new(lanes(m)))))
        .collect()
}

#[cfg(test)]
#[target_feature(enable = "avx512f")]
fn lanes(values: &[i64; 8]) -> __m512i {
    _mm512_set_epi64(
        values[7], values[6], values[5], values[4], values[3], values[2], values[1], values[0],
    )
}

#[cfg(test)]
#[target_feature(enable = "avx512f")]
fn values(lanes: __m512i) -> [i64; 8] {
    let mut values = [0; 8];
    let p = values.as_mut_ptr().cast::<__m512i>();
    // SAFETY: `values` is 64 bytes of `i64`, borrowed mutably; the write is unaligned.
    unsafe { _mm512_storeu_si512(p, lanes) };
    values
}
