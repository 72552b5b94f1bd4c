//! The wasm `simd128` backend of [`Wide`] (wasm32 built with `+simd128`): eight lanes in
//! four `v128` of two `i64` each (lanes 0–1, 2–3, 4–5, 6–7), lane masks from the lanes'
//! top bits (`i64x2_bitmask`). WebAssembly has no run-time detection: the instructions
//! exist when the module is built with them, and an engine that lacks them refuses the
//! module. Against AVX-512:
//!
//! * the products of 32-bit halves: the halves sign- or zero-extended to 64 bits, then the
//!   64-bit multiply (`i64x2_mul`, exact: the products are below 2⁶⁴), which also gives
//!   a·b_h directly ([`Wide::mul_low_by_high`]);
//! * the unsigned comparisons: signed ones of both operands with their sign bits flipped;
//! * the signed maximum and minimum: a comparison and a bit select;
//! * shifts by a count per lane, leading-zero counts, table lookups, gathers and masked
//!   loads: lane by lane through arrays (the trait's defaults where it has them).

use core::arch::wasm32::{
    i64x2_add, i64x2_bitmask, i64x2_eq, i64x2_gt, i64x2_mul, i64x2_shl, i64x2_shr, i64x2_splat,
    i64x2_sub, u64x2_shr, v128, v128_and, v128_bitselect, v128_load, v128_or, v128_store, v128_xor,
};

use super::{LANES, Wide, quarters};

/// The `simd128` backend. A value exists only in a module built with `simd128`, and only
/// when `FIXSTEP_SIMD` allows it.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Simd128(());

impl Simd128 {
    /// The backend, if the cap allows it.
    #[inline]
    pub(crate) fn detect() -> Option<Self> {
        crate::math::cpu::simd128().then_some(Self(()))
    }

    /// The lane mask of four comparison results (all ones or all zeros per lane).
    #[inline(always)]
    fn mask_of(self, x: [v128; 4]) -> u8 {
        i64x2_bitmask(x[0])
            | (i64x2_bitmask(x[1]) << 2)
            | (i64x2_bitmask(x[2]) << 4)
            | (i64x2_bitmask(x[3]) << 6)
    }

    /// A lane mask as vectors: all ones in the lanes of `mask`, zero elsewhere (each
    /// lane's bit of the mask tested).
    #[inline(always)]
    fn spread(self, mask: u8) -> [v128; 4] {
        let all = i64x2_splat(i64::from(mask));
        let bits = self.load_words([1, 2, 4, 8, 16, 32, 64, 128]);
        quarters!(v128; bits, bits, |b, _c| i64x2_eq(v128_and(all, b), b))
    }

    /// a ^ 2⁶³ per lane: unsigned order as signed order.
    #[inline(always)]
    fn flip(self, a: [v128; 4]) -> [v128; 4] {
        self.xor(a, self.splat(i64::MIN))
    }
}

impl Wide for Simd128 {
    type V = [v128; 4];

    #[inline(always)]
    fn zero(self) -> Self::V {
        self.splat(0)
    }

    #[inline(always)]
    fn splat(self, x: i64) -> Self::V {
        [i64x2_splat(x); 4]
    }

    #[inline(always)]
    unsafe fn load_at(self, words: *const i64) -> Self::V {
        let p = words.cast::<v128>();
        // SAFETY: the caller's promise: eight readable words, four runs of two
        // (`v128_load` needs no alignment).
        unsafe {
            [
                v128_load(p),
                v128_load(p.add(1)),
                v128_load(p.add(2)),
                v128_load(p.add(3)),
            ]
        }
    }

    #[inline(always)]
    unsafe fn store_at(self, out: *mut i64, x: Self::V) {
        let p = out.cast::<v128>();
        // SAFETY: the caller's promise: eight writable words, four runs of two.
        unsafe {
            v128_store(p, x[0]);
            v128_store(p.add(1), x[1]);
            v128_store(p.add(2), x[2]);
            v128_store(p.add(3), x[3]);
        }
    }

    #[inline(always)]
    fn add(self, a: Self::V, b: Self::V) -> Self::V {
        quarters!(v128; a, b, |a, b| i64x2_add(a, b))
    }

    #[inline(always)]
    fn sub(self, a: Self::V, b: Self::V) -> Self::V {
        quarters!(v128; a, b, |a, b| i64x2_sub(a, b))
    }

    #[inline(always)]
    fn and(self, a: Self::V, b: Self::V) -> Self::V {
        quarters!(v128; a, b, |a, b| v128_and(a, b))
    }

    #[inline(always)]
    fn or(self, a: Self::V, b: Self::V) -> Self::V {
        quarters!(v128; a, b, |a, b| v128_or(a, b))
    }

    #[inline(always)]
    fn xor(self, a: Self::V, b: Self::V) -> Self::V {
        quarters!(v128; a, b, |a, b| v128_xor(a, b))
    }

