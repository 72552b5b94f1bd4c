//! I32F32 arithmetic on eight `i64` lanes in AVX-512F, shared by the soft-body kernels
//! (the distance rows, the tethers, the prediction and the velocity update): exact sums and
//! differences modulo 2⁶⁴, the checked `*` and the fused dot product of values below 2⁶²
//! from 32-bit halves (with short forms when a factor is below 2³¹), the bound checks that
//! prove no operation of a kernel leaves the `i64` range, and the moves of vertex
//! positions between memory (x, y, z in a row) and x, y and z lanes, by plain loads and
//! stores and transposes in registers (gathers, scatters and masked moves are much slower on
//! some processors, Zen 4 among them).
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
    __m512i, __mmask8, _mm_cvtsi128_si64, _mm_loadl_epi64, _mm_loadu_si128, _mm_storel_epi64,
    _mm_storeu_si128, _mm512_add_epi64, _mm512_and_si512, _mm512_castsi128_si512,
    _mm512_castsi512_si128, _mm512_cmpge_epu64_mask, _mm512_extracti32x4_epi32, _mm512_inserti32x4,
    _mm512_loadu_si512, _mm512_mul_epi32, _mm512_permutex2var_epi64, _mm512_permutexvar_epi64,
    _mm512_set_epi64, _mm512_set1_epi64, _mm512_setzero_si512, _mm512_slli_epi64,
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

/// The positions of the vertices `indices` (at most eight: the lanes past them hold zero)
/// as x, y and z lanes, or `None` if an index is out of bounds: a load of three words per
/// vertex and a transpose (the processor's gather instructions are slower on some cores).
/// The soft kernels and the fluid's neighbour sums share it.
#[inline]
#[target_feature(enable = "avx512f")]
pub(crate) fn gather3(positions: &[Vec3<Fx>], indices: &[u32]) -> Option<[__m512i; 3]> {
    let indices = &indices[..indices.len().min(LANES)];
    let mut vertices = [_mm512_setzero_si512(); LANES];
    for (vertex, &i) in vertices.iter_mut().zip(indices) {
        let position = positions.get(i as usize)?;
        let words = core::ptr::from_ref(position).cast::<i64>();
        // SAFETY: a `Vec3<Fx>` is three readable `i64`: x and y, then z.
        let (xy, z) = unsafe {
            (
                _mm_loadu_si128(words.cast()),
                _mm_loadl_epi64(words.add(2).cast()),
            )
        };
        *vertex = _mm512_inserti32x4::<1>(_mm512_castsi128_si512(xy), z);
    }
    // Pairs: [x₀ x₁ y₀ y₁ z₀ z₁ · ·], then quads: [x₀..x₃ y₀..y₃] and [z₀..z₃ · · · ·].
    let pair = _mm512_set_epi64(0, 0, 10, 2, 9, 1, 8, 0);
    let [v0, v1, v2, v3, v4, v5, v6, v7] = vertices;
    let (p01, p23) = (
        _mm512_permutex2var_epi64(v0, pair, v1),
        _mm512_permutex2var_epi64(v2, pair, v3),
    );
    let (p45, p67) = (
        _mm512_permutex2var_epi64(v4, pair, v5),
        _mm512_permutex2var_epi64(v6, pair, v7),
    );
    let xy = _mm512_set_epi64(11, 10, 3, 2, 9, 8, 1, 0);
    let z = _mm512_set_epi64(0, 0, 0, 0, 13, 12, 5, 4);
    let (xy0, xy4) = (
        _mm512_permutex2var_epi64(p01, xy, p23),
        _mm512_permutex2var_epi64(p45, xy, p67),
    );
    let (z0, z4) = (
        _mm512_permutex2var_epi64(p01, z, p23),
        _mm512_permutex2var_epi64(p45, z, p67),
    );
    let low = _mm512_set_epi64(11, 10, 9, 8, 3, 2, 1, 0);
    let high = _mm512_set_epi64(15, 14, 13, 12, 7, 6, 5, 4);
    Some([
        _mm512_permutex2var_epi64(xy0, low, xy4),
        _mm512_permutex2var_epi64(xy0, high, xy4),
        _mm512_permutex2var_epi64(z0, low, z4),
    ])
}

