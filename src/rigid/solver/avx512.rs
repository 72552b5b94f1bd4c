//! Exact I32F32 arithmetic on eight `i64` lanes in AVX-512 (F and DQ), for the kernels that
//! have no AVX2 form yet: the tangents and twist arms of constraint preparation (with the
//! square roots of [`sqrt`]) and the box–box face points' world transform. Loads and
//! stores of lane arrays, sums, the checked `*` of values within the bound [−2⁴⁶, 2⁴⁶),
//! and the bound check itself. (The other kernels use the same arithmetic through
//! [`Wide`](crate::math::wide::Wide), whose documentation derives the products, with AVX-512 or
//! AVX2.)
//!
//! Values within the bound have products below 2⁶⁰ after rounding and sums of a few of
//! them stay below 2⁶³, so these wrapping operations give exactly what the checked scalar
//! operators give, which saturate nowhere there; each kernel states which values it checks.
//!
//! # Products
//!
//! `_mm512_mul_epi32` multiplies the signed low 32 bits of each lane into 64, and
//! `_mm512_mullo_epi64` (AVX-512DQ) keeps the low 64 bits of a 64 × 64 product. With
//! a = a_h·2³² + a_l, a_h = ⌊(a + 2³¹)/2³²⌋ (|a_h| ≤ 2¹⁴ for a checked a) and a_l ∈
//! [−2³¹, 2³¹) the signed low half of a, and b likewise,
//!
//! ```text
//! ⌊(a·b + 2³¹)/2³²⌋ = a·b_h + a_h·b_l + ⌊(a_l·b_l + 2³¹)/2³²⌋
//! ```
//!
//! since a·b = a·b_h·2³² + a_h·b_l·2³² + a_l·b_l; this is the checked `*` (to nearest, ties
//! toward +∞). The term a·b_h is below 2⁶⁰, so its low 64 bits are all of it.

pub(crate) mod sqrt;

use core::arch::x86_64::{
    __m512i, __mmask8, _mm512_add_epi64, _mm512_cmpge_epu64_mask, _mm512_loadu_si512,
    _mm512_mask_storeu_epi64, _mm512_mul_epi32, _mm512_mullo_epi64, _mm512_set1_epi64,
    _mm512_srai_epi64, _mm512_storeu_si512, _mm512_sub_epi64,
};

use super::lanes::{Lanes, Lanes3};
use crate::math::Fx;

/// Whether this processor runs the kernels: AVX-512F and AVX-512DQ (every processor with
/// AVX-512 for servers and desktops has both).
pub(crate) fn has_kernels() -> bool {
    crate::math::cpu::avx512f() && crate::math::cpu::avx512dq()
}

/// The raw bits of a lane array.
#[inline]
#[target_feature(enable = "avx512f,avx512dq")]
pub(crate) fn load(lanes: &Lanes<Fx>) -> __m512i {
    // SAFETY: eight `Fx`, each one `i64`: 64 readable bytes.
    unsafe { _mm512_loadu_si512(lanes.as_ptr().cast()) }
}

/// Writes raw bits to a lane array.
#[inline]
#[target_feature(enable = "avx512f,avx512dq")]
pub(crate) fn store(lanes: &mut Lanes<Fx>, value: __m512i) {
    // SAFETY: eight `Fx`, each one `i64`: 64 writable bytes.
    unsafe { _mm512_storeu_si512(lanes.as_mut_ptr().cast(), value) }
}

/// Writes the lanes of `mask` to a lane array; the others keep their values.
#[inline]
#[target_feature(enable = "avx512f,avx512dq")]
pub(crate) fn store_lanes(lanes: &mut Lanes<Fx>, mask: __mmask8, value: __m512i) {
    // SAFETY: eight `Fx`, each one `i64`: 64 writable bytes.
    unsafe { _mm512_mask_storeu_epi64(lanes.as_mut_ptr().cast(), mask, value) }
}

#[inline]
#[target_feature(enable = "avx512f,avx512dq")]
pub(crate) fn load3(lanes: &Lanes3<Fx>) -> [__m512i; 3] {
    [load(&lanes.x), load(&lanes.y), load(&lanes.z)]
}

#[inline]
#[target_feature(enable = "avx512f,avx512dq")]
pub(crate) fn add(a: __m512i, b: __m512i) -> __m512i {
    _mm512_add_epi64(a, b)
}

#[inline]
#[target_feature(enable = "avx512f,avx512dq")]
pub(crate) fn sub(a: __m512i, b: __m512i) -> __m512i {
    _mm512_sub_epi64(a, b)
}

/// ⌊(a + 2³¹)/2³²⌋: the high half of a around its signed low half.
#[inline]
#[target_feature(enable = "avx512f,avx512dq")]
pub(crate) fn high(a: __m512i) -> __m512i {
    _mm512_srai_epi64::<32>(add(a, _mm512_set1_epi64(1 << 31)))
}

/// The checked `*` of checked values: ⌊(a·b + 2³¹)/2³²⌋ = a·b_h + a_h·b_l +
/// ⌊(a_l·b_l + 2³¹)/2³²⌋ (module documentation).
#[inline]
#[target_feature(enable = "avx512f,avx512dq")]
pub(crate) fn mul(a: __m512i, b: __m512i) -> __m512i {
    let (ah, bh) = (high(a), high(b));
    let upper = add(_mm512_mullo_epi64(a, bh), _mm512_mul_epi32(ah, b));
    let low = _mm512_srai_epi64::<32>(add(_mm512_mul_epi32(a, b), _mm512_set1_epi64(1 << 31)));
    add(upper, low)
}

/// Each component times the same factor.
#[inline]
#[target_feature(enable = "avx512f,avx512dq")]
pub(crate) fn mul3(a: [__m512i; 3], b: __m512i) -> [__m512i; 3] {
    [mul(a[0], b), mul(a[1], b), mul(a[2], b)]
}

/// The lanes where x lies outside [−2⁴⁶, 2⁴⁶).
#[inline]
#[target_feature(enable = "avx512f,avx512dq")]
pub(crate) fn out_of_bound(x: __m512i) -> __mmask8 {
    _mm512_cmpge_epu64_mask(
        add(x, _mm512_set1_epi64(1 << 46)),
        _mm512_set1_epi64(1 << 47),
    )
}

#[inline]
#[target_feature(enable = "avx512f,avx512dq")]
pub(crate) fn out_of_bound3(x: [__m512i; 3]) -> __mmask8 {
    out_of_bound(x[0]) | out_of_bound(x[1]) | out_of_bound(x[2])
}
