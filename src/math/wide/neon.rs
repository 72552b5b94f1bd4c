//! The NEON backend of [`Wide`] (aarch64): eight lanes in four `int64x2_t` (lanes 0–1,
//! 2–3, 4–5, 6–7), lane masks built from the top bits of comparison results. NEON is part
//! of every aarch64 processor, so the backend is always there (unless `FIXSTEP_SIMD` caps
//! it). It lacks several 64-bit operations that AVX-512 has, so some take a few
//! instructions:
//!
//! * the products of 32-bit halves: the low halves narrowed (`vmovn`), then one widening
//!   multiply (`vmull`), signed or unsigned;
//! * the one 64-bit product the checked `*` needs, a·b_h with b_h a high half:
//!   a_h·b_h·2³² + a_l·b_h, two products of halves ([`Wide::mul_low_by_high`]);
//! * the signed maximum and minimum and the unsigned minimum: a comparison and a select;
//! * shifts by a count in a register: `vshl` by the count, or by its negation for a right
//!   shift;
//! * the blend of two values under a lane mask: the mask's bits tested against each
//!   lane's bit (`vtst`).
//!
//! Leading-zero counts, table lookups, gathers and masked loads go lane by lane through
//! arrays (the trait's defaults where it has them).

use core::arch::aarch64::{
    int64x2_t, uint64x2_t, vaddq_s64, vandq_s64, vbslq_s64, vceqq_s64, vcgeq_u64, vcgtq_s64,
    vcgtq_u64, vdupq_n_s64, vdupq_n_u64, veorq_s64, vgetq_lane_u64, vld1q_s64, vld1q_u64,
    vmovn_s64, vmovn_u64, vmull_s32, vmull_u32, vorrq_s64, vreinterpretq_s64_u64,
    vreinterpretq_u64_s64, vshlq_s64, vshlq_u64, vshrq_n_s64, vst1q_s64, vsubq_s64, vtstq_u64,
};

use super::{LANES, Wide, quarters};

/// The NEON backend. A value exists only on aarch64, where every processor has NEON, and
/// only when `FIXSTEP_SIMD` allows it.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Neon(());

impl Neon {
    /// The backend, if the cap allows it.
    #[inline]
    pub(crate) fn detect() -> Option<Self> {
        crate::math::cpu::neon().then_some(Self(()))
    }

    /// The lane mask of four comparison results (all ones or all zeros per lane).
    #[inline(always)]
    fn mask_of(self, x: [uint64x2_t; 4]) -> u8 {
        let mut mask = 0;
        for (q, lanes) in x.into_iter().enumerate() {
            // SAFETY: see the implementation's comment.
            let (low, high) = unsafe { (vgetq_lane_u64::<0>(lanes), vgetq_lane_u64::<1>(lanes)) };
            mask |= (((low >> 63) | ((high >> 63) << 1)) as u8) << (2 * q);
        }
        mask
    }

    /// A lane mask as vectors: all ones in the lanes of `mask`, zero elsewhere (each
    /// lane's bit of the mask tested).
    #[inline(always)]
    fn spread(self, mask: u8) -> [uint64x2_t; 4] {
        const BITS: [u64; LANES] = [1, 2, 4, 8, 16, 32, 64, 128];
        // SAFETY: see the implementation's comment; `BITS` is eight readable words.
        unsafe {
            let all = vdupq_n_u64(u64::from(mask));
            let p = BITS.as_ptr();
            [
                vtstq_u64(all, vld1q_u64(p)),
                vtstq_u64(all, vld1q_u64(p.add(2))),
                vtstq_u64(all, vld1q_u64(p.add(4))),
                vtstq_u64(all, vld1q_u64(p.add(6))),
            ]
        }
    }
}

// SAFETY (every `unsafe` block below that calls an intrinsic): NEON is part of every
// aarch64 processor, the only target this backend compiles for.
impl Wide for Neon {
    type V = [int64x2_t; 4];

    #[inline(always)]
    fn zero(self) -> Self::V {
        self.splat(0)
    }

