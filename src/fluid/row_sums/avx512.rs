//! The row sums in AVX-512F for I32F32: eight neighbour entries of one row side by side,
//! one `i64` lane each, then the lanes added.
//!
//! The smoothing sum's weights w = V₀W · ρ₀/ρⱼ are products too: with V₀W of at most 2ᶜ
//! and ρ₀/ρ of at most 2ᴰ, when C, D ≤ 61 and C + D − 32 ≤ 61 each weight is the checked
//! `*`; the kernel then measures the weights it made (bit length A in place of the
//! gradients' below) for the sum's bound.
//!
//! # Exactness
//!
//! Every operation is done modulo 2⁶⁴. The kernel ORs together the magnitudes of every
//! value it reads (as `v ^ (v >> 63)`, which is |v| or |v| − 1) and so knows bit lengths
//! A (gradients) and B (velocities, or stiffnesses) with |g| ≤ 2ᴬ and |v| ≤ 2ᴮ, and the
//! longest row L. A difference vᵢ − vⱼ (or sum kᵢ + kⱼ) is at most 2ᴮ⁺¹; a rounded product
//! of it with a gradient component at most 2^(A + B + 1 − 32); a row's sum has at most
//! T = 3L such terms (L for a push component). When A, B + 1 ≤ 61 and
//! A + B + 1 − 32 + ⌈log₂ T⌉ ≤ 61, every product, and every partial sum in any order, is
//! below 2⁶², so the checked operators of the scalar form saturate nowhere and their sums
//! are exact, and so are the kernel's. When the bound fails, the kernel's output is thrown
//! away (the caller runs the scalar form).
//!
//! # Products
//!
//! Each product is [`lanes::product`](crate::fluid::lanes::product), the checked `*` when
//! its operands are bounded as above. A lane past the end of a row loads zero for the
//! neighbour and the gradient, so its product is ⌊2³¹/2³²⌋ = 0 and adds nothing.

use core::any::Any;
use core::arch::x86_64::{
    __m512i, __mmask8, _mm512_add_epi64, _mm512_castsi512_si256, _mm512_cvtepu32_epi64,
    _mm512_mask_cmplt_epu64_mask, _mm512_maskz_loadu_epi32, _mm512_maskz_loadu_epi64,
    _mm512_or_si512, _mm512_reduce_add_epi64, _mm512_reduce_or_epi64, _mm512_set1_epi64,
    _mm512_setzero_si512, _mm512_sub_epi64,
};
use core::mem::size_of;

use crate::fluid::lanes::{
    bit_length, load_values, magnitude, mul, product, scalar_bits, vector_bits,
};
use crate::fluid::neighbours::NeighbourLists;
use crate::math::{Fx, Real, Vec3};
use crate::soft::lanes::gather3;

// The layout the loads rely on: `Fx` is one `i64`, `Vec3<Fx>` x, y, z in a row.
const _: () = {
    assert!(size_of::<Fx>() == 8);
    assert!(size_of::<Vec3<Fx>>() == 24);
};

/// The largest bit length of a value that enters a product (see the module documentation).
const MAX_OPERAND_BITS: u32 = 61;

/// [`density_rates`](super::density_rates) with the kernel when `R` is I32F32 and the
/// processor has AVX-512F; returns whether it did (if not, `out` holds nothing of use).
#[allow(clippy::ptr_arg)] // `out` is downcast to the `Vec` it grows
pub(super) fn density_rates<R: Real>(
    lists: &NeighbourLists<R>,
    gradient_bits: u32,
    velocities: &[Vec3<R>],
    out: &mut Vec<R>,
) -> bool {
    if !crate::math::cpu::avx512f() {
        return false;
    }
    let (Some(lists), Some(out)) = (
        (lists as &dyn Any).downcast_ref::<NeighbourLists<Fx>>(),
        (out as &mut dyn Any).downcast_mut::<Vec<Fx>>(),
    ) else {
        return false;
    };
    // SAFETY: `R` is `Fx` (the downcasts succeeded), so the slice's type is unchanged.
    let velocities = unsafe { &*(core::ptr::from_ref(velocities) as *const [Vec3<Fx>]) };
    // SAFETY: AVX-512F was detected above.
    let velocity_bits = unsafe { vector_bits(velocities) };
    // |vᵢ − vⱼ| < 2^(B + 1).
    let difference_bits = velocity_bits + 1;
    // SAFETY: AVX-512F was detected just above.
    unsafe {
        if difference_bits <= 31 {
            density_rates_kernel::<true>(lists, velocities, [gradient_bits, difference_bits], out)
        } else {
            density_rates_kernel::<false>(lists, velocities, [gradient_bits, difference_bits], out)
        }
    }
}

