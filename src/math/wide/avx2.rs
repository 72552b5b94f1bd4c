//! The AVX2 backend of [`Wide`]: eight lanes in two `__m256i` (lanes 0–3, then 4–7), lane
//! masks built from the sign bits of comparison results. AVX2 lacks several 64-bit
//! operations that AVX-512 has, so some take a few instructions:
//!
//! * the one 64-bit product the checked `*` needs, a·b_h with b_h a high half: two signed
//!   products of 32-bit halves, a_h·b_h·2³² + a_l·b_h ([`Wide::mul_low_by_high`]);
//! * the arithmetic shift right by 32: the high half moved down (a logical shift), with
//!   the sign of the high half (an arithmetic shift of the 32-bit elements) above it;
//! * the signed maximum and minimum: a comparison and a blend;
//! * the unsigned comparison: a signed one of both operands with their sign bits flipped;
//! * the blend of two values under a lane mask: the mask's bits spread over the lanes by a
//!   comparison.
//!
//! The bodies are loaded and stored lane by lane, through arrays.
//!
//! As in the AVX-512 backend, the operations carry no `#[target_feature]` of their own:
//! they are always inlined into a kernel entry point that enables AVX2.

use core::arch::x86_64::{
    __m256i, _mm_cmplt_epi32, _mm_cvtsi32_si128, _mm_maskload_epi32, _mm_set_epi32, _mm_set1_epi32,
    _mm256_add_epi64, _mm256_and_si256, _mm256_blend_epi32, _mm256_blendv_epi8,
    _mm256_castsi256_pd, _mm256_cmpeq_epi64, _mm256_cmpgt_epi64, _mm256_cvtepu32_epi64,
    _mm256_i64gather_epi64, _mm256_loadu_si256, _mm256_mask_i64gather_epi64, _mm256_maskload_epi64,
    _mm256_movemask_pd, _mm256_mul_epi32, _mm256_mul_epu32, _mm256_or_si256,
    _mm256_permute4x64_epi64, _mm256_set_epi64x, _mm256_set1_epi64x, _mm256_setzero_si256,
    _mm256_sll_epi64, _mm256_slli_epi64, _mm256_sllv_epi64, _mm256_srai_epi32, _mm256_srl_epi64,
    _mm256_srli_epi64, _mm256_srlv_epi64, _mm256_storeu_si256, _mm256_sub_epi64,
    _mm256_testz_si256, _mm256_xor_si256,
};

use super::Wide;

/// `f` of each half of two values. A macro, not a closure: the kernels are large, and a
/// closure there may not be inlined (nor, then, the intrinsics inside it).
macro_rules! halves {
    ($a:expr, $b:expr, |$x:ident, $y:ident| $f:expr) => {{
        let (a, b): ([__m256i; 2], [__m256i; 2]) = ($a, $b);
        [
            {
                let ($x, $y) = (a[0], b[0]);
                $f
            },
            {
                let ($x, $y) = (a[1], b[1]);
                $f
            },
        ]
    }};
}

/// The AVX2 backend. A value exists only where the processor has AVX2.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Avx2(());

impl Avx2 {
    /// The backend, if this processor runs it.
    #[inline]
    pub(crate) fn detect() -> Option<Self> {
        crate::math::cpu::avx2().then_some(Self(()))
    }

    /// A lane mask as vectors: all ones in the lanes of `mask`, zero elsewhere (lane l of
    /// a half is on when bit l of its nibble is set).
    #[inline(always)]
    fn spread(self, mask: u8) -> [__m256i; 2] {
        // SAFETY: see `mask_of`.
        unsafe {
            let bits = _mm256_set_epi64x(8, 4, 2, 1);
            let low = _mm256_and_si256(_mm256_set1_epi64x(i64::from(mask & 0xf)), bits);
            let high = _mm256_and_si256(_mm256_set1_epi64x(i64::from(mask >> 4)), bits);
            [
                _mm256_cmpeq_epi64(low, bits),
                _mm256_cmpeq_epi64(high, bits),
            ]
        }
    }

