//! The prediction (step 1) and the velocity update (step 4) of I32F32 in AVX-512: eight
//! vertices at a time, their 24 coordinates as three vectors of eight `i64` lanes, with the
//! bits of [`predict_vertex`] and [`update_velocity`].
//!
//! Both steps treat the three coordinates alike, so the kernels work on the positions and
//! velocities as they are stored (x, y, z of each vertex in a row); gravity's step g·h is
//! laid out in the same x, y, z pattern, and each vertex's inverse mass is spread over its
//! three coordinates to mask the pinned ones, which the kernels do not write (their
//! previous position is copied as the scalar step copies it).
//!
//! # Exactness
//!
//! The scalar prediction of a free vertex computes v·r (r = 1/(1 + h c), only when c ≠ 0),
//! then v + g·h and x + v·h with fused multiply-adds, each the product rounded once and
//! added: since v·2³² is a multiple of 2³², round(v·2³² + g·h) = v + round(g·h) exactly,
//! so the kernel adds the checked g·h, computed once. The velocity update computes
//! (x − x_prev)·(1/h). The kernels check that h, 1/h, r and g·h and, per coordinate of a
//! free vertex, x, v, x_prev, the new v and x − x_prev lie in [−2⁴⁶, 2⁴⁶) as raw bits:
//! then every product is of checked values, below 2⁶⁰ after rounding, every sum has two
//! such terms, and no operation leaves the `i64` range, so the kernels' exact values are
//! the checked operators'. A block of eight vertices where a check fails takes the scalar
//! step, before anything of it is written. Bodies with air drag take the scalar step.

use core::any::TypeId;
use core::arch::x86_64::{
    __m512i, __mmask8, _mm512_cmpneq_epi64_mask, _mm512_loadu_si512, _mm512_mask_storeu_epi64,
    _mm512_permutexvar_epi64, _mm512_set_epi64, _mm512_setzero_si512, _mm512_storeu_si512,
};
use core::ops::Range;

use super::{Motion, Vertices, predict_vertex, update_velocity};
use crate::math::{Fx, Real, Vec3};
use crate::soft::lanes::{LANES, Split, add, load, mul, out_of_bound, split, sub, within_bound};

/// Step 1 for the vertices `range` with the kernel when `R` is I32F32, the body has no
/// air drag and the processor has AVX-512F; returns whether it ran (if not, nothing was
/// written).
pub(super) fn predict<R: Real>(
    range: Range<usize>,
    vertices: &mut Vertices<'_, R>,
    motion: &Motion<R>,
) -> bool {
    if !crate::math::cpu::avx512f()
        || TypeId::of::<R>() != TypeId::of::<Fx>()
        || motion.drag != R::ZERO
    {
        return false;
    }
    // SAFETY: `R` is `Fx` (checked just above), so every type below is unchanged.
    let (mut vertices, motion) = unsafe {
        (
            Vertices {
                x: &mut *(core::ptr::from_mut(vertices.x) as *mut [Vec3<Fx>]),
                v: &mut *(core::ptr::from_mut(vertices.v) as *mut [Vec3<Fx>]),
                previous: &mut *(core::ptr::from_mut(vertices.previous) as *mut [Vec3<Fx>]),
                w: &*(core::ptr::from_ref(vertices.w) as *const [Fx]),
            },
            &*(core::ptr::from_ref(motion).cast::<Motion<Fx>>()),
        )
    };
    let step = motion.gravity * motion.h;
    let constants = [motion.h, motion.retain, step.x, step.y, step.z];
    if !constants.into_iter().all(within_bound) {
        return false;
    }
    // SAFETY: AVX-512F was detected on this processor just above.
    unsafe { predict_range(range, &mut vertices, motion, step) };
    true
}