/// The positions of the eight consecutive vertices `first..first + 8` as x, y and z lanes,
/// or `None` if they are out of bounds: three loads and a transpose.
#[inline]
#[target_feature(enable = "avx512f")]
pub(crate) fn load_run3(positions: &[Vec3<Fx>], first: usize) -> Option<[__m512i; 3]> {
    let run = positions.get(first..first + LANES)?;
    let words = run.as_ptr().cast::<i64>();
    // SAFETY: eight `Vec3<Fx>` are 24 readable `i64`.
    let (v0, v1, v2) = unsafe {
        (
            _mm512_loadu_si512(words.cast()),
            _mm512_loadu_si512(words.add(LANES).cast()),
            _mm512_loadu_si512(words.add(2 * LANES).cast()),
        )
    };
    // Word 3i + c is component c of vertex i: v0 holds words 0..8, v1 8..16, v2 16..24.
    let x = _mm512_permutex2var_epi64(v0, _mm512_set_epi64(0, 0, 15, 12, 9, 6, 3, 0), v1);
    let y = _mm512_permutex2var_epi64(v0, _mm512_set_epi64(0, 0, 0, 13, 10, 7, 4, 1), v1);
    let z = _mm512_permutex2var_epi64(v0, _mm512_set_epi64(0, 0, 0, 14, 11, 8, 5, 2), v1);
    Some([
        _mm512_permutex2var_epi64(x, _mm512_set_epi64(13, 10, 5, 4, 3, 2, 1, 0), v2),
        _mm512_permutex2var_epi64(y, _mm512_set_epi64(14, 11, 8, 4, 3, 2, 1, 0), v2),
        _mm512_permutex2var_epi64(z, _mm512_set_epi64(15, 12, 9, 4, 3, 2, 1, 0), v2),
    ])
}

/// Lane `l` of a vector.
#[inline]
#[target_feature(enable = "avx512f")]
pub(crate) fn lane(value: __m512i, l: usize) -> i64 {
    let moved = _mm512_permutexvar_epi64(_mm512_set1_epi64(l as i64), value);
    _mm_cvtsi128_si64(_mm512_castsi512_si128(moved))
}

/// Lane `l` of x, y and z lanes, in the low three lanes of a vector (for [`put3`]).
#[inline]
#[target_feature(enable = "avx512f")]
pub(crate) fn lane3(value: [__m512i; 3], l: usize) -> __m512i {
    let l = l as i64;
    let xy = _mm512_permutex2var_epi64(
        value[0],
        _mm512_set_epi64(0, 0, 0, 0, 0, 0, 8 + l, l),
        value[1],
    );
    _mm512_permutex2var_epi64(xy, _mm512_set_epi64(0, 0, 0, 0, 0, 8 + l, 1, 0), value[2])
}

/// Writes the low three lanes of `value` (x, y, z) to `target`.
#[inline]
#[target_feature(enable = "avx512f")]
pub(crate) fn put3(target: &mut Vec3<Fx>, value: __m512i) {
    let words = core::ptr::from_mut(target).cast::<i64>();
    // SAFETY: a `Vec3<Fx>` is three writable `i64`: x and y, then z.
    unsafe {
        _mm_storeu_si128(words.cast(), _mm512_castsi512_si128(value));
        _mm_storel_epi64(words.add(2).cast(), _mm512_extracti32x4_epi32::<1>(value));
    }
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

/// [`split`] of three vectors.
#[inline]
#[target_feature(enable = "avx512f")]
pub(crate) fn split3(value: [__m512i; 3]) -> [Split; 3] {
    [split(value[0]), split(value[1]), split(value[2])]
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

/// [`mul`] when |b| < 2³¹ ([`out_of_short`] clear): b is its own signed low half (b_h =
/// 0), so ⌊(a·b + 2³¹)/2³²⌋ = a_h·b + ⌊(a_l·b + 2³¹)/2³²⌋, two multiplies instead of four.
#[inline]
#[target_feature(enable = "avx512f")]
pub(crate) fn mul_short(a: Split, b: __m512i) -> __m512i {
    let low = _mm512_srai_epi64::<32>(add(
        _mm512_mul_epi32(a.value, b),
        _mm512_set1_epi64(1 << 31),
    ));
    add(_mm512_mul_epi32(a.high, b), low)
}

/// [`mul`] of x by itself when |x| < 2³¹ ([`out_of_short`] clear): ⌊(x² + 2³¹)/2³²⌋, x
/// being its own signed low half.
#[inline]
#[target_feature(enable = "avx512f")]
pub(crate) fn square_short(x: __m512i) -> __m512i {
    _mm512_srai_epi64::<32>(add(_mm512_mul_epi32(x, x), _mm512_set1_epi64(1 << 31)))
}

/// The lanes where x lies outside [−2³¹, 2³¹), the range of [`mul_short`]'s second factor.
#[inline]
#[target_feature(enable = "avx512f")]
pub(crate) fn out_of_short(x: __m512i) -> __mmask8 {
    _mm512_cmpge_epu64_mask(
        add(x, _mm512_set1_epi64(1 << 31)),
        _mm512_set1_epi64(1 << 32),
    )
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
