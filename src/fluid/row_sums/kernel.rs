//! The row sums on the lanes of [`Wide`] for I32F32: eight neighbour entries of one row
//! side by side, one lane each, then the lanes added; one kernel for every backend.
//!
//! The smoothing sum's weights w = V₀W · ρ₀/ρⱼ are products too: with V₀W of at most 2ᶜ
//! and ρ₀/ρ of at most 2ᴰ, when C, D ≤ 61 and C + D − 32 ≤ 61 each weight is the checked
//! `*`; the kernel then measures the weights it made (bit length A in place of the
//! gradients' below) for the sum's bound.
//!
//! # Exactness
//!
//! Every operation is done modulo 2⁶⁴. The kernel ORs together the magnitudes of every
//! value it reads ([`Wide::magnitude`], |v| or |v| − 1) and so knows bit lengths A
//! (gradients) and B (velocities, or stiffnesses) with |g| ≤ 2ᴬ and |v| ≤ 2ᴮ, and the
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
//! Each product is [`Wide::mul`] (or [`Wide::times`] when the differences are 32-bit
//! signed numbers), the checked `*` for operands of these bounds: the proof is in
//! [`wide`](crate::math::wide). A lane past the end of a row loads zero for the neighbour
//! and the gradient, so its product is ⌊2³¹/2³²⌋ = 0 and adds nothing.

use crate::fluid::neighbours::NeighbourLists;
use crate::math::wide::{LANES, Wide, bit_length, kernel_entry, scalar_bits, vector_bits};
use crate::math::{Fx, Vec3};

/// The largest bit length of a value that enters a product (see the module documentation).
const MAX_OPERAND_BITS: u32 = 61;

kernel_entry! {
    /// [`density_rates_kernel`] with the instructions of `backend`.
    pub(super) fn density_rates(
        lists: &NeighbourLists<Fx>,
        gradient_bits: u32,
        velocities: &[Vec3<Fx>],
        out: &mut Vec<Fx>,
    ) -> bool = density_rates_kernel;
}

kernel_entry! {
    /// [`pressure_pushes_kernel`] with the instructions of `backend`.
    pub(super) fn pressure_pushes(
        lists: &NeighbourLists<Fx>,
        gradient_bits: u32,
        stiffness: &[Fx],
        out: &mut Vec<Vec3<Fx>>,
    ) -> bool = pressure_pushes_kernel;
}

kernel_entry! {
    /// [`smoothing_sums_kernel`] with the instructions of `backend`.
    pub(super) fn smoothing_sums(
        lists: &NeighbourLists<Fx>,
        velocities: &[Vec3<Fx>],
        inv_density: &[Fx],
        out: &mut Vec<Vec3<Fx>>,
    ) -> bool = smoothing_sums_kernel;
}

kernel_entry! {
    /// [`gradient_sums_kernel`] with the instructions of `backend`.
    pub(super) fn gradient_sums(
        lists: &NeighbourLists<Fx>,
        sums: &mut Vec<Vec3<Fx>>,
        squares: &mut Vec<Fx>,
    ) -> (bool, Option<u32>) = gradient_sums_kernel;
}

/// Whether products and row sums with operands of `a` and `b` bits (see the module
/// documentation) over rows of at most `terms` terms stay below 2⁶².
fn within_bound(a: u32, b: u32, terms: usize) -> bool {
    let sum_bits = usize::BITS - terms.max(1).saturating_sub(1).leading_zeros();
    a <= MAX_OPERAND_BITS && b <= MAX_OPERAND_BITS && (a + b).saturating_sub(32) + sum_bits <= 61
}

/// The number of entries every list of `lists` has.
fn entries(lists: &NeighbourLists<Fx>) -> usize {
    lists
        .gradients
        .iter()
        .fold(lists.index.len().min(lists.value.len()), |n, g| {
            n.min(g.len())
        })
}