    /// The lane mask of a comparison result (all ones or all zeros per lane).
    #[inline(always)]
    fn mask_of(self, x: [__m256i; 2]) -> u8 {
        // SAFETY (here and below): a value of `Avx2` exists only on a processor with AVX2.
        let (low, high) = unsafe {
            (
                _mm256_movemask_pd(_mm256_castsi256_pd(x[0])),
                _mm256_movemask_pd(_mm256_castsi256_pd(x[1])),
            )
        };
        (low | (high << 4)) as u8
    }
}

// SAFETY (every `unsafe` block below that calls an intrinsic): a value of `Avx2` exists only
// on a processor with AVX2 (`Avx2::detect`).
impl Wide for Avx2 {
    type V = [__m256i; 2];

    #[inline(always)]
    fn zero(self) -> Self::V {
        unsafe { [_mm256_setzero_si256(); 2] }
    }

    #[inline(always)]
    fn splat(self, x: i64) -> Self::V {
        unsafe { [_mm256_set1_epi64x(x); 2] }
    }

    #[inline(always)]
    unsafe fn load_at(self, words: *const i64) -> Self::V {
        // SAFETY: the caller's promise: eight readable words, two runs of four.
        unsafe {
            [
                _mm256_loadu_si256(words.cast()),
                _mm256_loadu_si256(words.add(4).cast()),
            ]
        }
    }

    #[inline(always)]
    unsafe fn store_at(self, out: *mut i64, x: Self::V) {
        // SAFETY: the caller's promise: eight writable words, two runs of four.
        unsafe {
            _mm256_storeu_si256(out.cast(), x[0]);
            _mm256_storeu_si256(out.add(4).cast(), x[1]);
        }
    }

    #[inline(always)]
    fn add(self, a: Self::V, b: Self::V) -> Self::V {
        halves!(a, b, |a, b| unsafe { _mm256_add_epi64(a, b) })
    }

    #[inline(always)]
    fn sub(self, a: Self::V, b: Self::V) -> Self::V {
        halves!(a, b, |a, b| unsafe { _mm256_sub_epi64(a, b) })
    }

    #[inline(always)]
    fn and(self, a: Self::V, b: Self::V) -> Self::V {
        halves!(a, b, |a, b| unsafe { _mm256_and_si256(a, b) })
    }

    #[inline(always)]
    fn or(self, a: Self::V, b: Self::V) -> Self::V {
        halves!(a, b, |a, b| unsafe { _mm256_or_si256(a, b) })
    }

    #[inline(always)]
    fn xor(self, a: Self::V, b: Self::V) -> Self::V {
        halves!(a, b, |a, b| unsafe { _mm256_xor_si256(a, b) })
    }

    /// A signed comparison with zero.
    #[inline(always)]
    fn sign(self, a: Self::V) -> Self::V {
        halves!(a, a, |a, _b| unsafe {
            _mm256_cmpgt_epi64(_mm256_setzero_si256(), a)
        })
    }

    #[inline(always)]
    fn max(self, a: Self::V, b: Self::V) -> Self::V {
        halves!(a, b, |a, b| unsafe {
            _mm256_blendv_epi8(b, a, _mm256_cmpgt_epi64(a, b))
        })
    }

    #[inline(always)]
    fn min(self, a: Self::V, b: Self::V) -> Self::V {
        halves!(a, b, |a, b| unsafe {
            _mm256_blendv_epi8(a, b, _mm256_cmpgt_epi64(a, b))
        })
    }

    #[inline(always)]
    fn abs(self, a: Self::V) -> Self::V {
        halves!(a, a, |a, _b| unsafe {
            let zero = _mm256_setzero_si256();
            _mm256_blendv_epi8(a, _mm256_sub_epi64(zero, a), _mm256_cmpgt_epi64(zero, a))
        })
    }

    #[inline(always)]
    fn mul_low_halves(self, a: Self::V, b: Self::V) -> Self::V {
        halves!(a, b, |a, b| unsafe { _mm256_mul_epi32(a, b) })
    }

