//! Two preparation kernels of a block of I32F32 constraints in AVX-512 (F and DQ), any
//! block, independent or not: the tangents ([`tangents`](fn@tangents)) and the twist arms
//! ([`twist_arms`](fn@twist_arms)), each with the bits of its scalar form (they need the AVX-512 square
//! root, which has no AVX2 form yet). The products of the anchors and inertias are in
//! [`prepare_kernel`](super::prepare_kernel), the solve and warm-start passes in
//! [`kernel`](super::kernel), both for AVX-512 and AVX2.

mod tangents;
mod twist_arms;

pub(super) use tangents::tangents;
pub(super) use twist_arms::twist_arms;

use core::any::Any;

use super::{ContactArms, ContactBlock};
use crate::math::{Fx, Real};
use crate::rigid::solver::avx512::{
    add, has_kernels, load, load3, mul, mul3, out_of_bound3, store, store_lanes, sub,
};

/// `block` and `arms` as I32F32 values when `R` is I32F32 and the processor has AVX-512F
/// and DQ (the preparation kernels' condition); `None` otherwise.
fn fx_operands<'a, R: Real>(
    block: &'a mut ContactBlock<R>,
    arms: &'a ContactArms<R>,
) -> Option<(&'a mut ContactBlock<Fx>, &'a ContactArms<Fx>)> {
    if !has_kernels() {
        return None;
    }
    Some((
        (block as &mut dyn Any).downcast_mut::<ContactBlock<Fx>>()?,
        (arms as &dyn Any).downcast_ref::<ContactArms<Fx>>()?,
    ))
}
