//! I32F32 arithmetic on eight `i64` lanes in AVX-512F, shared by the soft-body kernels
//! (the distance rows, the prediction and the velocity update): exact sums and differences
//! modulo 2⁶⁴, the checked `*` and the fused dot product of values below 2⁶² from 32-bit
//! halves, and the bound check
//! that proves no operation of a kernel leaves the `i64` range.
//!
//! # Products
//!
//! `_mm512_mul_epi32` multiplies the signed low 32 bits of each lane into 64. With
//! a = a_h·2³² + a_l, a_h = ⌊(a + 2³¹)/2³²⌋ (|a_h| < 2³¹ for |a| < 2⁶²) and a_l ∈
//! [−2³¹, 2³¹) the signed low half of a, and b likewise,
//!
//! ```text
//! ⌊(a·b + 2³¹)/2³²⌋ = a_h·b_h·2³² + a_h·b_l + a_l·b_h + ⌊(a_l·b_l + 2³¹)/2³²⌋
//! ```
//!
//! since the first three terms of a·b are multiples of 2³²: the checked `*` (to nearest,
//! ties toward +∞) whenever that one does not saturate. A value used in several products
//! is split into its halves once ([`Split`]).

use core::arch::x86_64::{
    __m256i, __m512i, __mmask8, _mm256_loadu_si256, _mm512_add_epi64, _mm512_and_si512,
    _mm512_cmpge_epu64_mask, _mm512_cvtepu32_epi64, _mm512_i64gather_epi64, _mm512_loadu_si512,
    _mm512_mul_epi32, _mm512_set1_epi64, _mm512_setzero_si512, _mm512_slli_epi64,
    _mm512_srai_epi64, _mm512_sub_epi64,
};
use core::mem::size_of;

use crate::math::{Fx, Vec3};

/// Lanes per vector.
pub(crate) const LANES: usize = 8;

/// The bound every kernel checks its values against: |x| < 2⁴⁶ as raw bits (16384 in
/// I32F32). The product of two such values is below 2⁶⁰ after rounding.
pub(crate) const BOUND_BITS: u32 = 46;

// The layout the kernels rely on: `Fx` is one `i64`, `Vec3<Fx>` x, y, z in a row.
const _: () = {
    assert!(size_of::<Fx>() == 8);
    assert!(size_of::<Vec3<Fx>>() == 24);
};

/// a + b, exact modulo 2⁶⁴.
#[inline]
#[target_feature(enable = "avx512f")]
pub(crate) fn add(a: __m512i, b: __m512i) -> __m512i {
    _mm512_add_epi64(a, b)
}

/// a − b, exact modulo 2⁶⁴.
#[inline]
#[target_feature(enable = "avx512f")]
pub(crate) fn sub(a: __m512i, b: __m512i) -> __m512i {
    _mm512_sub_epi64(a, b)
}

/// The same value in every lane.
#[inline]
#[target_feature(enable = "avx512f")]
pub(crate) fn splat(x: Fx) -> __m512i {
    _mm512_set1_epi64(x.to_bits())
}

/// The raw bits of eight values.
#[inline]
#[target_feature(enable = "avx512f")]
pub(crate) fn load(values: &[Fx]) -> __m512i {
    let values = &values[..LANES];
    // SAFETY: eight `Fx`, each one `i64`: 64 readable bytes.
    unsafe { _mm512_loadu_si512(values.as_ptr().cast()) }
}

/// The positions of the eight vertices `indices` as x, y and z lanes, or `None` if an
/// index is out of bounds.
#[inline]
#[target_feature(enable = "avx512f")]
pub(crate) fn gather3(positions: &[Vec3<Fx>], indices: &[u32]) -> Option<[__m512i; 3]> {
    let indices = &indices[..LANES];
    // SAFETY: eight `u32`: 32 readable bytes.
    let indices =
        _mm512_cvtepu32_epi64(unsafe { _mm256_loadu_si256(indices.as_ptr().cast::<__m256i>()) });
    let count = _mm512_set1_epi64(positions.len() as i64);
    if _mm512_cmpge_epu64_mask(indices, count) != 0 {
        return None;
    }
    // Each vertex is three words.
    let words = add(_mm512_slli_epi64::<1>(indices), indices);
    let base = positions.as_ptr().cast::<i64>();
    // SAFETY: every lane's index was checked against the positions just above, and a
    // `Vec3<Fx>` is three `i64`.
    Some(
        [0, 1, 2].map(|k| unsafe {
            _mm512_i64gather_epi64::<8>(add(words, _mm512_set1_epi64(k)), base)
        }),
    )
}

