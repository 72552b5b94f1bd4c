//! The tethers of I32F32 on the lanes of [`Wide`] (every backend): eight rows side by side,
//! with the bits of the scalar row ([`Tethers::solve_row`]).
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
//! kernel's exact values ([`Wide::dot`], [`Wide::mul`]) are the scalar ones. The square root of a taut
//! row (|d|² > ℓ₀² ≥ 0) never saturates, so computing it in the kernel and again in the
//! scalar row of a lane that then fails a check counts nothing twice.

use super::Tethers;
use crate::math::over_real::Vectors;
use crate::math::wide::{LANES, Wide, backend, kernel_entry};
use crate::math::{Fx, OverReal, Real, Vec3};

/// The family of [`Tethers`] over the scalar formats.
struct TethersOf;

impl OverReal for TethersOf {
    type Of<R: Real> = Tethers<R>;
}

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

/// One pass over every row with the kernel when `R` is I32F32 and a backend runs; returns
/// whether it ran (if not, nothing was written).
pub(super) fn solve<R: Real>(
    rows: &Tethers<R>,
    positions: &mut [Vec3<R>],
    independent: &[bool],
) -> bool {
    let (Some(backend), Some(rows), Some(positions)) = (
        backend(),
        R::as_fixed::<TethersOf>(rows),
        R::as_fixed_mut::<Vectors>(positions),
    ) else {
        return false;
    };
    solve_rows(backend, rows, positions, independent);
    true
}

kernel_entry! {
    /// [`solve_rows_kernel`] with the instructions of `backend`.
    fn solve_rows(rows: &Tethers<Fx>, positions: &mut [Vec3<Fx>], independent: &[bool]) -> () =
        solve_rows_kernel;
}

/// Every row in order: the independent blocks with the kernel and the scalar row for what
/// it leaves; the other rows with the scalar row.
#[inline(always)]
fn solve_rows_kernel<W: Wide>(
    w: W,
    rows: &Tethers<Fx>,
    positions: &mut [Vec3<Fx>],
    independent: &[bool],
) {
    let count = rows.vertex.len();
    for k in 0..count / LANES {
        let start = k * LANES;
        let done = if independent.get(k).copied().unwrap_or(false) {
            solve_block(w, rows, positions, start)
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
#[inline(always)]
fn solve_block<W: Wide>(w: W, rows: &Tethers<Fx>, positions: &mut [Vec3<Fx>], start: usize) -> u8 {
    let block = start..start + LANES;
    let anchors = &rows.anchor[block.clone()];
    // A round's rows to one pin share their anchor: one load instead of eight.
    let p = if anchors.iter().all(|&a| a == anchors[0]) {
        let Some(pin) = positions.get(anchors[0] as usize) else {
            return 0;
        };
        Some([
            w.splat(pin.x.to_bits()),
            w.splat(pin.y.to_bits()),
            w.splat(pin.z.to_bits()),
        ])
    } else {
        w.gather_vectors(positions, anchors)
    };
    let vertices = &rows.vertex[block.clone()];
    // A round's rows of consecutive vertices: one run instead of eight.
    let first = vertices[0];
    let x = if (1..LANES).all(|l| vertices[l] == first.wrapping_add(l as u32)) {
        w.load_run(positions, first as usize)
    } else {
        w.gather_vectors(positions, vertices)
    };
    let (Some(x), Some(p)) = (x, p) else {
        return 0;
    };
    let rest: &[Fx; LANES] = rows.rest[block].try_into().expect("eight values");
    let rest = w.load(rest);
    let d = w.sub3(x, p);
    let bad = w.out_of_bound3(x) | w.out_of_bound3(p) | w.out_of_bound3(d) | w.out_of_bound(rest);
    let length_squared = w.dot::<false>(d, d);
    let slack = !w.greater(length_squared, w.mul(rest, rest)) & !bad;
    let taut = !slack & !bad;
    if taut == 0 {
        return slack;
    }
    // 1/|d| per taut lane with the scalar square root (|d|² > ℓ₀² ≥ 0, so it never
    // saturates); the lanes are independent, so the processor overlaps them.
    let squares = w.store_words(length_squared);
    let mut inverse = [0i64; LANES];
    for (l, y) in inverse.iter_mut().enumerate() {
        if taut & (1 << l) != 0 {
            *y = Fx::from_bits(squares[l]).rsqrt().to_bits();
        }
    }
    let inverse = w.load_words(inverse);
    let shrink = w.sub(w.splat(Fx::ONE.to_bits()), w.mul(rest, inverse));
    let minus = w.sub(w.zero(), shrink);
    let taut = taut & !(w.out_of_bound(inverse) | w.out_of_bound(minus));
    let moved = [
        w.store_words(w.add(x[0], w.mul(d[0], minus))),
        w.store_words(w.add(x[1], w.mul(d[1], minus))),
        w.store_words(w.add(x[2], w.mul(d[2], minus))),
    ];
    for l in 0..LANES {
        if taut & (1 << l) != 0 {
            positions[rows.vertex[start + l] as usize] = Vec3::new(
                Fx::from_bits(moved[0][l]),
                Fx::from_bits(moved[1][l]),
                Fx::from_bits(moved[2][l]),
            );
        }
    }
    slack | taut
}