/// Whether the neighbour indices of entries `first..first + count` (count 1 to 8) of a row
/// are all below `points`.
///
/// # Safety
/// `first + count` must not exceed the number of entries of `lists.index`.
#[inline(always)]
unsafe fn indices_below<W: Wide>(
    w: W,
    lists: &NeighbourLists<Fx>,
    first: usize,
    count: usize,
    points: W::V,
) -> bool {
    // SAFETY: the `count` indices from `first` exist.
    let index = unsafe { w.load_prefix_u32(lists.index.as_ptr().add(first), count) };
    // The lanes past `count` hold zero, below any positive `points`.
    w.at_least_unsigned(index, points) == 0
}

/// The three gradient components of entries `first..first + count` (count 1 to 8) of a row
/// (zero past `count`).
///
/// # Safety
/// `first + count` must not exceed the number of entries of `lists.gradients`.
#[inline(always)]
unsafe fn load_gradients<W: Wide>(
    w: W,
    lists: &NeighbourLists<Fx>,
    first: usize,
    count: usize,
) -> [W::V; 3] {
    let [x, y, z] = &lists.gradients;
    // SAFETY: the `count` entries from `first` exist.
    unsafe {
        [
            w.load_prefix(x.as_ptr().add(first).cast(), count),
            w.load_prefix(y.as_ptr().add(first).cast(), count),
            w.load_prefix(z.as_ptr().add(first).cast(), count),
        ]
    }
}

/// The product of a gradient (or weight) and a difference below 2³¹ when `NARROW`.
#[inline(always)]
fn product<W: Wide, const NARROW: bool>(w: W, g: W::V, difference: W::V) -> W::V {
    if NARROW {
        w.times::<true>(difference, g)
    } else {
        w.mul(g, difference)
    }
}

/// The density rate kernel: false when the bound fails or a row runs past the entries or
/// names a neighbour beyond `velocities` (`out` then holds nothing of use).
#[inline(always)]
fn density_rates_kernel<W: Wide>(
    w: W,
    lists: &NeighbourLists<Fx>,
    gradient_bits: u32,
    velocities: &[Vec3<Fx>],
    out: &mut Vec<Fx>,
) -> bool {
    // |vᵢ − vⱼ| < 2^(B + 1).
    let difference_bits = vector_bits(velocities) + 1;
    let bits = [gradient_bits, difference_bits];
    if difference_bits <= 31 {
        density_rates_rows::<W, true>(w, lists, velocities, bits, out)
    } else {
        density_rates_rows::<W, false>(w, lists, velocities, bits, out)
    }
}

#[inline(always)]
fn density_rates_rows<W: Wide, const NARROW: bool>(
    w: W,
    lists: &NeighbourLists<Fx>,
    velocities: &[Vec3<Fx>],
    [gradient_bits, difference_bits]: [u32; 2],
    out: &mut Vec<Fx>,
) -> bool {
    out.clear();
    let points = w.splat(velocities.len() as i64);
    let entries = entries(lists);
    let mut longest = 0;
    for (i, vi) in velocities.iter().enumerate().take(lists.len()) {
        let range = lists.range(i);
        if range.end > entries {
            return false;
        }
        longest = longest.max(range.len());
        let vi = [
            w.splat(vi.x.to_bits()),
            w.splat(vi.y.to_bits()),
            w.splat(vi.z.to_bits()),
        ];
        let mut sum = w.zero();
        let mut first = range.start;
        while first < range.end {
            let count = (range.end - first).min(LANES);
            // SAFETY (both): `first + count` is within the row, which ends within the
            // entries.
            if !unsafe { indices_below(w, lists, first, count, points) } {
                return false;
            }
            let gradient = unsafe { load_gradients(w, lists, first, count) };
            let Some(vj) = w.gather_vectors(velocities, &lists.index[first..first + count]) else {
                return false;
            };
            for c in 0..3 {
                let difference = w.sub(vi[c], vj[c]);
                sum = w.add(sum, product::<W, NARROW>(w, gradient[c], difference));
            }
            first += count;
        }
        out.push(Fx::from_bits(w.sum_lanes(sum)));
    }
    within_bound(gradient_bits, difference_bits, 3 * longest)
}

