//! Eight I32F32 values side by side in an AVX-512 register: the exact products of the
//! fluid's neighbour search kernel ([`neighbours`](super::neighbours)), the one fluid kernel
//! not yet written against [`wide`](crate::math::wide) (whose [`Wide::mul`] gives the same
//! products on every backend).
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
//!
//! [`Wide::mul`]: crate::math::wide::Wide::mul

use core::arch::x86_64::{
    __m512i, _mm512_add_epi64, _mm512_mul_epi32, _mm512_set1_epi64, _mm512_slli_epi64,
    _mm512_srai_epi64,
};

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
