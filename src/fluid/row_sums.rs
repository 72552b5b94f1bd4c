//! The sums over a particle's fluid neighbours that every substep (XSPH, DFSPH's factors)
//! and every DFSPH iteration (the other two) repeat, kept apart so that I32F32 can take a vector kernel
//! with the same bits.
//!
//! For fluid particle i and its neighbour entries e = (j, V₀Wᵢⱼ, V₀∇ᵢWᵢⱼ) (see
//! [`neighbours`](super::neighbours)):
//!
//! - density rate: Σⱼ (vᵢ − vⱼ)·V₀∇ᵢWᵢⱼ (1/s), each dot product the three rounded products
//!   added in order, the terms added in entry order;
//! - pressure push: Σⱼ (kᵢ + kⱼ) V₀∇ᵢWᵢⱼ (m/s²) for the stiffnesses k (m²/s²), each
//!   component a rounded product, added in entry order;
//! - smoothing sum: Σⱼ (vⱼ − vᵢ) wᵢⱼ (m/s) with the rounded weight wᵢⱼ = V₀Wᵢⱼ · ρ₀/ρⱼ,
//!   each component a rounded product, added in entry order;
//! - gradient sums, once per DFSPH substep: Σⱼ V₀∇ᵢWᵢⱼ (1/m) and Σⱼ |V₀∇ᵢWᵢⱼ|² (1/m²),
//!   each square the three rounded products added in order.
//!
//! # Same bits
//!
//! In fixed point a sum of already-rounded terms is exact whatever its order unless a
//! partial sum leaves the range. The vector kernel ([`kernel`], I32F32 on x86-64 with AVX-512
//! or AVX2, through the lanes of [`wide`](crate::math::wide)) computes every product rounded exactly as the checked `*`, and
//! sums eight entries side by side, then the lanes. It measures the bit lengths of what it
//! reads (gradients, velocities or stiffnesses) and the longest row, and its result stands
//! only when those bounds prove that no product and no partial sum, in any order, can leave
//! the range: then the checked operators of the scalar form saturate nowhere and both give
//! the exact sums (the smoothing sum's weights, themselves products, are checked the same
//! way). Otherwise the scalar form runs, saturating and counting as it always
//! does. Other formats and targets run the scalar form only.
//!
//! The gradients stay the same through a substep while the DFSPH iterations read them again
//! and again, so their bit length is measured once, by [`gradient_sums`] at the start of
//! the substep ([`GradientBits`]), and [`density_rates`] and [`pressure_pushes`] take it
//! from there.

#[cfg(vector_kernels)]
mod kernel;
#[cfg(test)]
mod tests;

use super::neighbours::NeighbourLists;
#[cfg(vector_kernels)]
use super::neighbours::NeighbourListsOf;
#[cfg(vector_kernels)]
use crate::math::over_real::{ScalarVec, Scalars, VectorVec, Vectors};
use crate::math::{Real, Vec3};

/// The bit length A of the largest gradient component of a set of lists (|V₀∇W| ≤ 2ᴬ as
/// raw bits), as [`gradient_sums`] measured it, on which the vector kernels of
/// [`density_rates`] and [`pressure_pushes`] rest; `None` where it was not measured (other
/// formats and targets, or rows running past the entries), and those sums then take the
/// scalar form.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub(crate) struct GradientBits(Option<u32>);

/// Σⱼ (vᵢ − vⱼ)·V₀∇ᵢWᵢⱼ over the fluid neighbours of each particle of `lists` (1/s), into
/// `out`, one per particle. `gradients` must be what [`gradient_sums`] returned for these
/// lists, unchanged since.
pub(crate) fn density_rates<R: Real>(
    lists: &NeighbourLists<R>,
    gradients: GradientBits,
    velocities: &[Vec3<R>],
    out: &mut Vec<R>,
) {
    #[cfg(vector_kernels)]
    if let GradientBits(Some(bits)) = gradients
        && let Some(backend) = crate::math::wide::backend()
        && let (Some(lists), Some(velocities), Some(out)) = (
            R::as_fixed::<NeighbourListsOf>(lists),
            R::as_fixed::<Vectors>(velocities),
            R::as_fixed_mut::<ScalarVec>(out),
        )
        && kernel::density_rates(backend, lists, bits, velocities, out)
    {
        return;
    }
    #[cfg(not(vector_kernels))]
    let _ = gradients; // only the vector kernels read it
    density_rates_scalar(lists, velocities, out);
}

/// [`density_rates`] with the checked operators, entry after entry.
pub(crate) fn density_rates_scalar<R: Real>(
    lists: &NeighbourLists<R>,
    velocities: &[Vec3<R>],
    out: &mut Vec<R>,
) {
    out.clear();
    for (i, &vi) in velocities.iter().enumerate().take(lists.len()) {
        let mut rate = R::ZERO;
        for e in lists.range(i) {
            let j = lists.index[e] as usize;
            rate += (vi - velocities[j]).dot(lists.gradient(e));
        }
        out.push(rate);
    }
}

