//! The bending rows of I32F32 in AVX-512: eight hinges side by side, one `i64` lane per
//! hinge, with the bits of the scalar row ([`Hinges::solve_row`]).
//!
//! Hinges that share no vertex read nothing the others write, so solving eight of them
//! together gives the bits of solving them one after another; the blocks of eight
//! consecutive hinges that share no vertex are listed once per substep length
//! ([`Hinges::independent_blocks`]), nearly all of them in colour order. The other blocks,
//! the blocks where a check fails (before anything is written) and the rows past the last
//! multiple of eight take the scalar row.
//!
//! # Exactness
//!
//! The scalar row computes C = Σₖ cₖxₖ, r = (0 − C) − μ, μ + ρr and xₖ + sₖr per
//! component, each product rounded once and then added. The kernel computes the same
//! operations modulo 2⁶⁴ after checking that the corners' positions, the cₖ, μ, the shares
//! sₖ, ρ and r lie in [−2⁴⁶, 2⁴⁶) as raw bits: every product is then below 2⁶⁰, every sum
//! has at most four such terms or checked values, below 2⁶³, and nothing saturates, so
//! the kernel's exact values ([`mul`]) are the checked operators', which the scalar row
//! gives whether its guard stays clear or it reruns checked.

use core::any::Any;
use core::arch::x86_64::{
    __m512i, _mm512_permutex2var_epi64, _mm512_set_epi64, _mm512_setzero_si512,
};

use super::Hinges;
use crate::math::{Fx, Real, Vec3};
use crate::soft::lanes::{
    LANES, Split, add, gather3, lane3, load, load_run3, mul, out_of_bound, out_of_bound3, put3,
    split, sub,
};

impl<R: Real> Hinges<R> {
    /// Whether hinges 8k..8k+8 share no vertex, for each whole block k.
    pub fn independent_blocks(&self) -> Vec<bool> {
        self.vertices
            .chunks_exact(LANES)
            .map(|block| {
                let mut corners = [0u32; 4 * LANES];
                for (k, hinge) in block.iter().enumerate() {
                    corners[4 * k..4 * k + 4].copy_from_slice(hinge);
                }
                corners.sort_unstable();
                corners.windows(2).all(|w| w[0] != w[1])
            })
            .collect()
    }
}

/// One pass over every hinge with the kernel when `R` is I32F32 and the processor has
/// AVX-512F; returns whether it ran (if not, nothing was written).
pub(super) fn solve<R: Real>(
    rows: &mut Hinges<R>,
    positions: &mut [Vec3<R>],
    shares: &[[R; 4]],
    relax: &[R],
    independent: &[bool],
) -> bool {
    if !crate::math::cpu::avx512f() {
        return false;
    }
    let Some(rows) = (rows as &mut dyn Any).downcast_mut::<Hinges<Fx>>() else {
        return false;
    };
    // SAFETY: `R` is `Fx` (the downcast succeeded), so the slices' types are unchanged.
    let (positions, shares, relax) = unsafe {
        (
            &mut *(core::ptr::from_mut(positions) as *mut [Vec3<Fx>]),
            &*(core::ptr::from_ref(shares) as *const [[Fx; 4]]),
            &*(core::ptr::from_ref(relax) as *const [Fx]),
        )
    };
    // SAFETY: AVX-512F was detected on this processor just above.
    unsafe { solve_rows(rows, positions, shares, relax, independent) };
    true
}

/// Every hinge in order: the independent blocks with the kernel, the rest with the scalar
/// row.
///
/// # Safety
/// The processor must have AVX-512F.
#[target_feature(enable = "avx512f")]
unsafe fn solve_rows(
    rows: &mut Hinges<Fx>,
    positions: &mut [Vec3<Fx>],
    shares: &[[Fx; 4]],
    relax: &[Fx],
    independent: &[bool],
) {
    let count = rows.vertices.len();
    for k in 0..count / LANES {
        let start = k * LANES;
        let solved = independent.get(k).copied().unwrap_or(false)
            && solve_block(rows, positions, shares, relax, start);
        if !solved {
            for h in start..start + LANES {
                rows.solve_row(positions, shares, relax, h);
            }
        }
    }
    for h in count - count % LANES..count {
        rows.solve_row(positions, shares, relax, h);
    }
}

