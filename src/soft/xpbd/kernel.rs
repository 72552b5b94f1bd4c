//! The prediction (step 1) and the velocity update (step 4) of I32F32 on the lanes of
//! [`Wide`] (every backend): eight vertices at a time, their 24 coordinates as three
//! vectors of eight `i64` lanes, with the bits of [`predict_vertex`] and
//! [`update_velocity`].
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

use core::ops::Range;

use super::{Motion, Vertices, predict_vertex, update_velocity};
use crate::math::over_real::{Scalar, Scalars, Vectors};
use crate::math::wide::{LANES, Wide, backend, kernel_entry};
use crate::math::{Fx, OverReal, Real, Vec3};

/// The bound every value of the kernels must lie within: |x| < 2⁴⁶ as raw bits.
const BOUND: u64 = 1 << 46;

/// Whether a constant, checked once per call, lies within [`BOUND`].
fn within_bound(x: Fx) -> bool {
    x.to_bits().unsigned_abs() < BOUND
}

/// The family of [`Motion`] over the scalar formats.
struct MotionOf;

impl OverReal for MotionOf {
    type Of<R: Real> = Motion<R>;
}

/// Step 1 for the vertices `range` with the kernel when `R` is I32F32, the body has no
/// air drag and a backend runs; returns whether it ran (if not, nothing was written).
pub(super) fn predict<R: Real>(
    range: Range<usize>,
    vertices: &mut Vertices<'_, R>,
    motion: &Motion<R>,
) -> bool {
    if motion.drag != R::ZERO {
        return false;
    }
    let (Some(backend), Some(x), Some(v), Some(previous), Some(w), Some(motion)) = (
        backend(),
        R::as_fixed_mut::<Vectors>(vertices.x),
        R::as_fixed_mut::<Vectors>(vertices.v),
        R::as_fixed_mut::<Vectors>(vertices.previous),
        R::as_fixed::<Scalars>(vertices.w),
        R::as_fixed::<MotionOf>(motion),
    ) else {
        return false;
    };
    let mut vertices = Vertices { x, v, previous, w };
    let step = motion.gravity * motion.h;
    let constants = [motion.h, motion.retain, step.x, step.y, step.z];
    if !constants.into_iter().all(within_bound) {
        return false;
    }
    predict_range(backend, range, &mut vertices, motion, step);
    true
}

/// Step 4 for the vertices `range` with the kernel when `R` is I32F32 and a backend runs;
/// returns whether it ran (if not, nothing was written).
pub(super) fn update_velocities<R: Real>(
    range: Range<usize>,
    x: &[Vec3<R>],
    previous: &[Vec3<R>],
    w: &[R],
    v: &mut [Vec3<R>],
    inv_h: R,
) -> bool {
    let (Some(backend), Some(x), Some(previous), Some(w), Some(v), Some(&inv_h)) = (
        backend(),
        R::as_fixed::<Vectors>(x),
        R::as_fixed::<Vectors>(previous),
        R::as_fixed::<Scalars>(w),
        R::as_fixed_mut::<Vectors>(v),
        R::as_fixed::<Scalar>(&inv_h),
    ) else {
        return false;
    };
    if !within_bound(inv_h) {
        return false;
    }
    update_range(backend, range, x, previous, w, v, inv_h);
    true
}

kernel_entry! {
    /// [`predict_range_kernel`] with the instructions of `backend`.
    fn predict_range(
        range: Range<usize>,
        vertices: &mut Vertices<'_, Fx>,
        motion: &Motion<Fx>,
        step: Vec3<Fx>,
    ) -> () = predict_range_kernel;
}

kernel_entry! {
    /// [`update_range_kernel`] with the instructions of `backend`.
    fn update_range(
        range: Range<usize>,
        x: &[Vec3<Fx>],
        previous: &[Vec3<Fx>],
        w: &[Fx],
        v: &mut [Vec3<Fx>],
        inv_h: Fx,
    ) -> () = update_range_kernel;
}

