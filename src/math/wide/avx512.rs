//! The AVX-512 backend of [`Wide`] (F, CD and DQ): eight lanes in one `__m512i`, lane masks in
//! mask registers. `_mm512_mul_epi32` gives the products of low halves and
//! `_mm512_mullo_epi64` the low 64 bits of a 64 × 64 product; masked loads read a row's
//! prefix and the values of a neighbour list, and a transpose of eight rows turns records
//! (vectors, bodies) into one vector per field.
//!
//! The operations carry no `#[target_feature]` of their own: they are always inlined, and
//! a kernel runs them inside an entry point with `#[target_feature(enable =
//! "avx512f,avx512cd,avx512dq")]`, where they compile to single instructions (CD for the
//! leading-zero count; every processor with DQ has it).

use core::arch::x86_64::{
    __m512i, _mm_cvtsi32_si128, _mm_loadl_epi64, _mm_loadu_si128, _mm512_abs_epi64,
    _mm512_add_epi64, _mm512_and_si512, _mm512_castsi128_si512, _mm512_castsi512_si256,
    _mm512_cmpeq_epi64_mask, _mm512_cmpge_epu64_mask, _mm512_cmpgt_epi64_mask,
    _mm512_cmpgt_epu64_mask, _mm512_cvtepu32_epi64, _mm512_inserti32x4, _mm512_loadu_si512,
    _mm512_lzcnt_epi64, _mm512_mask_blend_epi64, _mm512_mask_i64gather_epi64,
    _mm512_mask_loadu_epi64, _mm512_mask_storeu_epi64, _mm512_maskz_compress_epi64,
    _mm512_maskz_loadu_epi32, _mm512_maskz_loadu_epi64, _mm512_max_epi64, _mm512_min_epi64,
    _mm512_min_epu64, _mm512_mul_epi32, _mm512_mul_epu32, _mm512_mullo_epi64, _mm512_or_si512,
    _mm512_permutex2var_epi64, _mm512_permutexvar_epi64, _mm512_reduce_add_epi64,
    _mm512_reduce_or_epi64, _mm512_set_epi64, _mm512_set1_epi64, _mm512_setzero_si512,
    _mm512_sll_epi64, _mm512_sllv_epi64, _mm512_sra_epi64, _mm512_srai_epi64, _mm512_srl_epi64,
    _mm512_srlv_epi64, _mm512_storeu_si512, _mm512_sub_epi64, _mm512_test_epi64_mask,
    _mm512_unpackhi_epi64, _mm512_unpacklo_epi64, _mm512_xor_si512,
};

use super::{LANES, Wide};
use crate::math::{Fx, Vec3};

/// The AVX-512 backend. A value exists only where the processor has AVX-512F, CD and DQ.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Avx512(());

impl Avx512 {
    /// The backend, if this processor runs it.
    #[inline]
    pub(crate) fn detect() -> Option<Self> {
        crate::math::cpu::avx512_kernels().then_some(Self(()))
    }
}

