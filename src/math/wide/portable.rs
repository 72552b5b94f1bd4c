//! Eight `i64` lanes in plain Rust, an array, for the kernels that also run where no
//! backend does (the `scalar` cap, or a processor without one): every operation is the
//! lane-by-lane integer operation the [`Wide`] contract states, which the compiler is free
//! to vectorise with the target's baseline instructions. It is not a [`Backend`](super::Backend)
//! ([`backend`](super::backend) never returns it): a kernel opts in by running itself on
//! `Portable` when there is none.

use super::{LANES, Wide};

/// The portable lanes: any processor runs them.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Portable;

/// `f` of each lane of one or two arrays. A macro, not a closure, as in the backends.
macro_rules! lanes {
    ($a:expr, $b:expr, |$x:ident, $y:ident| $f:expr) => {{
        let (a, b): ([i64; LANES], [i64; LANES]) = ($a, $b);
        let mut out = [0; LANES];
        for l in 0..LANES {
            let ($x, $y) = (a[l], b[l]);
            out[l] = $f;
        }
        out
    }};
}

/// The mask of the lanes where `f` holds.
macro_rules! mask {
    ($a:expr, $b:expr, |$x:ident, $y:ident| $f:expr) => {{
        let (a, b): ([i64; LANES], [i64; LANES]) = ($a, $b);
        let mut mask = 0u8;
        for l in 0..LANES {
            let ($x, $y) = (a[l], b[l]);
            mask |= u8::from($f) << l;
        }
        mask
    }};
}

/// The signed low 32 bits of a word.
#[inline(always)]
fn low_half(x: i64) -> i64 {
    i64::from(x as i32)
}

impl Wide for Portable {
    type V = [i64; LANES];

    #[inline(always)]
    fn zero(self) -> Self::V {
        [0; LANES]
    }

    #[inline(always)]
    fn splat(self, x: i64) -> Self::V {
        [x; LANES]
    }

    #[inline(always)]
    unsafe fn load_at(self, words: *const i64) -> Self::V {
        // SAFETY: the caller's promise: eight readable words (any alignment).
        unsafe { words.cast::<[i64; LANES]>().read_unaligned() }
    }

    #[inline(always)]
    unsafe fn store_at(self, out: *mut i64, x: Self::V) {
        // SAFETY: the caller's promise: eight writable words (any alignment).
        unsafe { out.cast::<[i64; LANES]>().write_unaligned(x) }
    }

    #[inline(always)]
    fn add(self, a: Self::V, b: Self::V) -> Self::V {
        lanes!(a, b, |x, y| x.wrapping_add(y))
    }

    #[inline(always)]
    fn sub(self, a: Self::V, b: Self::V) -> Self::V {
        lanes!(a, b, |x, y| x.wrapping_sub(y))
    }

    #[inline(always)]
    fn and(self, a: Self::V, b: Self::V) -> Self::V {
        lanes!(a, b, |x, y| x & y)
    }

    #[inline(always)]
    fn or(self, a: Self::V, b: Self::V) -> Self::V {
        lanes!(a, b, |x, y| x | y)
    }

    #[inline(always)]
    fn xor(self, a: Self::V, b: Self::V) -> Self::V {
        lanes!(a, b, |x, y| x ^ y)
    }

    #[inline(always)]
    fn sign(self, a: Self::V) -> Self::V {
        lanes!(a, a, |x, _y| x >> 63)
    }

    #[inline(always)]
    fn max(self, a: Self::V, b: Self::V) -> Self::V {
        lanes!(a, b, |x, y| x.max(y))
    }

    #[inline(always)]
    fn min(self, a: Self::V, b: Self::V) -> Self::V {
        lanes!(a, b, |x, y| x.min(y))
    }

    #[inline(always)]
    fn abs(self, a: Self::V) -> Self::V {
        lanes!(a, a, |x, _y| x.wrapping_abs())
    }

    #[inline(always)]
    fn mul_low_halves(self, a: Self::V, b: Self::V) -> Self::V {
        lanes!(a, b, |x, y| low_half(x) * low_half(y))
    }

    /// One 64-bit multiply: a·b_h modulo 2⁶⁴.
    #[inline(always)]
    fn mul_low_by_high(self, a: Self::V, _a_high: Self::V, b_high: Self::V) -> Self::V {
        lanes!(a, b_high, |x, y| x.wrapping_mul(y))
    }

    #[inline(always)]
    fn shift_down_32(self, a: Self::V) -> Self::V {
        lanes!(a, a, |x, _y| x >> 32)
    }

    #[inline(always)]
    fn greater(self, a: Self::V, b: Self::V) -> u8 {
        mask!(a, b, |x, y| x > y)
    }

    #[inline(always)]
    fn at_least_unsigned(self, a: Self::V, b: Self::V) -> u8 {
        mask!(a, b, |x, y| x as u64 >= y as u64)
    }

    #[inline(always)]
    fn equal(self, a: Self::V, b: Self::V) -> u8 {
        mask!(a, b, |x, y| x == y)
    }

    #[inline(always)]
    fn select(self, mask: u8, on: Self::V, off: Self::V) -> Self::V {
        let mut out = off;
        for (l, word) in out.iter_mut().enumerate() {
            if mask & (1 << l) != 0 {
                *word = on[l];
            }
        }
        out
    }

    #[inline(always)]
    fn shift_left(self, a: Self::V, n: u32) -> Self::V {
        lanes!(a, a, |x, _y| x << n)
    }

    #[inline(always)]
    fn shift_right_unsigned(self, a: Self::V, n: u32) -> Self::V {
        lanes!(a, a, |x, _y| ((x as u64) >> n) as i64)
    }

    #[inline(always)]
    fn shift_right(self, a: Self::V, n: u32) -> Self::V {
        lanes!(a, a, |x, _y| x >> n)
    }

    #[inline(always)]
    fn shift_left_lanes(self, a: Self::V, n: Self::V) -> Self::V {
        lanes!(a, n, |x, n| if (n as u64) < 64 { x << n } else { 0 })
    }

    #[inline(always)]
    fn shift_right_unsigned_lanes(self, a: Self::V, n: Self::V) -> Self::V {
        lanes!(a, n, |x, n| if (n as u64) < 64 {
            ((x as u64) >> n) as i64
        } else {
            0
        })
    }

    #[inline(always)]
    fn mul_unsigned_low_halves(self, a: Self::V, b: Self::V) -> Self::V {
        lanes!(a, b, |x, y| (u64::from(x as u32) * u64::from(y as u32))
            as i64)
    }
}
