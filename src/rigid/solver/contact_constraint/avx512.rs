//! The preparation kernels of a block of I32F32 constraints in AVX-512 (F and DQ), any
//! block, independent or not: the products of the anchors and inertias
//! ([`prepare`]), the tangents ([`tangents`]) and the twist arms ([`twist_arms`]), each
//! with the bits of its scalar form. The solve and warm-start passes are in
//! [`kernel`](super::kernel).

mod prepare;
mod tangents;
mod twist_arms;

pub(super) use prepare::prepare;
pub(super) use tangents::tangents;
pub(super) use twist_arms::twist_arms;

use core::any::Any;
use core::arch::x86_64::{__m512i, __mmask8, _mm512_loadu_si512};

use super::{ContactArms, ContactBlock};
use crate::math::{Fx, Real};
use crate::rigid::solver::avx512::{
    add, has_kernels, load, load3, mul, mul3, out_of_bound, out_of_bound3, store, store_lanes, sub,
    sub3,
};
use crate::rigid::solver::lanes::LANES;
use crate::rigid::solver::wide::avx512::{BODY_WORDS, V, W};

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

/// The lanes in use of `block`, and the first word of each lane's body A and body B in
/// an array of `body_count` solver bodies; `None` if an index is out of bounds.
#[inline]
#[target_feature(enable = "avx512f,avx512dq")]
fn lane_words(block: &ContactBlock<Fx>, body_count: usize) -> Option<(__mmask8, __m512i, __m512i)> {
    let mut words_a = [0i64; LANES];
    let mut words_b = [0i64; LANES];
    for l in 0..block.len {
        let (a, b) = (block.a[l] as usize, block.b[l] as usize);
        if a >= body_count || b >= body_count {
            return None;
        }
        words_a[l] = a as i64 * BODY_WORDS;
        words_b[l] = b as i64 * BODY_WORDS;
    }
    // SAFETY: 64 readable bytes each.
    let (words_a, words_b) = unsafe {
        (
            _mm512_loadu_si512(words_a.as_ptr().cast()),
            _mm512_loadu_si512(words_b.as_ptr().cast()),
        )
    };
    Some((((1u16 << block.len) - 1) as __mmask8, words_a, words_b))
}
