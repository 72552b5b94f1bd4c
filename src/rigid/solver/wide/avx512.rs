//! The AVX-512 backend of [`Wide`] (F and DQ): eight lanes in one `__m512i`, lane masks in
//! mask registers. `_mm512_mul_epi32` gives the products of low halves and
//! `_mm512_mullo_epi64` the low 64 bits of a 64 × 64 product. The bodies' velocities are
//! loaded one 64-byte row per body and turned into one vector per component by a transpose.
//!
//! The operations carry no `#[target_feature]` of their own: they are always inlined, and
//! a kernel runs them inside an entry point with `#[target_feature(enable =
//! "avx512f,avx512dq")]`, where they compile to single instructions.

use core::arch::x86_64::{
    __m512i, _mm512_abs_epi64, _mm512_add_epi64, _mm512_and_si512, _mm512_cmpeq_epi64_mask,
    _mm512_cmpge_epu64_mask, _mm512_cmpgt_epi64_mask, _mm512_loadu_si512, _mm512_mask_blend_epi64,
    _mm512_mask_i64gather_epi64, _mm512_mask_storeu_epi64, _mm512_maskz_loadu_epi64,
    _mm512_max_epi64, _mm512_min_epi64, _mm512_mul_epi32, _mm512_mullo_epi64,
    _mm512_permutex2var_epi64, _mm512_set_epi64, _mm512_set1_epi64, _mm512_setzero_si512,
    _mm512_srai_epi64, _mm512_storeu_si512, _mm512_sub_epi64, _mm512_unpackhi_epi64,
    _mm512_unpacklo_epi64,
};
use core::mem::{offset_of, size_of};

use super::Wide;
use crate::math::{Fx, Vec3};
use crate::rigid::solver::avx512::has_kernels;
use crate::rigid::solver::body::SolverBody;
use crate::rigid::solver::lanes::{LANES, Lanes};

/// `SolverBody<Fx>` in `i64` words, and the word offsets of the fields the kernels read.
pub(crate) const BODY_WORDS: i64 = (size_of::<SolverBody<Fx>>() / 8) as i64;
pub(crate) const V: i64 = (offset_of!(SolverBody<Fx>, v) / 8) as i64;
pub(crate) const W: i64 = (offset_of!(SolverBody<Fx>, w) / 8) as i64;
const DP: i64 = (offset_of!(SolverBody<Fx>, dp) / 8) as i64;
const DTHETA: i64 = (offset_of!(SolverBody<Fx>, dtheta) / 8) as i64;

// The layout the loads rely on: `Fx` is one `i64`, `Vec3<Fx>` x, y, z in a row, the body
// a whole number of words; v, ω, Δp and Δθ in a row from word 0, so that words 0–7 (v, ω,
// Δp_x, Δp_y) and 8–15 (Δp_z, Δθ, ...) are two rows of eight.
const _: () = {
    assert!(size_of::<Fx>() == 8);
    assert!(size_of::<Vec3<Fx>>() == 24);
    assert!(size_of::<SolverBody<Fx>>().is_multiple_of(8));
    assert!(V == 0 && W == 3 && DP == 6 && DTHETA == 9);
    assert!(BODY_WORDS >= 16);
    assert!(LANES == 8);
};

/// The AVX-512 backend. A value exists only where the processor has AVX-512F and DQ.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Avx512(());

impl Avx512 {
    /// The backend, if this processor runs it.
    #[inline]
    pub(crate) fn detect() -> Option<Self> {
        has_kernels().then_some(Self(()))
    }
}

// SAFETY (every `unsafe` block below that calls an intrinsic): a value of `Avx512` exists
// only on a processor with AVX-512F and DQ (`Avx512::detect`).
impl Wide for Avx512 {
    type V = __m512i;

    #[inline(always)]
    fn zero(self) -> __m512i {
        unsafe { _mm512_setzero_si512() }
    }

    #[inline(always)]
    fn splat(self, x: i64) -> __m512i {
        unsafe { _mm512_set1_epi64(x) }
    }