// SAFETY (every `unsafe` block below that calls an intrinsic): a value of `Avx512` exists
// only on a processor with AVX-512F, CD and DQ (`Avx512::detect`).
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
    unsafe fn load_at(self, words: *const i64) -> __m512i {
        // SAFETY: the caller's promise: eight readable words.
        unsafe { _mm512_loadu_si512(words.cast()) }
    }

    #[inline(always)]
    unsafe fn store_at(self, out: *mut i64, x: __m512i) {
        // SAFETY: the caller's promise: eight writable words.
        unsafe { _mm512_storeu_si512(out.cast(), x) }
    }

    #[inline(always)]
    fn load(self, lanes: &[Fx; LANES]) -> __m512i {
        // SAFETY: eight `Fx`, each one `i64`: 64 readable bytes.
        unsafe { _mm512_loadu_si512(lanes.as_ptr().cast()) }
    }

    #[inline(always)]
    fn store(self, lanes: &mut [Fx; LANES], value: __m512i) {
        // SAFETY: eight `Fx`, each one `i64`: 64 writable bytes.
        unsafe { _mm512_storeu_si512(lanes.as_mut_ptr().cast(), value) }
    }

    #[inline(always)]
    fn store_lanes(self, lanes: &mut [Fx; LANES], mask: u8, value: __m512i) {
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
    fn or(self, a: __m512i, b: __m512i) -> __m512i {
        unsafe { _mm512_or_si512(a, b) }
    }

    #[inline(always)]
    fn xor(self, a: __m512i, b: __m512i) -> __m512i {
        unsafe { _mm512_xor_si512(a, b) }
    }

    #[inline(always)]
    fn sign(self, a: __m512i) -> __m512i {
        unsafe { _mm512_srai_epi64::<63>(a) }
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
    unsafe fn gather_words(self, base: *const i64, words: __m512i, active: u8) -> __m512i {
        // SAFETY: the caller's promise; outside `active` nothing is read.
        unsafe { _mm512_mask_i64gather_epi64::<8>(self.zero(), active, words, base) }
    }

    /// One masked load of a word per lane, in two chains of merges (even and odd lanes)
    /// joined at the end, which costs less than a gather.
    #[inline(always)]
    unsafe fn gather_values(self, values: *const i64, indices: &[u32], count: usize) -> __m512i {
        let mut chains = [self.zero(); 2];
        for l in 0..count {
            // SAFETY: the caller's conditions: the masked load reads one word, value
            // `indices[l]`, into lane l (from l words before it, the others masked off).
            unsafe {
                let at = values.add(*indices.get_unchecked(l) as usize);
                chains[l & 1] =
                    _mm512_mask_loadu_epi64(chains[l & 1], 1 << l, at.wrapping_sub(l).cast());
            }
        }
        self.or(chains[0], chains[1])
    }

    /// A load of three words per vector and a transpose (the processor's gather
    /// instructions are slower on some cores).
    #[inline(always)]
    fn gather_vectors(self, vectors: &[Vec3<Fx>], indices: &[u32]) -> Option<[__m512i; 3]> {
        let indices = &indices[..indices.len().min(LANES)];
        let mut rows = [self.zero(); LANES];
        for (row, &i) in rows.iter_mut().zip(indices) {
            let words = core::ptr::from_ref(vectors.get(i as usize)?).cast::<i64>();
            // SAFETY: a `Vec3<Fx>` is three readable `i64`: x and y, then z.
            *row = unsafe {
                let (xy, z) = (
                    _mm_loadu_si128(words.cast()),
                    _mm_loadl_epi64(words.add(2).cast()),
                );
                _mm512_inserti32x4::<1>(_mm512_castsi128_si512(xy), z)
            };
        }
        let [x, y, z, ..] = self.transpose(rows);
        Some([x, y, z])
    }

    /// Three loads and a transpose.
    #[inline(always)]
    fn load_run(self, vectors: &[Vec3<Fx>], first: usize) -> Option<[__m512i; 3]> {
        let run = vectors.get(first..first + LANES)?;
        let words = run.as_ptr().cast::<i64>();
        // SAFETY: eight `Vec3<Fx>` are 24 readable `i64`.
        unsafe {
            let (v0, v1, v2) = (
                _mm512_loadu_si512(words.cast()),
                _mm512_loadu_si512(words.add(LANES).cast()),
                _mm512_loadu_si512(words.add(2 * LANES).cast()),
            );
            // Word 3i + c is component c of vector i: v0 holds words 0..8, v1 8..16, v2
            // 16..24.
            let x = _mm512_permutex2var_epi64(v0, _mm512_set_epi64(0, 0, 15, 12, 9, 6, 3, 0), v1);
            let y = _mm512_permutex2var_epi64(v0, _mm512_set_epi64(0, 0, 0, 13, 10, 7, 4, 1), v1);
            let z = _mm512_permutex2var_epi64(v0, _mm512_set_epi64(0, 0, 0, 14, 11, 8, 5, 2), v1);
            Some([
                _mm512_permutex2var_epi64(x, _mm512_set_epi64(13, 10, 5, 4, 3, 2, 1, 0), v2),
                _mm512_permutex2var_epi64(y, _mm512_set_epi64(14, 11, 8, 4, 3, 2, 1, 0), v2),
                _mm512_permutex2var_epi64(z, _mm512_set_epi64(15, 12, 9, 4, 3, 2, 1, 0), v2),
            ])
        }
    }

    /// One permute per result.
    #[inline(always)]
    fn spread_thirds(self, a: __m512i) -> [__m512i; 3] {
        unsafe {
            [
                _mm512_permutexvar_epi64(_mm512_set_epi64(2, 2, 1, 1, 1, 0, 0, 0), a),
                _mm512_permutexvar_epi64(_mm512_set_epi64(5, 4, 4, 4, 3, 3, 3, 2), a),
                _mm512_permutexvar_epi64(_mm512_set_epi64(7, 7, 7, 6, 6, 6, 5, 5), a),
            ]
        }
    }

    /// Four loads and a transpose in registers.
    #[inline(always)]
    fn load_columns(self, rows: &[[Fx; 4]; LANES]) -> [__m512i; 4] {
        let words = rows.as_ptr().cast::<i64>();
        // SAFETY: eight rows of four `Fx` are 32 readable `i64`. Word 4l + k is column k
        // of row l: v0 holds rows 0 and 1, v1 rows 2 and 3, and so on.
        unsafe {
            let (v0, v1, v2, v3) = (
                _mm512_loadu_si512(words.cast()),
                _mm512_loadu_si512(words.add(LANES).cast()),
                _mm512_loadu_si512(words.add(2 * LANES).cast()),
                _mm512_loadu_si512(words.add(3 * LANES).cast()),
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
    }

    #[inline(always)]
    unsafe fn load_prefix(self, words: *const i64, count: usize) -> __m512i {
        let mask = ((1u16 << count) - 1) as u8;
        // SAFETY: the caller's promise: the `count` words read are readable.
        unsafe { _mm512_maskz_loadu_epi64(mask, words.cast()) }
    }

    #[inline(always)]
    unsafe fn load_prefix_u32(self, numbers: *const u32, count: usize) -> __m512i {
        let mask = ((1u16 << count) - 1) as u8;
        // SAFETY: the caller's promise: the `count` numbers read are readable.
        unsafe {
            let numbers = _mm512_maskz_loadu_epi32(u16::from(mask), numbers.cast());
            _mm512_cvtepu32_epi64(_mm512_castsi512_si256(numbers))
        }
    }

    #[inline(always)]
    fn shift_left(self, a: __m512i, n: u32) -> __m512i {
        unsafe { _mm512_sll_epi64(a, _mm_cvtsi32_si128(n as i32)) }
    }

    #[inline(always)]
    fn shift_right_unsigned(self, a: __m512i, n: u32) -> __m512i {
        unsafe { _mm512_srl_epi64(a, _mm_cvtsi32_si128(n as i32)) }
    }

    #[inline(always)]
    fn shift_right(self, a: __m512i, n: u32) -> __m512i {
        unsafe { _mm512_sra_epi64(a, _mm_cvtsi32_si128(n as i32)) }
    }

    #[inline(always)]
    fn shift_left_lanes(self, a: __m512i, n: __m512i) -> __m512i {
        unsafe { _mm512_sllv_epi64(a, n) }
    }

    #[inline(always)]
    fn shift_right_unsigned_lanes(self, a: __m512i, n: __m512i) -> __m512i {
        unsafe { _mm512_srlv_epi64(a, n) }
    }

    #[inline(always)]
    fn mul_unsigned_low_halves(self, a: __m512i, b: __m512i) -> __m512i {
        unsafe { _mm512_mul_epu32(a, b) }
    }

    /// `vplzcntq` (AVX-512CD).
    #[inline(always)]
    fn leading_zeros(self, a: __m512i) -> __m512i {
        unsafe { _mm512_lzcnt_epi64(a) }
    }

    /// One two-source permute of the table's two halves.
    #[inline(always)]
    fn lookup16(self, table: &[i64; 16], index: __m512i) -> __m512i {
        // SAFETY: 16 readable words, eight from each pointer.
        unsafe {
            let low = _mm512_loadu_si512(table.as_ptr().cast());
            let high = _mm512_loadu_si512(table.as_ptr().add(8).cast());
            _mm512_permutex2var_epi64(low, index, high)
        }
    }

    /// Packed in a register, then stored whole: a compressing store to memory is slow on
    /// some processors (Zen 4).
    #[inline(always)]
    unsafe fn store_kept(self, out: *mut i64, keep: u8, a: __m512i) {
        // SAFETY: the caller's promise: eight writable words.
        unsafe { _mm512_storeu_si512(out.cast(), _mm512_maskz_compress_epi64(keep, a)) }
    }

    #[inline(always)]
    fn greater_unsigned(self, a: __m512i, b: __m512i) -> u8 {
        unsafe { _mm512_cmpgt_epu64_mask(a, b) }
    }

    #[inline(always)]
    fn min_unsigned(self, a: __m512i, b: __m512i) -> __m512i {
        unsafe { _mm512_min_epu64(a, b) }
    }

    #[inline(always)]
    fn sum_lanes(self, a: __m512i) -> i64 {
        unsafe { _mm512_reduce_add_epi64(a) }
    }

    #[inline(always)]
    fn or_lanes(self, a: __m512i) -> u64 {
        unsafe { _mm512_reduce_or_epi64(a) as u64 }
    }

    /// One `vptestmq` against the bits from n up.
    #[inline(always)]
    fn below_power(self, a: __m512i, n: u32) -> bool {
        unsafe { _mm512_test_epi64_mask(a, _mm512_set1_epi64(-1i64 << n)) == 0 }
    }
}

impl Avx512 {
    /// The transpose of an 8 × 8 matrix of words given by rows: row i of the result holds
    /// word i of every input row. Three rounds of two-source permutes, 24 in all.
    #[inline(always)]
    pub(crate) fn transpose(self, rows: [__m512i; 8]) -> [__m512i; 8] {
        // SAFETY: as in the `Wide` implementation.
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