/// The pressure push kernel: false when the bound fails or a row runs past the entries or
/// names a neighbour beyond `stiffness` (`out` then holds nothing of use).
#[inline(always)]
fn pressure_pushes_kernel<W: Wide>(
    w: W,
    lists: &NeighbourLists<Fx>,
    gradient_bits: u32,
    stiffness: &[Fx],
    out: &mut Vec<Vec3<Fx>>,
) -> bool {
    // |kᵢ + kⱼ| < 2^(B + 1).
    let sum_bits = scalar_bits(stiffness) + 1;
    let bits = [gradient_bits, sum_bits];
    if sum_bits <= 31 {
        pressure_pushes_rows::<W, true>(w, lists, stiffness, bits, out)
    } else {
        pressure_pushes_rows::<W, false>(w, lists, stiffness, bits, out)
    }
}

#[inline(always)]
fn pressure_pushes_rows<W: Wide, const NARROW: bool>(
    w: W,
    lists: &NeighbourLists<Fx>,
    stiffness: &[Fx],
    [gradient_bits, sum_bits]: [u32; 2],
    out: &mut Vec<Vec3<Fx>>,
) -> bool {
    out.clear();
    let base = stiffness.as_ptr().cast::<i64>();
    let points = w.splat(stiffness.len() as i64);
    let entries = entries(lists);
    let mut longest = 0;
    for (i, ki) in stiffness.iter().enumerate().take(lists.len()) {
        let range = lists.range(i);
        if range.end > entries {
            return false;
        }
        longest = longest.max(range.len());
        let ki = w.splat(ki.to_bits());
        let mut push = [w.zero(); 3];
        let mut first = range.start;
        while first < range.end {
            let count = (range.end - first).min(LANES);
            // SAFETY (all three): `first + count` is within the row, which ends within
            // the entries, and every index in use is below `stiffness.len()`.
            if !unsafe { indices_below(w, lists, first, count, points) } {
                return false;
            }
            let gradient = unsafe { load_gradients(w, lists, first, count) };
            let kj = unsafe { w.gather_values(base, &lists.index[first..], count) };
            let k = w.add(ki, kj);
            for c in 0..3 {
                push[c] = w.add(push[c], product::<W, NARROW>(w, gradient[c], k));
            }
            first += count;
        }
        let [x, y, z] = push;
        out.push(Vec3::new(
            Fx::from_bits(w.sum_lanes(x)),
            Fx::from_bits(w.sum_lanes(y)),
            Fx::from_bits(w.sum_lanes(z)),
        ));
    }
    within_bound(gradient_bits, sum_bits, longest)
}

/// The smoothing sum kernel: false when a bound fails or a row runs past the entries or
/// names a neighbour beyond the slices (`out` then holds nothing of use).
#[inline(always)]
fn smoothing_sums_kernel<W: Wide>(
    w: W,
    lists: &NeighbourLists<Fx>,
    velocities: &[Vec3<Fx>],
    inv_density: &[Fx],
    out: &mut Vec<Vec3<Fx>>,
) -> bool {
    // |vⱼ − vᵢ| < 2^(B + 1); ρ₀/ρ below 2^D.
    let bits = [vector_bits(velocities) + 1, scalar_bits(inv_density)];
    if bits[0] <= 31 {
        smoothing_sums_rows::<W, true>(w, lists, velocities, inv_density, bits, out)
    } else {
        smoothing_sums_rows::<W, false>(w, lists, velocities, inv_density, bits, out)
    }
}

