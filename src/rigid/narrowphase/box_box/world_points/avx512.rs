//! The four world transforms of a face contact's points in AVX-512 (F and DQ) on I32F32,
//! with the bits of [`Transform::point`]:
//!
//! ```text
//! (R p)_c + t_c = (R_c0 p_0 + R_c1 p_1) + R_c2 p_2 + t_c    (m; R_cm = column m's c)
//! ```
//!
//! each product rounded on its own as the scalar `*` rounds it. The twelve outputs
//! (point i, component c) fill the lanes 3i + c of two vectors, lanes 0–7 and 8–11, in the
//! order of `[Vec3; 4]` in memory, so that each vector is one store; permutes bring each
//! lane its operands: p_i,m (from the points' twelve words), R_cm (from the matrix's nine)
//! and t_c.
//!
//! # Exactness
//!
//! Every operand (each p_i,m, R_cm and t_c as it reaches a lane) is checked to lie in
//! [−2⁴⁶, 2⁴⁶) as raw bits: each product then is below 2⁶⁰ and each sum below 2⁶², so
//! no operation of the scalar form saturates and the wrapping arithmetic of
//! [`solver::avx512`](crate::rigid::solver::avx512) gives its exact results. When an
//! operand fails, nothing is written and the caller transforms the points one by one.

use core::any::Any;
use core::arch::x86_64::{
    __m512i, __mmask8, _mm512_loadu_si512, _mm512_mask_storeu_epi64, _mm512_maskz_loadu_epi64,
    _mm512_permutex2var_epi64, _mm512_permutexvar_epi64, _mm512_set1_epi64, _mm512_storeu_si512,
};

use crate::math::{Fx, Real, Vec3};
use crate::rigid::manifold::MAX_MANIFOLD_POINTS;
use crate::rigid::solver::avx512::{add, has_kernels, mul, out_of_bound};
use crate::rigid::transform::Transform;

/// Lanes of the second output vector that hold outputs (8–11).
const SECOND: __mmask8 = 0x0f;

/// The output (point i, component c) of lane `lane` of output vector `half`: the lane
/// 8·half + lane of `[Vec3; 4]` seen as twelve words, i.e. i = ⌊o/3⌋ and c = o mod 3
/// (lanes past the eleventh repeat it).
const fn output(half: usize, lane: usize) -> (usize, usize) {
    let o = 8 * half + lane;
    let o = if o < 12 { o } else { 11 };
    (o / 3, o % 3)
}

/// Per output vector and column m, the index of p_i,m among the points' twelve words for
/// each lane (0–7 the first vector of words, 8–15 the second).
const POINT: [[[i64; 8]; 3]; 2] = operand_indices(false);

/// Per output vector and column m, the index of R_cm among the matrix's nine words
/// (column-major: word 3m + c; the ninth is the second vector's first lane).
const ROTATION: [[[i64; 8]; 3]; 2] = operand_indices(true);

/// Per output vector and column m, each lane's operand index for its output (i, c):
/// 3m + c (R_cm) when `rotation`, 3i + m (p_i,m) otherwise.
const fn operand_indices(rotation: bool) -> [[[i64; 8]; 3]; 2] {
    let mut index = [[[0; 8]; 3]; 2];
    let mut half = 0;
    while half < 2 {
        let mut m = 0;
        while m < 3 {
            let mut lane = 0;
            while lane < 8 {
                let (i, c) = output(half, lane);
                index[half][m][lane] = if rotation { 3 * m + c } else { 3 * i + m } as i64;
                lane += 1;
            }
            m += 1;
        }
        half += 1;
    }
    index
}

/// Per output vector, the index of t_c among the translation's three words.
const TRANSLATION: [[i64; 8]; 2] = {
    let mut index = [[0; 8]; 2];
    let mut half = 0;
    while half < 2 {
        let mut lane = 0;
        while lane < 8 {
            let (_, c) = output(half, lane);
            index[half][lane] = c as i64;
            lane += 1;
        }
        half += 1;
    }
    index
};