/// [`pressure_pushes`](super::pressure_pushes) with the kernel, under the same conditions
/// as [`density_rates`].
#[allow(clippy::ptr_arg)] // `out` is downcast to the `Vec` it grows
pub(super) fn pressure_pushes<R: Real>(
    lists: &NeighbourLists<R>,
    gradient_bits: u32,
    stiffness: &[R],
    out: &mut Vec<Vec3<R>>,
) -> bool {
    if !crate::math::cpu::avx512f() {
        return false;
    }
    let (Some(lists), Some(out)) = (
        (lists as &dyn Any).downcast_ref::<NeighbourLists<Fx>>(),
        (out as &mut dyn Any).downcast_mut::<Vec<Vec3<Fx>>>(),
    ) else {
        return false;
    };
    // SAFETY: `R` is `Fx` (the downcasts succeeded), so the slice's type is unchanged.
    let stiffness = unsafe { &*(core::ptr::from_ref(stiffness) as *const [Fx]) };
    // SAFETY: AVX-512F was detected above.
    let stiffness_bits = unsafe { scalar_bits(stiffness) };
    // |kᵢ + kⱼ| < 2^(B + 1).
    let sum_bits = stiffness_bits + 1;
    // SAFETY: AVX-512F was detected just above.
    unsafe {
        if sum_bits <= 31 {
            pressure_pushes_kernel::<true>(lists, stiffness, [gradient_bits, sum_bits], out)
        } else {
            pressure_pushes_kernel::<false>(lists, stiffness, [gradient_bits, sum_bits], out)
        }
    }
}

/// [`smoothing_sums`](super::smoothing_sums) with the kernel, under the same conditions
/// as [`density_rates`].
#[allow(clippy::ptr_arg)] // `out` is downcast to the `Vec` it grows
pub(super) fn smoothing_sums<R: Real>(
    lists: &NeighbourLists<R>,
    velocities: &[Vec3<R>],
    inv_density: &[R],
    out: &mut Vec<Vec3<R>>,
) -> bool {
    if !crate::math::cpu::avx512f() {
        return false;
    }
    let (Some(lists), Some(out)) = (
        (lists as &dyn Any).downcast_ref::<NeighbourLists<Fx>>(),
        (out as &mut dyn Any).downcast_mut::<Vec<Vec3<Fx>>>(),
    ) else {
        return false;
    };
    // SAFETY: `R` is `Fx` (the downcasts succeeded), so the slices' types are unchanged.
    let (velocities, inv_density) = unsafe {
        (
            &*(core::ptr::from_ref(velocities) as *const [Vec3<Fx>]),
            &*(core::ptr::from_ref(inv_density) as *const [Fx]),
        )
    };
    // SAFETY: AVX-512F was detected above.
    let (velocity_bits, density_bits) =
        unsafe { (vector_bits(velocities), scalar_bits(inv_density)) };
    let bits = Bits {
        difference: velocity_bits + 1,
        density: density_bits,
    };
    // SAFETY: AVX-512F was detected just above.
    unsafe {
        if bits.difference <= 31 {
            smoothing_sums_kernel::<true>(lists, velocities, inv_density, bits, out)
        } else {
            smoothing_sums_kernel::<false>(lists, velocities, inv_density, bits, out)
        }
    }
}

/// [`gradient_sums`](super::gradient_sums) with the kernel, under the same conditions as
/// [`density_rates`]: whether it did (if not, `sums` and `squares` hold nothing of use),
/// and the bit length A of the largest gradient component when it read every row (the
/// bound of [`density_rates`] and [`pressure_pushes`] over the same lists).
#[allow(clippy::ptr_arg)] // `sums` and `squares` are downcast to the `Vec`s they grow
pub(super) fn gradient_sums<R: Real>(
    lists: &NeighbourLists<R>,
    sums: &mut Vec<Vec3<R>>,
    squares: &mut Vec<R>,
) -> (bool, Option<u32>) {
    if !crate::math::cpu::avx512f() {
        return (false, None);
    }
    let (Some(lists), Some(sums), Some(squares)) = (
        (lists as &dyn Any).downcast_ref::<NeighbourLists<Fx>>(),
        (sums as &mut dyn Any).downcast_mut::<Vec<Vec3<Fx>>>(),
        (squares as &mut dyn Any).downcast_mut::<Vec<Fx>>(),
    ) else {
        return (false, None);
    };
    // SAFETY: AVX-512F was detected just above.
    unsafe { gradient_sums_kernel(lists, sums, squares) }
}