    #[inline(always)]
    fn splat(self, x: i64) -> Self::V {
        unsafe { [vdupq_n_s64(x); 4] }
    }

    #[inline(always)]
    unsafe fn load_at(self, words: *const i64) -> Self::V {
        // SAFETY: the caller's promise: eight readable words, four runs of two.
        unsafe {
            [
                vld1q_s64(words),
                vld1q_s64(words.add(2)),
                vld1q_s64(words.add(4)),
                vld1q_s64(words.add(6)),
            ]
        }
    }

    #[inline(always)]
    unsafe fn store_at(self, out: *mut i64, x: Self::V) {
        // SAFETY: the caller's promise: eight writable words, four runs of two.
        unsafe {
            vst1q_s64(out, x[0]);
            vst1q_s64(out.add(2), x[1]);
            vst1q_s64(out.add(4), x[2]);
            vst1q_s64(out.add(6), x[3]);
        }
    }

    #[inline(always)]
    fn add(self, a: Self::V, b: Self::V) -> Self::V {
        quarters!(int64x2_t; a, b, |a, b| unsafe { vaddq_s64(a, b) })
    }

    #[inline(always)]
    fn sub(self, a: Self::V, b: Self::V) -> Self::V {
        quarters!(int64x2_t; a, b, |a, b| unsafe { vsubq_s64(a, b) })
    }

    #[inline(always)]
    fn and(self, a: Self::V, b: Self::V) -> Self::V {
        quarters!(int64x2_t; a, b, |a, b| unsafe { vandq_s64(a, b) })
    }

    #[inline(always)]
    fn or(self, a: Self::V, b: Self::V) -> Self::V {
        quarters!(int64x2_t; a, b, |a, b| unsafe { vorrq_s64(a, b) })
    }

    #[inline(always)]
    fn xor(self, a: Self::V, b: Self::V) -> Self::V {
        quarters!(int64x2_t; a, b, |a, b| unsafe { veorq_s64(a, b) })
    }

    /// An arithmetic shift by 63.
    #[inline(always)]
    fn sign(self, a: Self::V) -> Self::V {
        quarters!(int64x2_t; a, a, |a, _b| unsafe { vshrq_n_s64::<63>(a) })
    }

    #[inline(always)]
    fn max(self, a: Self::V, b: Self::V) -> Self::V {
        quarters!(int64x2_t; a, b, |a, b| unsafe { vbslq_s64(vcgtq_s64(a, b), a, b) })
    }

    #[inline(always)]
    fn min(self, a: Self::V, b: Self::V) -> Self::V {
        quarters!(int64x2_t; a, b, |a, b| unsafe { vbslq_s64(vcgtq_s64(a, b), b, a) })
    }

    /// −a where a is negative (wrapping: i64::MIN stays itself).
    #[inline(always)]
    fn abs(self, a: Self::V) -> Self::V {
        let negative = self.sign(a);
        self.sub(self.xor(a, negative), negative)
    }

    #[inline(always)]
    fn mul_low_halves(self, a: Self::V, b: Self::V) -> Self::V {
        quarters!(int64x2_t; a, b, |a, b| unsafe {
            vmull_s32(vmovn_s64(a), vmovn_s64(b))
        })
    }

    /// a_h·b_h·2³² + a_l·b_h: two signed products of halves, a shift and a sum (NEON has
    /// no 64-bit multiply).
    #[inline(always)]
    fn mul_low_by_high(self, a: Self::V, a_high: Self::V, b_high: Self::V) -> Self::V {
        let high = self.shift_left(self.mul_low_halves(a_high, b_high), 32);
        self.add(high, self.mul_low_halves(a, b_high))
    }

    #[inline(always)]
    fn shift_down_32(self, a: Self::V) -> Self::V {
        quarters!(int64x2_t; a, a, |a, _b| unsafe { vshrq_n_s64::<32>(a) })
    }

    #[inline(always)]
    fn greater(self, a: Self::V, b: Self::V) -> u8 {
        self.mask_of(quarters!(int64x2_t; a, b, |a, b| unsafe { vcgtq_s64(a, b) }))
    }

