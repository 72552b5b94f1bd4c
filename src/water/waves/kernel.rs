//! The wave step of I32F32 on the lanes of [`Wide`] (every backend), eight edges or cells
//! at a time, with the bits of the scalar step ([`super`]).
//!
//! # Layout
//!
//! The flows along x of row k are the edges (n − 1)k … (n − 1)(k + 1) − 1, between the
//! cells nk + i and nk + i + 1; the flows along z are one run, edge j between the cells j
//! and j + n. Both update as q ← (q − p (u_high − u_low))·κ over runs of contiguous
//! memory. The heights then take the transfers t = (h/s) q of their four edges, read from
//! two padded copies, so that every cell reads the same four slots:
//!
//! ```text
//! u_c ← u_c + X[c] − X[c + 1] + Z[c] − Z[c + n]
//! X[c + 1] = t of the x edge from c (0 at a row's last cell), X[0] = 0
//! Z[c + n] = t of the z edge from c (0 on the last row),     Z[0 … n) = 0
//! ```
//!
//! # Exactness
//!
//! The scalar step rounds each product once ([`Fx`]'s `*`: to nearest, ties toward +∞)
//! and adds exactly unless a sum leaves the format. The kernel computes every product with
//! [`Wide::mul`], which is that rounding for factors within [−2⁴⁶, 2⁴⁶) as raw bits: the
//! constants p, κ and h/s are checked once per step, and per lane the heights, the old
//! flow, the rise u_high − u_low and q − p·rise (whose products are then below 2⁶⁰, no sum
//! leaving `i64` nor the format). A cell adds five terms within [−2⁴⁶, 2⁴⁶), below 2⁴⁹:
//! the scalar step's sums, taken in its order (left, right, up, down), never saturate
//! either, and integer sums do not depend on their order. A block of eight where a check
//! fails takes the scalar operators, in the scalar order, before anything of it is
//! written; so does the tail of each run.

use super::super::system::WaveScratch;
use crate::math::over_real::{Scalar, Scalars};
use crate::math::wide::{LANES, Wide, backend, kernel_entry};
use crate::math::{Fx, Real};

/// The bound every factor must lie within: |x| < 2⁴⁶ as raw bits.
const BOUND: u64 = 1 << 46;

/// Whether a constant, checked once per step, lies within [`BOUND`].
fn within_bound(x: Fx) -> bool {
    x.to_bits().unsigned_abs() < BOUND
}

/// The scalar flow update of one edge: (q − p (high − low))·κ.
#[inline(always)]
fn flow(q: Fx, low: Fx, high: Fx, push: Fx, keep: Fx) -> Fx {
    (q - push * (high - low)) * keep
}

/// Every flow of an n-column grid (`columns`) from the `heights`, with the kernel when `R`
/// is I32F32, a backend runs and the factors `push` (p, m/s) and `keep` (κ) lie within the
/// bound; returns whether it ran (if not, nothing was written).
pub(super) fn flows<R: Real>(
    heights: &[R],
    flow_x: &mut [R],
    flow_z: &mut [R],
    columns: usize,
    push: R,
    keep: R,
) -> bool {
    let (Some(backend), Some(u), Some(qx), Some(qz), Some(&push), Some(&keep)) = (
        backend(),
        R::as_fixed::<Scalars>(heights),
        R::as_fixed_mut::<Scalars>(flow_x),
        R::as_fixed_mut::<Scalars>(flow_z),
        R::as_fixed::<Scalar>(&push),
        R::as_fixed::<Scalar>(&keep),
    ) else {
        return false;
    };
    if !within_bound(push) || !within_bound(keep) {
        return false;
    }
    flows_on(backend, u, qx, qz, columns, push, keep);
    true
}

/// Every height from the new flows, as [`flows`] (`carry` is h/s, s/m).
pub(super) fn heights<R: Real>(
    heights: &mut [R],
    flow_x: &[R],
    flow_z: &[R],
    columns: usize,
    carry: R,
    scratch: &mut WaveScratch,
) -> bool {
    let (Some(backend), Some(u), Some(qx), Some(qz), Some(&carry)) = (
        backend(),
        R::as_fixed_mut::<Scalars>(heights),
        R::as_fixed::<Scalars>(flow_x),
        R::as_fixed::<Scalars>(flow_z),
        R::as_fixed::<Scalar>(&carry),
    ) else {
        return false;
    };
    if !within_bound(carry) {
        return false;
    }
    let cells = u.len();
    scratch.x.resize(cells + 1, Fx::ZERO);
    scratch.z.resize(cells + columns, Fx::ZERO);
    heights_on(backend, u, qx, qz, columns, carry, scratch);
    true
}

kernel_entry! {
    /// [`flows_kernel`] with the instructions of `backend`.
    fn flows_on(
        u: &[Fx],
        qx: &mut [Fx],
        qz: &mut [Fx],
        n: usize,
        push: Fx,
        keep: Fx,
    ) -> () = flows_kernel;
}

kernel_entry! {
    /// [`heights_kernel`] with the instructions of `backend`.
    fn heights_on(
        u: &mut [Fx],
        qx: &[Fx],
        qz: &[Fx],
        n: usize,
        carry: Fx,
        scratch: &mut WaveScratch,
    ) -> () = heights_kernel;
}