/// Bit lengths of what the smoothing sum reads: velocity differences (at most
/// 2^`difference`) and inverse densities (at most 2^`density`).
#[derive(Clone, Copy)]
struct Bits {
    difference: u32,
    density: u32,
}

/// Whether products and row sums with operands of `a` and `b` bits (see the module
/// documentation) over rows of at most `terms` terms stay below 2⁶².
fn within_bound(a: u32, b: u32, terms: usize) -> bool {
    let sum_bits = usize::BITS - terms.max(1).saturating_sub(1).leading_zeros();
    a <= MAX_OPERAND_BITS && b <= MAX_OPERAND_BITS && (a + b).saturating_sub(32) + sum_bits <= 61
}

/// The lane mask of entries `first..first + count` (count 1 to 8) of a row, or `None` when
/// one of their neighbour indices is not below `points`.
///
/// # Safety
/// `first + count` must not exceed the number of entries of `lists.index`.
#[inline]
#[target_feature(enable = "avx512f")]
unsafe fn load_indices(
    lists: &NeighbourLists<Fx>,
    first: usize,
    count: usize,
    points: __m512i,
) -> Option<__mmask8> {
    let mask = ((1u16 << count) - 1) as __mmask8;
    // SAFETY: the masked load reads only the `count` entries from `first`, which exist.
    let index32 = unsafe {
        _mm512_maskz_loadu_epi32(u16::from(mask), lists.index.as_ptr().add(first).cast())
    };
    let index = _mm512_cvtepu32_epi64(_mm512_castsi512_si256(index32));
    (_mm512_mask_cmplt_epu64_mask(mask, index, points) == mask).then_some(mask)
}

/// The three gradient components of entries `first..first + count` (count 1 to 8) of a row
/// (zero past `count`), or `None` when one of their neighbour indices is not below
/// `points`.
///
/// # Safety
/// `first + count` must not exceed the number of entries of `lists.index` and
/// `lists.gradients`.
#[inline]
#[target_feature(enable = "avx512f")]
unsafe fn load_entries(
    lists: &NeighbourLists<Fx>,
    first: usize,
    count: usize,
    points: __m512i,
) -> Option<[__m512i; 3]> {
    // SAFETY: the caller's condition covers `lists.index`.
    let mask = unsafe { load_indices(lists, first, count, points) }?;
    // SAFETY: the masked loads read only the `count` entries from `first`, which exist.
    let gradient = lists
        .gradients
        .each_ref()
        .map(|g| unsafe { _mm512_maskz_loadu_epi64(mask, g.as_ptr().add(first).cast()) });
    Some(gradient)
}

/// The density rate kernel, for gradients below 2^`gradient_bits` and velocity
/// differences below 2^`difference_bits` (32-bit signed numbers when `NARROW`): returns
/// false when the bound fails (`out` then holds nothing of use).
///
/// # Safety
/// The processor must have AVX-512F; with `NARROW`, `difference_bits` must be at most 31.
#[target_feature(enable = "avx512f")]
unsafe fn density_rates_kernel<const NARROW: bool>(
    lists: &NeighbourLists<Fx>,
    velocities: &[Vec3<Fx>],
    [gradient_bits, difference_bits]: [u32; 2],
    out: &mut Vec<Fx>,
) -> bool {
    out.clear();
    let zero = _mm512_setzero_si512();
    let points = _mm512_set1_epi64(velocities.len() as i64);
    let entries = lists
        .gradients
        .iter()
        .fold(lists.index.len(), |n, g| n.min(g.len()));
    let mut longest = 0;
    for (i, vi) in velocities.iter().enumerate().take(lists.len()) {
        let range = lists.range(i);
        if range.end > entries {
            return false;
        }
        longest = longest.max(range.len());
        let vi = [vi.x, vi.y, vi.z].map(|c| _mm512_set1_epi64(c.to_bits()));
        let mut sum = zero;
        let mut first = range.start;
        while first < range.end {
            let count = (range.end - first).min(8);
            // SAFETY: `first + count` is within the row, which ends within the entries.
            let Some(gradient) = (unsafe { load_entries(lists, first, count, points) }) else {
                return false;
            };
            // Every index in use is below `velocities.len()` (`load_entries`).
            let Some(vj) = gather3(velocities, &lists.index[first..first + count]) else {
                return false;
            };
            for c in 0..3 {
                let difference = _mm512_sub_epi64(vi[c], vj[c]);
                sum = _mm512_add_epi64(sum, product::<NARROW>(gradient[c], difference));
            }
            first += count;
        }
        out.push(Fx::from_bits(_mm512_reduce_add_epi64(sum)));
    }
    within_bound(gradient_bits, difference_bits, 3 * longest)
}