/// Writes R pᵢ + t (m) for the four points `local` (m) to `world` when `R` is I32F32, the processor
/// has AVX-512F and DQ and every operand is within the bound (module documentation), and
/// says whether it did.
#[inline]
pub(super) fn to_world<R: Real>(
    xf: &Transform<R>,
    local: &[Vec3<R>; MAX_MANIFOLD_POINTS],
    world: &mut [Vec3<R>; MAX_MANIFOLD_POINTS],
) -> bool {
    let (Some(xf), Some(local), Some(world)) = (
        (xf as &dyn Any).downcast_ref::<Transform<Fx>>(),
        (local as &dyn Any).downcast_ref::<[Vec3<Fx>; MAX_MANIFOLD_POINTS]>(),
        (world as &mut dyn Any).downcast_mut::<[Vec3<Fx>; MAX_MANIFOLD_POINTS]>(),
    ) else {
        return false;
    };
    if !has_kernels() {
        return false;
    }
    // SAFETY: AVX-512F and DQ were detected on this processor just above.
    unsafe { transform(xf, local, world) }
}

/// One of the index vectors above, as the permutes take it (lane l selects word
/// `words[l]` of their sources).
#[inline]
#[target_feature(enable = "avx512f,avx512dq")]
fn index(words: &[i64; 8]) -> __m512i {
    // SAFETY: eight `i64`: 64 readable bytes.
    unsafe { _mm512_loadu_si512(words.as_ptr().cast()) }
}

/// The kernel (see the module documentation).
///
/// # Safety
/// The processor must have AVX-512F and AVX-512DQ.
#[target_feature(enable = "avx512f,avx512dq")]
unsafe fn transform(
    xf: &Transform<Fx>,
    local: &[Vec3<Fx>; MAX_MANIFOLD_POINTS],
    world: &mut [Vec3<Fx>; MAX_MANIFOLD_POINTS],
) -> bool {
    // `Vec3<Fx>` is three `i64` with no padding (`repr(C)`), so three columns are nine
    // words, the translation three and four points twelve.
    let columns = xf.rotation.cols.as_ptr().cast::<i64>();
    let points = local.as_ptr().cast::<i64>();
    // SAFETY: the loads read words 0–7 of the columns, 0–2 of the translation (masked),
    // and 0–7 and 8–11 (masked) of the points.
    let (r0, t, p0, p1) = unsafe {
        (
            _mm512_loadu_si512(columns.cast()),
            _mm512_maskz_loadu_epi64(0b111, core::ptr::from_ref(&xf.translation).cast()),
            _mm512_loadu_si512(points.cast()),
            _mm512_maskz_loadu_epi64(SECOND, points.add(8)),
        )
    };
    let r1 = _mm512_set1_epi64(xf.rotation.cols[2].z.to_bits());
    let mut unchecked: __mmask8 = 0;
    let mut out = [t; 2];
    for (half, sum) in out.iter_mut().enumerate() {
        let mut products = [t; 3];
        for (m, product) in products.iter_mut().enumerate() {
            let p = _mm512_permutex2var_epi64(p0, index(&POINT[half][m]), p1);
            let r = _mm512_permutex2var_epi64(r0, index(&ROTATION[half][m]), r1);
            unchecked |= out_of_bound(p) | out_of_bound(r);
            *product = mul(r, p);
        }
        let translation = _mm512_permutexvar_epi64(index(&TRANSLATION[half]), t);
        unchecked |= out_of_bound(translation);
        *sum = add(add(add(products[0], products[1]), products[2]), translation);
    }
    if unchecked != 0 {
        return false;
    }
    let world = world.as_mut_ptr().cast::<i64>();
    // SAFETY: the stores write words 0–7 and 8–11 (masked) of the four points.
    unsafe {
        _mm512_storeu_si512(world.cast(), out[0]);
        _mm512_mask_storeu_epi64(world.add(8), SECOND, out[1]);
    }
    true
}