/// Step 4 for the vertices `range` with the kernel when `R` is I32F32 and the processor
/// has AVX-512F; returns whether it ran (if not, nothing was written).
pub(super) fn update_velocities<R: Real>(
    range: Range<usize>,
    x: &[Vec3<R>],
    previous: &[Vec3<R>],
    w: &[R],
    v: &mut [Vec3<R>],
    inv_h: R,
) -> bool {
    if !crate::math::cpu::avx512f() || TypeId::of::<R>() != TypeId::of::<Fx>() {
        return false;
    }
    // SAFETY: `R` is `Fx` (checked just above), so every type below is unchanged.
    let (x, previous, w, v, inv_h) = unsafe {
        (
            &*(core::ptr::from_ref(x) as *const [Vec3<Fx>]),
            &*(core::ptr::from_ref(previous) as *const [Vec3<Fx>]),
            &*(core::ptr::from_ref(w) as *const [Fx]),
            &mut *(core::ptr::from_mut(v) as *mut [Vec3<Fx>]),
            *(core::ptr::from_ref(&inv_h).cast::<Fx>()),
        )
    };
    if !within_bound(inv_h) {
        return false;
    }
    // SAFETY: AVX-512F was detected on this processor just above.
    unsafe { update_range(range, x, previous, w, v, inv_h) };
    true
}

/// The prediction of `range`, eight vertices at a time, the rest and the blocks that fail
/// a check with the scalar step; `step` is g·h.
///
/// # Safety
/// The processor must have AVX-512F.
#[target_feature(enable = "avx512f")]
unsafe fn predict_range(
    range: Range<usize>,
    vertices: &mut Vertices<'_, Fx>,
    motion: &Motion<Fx>,
    step: Vec3<Fx>,
) {
    let h = split(splat_bits(motion.h));
    let retain = motion.damped.then(|| split(splat_bits(motion.retain)));
    let step = pattern(step);
    let mut start = range.start;
    while start + LANES <= range.end {
        if !predict_block(start, vertices, h, retain, step) {
            for i in start..start + LANES {
                predict_vertex(i, vertices, motion);
            }
        }
        start += LANES;
    }
    for i in start..range.end {
        predict_vertex(i, vertices, motion);
    }
}

/// The kernel on vertices `start..start + 8`; returns false, having written nothing, when a
/// check fails.
#[inline]
#[target_feature(enable = "avx512f")]
fn predict_block(
    start: usize,
    vertices: &mut Vertices<'_, Fx>,
    h: Split,
    retain: Option<Split>,
    step: [__m512i; 3],
) -> bool {
    let block = start..start + LANES;
    let free = free_coordinates(load(&vertices.w[block.clone()]));
    let x = load3(&vertices.x[block.clone()]);
    let v = load3(&vertices.v[block.clone()]);
    let mut bad = 0;
    let mut new_v = v;
    let mut new_x = x;
    for k in 0..3 {
        bad |= (out_of_bound(x[k]) | out_of_bound(v[k])) & free[k];
        let damped = match retain {
            Some(retain) => mul(split(v[k]), retain),
            None => v[k],
        };
        new_v[k] = add(damped, step[k]);
        bad |= out_of_bound(new_v[k]) & free[k];
        new_x[k] = add(x[k], mul(split(new_v[k]), h));
    }
    if bad != 0 {
        return false;
    }
    store3(&mut vertices.previous[block.clone()], [0xff; 3], x);
    store3(&mut vertices.v[block.clone()], free, new_v);
    store3(&mut vertices.x[block], free, new_x);
    true
}