    /// a_h·b_h·2³² + a_l·b_h: two signed products of halves, a shift and a sum (AVX2 has
    /// no 64-bit multiply; building one takes three products and five other
    /// instructions).
    #[inline(always)]
    fn mul_low_by_high(self, a: Self::V, a_high: Self::V, b_high: Self::V) -> Self::V {
        let high = self.mul_low_halves(a_high, b_high);
        let shifted = halves!(high, high, |x, _y| unsafe { _mm256_slli_epi64::<32>(x) });
        self.add(shifted, self.mul_low_halves(a, b_high))
    }

    #[inline(always)]
    fn shift_down_32(self, a: Self::V) -> Self::V {
        halves!(a, a, |a, _b| unsafe {
            _mm256_blend_epi32::<0b1010_1010>(
                _mm256_srli_epi64::<32>(a),
                _mm256_srai_epi32::<31>(a),
            )
        })
    }

    #[inline(always)]
    fn greater(self, a: Self::V, b: Self::V) -> u8 {
        self.mask_of(halves!(a, b, |a, b| unsafe { _mm256_cmpgt_epi64(a, b) }))
    }

    #[inline(always)]
    fn at_least_unsigned(self, a: Self::V, b: Self::V) -> u8 {
        // a ≥ b unsigned unless b > a unsigned, that is b ^ 2⁶³ > a ^ 2⁶³ signed.
        let below = halves!(a, b, |a, b| unsafe {
            let sign = _mm256_set1_epi64x(i64::MIN);
            _mm256_cmpgt_epi64(_mm256_xor_si256(b, sign), _mm256_xor_si256(a, sign))
        });
        !self.mask_of(below)
    }

    #[inline(always)]
    fn equal(self, a: Self::V, b: Self::V) -> u8 {
        self.mask_of(halves!(a, b, |a, b| unsafe { _mm256_cmpeq_epi64(a, b) }))
    }

    #[inline(always)]
    fn select(self, mask: u8, on: Self::V, off: Self::V) -> Self::V {
        // SAFETY: see the implementation's comment.
        unsafe {
            let [low, high] = self.spread(mask);
            [
                _mm256_blendv_epi8(off[0], on[0], low),
                _mm256_blendv_epi8(off[1], on[1], high),
            ]
        }
    }

    #[inline(always)]
    unsafe fn gather_words(self, base: *const i64, words: Self::V, active: u8) -> Self::V {
        let [low, high] = self.spread(active);
        // SAFETY: the caller's promise; outside `active` nothing is read.
        unsafe {
            [
                _mm256_mask_i64gather_epi64::<8>(self.zero()[0], base, words[0], low),
                _mm256_mask_i64gather_epi64::<8>(self.zero()[1], base, words[1], high),
            ]
        }
    }

    /// ⌊(a + 2³¹)/2³²⌋ with a logical shift: y = a + 2³¹ + 2⁶³ (mod 2⁶⁴) read unsigned is
    /// the signed a + 2³¹ plus 2⁶³, a multiple of 2³², so its logical shift is the
    /// arithmetic one plus 2³¹ (three instructions, where the arithmetic shift takes four).
    #[inline(always)]
    fn high(self, a: Self::V) -> Self::V {
        let biased = self.add(a, self.splat((1 << 31) + i64::MIN));
        self.sub(self.shift_right_unsigned(biased, 32), self.splat(1 << 31))
    }

    /// One `vptest` of the or of both halves against the bits from n up.
    #[inline(always)]
    fn below_power(self, a: Self::V, n: u32) -> bool {
        unsafe {
            let high_bits = _mm256_set1_epi64x(-1i64 << n);
            _mm256_testz_si256(_mm256_or_si256(a[0], a[1]), high_bits) == 1
        }
    }

    #[inline(always)]
    fn shift_left(self, a: Self::V, n: u32) -> Self::V {
        halves!(a, a, |a, _b| unsafe {
            _mm256_sll_epi64(a, _mm_cvtsi32_si128(n as i32))
        })
    }