#[inline(always)]
fn smoothing_sums_rows<W: Wide, const NARROW: bool>(
    w: W,
    lists: &NeighbourLists<Fx>,
    velocities: &[Vec3<Fx>],
    inv_density: &[Fx],
    [difference_bits, density_bits]: [u32; 2],
    out: &mut Vec<Vec3<Fx>>,
) -> bool {
    out.clear();
    let density_base = inv_density.as_ptr().cast::<i64>();
    let points = w.splat(velocities.len().min(inv_density.len()) as i64);
    let entries = entries(lists);
    let mut value_bits = w.zero();
    let mut weight_bits = w.zero();
    let mut longest = 0;
    for (i, vi) in velocities.iter().enumerate().take(lists.len()) {
        let range = lists.range(i);
        if range.end > entries {
            return false;
        }
        longest = longest.max(range.len());
        let vi = [
            w.splat(vi.x.to_bits()),
            w.splat(vi.y.to_bits()),
            w.splat(vi.z.to_bits()),
        ];
        let mut sum = [w.zero(); 3];
        let mut first = range.start;
        while first < range.end {
            let count = (range.end - first).min(LANES);
            // SAFETY (all three): `first + count` is within the row, which ends within
            // the entries, and every index in use is below both slices' lengths.
            if !unsafe { indices_below(w, lists, first, count, points) } {
                return false;
            }
            let value = unsafe { w.load_prefix(lists.value.as_ptr().add(first).cast(), count) };
            let indices = &lists.index[first..];
            let inverse = unsafe { w.gather_values(density_base, indices, count) };
            value_bits = w.or(value_bits, w.magnitude(value));
            let weight = w.mul(value, inverse);
            weight_bits = w.or(weight_bits, w.magnitude(weight));
            let Some(vj) = w.gather_vectors(velocities, &indices[..count]) else {
                return false;
            };
            for c in 0..3 {
                let difference = w.sub(vj[c], vi[c]);
                sum[c] = w.add(sum[c], product::<W, NARROW>(w, weight, difference));
            }
            first += count;
        }
        let [x, y, z] = sum;
        out.push(Vec3::new(
            Fx::from_bits(w.sum_lanes(x)),
            Fx::from_bits(w.sum_lanes(y)),
            Fx::from_bits(w.sum_lanes(z)),
        ));
    }
    let c = bit_length(w.or_lanes(value_bits));
    let a = bit_length(w.or_lanes(weight_bits));
    within_bound(c, density_bits, 1) && within_bound(a, difference_bits, longest)
}

/// The gradient sums kernel: whether its sums stand (if not, `sums` and `squares` hold
/// nothing of use), and the gradients' bit length A when every row lies within the
/// entries. With gradients of at most 2ᴬ in rows of at most L entries, the squares' sum is
/// bounded as a row sum of 3L products of A-bit operands, and the gradients' sum needs
/// A + ⌈log₂ L⌉ ≤ 61.
#[inline(always)]
fn gradient_sums_kernel<W: Wide>(
    w: W,
    lists: &NeighbourLists<Fx>,
    sums: &mut Vec<Vec3<Fx>>,
    squares: &mut Vec<Fx>,
) -> (bool, Option<u32>) {
    sums.clear();
    squares.clear();
    let entries = lists.gradients.iter().map(Vec::len).min().unwrap_or(0);
    let mut gradient_bits = w.zero();
    let mut longest = 0;
    for i in 0..lists.len() {
        let range = lists.range(i);
        if range.end > entries {
            return (false, None);
        }
        longest = longest.max(range.len());
        let mut sum = [w.zero(); 3];
        let mut square = w.zero();
        let mut first = range.start;
        while first < range.end {
            let count = (range.end - first).min(LANES);
            // SAFETY: `first + count` is within the row, which ends within the entries.
            let gradient = unsafe { load_gradients(w, lists, first, count) };
            for c in 0..3 {
                let g = gradient[c];
                gradient_bits = w.or(gradient_bits, w.magnitude(g));
                sum[c] = w.add(sum[c], g);
                square = w.add(square, w.mul(g, g));
            }
            first += count;
        }
        let [x, y, z] = sum;
        sums.push(Vec3::new(
            Fx::from_bits(w.sum_lanes(x)),
            Fx::from_bits(w.sum_lanes(y)),
            Fx::from_bits(w.sum_lanes(z)),
        ));
        squares.push(Fx::from_bits(w.sum_lanes(square)));
    }
    let a = bit_length(w.or_lanes(gradient_bits));
    let sum_bits = usize::BITS - longest.max(1).saturating_sub(1).leading_zeros();
    let stands = within_bound(a, a, 3 * longest) && a + sum_bits <= MAX_OPERAND_BITS;
    (stands, Some(a))
}