/// A value with its high half a_h = ⌊(a + 2³¹)/2³²⌋, ready for [`mul`].
#[derive(Clone, Copy)]
pub(crate) struct Split {
    value: __m512i,
    high: __m512i,
}

/// `value` split for [`mul`].
#[inline]
#[target_feature(enable = "avx512f")]
pub(crate) fn split(value: __m512i) -> Split {
    Split {
        value,
        high: _mm512_srai_epi64::<32>(add(value, _mm512_set1_epi64(1 << 31))),
    }
}

/// The checked `*` of values below 2⁶², when it does not saturate: ⌊(a·b + 2³¹)/2³²⌋
/// (see the [module](self)).
#[inline]
#[target_feature(enable = "avx512f")]
pub(crate) fn mul(a: Split, b: Split) -> __m512i {
    let hh = _mm512_slli_epi64::<32>(_mm512_mul_epi32(a.high, b.high));
    let cross = add(
        _mm512_mul_epi32(a.high, b.value),
        _mm512_mul_epi32(a.value, b.high),
    );
    let low = _mm512_srai_epi64::<32>(add(
        _mm512_mul_epi32(a.value, b.value),
        _mm512_set1_epi64(1 << 31),
    ));
    add(add(hh, cross), low)
}

/// The fused dot product of values below 2⁶²: the exact Σ aᵢbᵢ rounded once, as
/// [`Real::dot3`](crate::math::Real::dot3) gives it when it does not saturate. Each
/// a_l·b_l is split into q·2³² + r with 0 ≤ r < 2³², so that
/// ⌊(Σ aᵢbᵢ + 2³¹)/2³²⌋ = Σ (a_h·b_h·2³² + a_h·b_l + a_l·b_h + q) + ⌊(Σ r + 2³¹)/2³²⌋,
/// and Σ r + 2³¹ < 2³⁴ cannot overflow.
#[inline]
#[target_feature(enable = "avx512f")]
pub(crate) fn dot3(a: [Split; 3], b: [Split; 3]) -> __m512i {
    let mask = _mm512_set1_epi64(0xffff_ffff);
    let mut whole = _mm512_setzero_si512();
    let mut remainders = _mm512_setzero_si512();
    for i in 0..3 {
        let hh = _mm512_slli_epi64::<32>(_mm512_mul_epi32(a[i].high, b[i].high));
        let cross = add(
            _mm512_mul_epi32(a[i].high, b[i].value),
            _mm512_mul_epi32(a[i].value, b[i].high),
        );
        let low = _mm512_mul_epi32(a[i].value, b[i].value);
        whole = add(whole, add(add(hh, cross), _mm512_srai_epi64::<32>(low)));
        remainders = add(remainders, _mm512_and_si512(low, mask));
    }
    add(whole, split(remainders).high)
}

/// The lanes where x lies outside [−2⁴⁶, 2⁴⁶) ([`BOUND_BITS`]).
#[inline]
#[target_feature(enable = "avx512f")]
pub(crate) fn out_of_bound(x: __m512i) -> __mmask8 {
    _mm512_cmpge_epu64_mask(
        add(x, _mm512_set1_epi64(1 << BOUND_BITS)),
        _mm512_set1_epi64(1 << (BOUND_BITS + 1)),
    )
}

/// [`out_of_bound`] of three vectors.
#[inline]
#[target_feature(enable = "avx512f")]
pub(crate) fn out_of_bound3(x: [__m512i; 3]) -> __mmask8 {
    out_of_bound(x[0]) | out_of_bound(x[1]) | out_of_bound(x[2])
}

/// Whether `x` lies inside the bound, for constants checked once per call.
pub(crate) fn within_bound(x: Fx) -> bool {
    x.to_bits().unsigned_abs() < 1 << BOUND_BITS
}