/// The velocity update of `range`, eight vertices at a time, the rest and the blocks that
/// fail a check with the scalar step.
///
/// # Safety
/// The processor must have AVX-512F.
#[target_feature(enable = "avx512f")]
unsafe fn update_range(
    range: Range<usize>,
    x: &[Vec3<Fx>],
    previous: &[Vec3<Fx>],
    w: &[Fx],
    v: &mut [Vec3<Fx>],
    inv_h: Fx,
) {
    let inv_h_lanes = split(splat_bits(inv_h));
    let mut start = range.start;
    while start + LANES <= range.end {
        let block = start..start + LANES;
        let free = free_coordinates(load(&w[block.clone()]));
        let (now, before) = (load3(&x[block.clone()]), load3(&previous[block.clone()]));
        let mut bad = 0;
        let mut new_v = now;
        for k in 0..3 {
            let moved = sub(now[k], before[k]);
            bad |= (out_of_bound(now[k]) | out_of_bound(before[k]) | out_of_bound(moved)) & free[k];
            new_v[k] = mul(split(moved), inv_h_lanes);
        }
        if bad == 0 {
            store3(&mut v[block], free, new_v);
        } else {
            for i in block {
                update_velocity(i, x, previous, w, v, inv_h);
            }
        }
        start += LANES;
    }
    for i in start..range.end {
        update_velocity(i, x, previous, w, v, inv_h);
    }
}

/// The same value in every lane.
#[inline]
#[target_feature(enable = "avx512f")]
fn splat_bits(x: Fx) -> __m512i {
    crate::soft::lanes::splat(x)
}

/// A vector's x, y, z components repeated over 24 lanes, as three vectors.
#[inline]
#[target_feature(enable = "avx512f")]
fn pattern(v: Vec3<Fx>) -> [__m512i; 3] {
    let (x, y, z) = (v.x.to_bits(), v.y.to_bits(), v.z.to_bits());
    [
        _mm512_set_epi64(y, x, z, y, x, z, y, x),
        _mm512_set_epi64(x, z, y, x, z, y, x, z),
        _mm512_set_epi64(z, y, x, z, y, x, z, y),
    ]
}

/// The coordinates, in three masks of eight lanes, of the vertices whose inverse mass
/// (`inv_mass`, eight lanes) is not zero.
#[inline]
#[target_feature(enable = "avx512f")]
fn free_coordinates(inv_mass: __m512i) -> [__mmask8; 3] {
    let zero = _mm512_setzero_si512();
    let spread =
        |index: __m512i| _mm512_cmpneq_epi64_mask(_mm512_permutexvar_epi64(index, inv_mass), zero);
    [
        spread(_mm512_set_epi64(2, 2, 1, 1, 1, 0, 0, 0)),
        spread(_mm512_set_epi64(5, 4, 4, 4, 3, 3, 3, 2)),
        spread(_mm512_set_epi64(7, 7, 7, 6, 6, 6, 5, 5)),
    ]
}

/// The 24 coordinates of eight vertices as three vectors.
#[inline]
#[target_feature(enable = "avx512f")]
fn load3(vertices: &[Vec3<Fx>]) -> [__m512i; 3] {
    let vertices = &vertices[..LANES];
    let words = vertices.as_ptr().cast::<i64>();
    // SAFETY: eight `Vec3<Fx>` are 24 readable `i64`.
    unsafe {
        [
            _mm512_loadu_si512(words.cast()),
            _mm512_loadu_si512(words.add(LANES).cast()),
            _mm512_loadu_si512(words.add(2 * LANES).cast()),
        ]
    }
}

/// Writes the lanes of `lanes` of three vectors to the 24 coordinates of eight vertices.
#[inline]
#[target_feature(enable = "avx512f")]
fn store3(vertices: &mut [Vec3<Fx>], lanes: [__mmask8; 3], value: [__m512i; 3]) {
    let vertices = &mut vertices[..LANES];
    let words = vertices.as_mut_ptr().cast::<i64>();
    for k in 0..3 {
        // SAFETY: eight `Vec3<Fx>` are 24 writable `i64`.
        unsafe {
            if lanes[k] == 0xff {
                _mm512_storeu_si512(words.add(k * LANES).cast(), value[k]);
            } else {
                _mm512_mask_storeu_epi64(words.add(k * LANES), lanes[k], value[k]);
            }
        }
    }
}