/// The flows along x, row by row, then along z, in one run.
#[inline(always)]
fn flows_kernel<W: Wide>(
    w: W,
    u: &[Fx],
    qx: &mut [Fx],
    qz: &mut [Fx],
    n: usize,
    push: Fx,
    keep: Fx,
) {
    let rows = u.len() / n;
    for k in 0..rows {
        let cells = &u[n * k..n * (k + 1)];
        let edges = &mut qx[(n - 1) * k..(n - 1) * (k + 1)];
        flow_run(w, edges, &cells[..n - 1], &cells[1..], push, keep);
    }
    let edges = n * (rows - 1);
    flow_run(w, &mut qz[..edges], &u[..edges], &u[n..], push, keep);
}

/// q_j ← (q_j − p (high_j − low_j))·κ for every j of `q`.
#[inline(always)]
fn flow_run<W: Wide>(w: W, q: &mut [Fx], low: &[Fx], high: &[Fx], push: Fx, keep: Fx) {
    let len = q.len();
    assert!(low.len() >= len && high.len() >= len);
    let (p, kappa) = (w.splat(push.to_bits()), w.splat(keep.to_bits()));
    let mut j = 0;
    while j + LANES <= len {
        // SAFETY: words j … j + 7 lie in each slice (j + 8 ≤ len ≤ their lengths), and
        // `Fx` is an `i64` (`repr(transparent)`).
        let (a, b, old) = unsafe {
            (
                w.load_at(low.as_ptr().add(j).cast()),
                w.load_at(high.as_ptr().add(j).cast()),
                w.load_at(q.as_ptr().add(j).cast()),
            )
        };
        let rise = w.sub(b, a);
        let pushed = w.sub(old, w.mul(p, rise));
        let outside = w.out_of_bound(a)
            | w.out_of_bound(b)
            | w.out_of_bound(old)
            | w.out_of_bound(rise)
            | w.out_of_bound(pushed);
        if outside == 0 {
            // SAFETY: as above.
            unsafe { w.store_at(q.as_mut_ptr().add(j).cast(), w.mul(pushed, kappa)) };
        } else {
            for i in j..j + LANES {
                q[i] = flow(q[i], low[i], high[i], push, keep);
            }
        }
        j += LANES;
    }
    for i in j..len {
        q[i] = flow(q[i], low[i], high[i], push, keep);
    }
}

/// The padded transfers, then every height.
#[inline(always)]
fn heights_kernel<W: Wide>(
    w: W,
    u: &mut [Fx],
    qx: &[Fx],
    qz: &[Fx],
    n: usize,
    carry: Fx,
    scratch: &mut WaveScratch,
) {
    let cells = u.len();
    let rows = cells / n;
    for k in 0..rows {
        let edges = &qx[(n - 1) * k..(n - 1) * (k + 1)];
        transfer_run(w, &mut scratch.x[n * k + 1..n * k + n], edges, carry);
    }
    transfer_run(w, &mut scratch.z[n..cells], &qz[..cells - n], carry);
    let (x, z) = (&scratch.x, &scratch.z);
    assert!(x.len() > cells && z.len() >= cells + n);
    let mut c = 0;
    while c + LANES <= cells {
        // SAFETY: c + 8 ≤ cells, so words c … c + 8 of `x` (cells + 1 long) and c … c + 7 + n
        // of `z` (cells + n long) and c … c + 7 of `u` exist.
        let (height, left, right, up, down) = unsafe {
            (
                w.load_at(u.as_ptr().add(c).cast()),
                w.load_at(x.as_ptr().add(c).cast()),
                w.load_at(x.as_ptr().add(c + 1).cast()),
                w.load_at(z.as_ptr().add(c).cast()),
                w.load_at(z.as_ptr().add(c + n).cast()),
            )
        };
        let outside = w.out_of_bound(height)
            | w.out_of_bound(left)
            | w.out_of_bound(right)
            | w.out_of_bound(up)
            | w.out_of_bound(down);
        if outside == 0 {
            let along_x = w.sub(w.add(height, left), right);
            let new = w.sub(w.add(along_x, up), down);
            // SAFETY: as above.
            unsafe { w.store_at(u.as_mut_ptr().add(c).cast(), new) };
        } else {
            for i in c..c + LANES {
                u[i] = u[i] + x[i] - x[i + 1] + z[i] - z[i + n];
            }
        }
        c += LANES;
    }
    for i in c..cells {
        u[i] = u[i] + x[i] - x[i + 1] + z[i] - z[i + n];
    }
}

/// t_j = (h/s)·q_j for every j of `t`.
#[inline(always)]
fn transfer_run<W: Wide>(w: W, t: &mut [Fx], q: &[Fx], carry: Fx) {
    let len = t.len();
    assert!(q.len() >= len);
    let factor = w.splat(carry.to_bits());
    let mut j = 0;
    while j + LANES <= len {
        // SAFETY: words j … j + 7 lie in both slices, `Fx` an `i64`.
        let flow = unsafe { w.load_at(q.as_ptr().add(j).cast()) };
        if w.out_of_bound(flow) == 0 {
            // SAFETY: as above.
            unsafe { w.store_at(t.as_mut_ptr().add(j).cast(), w.mul(factor, flow)) };
        } else {
            for i in j..j + LANES {
                t[i] = carry * q[i];
            }
        }
        j += LANES;
    }
    for i in j..len {
        t[i] = carry * q[i];
    }
}