    #[inline(always)]
    fn at_least_unsigned(self, a: Self::V, b: Self::V) -> u8 {
        self.mask_of(quarters!(int64x2_t; a, b, |a, b| unsafe {
            vcgeq_u64(vreinterpretq_u64_s64(a), vreinterpretq_u64_s64(b))
        }))
    }

    #[inline(always)]
    fn greater_unsigned(self, a: Self::V, b: Self::V) -> u8 {
        self.mask_of(quarters!(int64x2_t; a, b, |a, b| unsafe {
            vcgtq_u64(vreinterpretq_u64_s64(a), vreinterpretq_u64_s64(b))
        }))
    }

    #[inline(always)]
    fn equal(self, a: Self::V, b: Self::V) -> u8 {
        self.mask_of(quarters!(int64x2_t; a, b, |a, b| unsafe { vceqq_s64(a, b) }))
    }

    #[inline(always)]
    fn select(self, mask: u8, on: Self::V, off: Self::V) -> Self::V {
        let lanes = self.spread(mask);
        // SAFETY: see the implementation's comment.
        unsafe {
            [
                vbslq_s64(lanes[0], on[0], off[0]),
                vbslq_s64(lanes[1], on[1], off[1]),
                vbslq_s64(lanes[2], on[2], off[2]),
                vbslq_s64(lanes[3], on[3], off[3]),
            ]
        }
    }

    #[inline(always)]
    fn shift_left(self, a: Self::V, n: u32) -> Self::V {
        let count = i64::from(n);
        quarters!(int64x2_t; a, a, |a, _b| unsafe { vshlq_s64(a, vdupq_n_s64(count)) })
    }

    #[inline(always)]
    fn shift_right_unsigned(self, a: Self::V, n: u32) -> Self::V {
        let count = -i64::from(n);
        quarters!(int64x2_t; a, a, |a, _b| unsafe {
            vreinterpretq_s64_u64(vshlq_u64(vreinterpretq_u64_s64(a), vdupq_n_s64(count)))
        })
    }

    #[inline(always)]
    fn shift_right(self, a: Self::V, n: u32) -> Self::V {
        let count = -i64::from(n);
        quarters!(int64x2_t; a, a, |a, _b| unsafe { vshlq_s64(a, vdupq_n_s64(count)) })
    }

    /// `vshl` reads the low byte of each count as signed; counts from 64 up are first
    /// capped at 64 (which gives zero).
    #[inline(always)]
    fn shift_left_lanes(self, a: Self::V, n: Self::V) -> Self::V {
        let n = self.min_unsigned(n, self.splat(64));
        quarters!(int64x2_t; a, n, |a, n| unsafe { vshlq_s64(a, n) })
    }

    /// As [`shift_left_lanes`](Self::shift_left_lanes), by the negated counts.
    #[inline(always)]
    fn shift_right_unsigned_lanes(self, a: Self::V, n: Self::V) -> Self::V {
        let n = self.sub(self.zero(), self.min_unsigned(n, self.splat(64)));
        quarters!(int64x2_t; a, n, |a, n| unsafe {
            vreinterpretq_s64_u64(vshlq_u64(vreinterpretq_u64_s64(a), n))
        })
    }

    #[inline(always)]
    fn min_unsigned(self, a: Self::V, b: Self::V) -> Self::V {
        quarters!(int64x2_t; a, b, |a, b| unsafe {
            vbslq_s64(
                vcgtq_u64(vreinterpretq_u64_s64(a), vreinterpretq_u64_s64(b)),
                b,
                a,
            )
        })
    }

    #[inline(always)]
    fn mul_unsigned_low_halves(self, a: Self::V, b: Self::V) -> Self::V {
        quarters!(int64x2_t; a, b, |a, b| unsafe {
            vreinterpretq_s64_u64(vmull_u32(
                vmovn_u64(vreinterpretq_u64_s64(a)),
                vmovn_u64(vreinterpretq_u64_s64(b)),
            ))
        })
    }
}
