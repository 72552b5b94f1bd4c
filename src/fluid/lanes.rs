//! Eight I32F32 values side by side in an AVX-512 register: the exact products, the
//! magnitudes and the loads of neighbours' scalars by index that the fluid's vector
//! kernels ([`row_sums`](super::row_sums), [`neighbours`](super::neighbours)) are built
//! from (their vectors come from the soft kernels' [`gather3`](crate::soft::lanes::gather3)).
//!
//! `_mm512_mul_epi32` multiplies the signed low 32 bits of two lanes into 64. With
//! a = a_h·2³² + a_l, a_h = ⌊(a + 2³¹)/2³²⌋ and a_l ∈ [−2³¹, 2³¹) the signed low half of a
//! (both 32-bit numbers for |a| < 2⁶²), and b likewise,
//!
//! ```text
//! ⌊(a·b + 2³¹)/2³²⌋ = a_h·b_h·2³² + a_h·b_l + a_l·b_h + ⌊(a_l·b_l + 2³¹)/2³²⌋,
//! ```
//!
//! since the first three terms of a·b are multiples of 2³²: the checked `*` (to nearest,
//! ties toward +∞). When b is itself a 32-bit signed number (b_h = 0) the product is
//! a_h·b + ⌊(a_l·b + 2³¹)/2³²⌋: two multiplies instead of four. The callers prove the
//! bounds.

use core::arch::x86_64::{
    __m512i, _mm512_add_epi64, _mm512_mask_loadu_epi64, _mm512_mul_epi32, _mm512_or_si512,
    _mm512_set1_epi64, _mm512_setzero_si512, _mm512_slli_epi64, _mm512_srai_epi64,
    _mm512_xor_si512,
};

use crate::math::{Fx, Vec3};

/// The bit length of `bits` as an unsigned number.
pub(super) fn bit_length(bits: u64) -> u32 {
    u64::BITS - bits.leading_zeros()
}

/// |v| or |v| − 1 per lane: `v ^ (v >> 63)`.
#[inline]
#[target_feature(enable = "avx512f")]
pub(super) fn magnitude(v: __m512i) -> __m512i {
    _mm512_xor_si512(v, _mm512_srai_epi64::<63>(v))
}

/// The same for one value.
#[inline(always)]
fn magnitude_of(v: i64) -> u64 {
    (v ^ (v >> 63)) as u64
}

/// The bit length of the largest magnitude of any component of `vectors`: a bound on
/// them all (|c| < 2^bits). Compiled for AVX-512F, which runs the scan eight words at a
/// time: the kernels' callers bound every particle's position or velocity before each
/// pass, and the boundary of a large tank has hundreds of thousands of particles.
#[target_feature(enable = "avx512f")]
pub(super) fn vector_bits(vectors: &[Vec3<Fx>]) -> u32 {
    // SAFETY: `Vec3<Fx>` is `repr(C)`, three `Fx` in a row with no padding, and `Fx` a
    // transparent `i64`: the slice's memory is 3·len `i64`.
    let words =
        unsafe { core::slice::from_raw_parts(vectors.as_ptr().cast::<i64>(), 3 * vectors.len()) };
    bit_length(words.iter().fold(0, |bits, &w| bits | magnitude_of(w)))
}

/// The bit length of the largest magnitude in `values`, as [`vector_bits`].
#[target_feature(enable = "avx512f")]
pub(super) fn scalar_bits(values: &[Fx]) -> u32 {
    bit_length(
        values
            .iter()
            .fold(0, |bits, v| bits | magnitude_of(v.to_bits())),
    )
}

/// a_h = ⌊(a + 2³¹)/2³²⌋ per lane.
#[inline]
#[target_feature(enable = "avx512f")]
fn high(a: __m512i) -> __m512i {
    _mm512_srai_epi64::<32>(_mm512_add_epi64(a, _mm512_set1_epi64(1 << 31)))
}

/// The checked `*` of bounded values: ⌊(a·b + 2³¹)/2³²⌋ per lane. `NARROW`: b is a
/// 32-bit signed number (b_h = 0), so that the product is a_h·b + ⌊(a_l·b + 2³¹)/2³²⌋,
/// two multiplies instead of four.
#[inline]
#[target_feature(enable = "avx512f")]
pub(super) fn product<const NARROW: bool>(a: __m512i, b: __m512i) -> __m512i {
    if NARROW {
        let low = _mm512_srai_epi64::<32>(_mm512_add_epi64(
            _mm512_mul_epi32(a, b),
            _mm512_set1_epi64(1 << 31),
        ));
        _mm512_add_epi64(_mm512_mul_epi32(high(a), b), low)
    } else {
        mul(a, b)
    }
}