/// Σⱼ (kᵢ + kⱼ) V₀∇ᵢWᵢⱼ over the fluid neighbours of each particle of `lists` (m/s²), for
/// the stiffnesses `stiffness` (m²/s²), into `out`, one per particle. `gradients` as for
/// [`density_rates`].
pub(crate) fn pressure_pushes<R: Real>(
    lists: &NeighbourLists<R>,
    gradients: GradientBits,
    stiffness: &[R],
    out: &mut Vec<Vec3<R>>,
) {
    #[cfg(vector_kernels)]
    if let GradientBits(Some(bits)) = gradients
        && let Some(backend) = crate::math::wide::backend()
        && let (Some(lists), Some(stiffness), Some(out)) = (
            R::as_fixed::<NeighbourListsOf>(lists),
            R::as_fixed::<Scalars>(stiffness),
            R::as_fixed_mut::<VectorVec>(out),
        )
        && kernel::pressure_pushes(backend, lists, bits, stiffness, out)
    {
        return;
    }
    #[cfg(not(vector_kernels))]
    let _ = gradients; // only the vector kernels read it
    pressure_pushes_scalar(lists, stiffness, out);
}

/// [`pressure_pushes`] with the checked operators, entry after entry.
pub(crate) fn pressure_pushes_scalar<R: Real>(
    lists: &NeighbourLists<R>,
    stiffness: &[R],
    out: &mut Vec<Vec3<R>>,
) {
    out.clear();
    for (i, &ki) in stiffness.iter().enumerate().take(lists.len()) {
        let mut push = Vec3::ZERO;
        for e in lists.range(i) {
            let j = lists.index[e] as usize;
            push += lists.gradient(e) * (ki + stiffness[j]);
        }
        out.push(push);
    }
}

/// Σⱼ (vⱼ − vᵢ) (V₀Wᵢⱼ · ρ₀/ρⱼ) over the fluid neighbours of each particle of `lists`
/// (m/s), for the inverse densities `inv_density` (ρ₀/ρ), into `out`, one per particle:
/// XSPH's sum ([`xsph`](super::xsph)).
pub(crate) fn smoothing_sums<R: Real>(
    lists: &NeighbourLists<R>,
    velocities: &[Vec3<R>],
    inv_density: &[R],
    out: &mut Vec<Vec3<R>>,
) {
    #[cfg(vector_kernels)]
    if let Some(backend) = crate::math::wide::backend()
        && let (Some(lists), Some(velocities), Some(inv_density), Some(out)) = (
            R::as_fixed::<NeighbourListsOf>(lists),
            R::as_fixed::<Vectors>(velocities),
            R::as_fixed::<Scalars>(inv_density),
            R::as_fixed_mut::<VectorVec>(out),
        )
        && kernel::smoothing_sums(backend, lists, velocities, inv_density, out)
    {
        return;
    }
    smoothing_sums_scalar(lists, velocities, inv_density, out);
}

/// [`smoothing_sums`] with the checked operators, entry after entry.
pub(crate) fn smoothing_sums_scalar<R: Real>(
    lists: &NeighbourLists<R>,
    velocities: &[Vec3<R>],
    inv_density: &[R],
    out: &mut Vec<Vec3<R>>,
) {
    out.clear();
    for (i, &vi) in velocities.iter().enumerate().take(lists.len()) {
        let mut sum = Vec3::ZERO;
        for e in lists.range(i) {
            let j = lists.index[e] as usize;
            sum += (velocities[j] - vi) * (lists.value[e] * inv_density[j]);
        }
        out.push(sum);
    }
}

/// Σⱼ V₀∇ᵢWᵢⱼ (1/m) into `sums` and Σⱼ |V₀∇ᵢWᵢⱼ|² (1/m²) into `squares` over the fluid
/// neighbours of each particle of `lists`, one each per particle: DFSPH's factor
/// ([`dfsph`](super::dfsph)). Returns the gradients' bit length where the vector kernel
/// measured it, for the other sums over the same lists.
pub(crate) fn gradient_sums<R: Real>(
    lists: &NeighbourLists<R>,
    sums: &mut Vec<Vec3<R>>,
    squares: &mut Vec<R>,
) -> GradientBits {
    #[cfg(vector_kernels)]
    if let Some(backend) = crate::math::wide::backend()
        && let (Some(fixed_lists), Some(fixed_sums), Some(fixed_squares)) = (
            R::as_fixed::<NeighbourListsOf>(lists),
            R::as_fixed_mut::<VectorVec>(sums),
            R::as_fixed_mut::<ScalarVec>(squares),
        )
    {
        let (stands, bits) = kernel::gradient_sums(backend, fixed_lists, fixed_sums, fixed_squares);
        if !stands {
            gradient_sums_scalar(lists, sums, squares);
        }
        return GradientBits(bits);
    }
    gradient_sums_scalar(lists, sums, squares);
    GradientBits(None)
}

/// [`gradient_sums`] with the checked operators, entry after entry.
pub(crate) fn gradient_sums_scalar<R: Real>(
    lists: &NeighbourLists<R>,
    sums: &mut Vec<Vec3<R>>,
    squares: &mut Vec<R>,
) {
    sums.clear();
    squares.clear();
    for i in 0..lists.len() {
        let mut sum = Vec3::ZERO;
        let mut square = R::ZERO;
        for g in lists.range(i).map(|e| lists.gradient(e)) {
            sum += g;
            square += g.length_squared();
        }
        sums.push(sum);
        squares.push(square);
    }
}