/// The prediction of `range`, eight vertices at a time, the rest and the blocks that fail
/// a check with the scalar step; `step` is g·h.
#[inline(always)]
fn predict_range_kernel<W: Wide>(
    w: W,
    range: Range<usize>,
    vertices: &mut Vertices<'_, Fx>,
    motion: &Motion<Fx>,
    step: Vec3<Fx>,
) {
    let h = w.splat(motion.h.to_bits());
    let retain = if motion.damped {
        Some(w.splat(motion.retain.to_bits()))
    } else {
        None
    };
    let step = pattern(w, step);
    let mut start = range.start;
    while start + LANES <= range.end {
        if !predict_block(w, start, vertices, h, retain, step) {
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
#[inline(always)]
fn predict_block<W: Wide>(
    w: W,
    start: usize,
    vertices: &mut Vertices<'_, Fx>,
    h: W::V,
    retain: Option<W::V>,
    step: [W::V; 3],
) -> bool {
    let block = start..start + LANES;
    let free = free_coordinates(&vertices.w[block.clone()]);
    let x = load3(w, &vertices.x[block.clone()]);
    let v = load3(w, &vertices.v[block.clone()]);
    let mut bad = 0;
    let mut new_v = v;
    let mut new_x = x;
    for k in 0..3 {
        bad |= (w.out_of_bound(x[k]) | w.out_of_bound(v[k])) & free[k];
        let damped = match retain {
            Some(retain) => w.mul(v[k], retain),
            None => v[k],
        };
        new_v[k] = w.add(damped, step[k]);
        bad |= w.out_of_bound(new_v[k]) & free[k];
        new_x[k] = w.add(x[k], w.mul(new_v[k], h));
    }
    if bad != 0 {
        return false;
    }
    store3(w, &mut vertices.previous[block.clone()], [0xff; 3], x);
    store3(w, &mut vertices.v[block.clone()], free, new_v);
    store3(w, &mut vertices.x[block], free, new_x);
    true
}

/// The velocity update of `range`, eight vertices at a time, the rest and the blocks that
/// fail a check with the scalar step.
#[inline(always)]
fn update_range_kernel<W: Wide>(
    wide: W,
    range: Range<usize>,
    x: &[Vec3<Fx>],
    previous: &[Vec3<Fx>],
    w: &[Fx],
    v: &mut [Vec3<Fx>],
    inv_h: Fx,
) {
    let inv_h_lanes = wide.splat(inv_h.to_bits());
    let mut start = range.start;
    while start + LANES <= range.end {
        let block = start..start + LANES;
        let free = free_coordinates(&w[block.clone()]);
        let (now, before) = (
            load3(wide, &x[block.clone()]),
            load3(wide, &previous[block.clone()]),
        );
        let mut bad = 0;
        let mut new_v = now;
        for k in 0..3 {
            let moved = wide.sub(now[k], before[k]);
            bad |= (wide.out_of_bound(now[k])
                | wide.out_of_bound(before[k])
                | wide.out_of_bound(moved))
                & free[k];
            new_v[k] = wide.mul(moved, inv_h_lanes);
        }
        if bad == 0 {
            store3(wide, &mut v[block], free, new_v);
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

/// A vector's x, y, z components repeated over 24 lanes, as three vectors.
#[inline(always)]
fn pattern<W: Wide>(w: W, v: Vec3<Fx>) -> [W::V; 3] {
    let (x, y, z) = (v.x.to_bits(), v.y.to_bits(), v.z.to_bits());
    [
        w.load_words([x, y, z, x, y, z, x, y]),
        w.load_words([z, x, y, z, x, y, z, x]),
        w.load_words([y, z, x, y, z, x, y, z]),
    ]
}

/// The coordinates, in three masks of eight lanes, of the vertices whose inverse mass
/// (`inv_mass`, eight of them) is not zero: coordinate c of vertex l is lane 3l + c of
/// the 24.
#[inline(always)]
fn free_coordinates(inv_mass: &[Fx]) -> [u8; 3] {
    let mut masks = [0u8; 3];
    for (l, &m) in inv_mass.iter().take(LANES).enumerate() {
        if m != Fx::ZERO {
            for c in 0..3 {
                let lane = 3 * l + c;
                masks[lane / LANES] |= 1 << (lane % LANES);
            }
        }
    }
    masks
}

/// The 24 coordinates of eight vertices as three vectors.
#[inline(always)]
fn load3<W: Wide>(w: W, vertices: &[Vec3<Fx>]) -> [W::V; 3] {
    let mut words = [[0; LANES]; 3];
    for (l, vertex) in vertices.iter().take(LANES).enumerate() {
        for (c, value) in [vertex.x, vertex.y, vertex.z].into_iter().enumerate() {
            let lane = 3 * l + c;
            words[lane / LANES][lane % LANES] = value.to_bits();
        }
    }
    w.load_components(&words)
}

/// Writes the lanes of `lanes` of three vectors to the 24 coordinates of eight vertices.
#[inline(always)]
fn store3<W: Wide>(w: W, vertices: &mut [Vec3<Fx>], lanes: [u8; 3], value: [W::V; 3]) {
    let words = [
        w.store_words(value[0]),
        w.store_words(value[1]),
        w.store_words(value[2]),
    ];
    for (l, vertex) in vertices.iter_mut().take(LANES).enumerate() {
        for c in 0..3 {
            let lane = 3 * l + c;
            if lanes[lane / LANES] & (1 << (lane % LANES)) != 0 {
                let value = Fx::from_bits(words[lane / LANES][lane % LANES]);
                match c {
                    0 => vertex.x = value,
                    1 => vertex.y = value,
                    _ => vertex.z = value,
                }
            }
        }
    }
}
