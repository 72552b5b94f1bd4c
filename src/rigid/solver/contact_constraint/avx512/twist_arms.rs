//! The twist lever arms of a block of I32F32 constraints in AVX-512: d_k = √(d_k²) for
//! every point of every lane at once, with the bits of
//! [`ContactBlock::twist_arms_lanes`] (the square roots of
//! [`sqrt`](crate::rigid::solver::avx512::sqrt), which round as `Real::sqrt` does). Only
//! the points in use are written, as the scalar form writes them.

use core::arch::x86_64::{
    __m512i, __mmask8, _mm512_cmpgt_epi64_mask, _mm512_loadu_si512, _mm512_maskz_mov_epi64,
    _mm512_set1_epi64,
};

use super::{fx_operands, load, store_lanes};
use crate::math::{Fx, Real};
use crate::rigid::manifold::MAX_MANIFOLD_POINTS;
use crate::rigid::solver::avx512::sqrt::sqrt;
use crate::rigid::solver::contact_constraint::{ContactArms, ContactBlock};

/// Sets the twist arms of `block` from the squares in `arms` when `R` is I32F32 and the
/// processor has AVX-512F and DQ; returns whether it did (if not, the caller must).
pub(in crate::rigid::solver::contact_constraint) fn twist_arms<R: Real>(
    block: &mut ContactBlock<R>,
    arms: &ContactArms<R>,
) -> bool {
    let Some((block, arms)) = fx_operands(block, arms) else {
        return false;
    };
    // SAFETY: `fx_operands` detected AVX-512F and DQ on this processor.
    unsafe { roots(block, arms) };
    true
}

/// The kernel: the squares of the points in use (zero elsewhere) through the square
/// roots, side by side, and the roots stored to the points in use.
///
/// # Safety
/// The processor must have AVX-512F and AVX-512DQ.
#[target_feature(enable = "avx512f,avx512dq")]
unsafe fn roots(block: &mut ContactBlock<Fx>, arms: &ContactArms<Fx>) {
    let active = ((1u16 << block.len) - 1) as __mmask8;
    // SAFETY: 64 readable bytes.
    let counts = unsafe { _mm512_loadu_si512(block.count.map(i64::from).as_ptr().cast()) };
    let in_use: [__mmask8; MAX_MANIFOLD_POINTS] = core::array::from_fn(|k| {
        _mm512_cmpgt_epi64_mask(counts, _mm512_set1_epi64(k as i64)) & active
    });
    let squares: [__m512i; MAX_MANIFOLD_POINTS] = core::array::from_fn(|k| {
        _mm512_maskz_mov_epi64(in_use[k], load(&arms.twist_arm_squared[k]))
    });
    let roots = sqrt(squares);
    for (k, cp) in block.points.iter_mut().enumerate() {
        store_lanes(&mut cp.twist_arm, in_use[k], roots[k]);
    }
}