/// The pressure push kernel, for gradients below 2^`gradient_bits` and stiffness sums
/// below 2^`sum_bits` (32-bit signed numbers when `NARROW`): returns false when the bound
/// fails (`out` then holds nothing of use).
///
/// # Safety
/// The processor must have AVX-512F; with `NARROW`, `sum_bits` must be at most 31.
#[target_feature(enable = "avx512f")]
unsafe fn pressure_pushes_kernel<const NARROW: bool>(
    lists: &NeighbourLists<Fx>,
    stiffness: &[Fx],
    [gradient_bits, sum_bits]: [u32; 2],
    out: &mut Vec<Vec3<Fx>>,
) -> bool {
    out.clear();
    let zero = _mm512_setzero_si512();
    let base = stiffness.as_ptr().cast::<i64>();
    let points = _mm512_set1_epi64(stiffness.len() as i64);
    let entries = lists
        .gradients
        .iter()
        .fold(lists.index.len(), |n, g| n.min(g.len()));
    let mut longest = 0;
    for (i, ki) in stiffness.iter().enumerate().take(lists.len()) {
        let range = lists.range(i);
        if range.end > entries {
            return false;
        }
        longest = longest.max(range.len());
        let ki = _mm512_set1_epi64(ki.to_bits());
        let mut push = [zero; 3];
        let mut first = range.start;
        while first < range.end {
            let count = (range.end - first).min(8);
            // SAFETY: `first + count` is within the row, which ends within the entries.
            let Some(gradient) = (unsafe { load_entries(lists, first, count, points) }) else {
                return false;
            };
            // SAFETY: every index in use is below `stiffness.len()` (`load_entries`).
            let kj = unsafe { load_values(base, &lists.index[first..], count) };
            let k = _mm512_add_epi64(ki, kj);
            for (p, g) in push.iter_mut().zip(gradient) {
                *p = _mm512_add_epi64(*p, product::<NARROW>(g, k));
            }
            first += count;
        }
        let [x, y, z] = push.map(|p| Fx::from_bits(_mm512_reduce_add_epi64(p)));
        out.push(Vec3::new(x, y, z));
    }
    within_bound(gradient_bits, sum_bits, longest)
}