    #[inline(always)]
    fn shift_right_unsigned(self, a: Self::V, n: u32) -> Self::V {
        halves!(a, a, |a, _b| unsafe {
            _mm256_srl_epi64(a, _mm_cvtsi32_si128(n as i32))
        })
    }

    /// The logical shift, with the sign's copies shifted in above it: (a >>ᵤ n) |
    /// (s << (63 − n) << 1) for s = a >> 63 (all ones or zero).
    #[inline(always)]
    fn shift_right(self, a: Self::V, n: u32) -> Self::V {
        let fill = self.shift_left(self.shift_left(self.sign(a), 63 - n), 1);
        self.or(self.shift_right_unsigned(a, n), fill)
    }

    #[inline(always)]
    fn shift_left_lanes(self, a: Self::V, n: Self::V) -> Self::V {
        halves!(a, n, |a, n| unsafe { _mm256_sllv_epi64(a, n) })
    }

    #[inline(always)]
    fn shift_right_unsigned_lanes(self, a: Self::V, n: Self::V) -> Self::V {
        halves!(a, n, |a, n| unsafe { _mm256_srlv_epi64(a, n) })
    }

    #[inline(always)]
    fn mul_unsigned_low_halves(self, a: Self::V, b: Self::V) -> Self::V {
        halves!(a, b, |a, b| unsafe { _mm256_mul_epu32(a, b) })
    }

    /// A gather from the table, four lanes at a time.
    #[inline(always)]
    fn lookup16(self, table: &[i64; 16], index: Self::V) -> Self::V {
        let index = self.and(index, self.splat(15));
        // SAFETY: every index is below 16, so each load lies in the table.
        halves!(index, index, |i, _j| unsafe {
            _mm256_i64gather_epi64::<8>(table.as_ptr(), i)
        })
    }

    /// Each half of each result comes from one half of `a`: six permutes within halves.
    #[inline(always)]
    fn spread_thirds(self, a: Self::V) -> [Self::V; 3] {
        let [low, high] = a;
        // Lanes (0 0 0 1 | 1 1 2 2), (2 3 3 3 | 4 4 4 5), (5 5 6 6 | 6 7 7 7).
        unsafe {
            [
                [
                    _mm256_permute4x64_epi64::<0b01_00_00_00>(low),
                    _mm256_permute4x64_epi64::<0b10_10_01_01>(low),
                ],
                [
                    _mm256_permute4x64_epi64::<0b11_11_11_10>(low),
                    _mm256_permute4x64_epi64::<0b01_00_00_00>(high),
                ],
                [
                    _mm256_permute4x64_epi64::<0b10_10_01_01>(high),
                    _mm256_permute4x64_epi64::<0b11_11_11_10>(high),
                ],
            ]
        }
    }

    /// Two masked loads of four words.
    #[inline(always)]
    unsafe fn load_prefix(self, words: *const i64, count: usize) -> Self::V {
        let [low, high] = self.spread(((1u16 << count) - 1) as u8);
        // SAFETY: the caller's promise: the `count` words the masks select are readable;
        // a masked-off word is not read.
        unsafe {
            [
                _mm256_maskload_epi64(words, low),
                _mm256_maskload_epi64(words.wrapping_add(4), high),
            ]
        }
    }

    /// One masked load of four numbers per half, widened.
    #[inline(always)]
    unsafe fn load_prefix_u32(self, numbers: *const u32, count: usize) -> Self::V {
        // SAFETY: the caller's promise: the `count` numbers the masks select are readable;
        // a masked-off number is not read.
        unsafe {
            let lanes = _mm_set_epi32(3, 2, 1, 0);
            let low = _mm_cmplt_epi32(lanes, _mm_set1_epi32(count.min(4) as i32));
            let high = _mm_cmplt_epi32(lanes, _mm_set1_epi32(count.saturating_sub(4) as i32));
            let at = numbers.cast::<i32>();
            [
                _mm256_cvtepu32_epi64(_mm_maskload_epi32(at, low)),
                _mm256_cvtepu32_epi64(_mm_maskload_epi32(at.wrapping_add(4), high)),
            ]
        }
    }
}
