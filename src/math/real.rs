//! The `Real` trait: the one scalar interface every algorithm in fixstep is written against.
//!
//! The engine simulates with [`Fx`] (I32F32). The same generic code also runs on
//! [`FxI48F16`](super::FxI48F16), [`FxI40F24`](super::FxI40F24) and plain `f64`, so that
//! benchmarks can compare number formats in one run. Only the fixed-point types are
//! deterministic across machines; `f64` exists as a reference and is never used by a
//! replay or a checksum.

use core::cmp::Ordering;
use core::fmt::{Debug, Display};
use core::ops::{Add, AddAssign, Div, DivAssign, Mul, MulAssign, Neg, Sub, SubAssign};

use serde::Serialize;
use serde::de::DeserializeOwned;

use super::Fx;
use super::guarded::{Fraction, Guard};
use super::over_real::OverReal;

/// A scalar number format.
///
/// Arithmetic operators follow the format's documented policy. For the fixed-point formats
/// (see [`Fixed`](super::Fixed)) every operator saturates and counts the event in the
/// [saturation counter](super::saturation), multiplication rounds to nearest, and division
/// by zero returns a defined value. The behaviour is identical in debug and release.
pub trait Real:
    Copy
    + Default
    + PartialEq
    + PartialOrd
    + Debug
    + Display
    + Send
    + Sync
    + 'static
    + Add<Output = Self>
    + Sub<Output = Self>
    + Mul<Output = Self>
    + Div<Output = Self>
    + Neg<Output = Self>
    + AddAssign
    + SubAssign
    + MulAssign
    + DivAssign
    + Serialize
    + DeserializeOwned
{
    /// Short name of the format, as written in replay headers and reports: `"I32F32"`, `"f64"`.
    const NAME: &'static str;
    /// 0.
    const ZERO: Self;
    /// 1.
    const ONE: Self;
    /// 2.
    const TWO: Self;
    /// 1/2.
    const HALF: Self;
    /// π, correctly rounded to the format.
    const PI: Self;
    /// π/2, correctly rounded to the format.
    const FRAC_PI_2: Self;
    /// 2π, correctly rounded to the format.
    const TAU: Self;
    /// The largest representable value.
    const MAX: Self;
    /// The most negative representable value.
    const MIN: Self;
    /// The smallest positive value (one ulp for fixed point).
    const EPSILON: Self;

    /// `x` as the I32F32 member of its family ([`OverReal`]) when this format is I32F32
    /// ([`Fx`]), `None` for every other: how a subsystem reaches the vector kernels, which
    /// compute on I32F32 bits, decided at compile time (the other formats compile only the
    /// plain path). See [`over_real`](super::over_real).
    fn as_fixed<T: OverReal>(x: &T::Of<Self>) -> Option<&T::Of<Fx>>;

    /// [`as_fixed`](Self::as_fixed) for a mutable member.
    fn as_fixed_mut<T: OverReal>(x: &mut T::Of<Self>) -> Option<&mut T::Of<Fx>>;

    /// Exact conversion of a small integer.
    fn from_int(value: i32) -> Self;

    /// `num / den`, rounded to nearest. `den == 0` gives the division-by-zero value of the
    /// format. Use this for constants in generic code: it is exact and deterministic.
    fn from_ratio(num: i64, den: i64) -> Self;

    /// Conversion from `f64`, rounded to nearest and saturated; NaN gives zero.
    ///
    /// For scene loading and reference solutions only, never inside a tick.
    fn from_f64(value: f64) -> Self;

    /// Conversion to `f64` for reporting. Never feed the result back into the simulation.
    fn to_f64(self) -> f64;

    /// Parses a decimal number such as `"-9.81"`, correctly rounded to the format.
    fn parse_decimal(text: &str) -> Result<Self, ParseRealError>;

    /// The canonical 64 bits of the value: the raw fixed-point bits, or the IEEE bits for
    /// `f64`. Checksums hash these as little-endian bytes.
    fn canonical_bits(self) -> u64;

    /// A total order (for fixed point, the integer order of the bits).
    fn total_cmp(&self, other: &Self) -> Ordering;

    /// |x|, saturating (`|MIN|` is `MAX`).
    fn abs(self) -> Self;

    /// The smaller of two values.
    #[inline]
    fn min(self, other: Self) -> Self {
        if other < self { other } else { self }
    }

    /// The larger of two values.
    #[inline]
    fn max(self, other: Self) -> Self {
        if other > self { other } else { self }
    }

    /// `self` limited to `[lo, hi]`.
    #[inline]
    fn clamp(self, lo: Self, hi: Self) -> Self {
        self.max(lo).min(hi)
    }

    /// −1, 0 or 1.
    #[inline]
    fn signum(self) -> Self {
        if self > Self::ZERO {
            Self::ONE
        } else if self < Self::ZERO {
            -Self::ONE
        } else {
            Self::ZERO
        }
    }

    /// `self + a·b`, the update of every integrator (x + v·h). The default is exactly
    /// `self + a * b`; a format may fuse the two, provided the result is the same whenever
    /// neither operation leaves the range.
    #[inline(always)]
    fn add_product(self, a: Self, b: Self) -> Self {
        self + a * b
    }

    /// a₀b₀ + a₁b₁ + a₂b₂ for the rigid-body solver. The default is exactly the operator
    /// expression `a[0] * b[0] + a[1] * b[1] + a[2] * b[2]`; a format may sum the exact
    /// products and round once, which is faster and more accurate but not bit-identical to
    /// the operators (the fixed-point formats do).
    #[inline(always)]
    fn dot3(a: [Self; 3], b: [Self; 3]) -> Self {
        a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
    }

    /// `self * c` for a [`Fraction`] c (0 ≤ c < 1/2), which is never out of range. The
    /// default is exactly `self * c`; a format may skip the range check.
    #[inline(always)]
    fn mul_fraction(self, c: Fraction<Self>) -> Self {
        self * c.get()
    }

    /// `self + rhs` for batch kernels: the checked sum whenever that does not saturate,
    /// with `guard` tripped whenever it might (see [`guarded`](super::guarded)). The default
    /// is the checked `+` itself, which needs no guard; a format overrides it with a cheaper
    /// form that does not count.
    #[inline(always)]
    fn guarded_add(self, rhs: Self, guard: &mut Guard) -> Self {
        let _ = guard;
        self + rhs
    }

    /// `self - rhs` for batch kernels; see [`Real::guarded_add`].
    #[inline(always)]
    fn guarded_sub(self, rhs: Self, guard: &mut Guard) -> Self {
        let _ = guard;
        self - rhs
    }

    /// `self * rhs` for batch kernels; see [`Real::guarded_add`].
    #[inline(always)]
    fn guarded_mul(self, rhs: Self, guard: &mut Guard) -> Self {
        let _ = guard;
        self * rhs
    }

    /// x·2⁻ˢʰⁱᶠᵗ (0 < shift < 32), rounded once as `*` rounds. The default multiplies by
    /// 2⁻ˢʰⁱᶠᵗ, which is exact whenever the format can hold that power of two; a format
    /// too coarse to hold it (fixed point with fewer than `shift` fractional bits) must
    /// shift instead, or the factor itself would round (2⁻¹⁷ to 2⁻¹⁶ in I48F16).
    #[inline]
    fn mul_pow2_recip(self, shift: u32) -> Self {
        self * Self::from_ratio(1, 1 << shift)
    }

    /// 1/x. Zero gives the division-by-zero value of the format.
    #[inline]
    fn recip(self) -> Self {
        Self::ONE / self
    }

    /// √x. Negative input gives 0.
    fn sqrt(self) -> Self;

    /// 1/√x. Zero or negative input gives [`Real::MAX`].
    fn rsqrt(self) -> Self;

    /// sin x, x in radians.
    fn sin(self) -> Self;

    /// cos x, x in radians.
    fn cos(self) -> Self;

    /// (sin x, cos x), x in radians, from one range reduction.
    fn sin_cos(self) -> (Self, Self);

    /// The angle of the point (x, y) from the +x axis, in (−π, π]. `atan2(0, 0)` is 0.
    fn atan2(self, x: Self) -> Self;

    /// asin x in [−π/2, π/2]. Input is clamped to [−1, 1].
    fn asin(self) -> Self;

    /// acos x in [0, π]. Input is clamped to [−1, 1].
    fn acos(self) -> Self;

    /// eˣ, saturating for large x.
    fn exp(self) -> Self;

    /// ln x. Zero or negative input gives [`Real::MIN`].
    fn ln(self) -> Self;

    /// xʸ for x > 0, as e^(y ln x). `0^y` is 0 for y > 0 and 1 for y = 0.
    fn powf(self, y: Self) -> Self;

    /// xⁿ by repeated squaring, with the format's multiply at each step.
    #[inline]
    fn powi(self, n: i32) -> Self {
        let mut base = if n < 0 { self.recip() } else { self };
        let mut e = n.unsigned_abs();
        let mut acc = Self::ONE;
        while e > 0 {
            if e & 1 == 1 {
                acc *= base;
            }
            e >>= 1;
            if e > 0 {
                base *= base;
            }
        }
        acc
    }
}

/// A decimal string that is not a number of the format.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct ParseRealError {
    /// The text that failed to parse.
    pub text: String,
    /// What is wrong with it.
    pub reason: String,
}

impl Display for ParseRealError {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        write!(f, "`{}` is not a number: {}", self.text, self.reason)
    }
}

impl std::error::Error for ParseRealError {}