/// The kernel on hinges `start..start + 8`, which share no vertex; returns false, having
/// written nothing, when a check fails.
#[inline]
#[target_feature(enable = "avx512f")]
fn solve_block(
    rows: &mut Hinges<Fx>,
    positions: &mut [Vec3<Fx>],
    shares: &[[Fx; 4]],
    relax: &[Fx],
    start: usize,
) -> bool {
    let block = start..start + LANES;
    let mut corners = [[0u32; LANES]; 4];
    for (l, hinge) in rows.vertices[block.clone()].iter().enumerate() {
        for k in 0..4 {
            corners[k][l] = hinge[k];
        }
    }
    let (Some(x0), Some(x1), Some(x2), Some(x3)) = (
        gather3(positions, &corners[0]),
        gather3(positions, &corners[1]),
        gather3(positions, &corners[2]),
        gather3(positions, &corners[3]),
    ) else {
        return false;
    };
    let x = [x0, x1, x2, x3];
    let c = columns(&rows.coefficients[block.clone()]);
    let s = columns(&shares[block.clone()]);
    let Some(mu) = load_run3(&rows.lambda, start) else {
        return false;
    };
    let relax = load(&relax[block]);
    let mut bad = out_of_bound3(mu) | out_of_bound(relax);
    for k in 0..4 {
        bad |= out_of_bound3(x[k]) | out_of_bound(c[k]) | out_of_bound(s[k]);
    }
    let zero = _mm512_setzero_si512();
    let mut value = [zero; 3];
    for k in 0..4 {
        let factor = split(c[k]);
        for i in 0..3 {
            value[i] = add(value[i], mul(split(x[k][i]), factor));
        }
    }
    let residual = [
        sub(sub(zero, value[0]), mu[0]),
        sub(sub(zero, value[1]), mu[1]),
        sub(sub(zero, value[2]), mu[2]),
    ];
    bad |= out_of_bound3(residual);
    if bad != 0 {
        return false;
    }
    let r: [Split; 3] = [split(residual[0]), split(residual[1]), split(residual[2])];
    let rho = split(relax);
    let new_mu = [
        add(mu[0], mul(r[0], rho)),
        add(mu[1], mul(r[1], rho)),
        add(mu[2], mul(r[2], rho)),
    ];
    let mut moved = x;
    for k in 0..4 {
        let share = split(s[k]);
        for i in 0..3 {
            moved[k][i] = add(x[k][i], mul(r[i], share));
        }
    }
    for l in 0..LANES {
        for k in 0..4 {
            put3(&mut positions[corners[k][l] as usize], lane3(moved[k], l));
        }
        put3(&mut rows.lambda[start + l], lane3(new_mu, l));
    }
    true
}

/// The four columns of eight rows of four values, as four vectors: eight loads' worth of
/// words, transposed in registers.
#[inline]
#[target_feature(enable = "avx512f")]
fn columns(rows: &[[Fx; 4]]) -> [__m512i; 4] {
    let rows = &rows[..LANES];
    let words: &[Fx] = rows.as_flattened();
    // Word 4l + k is column k of row l: v0 holds rows 0 and 1, v1 rows 2 and 3, and so on.
    let (v0, v1, v2, v3) = (
        load(&words[0..]),
        load(&words[LANES..]),
        load(&words[2 * LANES..]),
        load(&words[3 * LANES..]),
    );
    let even = _mm512_set_epi64(13, 9, 5, 1, 12, 8, 4, 0);
    let odd = _mm512_set_epi64(15, 11, 7, 3, 14, 10, 6, 2);
    let (a, b) = (
        _mm512_permutex2var_epi64(v0, even, v1),
        _mm512_permutex2var_epi64(v0, odd, v1),
    );
    let (a4, b4) = (
        _mm512_permutex2var_epi64(v2, even, v3),
        _mm512_permutex2var_epi64(v2, odd, v3),
    );
    let low = _mm512_set_epi64(11, 10, 9, 8, 3, 2, 1, 0);
    let high = _mm512_set_epi64(15, 14, 13, 12, 7, 6, 5, 4);
    [
        _mm512_permutex2var_epi64(a, low, a4),
        _mm512_permutex2var_epi64(a, high, a4),
        _mm512_permutex2var_epi64(b, low, b4),
        _mm512_permutex2var_epi64(b, high, b4),
    ]
}