/// The smoothing sum kernel, for velocity differences below 2^`bits.difference` (32-bit
/// signed numbers when `NARROW`): returns false when a bound fails (`out` then holds
/// nothing of use).
///
/// # Safety
/// The processor must have AVX-512F; with `NARROW`, `bits.difference` must be at most 31.
#[target_feature(enable = "avx512f")]
unsafe fn smoothing_sums_kernel<const NARROW: bool>(
    lists: &NeighbourLists<Fx>,
    velocities: &[Vec3<Fx>],
    inv_density: &[Fx],
    bits: Bits,
    out: &mut Vec<Vec3<Fx>>,
) -> bool {
    out.clear();
    let zero = _mm512_setzero_si512();
    let density_base = inv_density.as_ptr().cast::<i64>();
    let points = _mm512_set1_epi64(velocities.len().min(inv_density.len()) as i64);
    let entries = lists.index.len().min(lists.value.len());
    let mut value_bits = zero;
    let mut weight_bits = zero;
    let mut longest = 0;
    for (i, vi) in velocities.iter().enumerate().take(lists.len()) {
        let range = lists.range(i);
        if range.end > entries {
            return false;
        }
        longest = longest.max(range.len());
        let vi = [vi.x, vi.y, vi.z].map(|c| _mm512_set1_epi64(c.to_bits()));
        let mut sum = [zero; 3];
        let mut first = range.start;
        while first < range.end {
            let count = (range.end - first).min(8);
            // SAFETY: `first + count` is within the row, which ends within the entries.
            let Some(mask) = (unsafe { load_indices(lists, first, count, points) }) else {
                return false;
            };
            // SAFETY: the masked load reads only the `count` entries from `first`, which
            // exist (the row ends within the entries).
            let value =
                unsafe { _mm512_maskz_loadu_epi64(mask, lists.value.as_ptr().add(first).cast()) };
            let indices = &lists.index[first..];
            // SAFETY: every index in use is below both slices' lengths (checked above).
            let inverse = unsafe { load_values(density_base, indices, count) };
            value_bits = _mm512_or_si512(value_bits, magnitude(value));
            let weight = mul(value, inverse);
            weight_bits = _mm512_or_si512(weight_bits, magnitude(weight));
            // Every index in use is below `velocities.len()` (checked above).
            let Some(vj) = gather3(velocities, &indices[..count]) else {
                return false;
            };
            for ((s, vi), vj) in sum.iter_mut().zip(vi).zip(vj) {
                *s = _mm512_add_epi64(*s, product::<NARROW>(weight, _mm512_sub_epi64(vj, vi)));
            }
            first += count;
        }
        let [x, y, z] = sum.map(|s| Fx::from_bits(_mm512_reduce_add_epi64(s)));
        out.push(Vec3::new(x, y, z));
    }
    let c = bit_length(_mm512_reduce_or_epi64(value_bits) as u64);
    let a = bit_length(_mm512_reduce_or_epi64(weight_bits) as u64);
    within_bound(c, bits.density, 1) && within_bound(a, bits.difference, longest)
}

/// The gradient sums kernel: whether its sums stand (if not, `sums` and `squares` hold
/// nothing of use), and the gradients' bit length A when every row lies within the
/// entries. With gradients of at most 2ᴬ in rows of at most L entries, the
/// squares' sum is bounded as a row sum of 3L products of A-bit operands, and the
/// gradients' sum needs A + ⌈log₂ L⌉ ≤ 61.
///
/// # Safety
/// The processor must have AVX-512F.
#[target_feature(enable = "avx512f")]
unsafe fn gradient_sums_kernel(
    lists: &NeighbourLists<Fx>,
    sums: &mut Vec<Vec3<Fx>>,
    squares: &mut Vec<Fx>,
) -> (bool, Option<u32>) {
    sums.clear();
    squares.clear();
    let zero = _mm512_setzero_si512();
    let entries = lists.gradients.iter().map(Vec::len).min().unwrap_or(0);
    let mut gradient_bits = zero;
    let mut longest = 0;
    for i in 0..lists.len() {
        let range = lists.range(i);
        if range.end > entries {
            return (false, None);
        }
        longest = longest.max(range.len());
        let mut sum = [zero; 3];
        let mut square = zero;
        let mut first = range.start;
        while first < range.end {
            let count = (range.end - first).min(8);
            let mask = ((1u16 << count) - 1) as __mmask8;
            for (s, g) in sum.iter_mut().zip(&lists.gradients) {
                // SAFETY: the masked load reads only the `count` entries from `first`, which
                // exist (the row ends within the entries).
                let g = unsafe { _mm512_maskz_loadu_epi64(mask, g.as_ptr().add(first).cast()) };
                gradient_bits = _mm512_or_si512(gradient_bits, magnitude(g));
                *s = _mm512_add_epi64(*s, g);
                square = _mm512_add_epi64(square, mul(g, g));
            }
            first += count;
        }
        let [x, y, z] = sum.map(|s| Fx::from_bits(_mm512_reduce_add_epi64(s)));
        sums.push(Vec3::new(x, y, z));
        squares.push(Fx::from_bits(_mm512_reduce_add_epi64(square)));
    }
    let a = bit_length(_mm512_reduce_or_epi64(gradient_bits) as u64);
    let sum_bits = usize::BITS - longest.max(1).saturating_sub(1).leading_zeros();
    let stands = within_bound(a, a, 3 * longest) && a + sum_bits <= MAX_OPERAND_BITS;
    (stands, Some(a))
}