    #[inline(always)]
    fn load_words(self, x: [i64; LANES]) -> __m512i {
        // SAFETY: 64 readable bytes.
        unsafe { _mm512_loadu_si512(x.as_ptr().cast()) }
    }

    #[inline(always)]
    fn store_words(self, x: __m512i) -> [i64; LANES] {
        let mut out = [0; LANES];
        // SAFETY: 64 writable bytes.
        unsafe { _mm512_storeu_si512(out.as_mut_ptr().cast(), x) };
        out
    }

    #[inline(always)]
    fn load(self, lanes: &Lanes<Fx>) -> __m512i {
        // SAFETY: eight `Fx`, each one `i64`: 64 readable bytes.
        unsafe { _mm512_loadu_si512(lanes.as_ptr().cast()) }
    }

    #[inline(always)]
    fn store(self, lanes: &mut Lanes<Fx>, value: __m512i) {
        // SAFETY: eight `Fx`, each one `i64`: 64 writable bytes.
        unsafe { _mm512_storeu_si512(lanes.as_mut_ptr().cast(), value) }
    }

    #[inline(always)]
    fn store_lanes(self, lanes: &mut Lanes<Fx>, mask: u8, value: __m512i) {
        // SAFETY: eight `Fx`, each one `i64`: 64 writable bytes.
        unsafe { _mm512_mask_storeu_epi64(lanes.as_mut_ptr().cast(), mask, value) }
    }

    #[inline(always)]
    fn add(self, a: __m512i, b: __m512i) -> __m512i {
        unsafe { _mm512_add_epi64(a, b) }
    }

    #[inline(always)]
    fn sub(self, a: __m512i, b: __m512i) -> __m512i {
        unsafe { _mm512_sub_epi64(a, b) }
    }

    #[inline(always)]
    fn and(self, a: __m512i, b: __m512i) -> __m512i {
        unsafe { _mm512_and_si512(a, b) }
    }

    #[inline(always)]
    fn max(self, a: __m512i, b: __m512i) -> __m512i {
        unsafe { _mm512_max_epi64(a, b) }
    }

    #[inline(always)]
    fn min(self, a: __m512i, b: __m512i) -> __m512i {
        unsafe { _mm512_min_epi64(a, b) }
    }

    #[inline(always)]
    fn abs(self, a: __m512i) -> __m512i {
        unsafe { _mm512_abs_epi64(a) }
    }

    #[inline(always)]
    fn mul_low_halves(self, a: __m512i, b: __m512i) -> __m512i {
        unsafe { _mm512_mul_epi32(a, b) }
    }

    /// `vpmullq` (AVX-512DQ): one instruction, a_high unused.
    #[inline(always)]
    fn mul_low_by_high(self, a: __m512i, _a_high: __m512i, b_high: __m512i) -> __m512i {
        unsafe { _mm512_mullo_epi64(a, b_high) }
    }

    #[inline(always)]
    fn shift_down_32(self, a: __m512i) -> __m512i {
        unsafe { _mm512_srai_epi64::<32>(a) }
    }

    #[inline(always)]
    fn greater(self, a: __m512i, b: __m512i) -> u8 {
        unsafe { _mm512_cmpgt_epi64_mask(a, b) }
    }

    #[inline(always)]
    fn at_least_unsigned(self, a: __m512i, b: __m512i) -> u8 {
        unsafe { _mm512_cmpge_epu64_mask(a, b) }
    }

    #[inline(always)]
    fn equal(self, a: __m512i, b: __m512i) -> u8 {
        unsafe { _mm512_cmpeq_epi64_mask(a, b) }
    }

    #[inline(always)]
    fn select(self, mask: u8, on: __m512i, off: __m512i) -> __m512i {
        unsafe { _mm512_mask_blend_epi64(mask, off, on) }
    }