    #[inline(always)]
    fn sign(self, a: Self::V) -> Self::V {
        quarters!(v128; a, a, |a, _b| i64x2_shr(a, 63))
    }

    #[inline(always)]
    fn max(self, a: Self::V, b: Self::V) -> Self::V {
        quarters!(v128; a, b, |a, b| v128_bitselect(a, b, i64x2_gt(a, b)))
    }

    #[inline(always)]
    fn min(self, a: Self::V, b: Self::V) -> Self::V {
        quarters!(v128; a, b, |a, b| v128_bitselect(b, a, i64x2_gt(a, b)))
    }

    /// −a where a is negative (wrapping: i64::MIN stays itself).
    #[inline(always)]
    fn abs(self, a: Self::V) -> Self::V {
        let negative = self.sign(a);
        self.sub(self.xor(a, negative), negative)
    }

    /// The low halves sign-extended, then one 64-bit multiply.
    #[inline(always)]
    fn mul_low_halves(self, a: Self::V, b: Self::V) -> Self::V {
        quarters!(v128; a, b, |a, b| i64x2_mul(
            i64x2_shr(i64x2_shl(a, 32), 32),
            i64x2_shr(i64x2_shl(b, 32), 32)
        ))
    }

    /// The 64-bit multiply, modulo 2⁶⁴.
    #[inline(always)]
    fn mul_low_by_high(self, a: Self::V, _a_high: Self::V, b_high: Self::V) -> Self::V {
        quarters!(v128; a, b_high, |a, b| i64x2_mul(a, b))
    }

    #[inline(always)]
    fn shift_down_32(self, a: Self::V) -> Self::V {
        quarters!(v128; a, a, |a, _b| i64x2_shr(a, 32))
    }

    #[inline(always)]
    fn greater(self, a: Self::V, b: Self::V) -> u8 {
        self.mask_of(quarters!(v128; a, b, |a, b| i64x2_gt(a, b)))
    }

    #[inline(always)]
    fn at_least_unsigned(self, a: Self::V, b: Self::V) -> u8 {
        !self.greater(self.flip(b), self.flip(a))
    }

    #[inline(always)]
    fn equal(self, a: Self::V, b: Self::V) -> u8 {
        self.mask_of(quarters!(v128; a, b, |a, b| i64x2_eq(a, b)))
    }

    #[inline(always)]
    fn select(self, mask: u8, on: Self::V, off: Self::V) -> Self::V {
        let lanes = self.spread(mask);
        [
            v128_bitselect(on[0], off[0], lanes[0]),
            v128_bitselect(on[1], off[1], lanes[1]),
            v128_bitselect(on[2], off[2], lanes[2]),
            v128_bitselect(on[3], off[3], lanes[3]),
        ]
    }

    /// Zero for counts from 64 up (wasm shifts take the count modulo 64).
    #[inline(always)]
    fn shift_left(self, a: Self::V, n: u32) -> Self::V {
        if n >= 64 {
            return self.zero();
        }
        quarters!(v128; a, a, |a, _b| i64x2_shl(a, n))
    }

    /// Zero for counts from 64 up.
    #[inline(always)]
    fn shift_right_unsigned(self, a: Self::V, n: u32) -> Self::V {
        if n >= 64 {
            return self.zero();
        }
        quarters!(v128; a, a, |a, _b| u64x2_shr(a, n))
    }

    /// The sign's copies for counts from 64 up.
    #[inline(always)]
    fn shift_right(self, a: Self::V, n: u32) -> Self::V {
        let n = n.min(63);
        quarters!(v128; a, a, |a, _b| i64x2_shr(a, n))
    }

    /// Lane by lane.
    #[inline(always)]
    fn shift_left_lanes(self, a: Self::V, n: Self::V) -> Self::V {
        let (a, n) = (self.store_words(a), self.store_words(n));
        let mut out = [0; LANES];
        for ((out, a), n) in out.iter_mut().zip(a).zip(n) {
            *out = u32::try_from(n)
                .ok()
                .and_then(|n| a.checked_shl(n))
                .unwrap_or(0);
        }
        self.load_words(out)
    }

    /// Lane by lane.
    #[inline(always)]
    fn shift_right_unsigned_lanes(self, a: Self::V, n: Self::V) -> Self::V {
        let (a, n) = (self.store_words(a), self.store_words(n));
        let mut out = [0; LANES];
        for ((out, a), n) in out.iter_mut().zip(a).zip(n) {
            *out = u32::try_from(n)
                .ok()
                .and_then(|n| (a as u64).checked_shr(n))
                .unwrap_or(0) as i64;
        }
        self.load_words(out)
    }

    /// The low halves zero-extended, then one 64-bit multiply.
    #[inline(always)]
    fn mul_unsigned_low_halves(self, a: Self::V, b: Self::V) -> Self::V {
        let low = i64x2_splat(0xffff_ffff);
        quarters!(v128; a, b, |a, b| i64x2_mul(v128_and(a, low), v128_and(b, low)))
    }
}
