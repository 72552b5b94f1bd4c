//! The unit tangents of a block of I32F32 constraints in AVX-512, with the bits of
//! [`ContactBlock::tangents_lanes`]: for the vector o ⟂ n in the first tangent,
//! |o| = √(o·o) with the products of [`dot`] and the square roots of
//! [`sqrt`](crate::rigid::solver::avx512::sqrt) (both rounded as the scalar form rounds),
//! the reciprocal 1/|o| lane by lane with the checked `/`, then t₁ = o·(1/|o|) and
//! t₂ = n × t₁ with the checked `*` of [`mul`] and [`cross`].
//!
//! # Exactness
//!
//! The kernel takes a block when, in every lane in use, o and n lie within the bound
//! [−2⁴⁶, 2⁴⁶) as raw bits and |o| ≥ 2¹⁹ raw (2⁻¹³). Then o·o saturates nowhere (products
//! below 2⁶⁰), 1/|o| ≤ 2⁴⁵ raw neither saturates nor leaves the bound, and each
//! |t₁ᵢ| ≤ |oᵢ|(1/|o|) is within a few ulp of 1 (|oᵢ| ≤ |o| + 1 raw), inside the bound; so
//! every product is exact and nothing saturates, in the kernel or in the scalar form.
//! Otherwise it returns false before writing anything or dividing, and the caller takes
//! the scalar form. For a unit normal |o| ≥ 0.577, so every block of unit normals passes.

use core::any::Any;
use core::arch::x86_64::{
    __m512i, __mmask8, _mm512_cmplt_epi64_mask, _mm512_maskz_mov_epi64, _mm512_set1_epi64,
};

use super::{add, has_kernels, load, load3, mul, mul3, out_of_bound3, store, store_lanes, sub};
use crate::math::{Fx, Real};
use crate::rigid::solver::avx512::sqrt::sqrt;
use crate::rigid::solver::contact_constraint::ContactBlock;
use crate::rigid::solver::lanes::{LANES, Lanes, Lanes3};

/// The smallest |o| the kernel takes, as raw bits: 2¹⁹ (2⁻¹³), so that 1/|o| ≤ 2⁴⁵.
const SHORTEST: i64 = 1 << 19;

/// Sets the unit tangents of `block` with the kernel when `R` is I32F32, the processor has
/// AVX-512F and DQ and every value lies within the bound; returns whether it did (if not,
/// the caller must).
pub(in crate::rigid::solver::contact_constraint) fn tangents<R: Real>(
    block: &mut ContactBlock<R>,
) -> bool {
    if !has_kernels() {
        return false;
    }
    let Some(block) = (block as &mut dyn Any).downcast_mut::<ContactBlock<Fx>>() else {
        return false;
    };
    // SAFETY: AVX-512F and DQ were detected on this processor just above.
    unsafe { unit_tangents(block) }
}

/// The kernel (module documentation). Returns false, with nothing written, when a value
/// in a lane in use fails its check.
///
/// # Safety
/// The processor must have AVX-512F and AVX-512DQ.
#[target_feature(enable = "avx512f,avx512dq")]
unsafe fn unit_tangents(block: &mut ContactBlock<Fx>) -> bool {
    let active = ((1u16 << block.len) - 1) as __mmask8;
    let in_use = |v: [_; 3]| v.map(|x| _mm512_maskz_mov_epi64(active, x));
    let o = in_use(load3(&block.tangents[0]));
    let n = in_use(load3(&block.normal));
    if out_of_bound3(o) | out_of_bound3(n) != 0 {
        return false;
    }
    let [length] = sqrt([dot(o, o)]);
    if _mm512_cmplt_epi64_mask(length, _mm512_set1_epi64(SHORTEST)) & active != 0 {
        return false;
    }
    let mut lengths: Lanes<Fx> = [Fx::ZERO; LANES];
    store(&mut lengths, length);
    let inverses: Lanes<Fx> = core::array::from_fn(|l| {
        if l < block.len {
            lengths[l].recip()
        } else {
            Fx::ZERO
        }
    });
    let t0 = mul3(o, load(&inverses));
    store3(&mut block.tangents[0], active, t0);
    store3(&mut block.tangents[1], active, cross(n, t0));
    true
}

/// a × b with each product rounded on its own, as [`Vec3::cross`](crate::math::Vec3::cross).
#[inline]
#[target_feature(enable = "avx512f,avx512dq")]
fn cross(a: [__m512i; 3], b: [__m512i; 3]) -> [__m512i; 3] {
    [
        sub(mul(a[1], b[2]), mul(a[2], b[1])),
        sub(mul(a[2], b[0]), mul(a[0], b[2])),
        sub(mul(a[0], b[1]), mul(a[1], b[0])),
    ]
}

/// a·b with each product rounded on its own, as [`Vec3::dot`](crate::math::Vec3::dot).
#[inline]
#[target_feature(enable = "avx512f,avx512dq")]
fn dot(a: [__m512i; 3], b: [__m512i; 3]) -> __m512i {
    add(add(mul(a[0], b[0]), mul(a[1], b[1])), mul(a[2], b[2]))
}

#[inline]
#[target_feature(enable = "avx512f,avx512dq")]
fn store3(lanes: &mut Lanes3<Fx>, mask: __mmask8, value: [__m512i; 3]) {
    store_lanes(&mut lanes.x, mask, value[0]);
    store_lanes(&mut lanes.y, mask, value[1]);
    store_lanes(&mut lanes.z, mask, value[2]);
}
