//! The square roots of constraint preparation for a block of I32F32 constraints as
//! kernels, any block, independent or not, written once against
//! [`Wide`](crate::math::wide::Wide) and run with the backend
//! [`backend`] picks (AVX-512 or AVX2): the unit tangents, with the bits of
//! [`ContactBlock::tangents_lanes`], and the twist lever arms, with those of
//! [`ContactBlock::twist_arms_lanes`]. Both take their roots from
//! [`math::sqrt::lanes`](crate::math::sqrt::lanes), which rounds as `Real::sqrt` does.
//!
//! # The tangents
//!
//! For the vector o ⟂ n in the first tangent, |o| = √(o·o) with each product of o·o
//! rounded on its own (as [`Vec3::dot`](crate::math::Vec3::dot)), the reciprocal 1/|o|
//! lane by lane with the checked `/`, then t₁ = o·(1/|o|) and t₂ = n × t₁ with the checked
//! `*` ([`Wide::mul`](crate::math::wide::Wide::mul)).
//!
//! The kernel takes a block when, in every lane in use, o and n lie within the bound
//! [−2⁴⁶, 2⁴⁶) as raw bits and |o| ≥ 2¹⁹ raw (2⁻¹³). Then o·o saturates nowhere (products
//! below 2⁶⁰), 1/|o| ≤ 2⁴⁵ raw neither saturates nor leaves the bound, and each
//! |t₁ᵢ| ≤ |oᵢ|(1/|o|) is within a few ulp of 1 (|oᵢ| ≤ |o| + 1 raw), inside the bound; so
//! every product is exact and nothing saturates, in the kernel or in the scalar form.
//! Otherwise it returns false before writing anything or dividing, and the caller takes
//! the scalar form. For a unit normal |o| ≥ 0.577, so every block of unit normals passes.
//!
//! # The twist arms
//!
//! d_k = √(d_k²) for every point of every lane at once; only the points in use are
//! written, as the scalar form writes them. A square root saturates nowhere, so every
//! block passes.

use super::kernel::{counts_of, points_in_use};
use super::{ContactArms, ContactArmsOf, ContactBlock, ContactBlockOf};
use crate::math::sqrt::lanes::sqrt;
use crate::math::wide::{backend, kernel_entry};
use crate::math::{Fx, Real};
use crate::rigid::manifold::MAX_MANIFOLD_POINTS;
use crate::rigid::solver::lanes::{LANES, Lanes};
use crate::rigid::solver::wide_bodies::WideBodies;

/// The smallest |o| the tangent kernel takes, as raw bits: 2¹⁹ (2⁻¹³), so that
/// 1/|o| ≤ 2⁴⁵.
const SHORTEST: i64 = 1 << 19;

/// Sets the unit tangents of `block` with the kernel when `R` is I32F32, the processor has
/// a backend and every value lies within the bound; returns whether it did (if not, the
/// caller must).
pub(super) fn tangents<R: Real>(block: &mut ContactBlock<R>) -> bool {
    match (R::as_fixed_mut::<ContactBlockOf>(block), backend()) {
        (Some(block), Some(backend)) => tangents_on(backend, block),
        _ => false,
    }
}

/// Sets the twist arms of `block` from the squares in `arms` with the kernel when `R` is
/// I32F32 and the processor has a backend; returns whether it did (if not, the caller
/// must).
pub(super) fn twist_arms<R: Real>(block: &mut ContactBlock<R>, arms: &ContactArms<R>) -> bool {
    match (
        R::as_fixed_mut::<ContactBlockOf>(block),
        R::as_fixed::<ContactArmsOf>(arms),
        backend(),
    ) {
        (Some(block), Some(arms), Some(backend)) => {
            twist_arms_on(backend, block, arms);
            true
        }
        _ => false,
    }
}

kernel_entry! {
    /// [`unit_tangents`] with the instructions of `backend`.
    pub(super) fn tangents_on(block: &mut ContactBlock<Fx>) -> bool = unit_tangents;
}

kernel_entry! {
    /// [`twist_arm_roots`] with the instructions of `backend`.
    fn twist_arms_on(block: &mut ContactBlock<Fx>, arms: &ContactArms<Fx>) -> () = twist_arm_roots;
}

/// The tangent kernel (module documentation). Returns false, with nothing written, when a
/// value in a lane in use fails its check.
#[inline(always)]
fn unit_tangents<W: WideBodies>(w: W, block: &mut ContactBlock<Fx>) -> bool {
    let active = ((1u16 << block.len) - 1) as u8;
    let o = w.keep3(active, w.load3(&block.tangents[0]));
    let n = w.keep3(active, w.load3(&block.normal));
    if w.out_of_bound3(o) | w.out_of_bound3(n) != 0 {
        return false;
    }
    let [length] = sqrt(w, [w.rounded_dot(o, o)]);
    if w.greater(w.splat(SHORTEST), length) & active != 0 {
        return false;
    }
    let lengths = w.store_words(length);
    let mut inverses: Lanes<Fx> = [Fx::ZERO; LANES];
    for l in 0..block.len {
        inverses[l] = Fx::from_bits(lengths[l]).recip();
    }
    let inverse = w.load(&inverses);
    let t0 = [
        w.mul(o[0], inverse),
        w.mul(o[1], inverse),
        w.mul(o[2], inverse),
    ];
    w.store_lanes3(&mut block.tangents[0], active, t0);
    w.store_lanes3(&mut block.tangents[1], active, w.cross(n, t0));
    true
}

/// The twist arm kernel: the squares of the points in use (zero elsewhere) through the
/// square roots, side by side, and the roots stored to the points in use.
#[inline(always)]
fn twist_arm_roots<W: WideBodies>(w: W, block: &mut ContactBlock<Fx>, arms: &ContactArms<Fx>) {
    let active = ((1u16 << block.len) - 1) as u8;
    let counts = counts_of(w, block);
    let mut in_use = [0u8; MAX_MANIFOLD_POINTS];
    let mut squares = [w.zero(); MAX_MANIFOLD_POINTS];
    for k in 0..MAX_MANIFOLD_POINTS {
        in_use[k] = points_in_use(w, counts, active, k);
        squares[k] = w.select(in_use[k], w.load(&arms.twist_arm_squared[k]), w.zero());
    }
    let roots = sqrt(w, squares);
    for k in 0..MAX_MANIFOLD_POINTS {
        w.store_lanes(&mut block.points[k].twist_arm, in_use[k], roots[k]);
    }
}