    #[inline(always)]
    unsafe fn gather(self, bodies: &[SolverBody<Fx>], words: __m512i, active: u8) -> __m512i {
        let base = bodies.as_ptr().cast::<i64>();
        // SAFETY: the caller's promise; outside `active` nothing is read.
        unsafe { _mm512_mask_i64gather_epi64::<8>(self.zero(), active, words, base) }
    }

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
            unsafe { self.rows(base, indices, active, V as usize) };
        let (dp, dtheta) = if with_motion {
            // SAFETY: as above.
            let [pz, tx, ty, tz, ..] = unsafe { self.rows(base, indices, active, DP as usize + 2) };
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

impl Avx512 {
    /// Words `offset` to `offset + 7` of the body of each lane of `active` (zero
    /// elsewhere), one vector per word: one masked load per lane, all eight unrolled so that
    /// the rows stay in registers, then a transpose.
    ///
    /// # Safety
    /// In each lane of `active`, those words of the body must lie in the array at `base`.
    #[inline(always)]
    unsafe fn rows(
        self,
        base: *const i64,
        indices: &[u32; LANES],
        active: u8,
        offset: usize,
    ) -> [__m512i; 8] {
        let mut rows = [self.zero(); 8];
        for (l, row) in rows.iter_mut().enumerate() {
            let at = base.wrapping_add(first_word(indices[l]) + offset);
            // SAFETY: the caller's promise; outside `active` the mask is empty and nothing
            // is read.
            *row = unsafe { _mm512_maskz_loadu_epi64(lane_mask(active, l), at.cast()) };
        }
        self.transpose(rows)
    }

    /// The transpose of an 8 × 8 matrix of words given by rows: row i of the result holds
    /// word i of every input row. Three rounds of two-source permutes, 24 in all.
    #[inline(always)]
    fn transpose(self, rows: [__m512i; 8]) -> [__m512i; 8] {
        // SAFETY: see the `Wide` implementation.
        unsafe {
            let [a0, a1, a2, a3, a4, a5, a6, a7] = [
                _mm512_unpacklo_epi64(rows[0], rows[1]),
                _mm512_unpackhi_epi64(rows[0], rows[1]),
                _mm512_unpacklo_epi64(rows[2], rows[3]),
                _mm512_unpackhi_epi64(rows[2], rows[3]),
                _mm512_unpacklo_epi64(rows[4], rows[5]),
                _mm512_unpackhi_epi64(rows[4], rows[5]),
                _mm512_unpacklo_epi64(rows[6], rows[7]),
                _mm512_unpackhi_epi64(rows[6], rows[7]),
            ];
            // Words 0 and 1 of each 256-bit half from the first source, then from the
            // second (indices 8 and up), and likewise words 2 and 3.
            let low = _mm512_set_epi64(13, 12, 5, 4, 9, 8, 1, 0);
            let high = _mm512_set_epi64(15, 14, 7, 6, 11, 10, 3, 2);
            let [b0, b2, b1, b3, b4, b6, b5, b7] = [
                _mm512_permutex2var_epi64(a0, low, a2),
                _mm512_permutex2var_epi64(a0, high, a2),
                _mm512_permutex2var_epi64(a1, low, a3),
                _mm512_permutex2var_epi64(a1, high, a3),
                _mm512_permutex2var_epi64(a4, low, a6),
                _mm512_permutex2var_epi64(a4, high, a6),
                _mm512_permutex2var_epi64(a5, low, a7),
                _mm512_permutex2var_epi64(a5, high, a7),
            ];
            // The low 256 bits of each, then the high 256 bits.
            let first = _mm512_set_epi64(11, 10, 9, 8, 3, 2, 1, 0);
            let second = _mm512_set_epi64(15, 14, 13, 12, 7, 6, 5, 4);
            let [r0, r4, r1, r5, r2, r6, r3, r7] = [
                _mm512_permutex2var_epi64(b0, first, b4),
                _mm512_permutex2var_epi64(b0, second, b4),
                _mm512_permutex2var_epi64(b1, first, b5),
                _mm512_permutex2var_epi64(b1, second, b5),
                _mm512_permutex2var_epi64(b2, first, b6),
                _mm512_permutex2var_epi64(b2, second, b6),
                _mm512_permutex2var_epi64(b3, first, b7),
                _mm512_permutex2var_epi64(b3, second, b7),
            ];
            [r0, r1, r2, r3, r4, r5, r6, r7]
        }
    }
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