/// The checked `*` of bounded values: ⌊(a·b + 2³¹)/2³²⌋ per lane.
#[inline]
#[target_feature(enable = "avx512f")]
pub(super) fn mul(a: __m512i, b: __m512i) -> __m512i {
    let (ah, bh) = (high(a), high(b));
    let hh = _mm512_slli_epi64::<32>(_mm512_mul_epi32(ah, bh));
    let cross = _mm512_add_epi64(_mm512_mul_epi32(ah, b), _mm512_mul_epi32(a, bh));
    let low = _mm512_srai_epi64::<32>(_mm512_add_epi64(
        _mm512_mul_epi32(a, b),
        _mm512_set1_epi64(1 << 31),
    ));
    _mm512_add_epi64(_mm512_add_epi64(hh, cross), low)
}

/// `values[indices[l]]` (I32F32 bits) in lane l for the `count` first lanes (zero in the
/// others): one masked load of a word per lane, in two chains of merges (even and odd
/// lanes) joined at the end, which costs less than a gather.
///
/// # Safety
/// The processor must have AVX-512F; `count` ≤ 8 and ≤ `indices.len()`; each of the first
/// `count` indices must be below the number of values at `values`.
#[inline]
#[target_feature(enable = "avx512f")]
pub(super) unsafe fn load_values(values: *const i64, indices: &[u32], count: usize) -> __m512i {
    let mut chains = [_mm512_setzero_si512(); 2];
    for l in 0..count {
        // SAFETY: the caller's conditions: the masked load reads one word, value
        // `indices[l]`, into lane l (from l words before it, the others masked off).
        unsafe {
            let at = values.add(*indices.get_unchecked(l) as usize);
            chains[l & 1] = _mm512_mask_loadu_epi64(chains[l & 1], 1 << l, at.wrapping_sub(l));
        }
    }
    _mm512_or_si512(chains[0], chains[1])
}

#[cfg(test)]
mod tests {
    use core::arch::x86_64::{__m512i, _mm512_storeu_si512};

    use super::load_values;
    use crate::math::{Fx, Pcg32, Vec3};
    use crate::soft::lanes::gather3;

    fn words(lanes: __m512i) -> [i64; 8] {
        let mut out = [0i64; 8];
        // SAFETY: eight words into eight.
        unsafe { _mm512_storeu_si512(out.as_mut_ptr().cast(), lanes) };
        out
    }

    /// `load_values` and the vector load the fluid shares with the soft kernels
    /// ([`gather3`]), for every lane count from 0 to 8, indices anywhere in arrays of every
    /// length from 1 to 5 (the first and the last element among them): each lane in use
    /// holds its element, the others zero.
    #[test]
    fn the_loads_match_indexing() {
        if !crate::math::cpu::avx512f() {
            return;
        }
        let mut rng = Pcg32::new(11, 7);
        for len in 1..=5usize {
            let values: Vec<i64> = (0..len)
                .map(|_| i64::from(rng.next_u32()) - (1 << 31))
                .collect();
            let vectors: Vec<i64> = (0..3 * len)
                .map(|_| i64::from(rng.next_u32()) << 20)
                .collect();
            let points: Vec<Vec3<Fx>> = vectors
                .chunks(3)
                .map(|c| {
                    Vec3::new(
                        Fx::from_bits(c[0]),
                        Fx::from_bits(c[1]),
                        Fx::from_bits(c[2]),
                    )
                })
                .collect();
            for count in 0..=8 {
                for _ in 0..50 {
                    let indices: Vec<u32> =
                        (0..count).map(|_| rng.next_u32() % len as u32).collect();
                    // SAFETY: AVX-512F detected; every index below the arrays' lengths.
                    let (scalars, [x, y, z]) = unsafe {
                        (
                            words(load_values(values.as_ptr(), &indices, count)),
                            gather3(&points, &indices).expect("in bounds").map(words),
                        )
                    };
                    for l in 0..8 {
                        let at = indices.get(l).map(|&i| i as usize);
                        let expect = |array: &[i64], stride: usize, c: usize| {
                            at.map_or(0, |i| array[stride * i + c])
                        };
                        assert_eq!(scalars[l], expect(&values, 1, 0), "value lane {l}");
                        assert_eq!(x[l], expect(&vectors, 3, 0), "x lane {l}");
                        assert_eq!(y[l], expect(&vectors, 3, 1), "y lane {l}");
                        assert_eq!(z[l], expect(&vectors, 3, 2), "z lane {l}");
                    }
                }
            }
        }
    }
}
