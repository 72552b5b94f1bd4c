//! [`WideBodies`] on AVX-512: a solver body's words read one 64-byte row per body and turned
//! into one vector per component by a transpose, and written back the same way.

use core::arch::x86_64::{__m512i, _mm512_mask_storeu_epi64, _mm512_maskz_loadu_epi64};

use super::{BODY_WORDS, DP, V, WideBodies};
use crate::math::Fx;
use crate::math::wide::{Wide, avx512::Avx512};
use crate::rigid::solver::body::SolverBody;
use crate::rigid::solver::lanes::LANES;

// SAFETY (every `unsafe` block below that calls an intrinsic): a value of `Avx512` exists
// only on a processor with AVX-512F, CD and DQ (`Avx512::detect`).
impl WideBodies for Avx512 {
    /// One masked 64-byte load per lane (v, ω, Δp_x, Δp_y), and with the motions a second
    /// one (Δp_z, Δθ, ...), all eight unrolled so that the rows stay in registers, then a
    /// transpose; a lane outside `active` loads nothing.
    #[inline(always)]
    unsafe fn load_bodies(
        self,
        bodies: &[SolverBody<Fx>],
        indices: &[u32; LANES],
        active: u8,
        with_motion: bool,
    ) -> [[__m512i; 3]; 4] {
        let base = bodies.as_ptr().cast::<i64>();
        // SAFETY: the caller's promise, as for `rows`.
        let [vx, vy, vz, wx, wy, wz, px, py] =
            unsafe { rows(self, base, indices, active, V as usize) };
        let (dp, dtheta) = if with_motion {
            // SAFETY: as above.
            let [pz, tx, ty, tz, ..] =
                unsafe { rows(self, base, indices, active, DP as usize + 2) };
            ([px, py, pz], [tx, ty, tz])
        } else {
            ([self.zero(); 3], [self.zero(); 3])
        };
        [[vx, vy, vz], [wx, wy, wz], dp, dtheta]
    }

    /// The transpose back into rows, and one masked store of six words per lane.
    #[inline(always)]
    unsafe fn store_velocities(
        self,
        bodies: &mut [SolverBody<Fx>],
        indices: &[u32; LANES],
        active: u8,
        [[vx, vy, vz], [wx, wy, wz]]: [[__m512i; 3]; 2],
    ) {
        let base = bodies.as_mut_ptr().cast::<i64>();
        let zero = self.zero();
        let rows = self.transpose([vx, vy, vz, wx, wy, wz, zero, zero]);
        for (l, row) in rows.into_iter().enumerate() {
            let at = base.wrapping_add(first_word(indices[l]) + V as usize);
            // SAFETY: as in `load_bodies`; six words, none outside `active`.
            unsafe { _mm512_mask_storeu_epi64(at.cast(), lane_mask(active, l) & 0b11_1111, row) };
        }
    }
}

/// Words `offset` to `offset + 7` of the body of each lane of `active` (zero
/// elsewhere), one vector per word: one masked load per lane, all eight unrolled so that
/// the rows stay in registers, then a transpose.
///
/// # Safety
/// In each lane of `active`, those words of the body must lie in the array at `base`.
#[inline(always)]
unsafe fn rows(
    wide: Avx512,
    base: *const i64,
    indices: &[u32; LANES],
    active: u8,
    offset: usize,
) -> [__m512i; 8] {
    let mut rows = [wide.zero(); 8];
    for (l, row) in rows.iter_mut().enumerate() {
        let at = base.wrapping_add(first_word(indices[l]) + offset);
        // SAFETY: the caller's promise; outside `active` the mask is empty and nothing
        // is read.
        *row = unsafe { _mm512_maskz_loadu_epi64(lane_mask(active, l), at.cast()) };
    }
    wide.transpose(rows)
}

/// The first word of body `index` in an array of solver bodies taken as words:
/// index · [`BODY_WORDS`].
#[inline(always)]
pub(crate) fn first_word(index: u32) -> usize {
    index as usize * BODY_WORDS as usize
}

/// The mask of a 64-byte load or store of lane `l`'s row: all eight words when `l` is
/// one of the lanes of `active`, none otherwise.
#[inline(always)]
fn lane_mask(active: u8, l: usize) -> u8 {
    0u8.wrapping_sub((active >> l) & 1)
}
