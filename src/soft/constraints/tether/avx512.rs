//! The tethers of I32F32 in AVX-512: eight rows side by side, with the bits of the scalar
//! row ([`Tethers::solve_row`]).
//!
//! A slack row (|d|² ≤ ℓ₀²) changes nothing; a taut one moves its vertex by −(1 − ℓ₀/|d|) d.
//! The kernel solves eight rows at once, 1/|d| of each taut one from the scalar square root
//! (one call per taut lane; the lanes are independent, so the processor overlaps them), and
//! leaves the lanes where a check fails to the scalar row, after the others. That gives the
//! bits of the rows one after another when the block's rows are independent: no two move
//! the same vertex and none's anchor is another's vertex
//! ([`Tethers::independent_blocks`]), so each row reads the same positions whatever the
//! other rows of the block have done. In the tethers' round order (see `tether_order` in the
//! builder) nearly every block is independent.
//!
//! # Exactness
//!
//! The scalar row compares the fused |d|² = d·d (the exact sum rounded once) with the
//! checked ℓ₀·ℓ₀, then computes s = 1 − ℓ₀·(1/√|d|²) and x + d·(−s) per component, each a
//! product rounded once and added. The kernel checks that both ends' positions, d, ℓ₀,
//! 1/√|d|² and −s lie in [−2⁴⁶, 2⁴⁶) as raw bits: then d·d is below 2⁹⁴ before rounding,
//! every product below 2⁶⁰ after, no sum leaves the range and nothing saturates, so the
//! kernel's exact values ([`dot3`], [`mul`]) are the scalar ones. The square root of a taut
//! row (|d|² > ℓ₀² ≥ 0) never saturates, so computing it in the kernel and again in the
//! scalar row of a lane that then fails a check counts nothing twice.

use core::any::Any;
use core::arch::x86_64::{
    __mmask8, _mm512_cmple_epi64_mask, _mm512_loadu_si512, _mm512_setzero_si512,
};

use super::Tethers;
use crate::math::{Fx, Real, Vec3};
use crate::soft::lanes::{
    LANES, add, dot3, gather3, lane, lane3, load, load_run3, mul, out_of_bound, out_of_bound3,
    put3, splat, split, split3, sub,
};

impl<R: Real> Tethers<R> {
    /// Whether rows 8k..8k+8 are independent (no two move the same vertex, none's anchor
    /// is another's vertex), for each whole block k.
    pub fn independent_blocks(&self) -> Vec<bool> {
        self.vertex
            .chunks_exact(LANES)
            .zip(self.anchor.chunks_exact(LANES))
            .map(|(vertices, anchors)| {
                let mut moved = [0u32; LANES];
                moved.copy_from_slice(vertices);
                moved.sort_unstable();
                moved.windows(2).all(|w| w[0] != w[1])
                    && anchors.iter().all(|a| moved.binary_search(a).is_err())
            })
            .collect()
    }
}

/// One pass over every row with the kernel when `R` is I32F32 and the processor has
/// AVX-512F; returns whether it ran (if not, nothing was written).
pub(super) fn solve<R: Real>(
    rows: &Tethers<R>,
    positions: &mut [Vec3<R>],
    independent: &[bool],
) -> bool {
    if !crate::math::cpu::avx512f() {
        return false;
    }
    let Some(rows) = (rows as &dyn Any).downcast_ref::<Tethers<Fx>>() else {
        return false;
    };
    // SAFETY: `R` is `Fx` (the downcast succeeded), so the slice's type is unchanged.
    let positions = unsafe { &mut *(core::ptr::from_mut(positions) as *mut [Vec3<Fx>]) };
    // SAFETY: AVX-512F was detected on this processor just above.
    unsafe { solve_rows(rows, positions, independent) };
    true
}

/// Every row in order: the independent blocks with the kernel and the scalar row for what
/// it leaves; the other rows with the scalar row.
///
/// # Safety
/// The processor must have AVX-512F.
#[target_feature(enable = "avx512f")]
unsafe fn solve_rows(rows: &Tethers<Fx>, positions: &mut [Vec3<Fx>], independent: &[bool]) {
    let count = rows.vertex.len();
    for k in 0..count / LANES {
        let start = k * LANES;
        let done = if independent.get(k).copied().unwrap_or(false) {
            solve_block(rows, positions, start)
        } else {
            0
        };
        for l in 0..LANES {
            if done & (1 << l) == 0 {
                rows.solve_row(positions, start + l);
            }
        }
    }
    for t in count - count % LANES..count {
        rows.solve_row(positions, t);
    }
}

/// The kernel on the independent rows `start..start + 8`: returns the lanes it solved (the
/// slack ones, which write nothing, and the taut ones it wrote).
#[inline]
#[target_feature(enable = "avx512f")]
fn solve_block(rows: &Tethers<Fx>, positions: &mut [Vec3<Fx>], start: usize) -> __mmask8 {
    let block = start..start + LANES;
    let anchors = &rows.anchor[block.clone()];
    // A round's rows to one pin share their anchor: one load instead of eight.
    let p = if anchors.iter().all(|&a| a == anchors[0]) {
        positions
            .get(anchors[0] as usize)
            .map(|p| [splat(p.x), splat(p.y), splat(p.z)])
    } else {
        gather3(positions, anchors)
    };
    let vertices = &rows.vertex[block.clone()];
    // A round's rows of consecutive vertices: three loads instead of eight.
    let first = vertices[0];
    let x = if (1..LANES).all(|l| vertices[l] == first.wrapping_add(l as u32)) {
        load_run3(positions, first as usize)
    } else {
        gather3(positions, vertices)
    };
    let (Some(x), Some(p)) = (x, p) else {
        return 0;
    };
    let rest = load(&rows.rest[block]);
    let d = [sub(x[0], p[0]), sub(x[1], p[1]), sub(x[2], p[2])];
    let bad = out_of_bound3(x) | out_of_bound3(p) | out_of_bound3(d) | out_of_bound(rest);
    let d = split3(d);
    let rest = split(rest);
    let length_squared = dot3(d, d);
    let slack = _mm512_cmple_epi64_mask(length_squared, mul(rest, rest)) & !bad;
    let taut = !slack & !bad;
    if taut == 0 {
        return slack;
    }
    // 1/|d| per taut lane with the scalar square root (|d|² > ℓ₀² ≥ 0, so it never
    // saturates); the lanes are independent, so the processor overlaps them.
    let mut inverse = [0i64; LANES];
    for (l, y) in inverse.iter_mut().enumerate() {
        if taut & (1 << l) != 0 {
            *y = Fx::from_bits(lane(length_squared, l)).rsqrt().to_bits();
        }
    }
    // SAFETY: 64 readable bytes.
    let inverse = unsafe { _mm512_loadu_si512(inverse.as_ptr().cast()) };
    let shrink = sub(splat(Fx::ONE), mul(rest, split(inverse)));
    let minus = sub(_mm512_setzero_si512(), shrink);
    let taut = taut & !(out_of_bound(inverse) | out_of_bound(minus));
    let minus = split(minus);
    let moved = [
        add(x[0], mul(d[0], minus)),
        add(x[1], mul(d[1], minus)),
        add(x[2], mul(d[2], minus)),
    ];
    for l in 0..LANES {
        if taut & (1 << l) != 0 {
            put3(
                &mut positions[rows.vertex[start + l] as usize],
                lane3(moved, l),
            );
        }
    }
    slack | taut
}
