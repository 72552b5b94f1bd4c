//! `Fixed<Frac>`: a 64-bit fixed-point scalar with chosen, documented semantics.
//!
//! The value is `bits / 2^F`, where `F = Frac::U32` is the number of fractional bits and
//! `bits` is an `i64` held in a [`fixed::FixedI64`]. The engine default is [`Fx`]
//! (I32F32: F = 32, range ±2.1·10⁹, resolution 2.3·10⁻¹⁰).
//!
//! # Policy (identical in debug and release, on every target)
//!
//! | operation | rounding | out of range |
//! |---|---|---|
//! | `+`, `-`, unary `-` | exact | saturates to `MIN`/`MAX`, counted |
//! | `*` | to nearest, ties toward +∞ | saturates, counted |
//! | `/` | to nearest, ties away from zero | saturates, counted |
//! | `/ 0` | `MAX` for x > 0, `MIN` for x < 0, `0` for x = 0 | counted |
//! | conversions | to nearest | saturates, counted; NaN gives 0 |
//!
//! "Counted" means the thread's [saturation counter](super::saturation) goes up by one. The
//! `fixed` crate's own operators are never used on the simulation path: they panic on
//! overflow in debug, wrap in release, and round `*` toward −∞.

use core::cmp::Ordering;
use core::fmt;
use core::marker::PhantomData;
use core::ops::{Add, AddAssign, Div, DivAssign, Mul, MulAssign, Neg, Sub, SubAssign};

use fixed::FixedI64;
use fixed::types::extra::*;
use serde::de::{self, Deserializer, Visitor};
use serde::{Deserialize, Serialize, Serializer};

use super::guarded::{Fraction, Guard};
use super::over_real::OverReal;
use super::real::{ParseRealError, Real};
use super::saturation::{record_saturation, saturate_i128};
use super::wide_product::wide_product;
use super::{exp, sqrt, trig};

/// The fractional-bit count of a [`Fixed`] type: a `typenum` unsigned from the `fixed`
/// crate (`U16`, `U24`, `U32`, …, up to `U64`).
pub trait FracBits: LeEqU64 + Send + Sync + 'static {
    /// [`Real::as_fixed`] for [`Fixed<Self>`]: the identity for `U32` (I32F32), `None`
    /// otherwise.
    fn as_fixed<T: OverReal>(x: &T::Of<Fixed<Self>>) -> Option<&T::Of<Fx>>;

    /// [`Real::as_fixed_mut`] for [`Fixed<Self>`].
    fn as_fixed_mut<T: OverReal>(x: &mut T::Of<Fixed<Self>>) -> Option<&mut T::Of<Fx>>;
}

impl FracBits for U32 {
    #[inline(always)]
    fn as_fixed<T: OverReal>(x: &T::Of<Fx>) -> Option<&T::Of<Fx>> {
        Some(x)
    }

    #[inline(always)]
    fn as_fixed_mut<T: OverReal>(x: &mut T::Of<Fx>) -> Option<&mut T::Of<Fx>> {
        Some(x)
    }
}

/// The formats with no vector kernels.
macro_rules! without_kernels {
    ($($frac:ty),*) => {$(
        impl FracBits for $frac {
            #[inline(always)]
            fn as_fixed<T: OverReal>(_: &T::Of<Fixed<Self>>) -> Option<&T::Of<Fx>> {
                None
            }

            #[inline(always)]
            fn as_fixed_mut<T: OverReal>(_: &mut T::Of<Fixed<Self>>) -> Option<&mut T::Of<Fx>> {
                None
            }
        }
    )*};
}
without_kernels!(
    U0, U1, U2, U3, U4, U5, U6, U7, U8, U9, U10, U11, U12, U13, U14, U15, U16, U17, U18, U19, U20,
    U21, U22, U23, U24, U25, U26, U27, U28, U29, U30, U31, U33, U34, U35, U36, U37, U38, U39, U40,
    U41, U42, U43, U44, U45, U46, U47, U48, U49, U50, U51, U52, U53, U54, U55, U56, U57, U58, U59,
    U60, U61, U62, U63, U64
);

/// A fixed-point number with `Frac::U32` fractional bits in an `i64`. See the module
/// documentation for the arithmetic policy.
#[repr(transparent)]
pub struct Fixed<Frac: FracBits>(FixedI64<Frac>);

/// The engine's default scalar: I32F32.
pub type Fx = Fixed<U32>;
/// I32F32 by its format name; the same type as [`Fx`].
pub type FxI32F32 = Fixed<U32>;
/// I48F16: a larger range (±1.4·10¹⁴) and a coarser resolution (1.5·10⁻⁵).
pub type FxI48F16 = Fixed<U16>;
/// I40F24: range ±5.5·10¹¹, resolution 6·10⁻⁸.
pub type FxI40F24 = Fixed<U24>;

/// π·2⁶¹, correctly rounded: the source of π for every fractional width.
const PI_Q61: i64 = 7_244_019_458_077_122_842;

/// Product of two raw values with `frac` fractional bits: `(a·b + 2^(frac−1)) >> frac`,
/// i.e. rounded to nearest with ties toward +∞, saturated and counted.
#[inline(always)]
pub(crate) fn mul_bits(a: i64, b: i64, frac: u32) -> i64 {
    let product = wide_product(a, b);
    saturate_i128((product + (1i128 << (frac - 1))) >> frac)
}

/// round(a·c / 2⁶⁴), ties toward +∞: the high 64 bits of the 128-bit product a·c plus bit
/// 63 of its low 64 bits (adding 2⁶³ carries into the high half exactly when that bit is
/// set). Never out of range (|a·c/2⁶⁴| ≤ 2⁶²). One multiply, a shift and an add: no 128-bit
/// shift (`shrd`/`shld`, several micro-operations on some x86 cores).
#[inline(always)]
fn round_mul_high(a: i64, c: i64) -> i64 {
    let product = wide_product(a, c);
    (product >> 64) as i64 + (product as u64 >> 63) as i64
}

/// Quotient of two raw values with `frac` fractional bits: `round(a·2^frac / b)`, ties away
/// from zero, saturated and counted. `b = 0` gives `MAX`, `MIN` or `0` by the sign of `a`.
#[inline(always)]
pub(crate) fn div_bits(a: i64, b: i64, frac: u32) -> i64 {
    if b == 0 {
        record_saturation();
        return match a.cmp(&0) {
            Ordering::Greater => i64::MAX,
            Ordering::Less => i64::MIN,
            Ordering::Equal => 0,
        };
    }
    let numerator = (a.unsigned_abs() as u128) << frac;
    let divisor = b.unsigned_abs();
    let magnitude = quotient(numerator + u128::from(divisor >> 1), divisor);
    let negative = (a < 0) != (b < 0);
    if negative {
        if magnitude > 1u128 << 63 {
            record_saturation();
            i64::MIN
        } else {
            (magnitude as i128).wrapping_neg() as i64
        }
    } else if magnitude > i64::MAX as u128 {
        record_saturation();
        i64::MAX
    } else {
        magnitude as i64
    }
}

/// ⌊n / d⌋ for d > 0.
///
/// On x86-64, when the quotient fits in 64 bits (the high half of n below d, as for every
/// quotient that does not saturate), one `div` instruction, which divides the 128-bit
/// rdx:rax by a 64-bit register and leaves exactly ⌊n / d⌋ in rax; the general 128-bit
/// division otherwise, and on other targets. The same integer either way.
#[inline(always)]
fn quotient(n: u128, d: u64) -> u128 {
    #[cfg(target_arch = "x86_64")]
    {
        let high = (n >> 64) as u64;
        if high < d {
            let q: u64;
            // SAFETY: `div` faults only for d = 0 or a quotient of 2⁶⁴ or more; here d > high
            // ≥ 0 and n < d·2⁶⁴. It reads and writes registers only.
            unsafe {
                core::arch::asm!(
                    "div {d}",
                    d = in(reg) d,
                    inout("rax") n as u64 => q,
                    inout("rdx") high => _,
                    options(pure, nomem, nostack),
                );
            }
            return u128::from(q);
        }
    }
    n / u128::from(d)
}

impl<Frac: FracBits> Fixed<Frac> {
    /// Number of fractional bits.
    pub const FRAC_BITS: u32 = {
        assert!(
            Frac::U32 >= 8 && Frac::U32 <= 60,
            "fixstep supports 8 to 60 fractional bits"
        );
        Frac::U32
    };

    /// The value whose raw representation is `bits` (value = bits / 2^F).
    #[inline(always)]
    pub const fn from_bits(bits: i64) -> Self {
        Fixed(FixedI64::from_bits(bits))
    }

    /// The raw representation.
    #[inline(always)]
    pub const fn to_bits(self) -> i64 {
        self.0.to_bits()
    }

    /// The same value as the `fixed` crate's type.
    #[inline(always)]
    pub const fn to_fixed(self) -> FixedI64<Frac> {
        self.0
    }

    /// Wraps a value of the `fixed` crate's type.
    #[inline(always)]
    pub const fn from_fixed(value: FixedI64<Frac>) -> Self {
        Fixed(value)
    }

    /// Converts any number the `fixed` crate can convert (integers, floats, other fixed
    /// types), rounded to nearest and saturated; NaN gives zero. For scene loading.
    pub fn from_num<Src: fixed::traits::ToFixed + Copy>(value: Src) -> Self {
        match value.checked_to_fixed::<FixedI64<Frac>>() {
            Some(v) => Fixed(v),
            None => {
                record_saturation();
                Fixed(value.saturating_to_fixed())
            }
        }
    }

    /// π·2^F rounded to nearest, from the Q61 constant.
    const fn pi_bits(multiple_log2: u32) -> i64 {
        let shift = 61 - Frac::U32 - multiple_log2;
        (PI_Q61 + (1i64 << (shift - 1))) >> shift
    }
}

impl<Frac: FracBits> Clone for Fixed<Frac> {
    #[inline(always)]
    fn clone(&self) -> Self {
        *self
    }
}

impl<Frac: FracBits> Copy for Fixed<Frac> {}

impl<Frac: FracBits> Default for Fixed<Frac> {
    #[inline(always)]
    fn default() -> Self {
        Self::from_bits(0)
    }
}

impl<Frac: FracBits> PartialEq for Fixed<Frac> {
    #[inline(always)]
    fn eq(&self, other: &Self) -> bool {
        self.to_bits() == other.to_bits()
    }
}

impl<Frac: FracBits> Eq for Fixed<Frac> {}

impl<Frac: FracBits> PartialOrd for Fixed<Frac> {
    #[inline(always)]
    fn partial_cmp(&self, other: &Self) -> Option<Ordering> {
        Some(self.cmp(other))
    }
}

impl<Frac: FracBits> Ord for Fixed<Frac> {
    #[inline(always)]
    fn cmp(&self, other: &Self) -> Ordering {
        self.to_bits().cmp(&other.to_bits())
    }
}

impl<Frac: FracBits> fmt::Debug for Fixed<Frac> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        fmt::Display::fmt(&self.0, f)
    }
}

impl<Frac: FracBits> fmt::Display for Fixed<Frac> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        fmt::Display::fmt(&self.0, f)
    }
}

impl<Frac: FracBits> Add for Fixed<Frac> {
    type Output = Self;
    /// Saturating, counted.
    #[inline(always)]
    fn add(self, rhs: Self) -> Self {
        match self.to_bits().checked_add(rhs.to_bits()) {
            Some(bits) => Self::from_bits(bits),
            None => {
                record_saturation();
                Self::from_bits(self.to_bits().saturating_add(rhs.to_bits()))
            }
        }
    }
}

impl<Frac: FracBits> Sub for Fixed<Frac> {
    type Output = Self;
    /// Saturating, counted.
    #[inline(always)]
    fn sub(self, rhs: Self) -> Self {
        match self.to_bits().checked_sub(rhs.to_bits()) {
            Some(bits) => Self::from_bits(bits),
            None => {
                record_saturation();
                Self::from_bits(self.to_bits().saturating_sub(rhs.to_bits()))
            }
        }
    }
}

impl<Frac: FracBits> Neg for Fixed<Frac> {
    type Output = Self;
    /// Saturating: −MIN is MAX, counted.
    #[inline(always)]
    fn neg(self) -> Self {
        match self.to_bits().checked_neg() {
            Some(bits) => Self::from_bits(bits),
            None => {
                record_saturation();
                Self::from_bits(i64::MAX)
            }
        }
    }
}

impl<Frac: FracBits> Mul for Fixed<Frac> {
    type Output = Self;
    /// Rounded to nearest (ties toward +∞), saturating, counted.
    #[inline(always)]
    fn mul(self, rhs: Self) -> Self {
        Self::from_bits(mul_bits(self.to_bits(), rhs.to_bits(), Self::FRAC_BITS))
    }
}

impl<Frac: FracBits> Div for Fixed<Frac> {
    type Output = Self;
    /// Rounded to nearest (ties away from zero), saturating; `x / 0` is `MAX`, `MIN` or 0.
    #[inline(always)]
    fn div(self, rhs: Self) -> Self {
        Self::from_bits(div_bits(self.to_bits(), rhs.to_bits(), Self::FRAC_BITS))
    }
}

macro_rules! assign_op {
    ($Trait:ident, $method:ident, $op:tt) => {
        impl<Frac: FracBits> $Trait for Fixed<Frac> {
            #[inline(always)]
            fn $method(&mut self, rhs: Self) {
                *self = *self $op rhs;
            }
        }
    };
}
assign_op!(AddAssign, add_assign, +);
assign_op!(SubAssign, sub_assign, -);
assign_op!(MulAssign, mul_assign, *);
assign_op!(DivAssign, div_assign, /);

impl<Frac: FracBits> Real for Fixed<Frac> {
    const NAME: &'static str = match Frac::U32 {
        16 => "I48F16",
        24 => "I40F24",
        32 => "I32F32",
        _ => "I64Fx",
    };
    const ZERO: Self = Self::from_bits(0);
    const ONE: Self = Self::from_bits(1 << Self::FRAC_BITS);
    const TWO: Self = Self::from_bits(2 << Self::FRAC_BITS);
    const HALF: Self = Self::from_bits(1 << (Self::FRAC_BITS - 1));
    const PI: Self = Self::from_bits(Self::pi_bits(0));
    const FRAC_PI_2: Self = Self::from_bits(Self::pi_bits(0) >> 1);
    const TAU: Self = Self::from_bits(Self::pi_bits(1));
    const MAX: Self = Self::from_bits(i64::MAX);
    const MIN: Self = Self::from_bits(i64::MIN);
    const EPSILON: Self = Self::from_bits(1);

    #[inline(always)]
    fn as_fixed<T: OverReal>(x: &T::Of<Self>) -> Option<&T::Of<Fx>> {
        Frac::as_fixed::<T>(x)
    }

    #[inline(always)]
    fn as_fixed_mut<T: OverReal>(x: &mut T::Of<Self>) -> Option<&mut T::Of<Fx>> {
        Frac::as_fixed_mut::<T>(x)
    }

    #[inline]
    fn from_int(value: i32) -> Self {
        Self::from_bits(saturate_i128((value as i128) << Self::FRAC_BITS))
    }

    /// Fused: `(self·2^F + a·b + 2^(F−1)) >> F` in 128 bits, saturated and counted once.
    /// Since self·2^F is a multiple of 2^F, this equals `self + a * b` (the product rounded
    /// to nearest, ties toward +∞, then added) bit for bit whenever neither of those two
    /// operations saturates; when the product alone leaves the range, the fused result is
    /// the exact sum, saturated, rather than the sum of a saturated product.
    #[inline(always)]
    fn add_product(self, a: Self, b: Self) -> Self {
        let product = wide_product(a.to_bits(), b.to_bits());
        let sum = ((self.to_bits() as i128) << Self::FRAC_BITS) + product;
        Self::from_bits(saturate_i128(
            (sum + (1i128 << (Self::FRAC_BITS - 1))) >> Self::FRAC_BITS,
        ))
    }

    /// The three exact 128-bit products summed, then rounded once to nearest (ties toward
    /// +∞) and saturated and counted once. Exact unless two products are both near 2¹²⁶,
    /// which needs operands near the ends of the range; the 128-bit sum then saturates too.
    #[inline(always)]
    fn dot3(a: [Self; 3], b: [Self; 3]) -> Self {
        let product = |i: usize| wide_product(a[i].to_bits(), b[i].to_bits());
        let sum = product(0)
            .saturating_add(product(1))
            .saturating_add(product(2));
        Self::from_bits(saturate_i128(
            sum.saturating_add(1i128 << (Self::FRAC_BITS - 1)) >> Self::FRAC_BITS,
        ))
    }

    /// `(a·c + 2^(F−1)) >> F` without a range check or a 128-bit shift. A [`Fraction`] has
    /// 0 ≤ c < 2^(F−1) as bits, so c' = c·2^(64−F) < 2⁶³ is an `i64`, and
    /// round(a·c'/2⁶⁴) = round(a·c/2^F) (`round_mul_high`) is the checked `a * c`, which
    /// never saturates since |a·c/2^F| < |a|/2.
    #[inline(always)]
    fn mul_fraction(self, c: Fraction<Self>) -> Self {
        Self::from_bits(round_mul_high(
            self.to_bits(),
            c.get().to_bits() << (64 - Self::FRAC_BITS),
        ))
    }

    /// round(x / 2ˢʰⁱᶠᵗ), ties toward +∞: the raw bits shifted, which is exactly the checked
    /// `x * 2⁻ˢʰⁱᶠᵗ` whenever the format holds that factor (F ≥ shift), and the one correct
    /// rounding when it does not. Never out of range.
    #[inline(always)]
    fn mul_pow2_recip(self, shift: u32) -> Self {
        let bits = self.to_bits() as i128;
        Self::from_bits(((bits + (1i128 << (shift - 1))) >> shift) as i64)
    }

    /// The wrapped sum; the guard trips exactly when the checked `+` would saturate.
    #[inline(always)]
    fn guarded_add(self, rhs: Self, guard: &mut Guard) -> Self {
        let (sum, overflow) = self.to_bits().overflowing_add(rhs.to_bits());
        guard.trip_if(overflow);
        Self::from_bits(sum)
    }

    /// The wrapped difference; the guard trips exactly when the checked `-` would saturate.
    #[inline(always)]
    fn guarded_sub(self, rhs: Self, guard: &mut Guard) -> Self {
        let (difference, overflow) = self.to_bits().overflowing_sub(rhs.to_bits());
        guard.trip_if(overflow);
        Self::from_bits(difference)
    }

    /// The rounded product `(a·b + 2^(F−1)) >> F`; the guard trips whenever the checked `*`
    /// would saturate.
    ///
    /// For F = 32, without a 128-bit shift: b = b_h·2³² + b_l with b_l the low half read as
    /// a signed number (−2³¹ ≤ b_l < 2³¹) and b_h = (b − b_l)/2³². Since a·b_h·2³² is a
    /// multiple of 2³², round(a·b/2³²) = a·b_h + round(a·b_l/2³²) exactly; the second term
    /// is `round_mul_high` of a and b_l·2³² (an `i64`), always in range. The guard trips
    /// when a·b_h or the sum overflows, so a clear guard means the sum is the exact rounded
    /// product, which then lies in range: the checked `*`'s result. (It may trip although
    /// the product fits, when a·b_h alone does not.) For other F, in 128 bits, tripping
    /// exactly when `*` saturates.
    #[inline(always)]
    fn guarded_mul(self, rhs: Self, guard: &mut Guard) -> Self {
        let (a, b) = (self.to_bits(), rhs.to_bits());
        if Self::FRAC_BITS == 32 {
            let low = b as i32 as i64;
            let high = (b >> 32) - (low >> 63);
            let (high_product, high_overflow) = a.overflowing_mul(high);
            let (sum, sum_overflow) = high_product.overflowing_add(round_mul_high(a, low << 32));
            guard.trip_if(high_overflow | sum_overflow);
            Self::from_bits(sum)
        } else {
            let product = wide_product(a, b);
            let rounded = (product + (1i128 << (Self::FRAC_BITS - 1))) >> Self::FRAC_BITS;
            let narrow = rounded as i64;
            guard.trip_if(narrow as i128 != rounded);
            Self::from_bits(narrow)
        }
    }

    #[inline]
    fn from_ratio(num: i64, den: i64) -> Self {
        Self::from_bits(div_bits(num, den, Self::FRAC_BITS))
    }

    fn from_f64(value: f64) -> Self {
        if value.is_nan() {
            record_saturation();
            return Self::ZERO;
        }
        Self::from_num(value)
    }

    #[inline]
    fn to_f64(self) -> f64 {
        self.0.to_num::<f64>() // ok-det: reporting conversion
    }

    fn parse_decimal(text: &str) -> Result<Self, ParseRealError> {
        text.trim()
            .parse::<FixedI64<Frac>>()
            .map(Fixed)
            .map_err(|e| ParseRealError {
                text: text.to_owned(),
                reason: e.to_string(),
            })
    }

    #[inline(always)]
    fn canonical_bits(self) -> u64 {
        self.to_bits() as u64
    }

    #[inline(always)]
    fn total_cmp(&self, other: &Self) -> Ordering {
        self.cmp(other)
    }

    #[inline(always)]
    fn abs(self) -> Self {
        match self.to_bits().checked_abs() {
            Some(bits) => Self::from_bits(bits),
            None => {
                record_saturation();
                Self::MAX
            }
        }
    }

    #[inline]
    fn sqrt(self) -> Self {
        Self::from_bits(sqrt::sqrt_bits(self.to_bits(), Self::FRAC_BITS))
    }

    #[inline]
    fn rsqrt(self) -> Self {
        Self::from_bits(sqrt::rsqrt_bits(self.to_bits(), Self::FRAC_BITS))
    }

    #[inline]
    fn sin(self) -> Self {
        Self::from_bits(trig::sin_bits(self.to_bits(), Self::FRAC_BITS))
    }

    #[inline]
    fn cos(self) -> Self {
        Self::from_bits(trig::cos_bits(self.to_bits(), Self::FRAC_BITS))
    }

    #[inline]
    fn sin_cos(self) -> (Self, Self) {
        let (s, c) = trig::sin_cos_bits(self.to_bits(), Self::FRAC_BITS);
        (Self::from_bits(s), Self::from_bits(c))
    }

    #[inline]
    fn atan2(self, x: Self) -> Self {
        Self::from_bits(trig::atan2_bits(
            self.to_bits(),
            x.to_bits(),
            Self::FRAC_BITS,
        ))
    }

    #[inline]
    fn asin(self) -> Self {
        Self::from_bits(trig::asin_bits(self.to_bits(), Self::FRAC_BITS))
    }

    #[inline]
    fn acos(self) -> Self {
        Self::from_bits(trig::acos_bits(self.to_bits(), Self::FRAC_BITS))
    }

    #[inline]
    fn exp(self) -> Self {
        Self::from_bits(exp::exp_bits(self.to_bits(), Self::FRAC_BITS))
    }

    #[inline]
    fn ln(self) -> Self {
        Self::from_bits(exp::ln_bits(self.to_bits(), Self::FRAC_BITS))
    }

    #[inline]
    fn powf(self, y: Self) -> Self {
        Self::from_bits(exp::powf_bits(self.to_bits(), y.to_bits(), Self::FRAC_BITS))
    }
}

impl<Frac: FracBits> Serialize for Fixed<Frac> {
    /// Binary formats: the raw `i64` bits (bincode writes them as 8 little-endian bytes).
    /// Human-readable formats: a plain number when it converts back to exactly these bits,
    /// otherwise the shortest exact decimal string.
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        if serializer.is_human_readable() {
            let text = self.0.to_string();
            let shortest = text.parse::<f64>(); // ok-det: human-readable serde only
            match shortest {
                Ok(v) if fixed::traits::ToFixed::checked_to_fixed(v) == Some(self.0) => {
                    serializer.serialize_f64(v)
                }
                _ => serializer.serialize_str(&text),
            }
        } else {
            serializer.serialize_i64(self.to_bits())
        }
    }
}

impl<'de, Frac: FracBits> Deserialize<'de> for Fixed<Frac> {
    /// Binary formats: the raw `i64` bits. Human-readable formats: a number (integer or
    /// float) or a decimal string, rounded to nearest; out-of-range values are an error.
    fn deserialize<D: Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        if deserializer.is_human_readable() {
            deserializer.deserialize_any(HumanVisitor(PhantomData))
        } else {
            i64::deserialize(deserializer).map(Self::from_bits)
        }
    }
}

struct HumanVisitor<Frac>(PhantomData<Frac>);

impl<Frac: FracBits> Visitor<'_> for HumanVisitor<Frac> {
    type Value = Fixed<Frac>;

    fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "a number in the range of {}",
            <Fixed<Frac> as Real>::NAME
        )
    }

    fn visit_i64<E: de::Error>(self, v: i64) -> Result<Self::Value, E> {
        v.checked_to_fixed_or(self)
    }

    fn visit_u64<E: de::Error>(self, v: u64) -> Result<Self::Value, E> {
        v.checked_to_fixed_or(self)
    }

    fn visit_f64<E: de::Error>(self, v: f64) -> Result<Self::Value, E> // ok-det: scene loading
    {
        if !v.is_finite() {
            return Err(E::custom(format_args!("{v} is not a finite number")));
        }
        v.checked_to_fixed_or(self)
    }

    fn visit_str<E: de::Error>(self, v: &str) -> Result<Self::Value, E> {
        Fixed::<Frac>::parse_decimal(v).map_err(E::custom)
    }
}

/// Range-checked conversion for the human-readable visitor.
trait CheckedToFixedOr: fixed::traits::ToFixed + fmt::Display + Copy {
    fn checked_to_fixed_or<Frac: FracBits, E: de::Error>(
        self,
        visitor: HumanVisitor<Frac>,
    ) -> Result<Fixed<Frac>, E> {
        self.checked_to_fixed::<FixedI64<Frac>>()
            .map(Fixed)
            .ok_or_else(|| E::invalid_value(de::Unexpected::Other(&self.to_string()), &visitor))
    }
}

impl<T: fixed::traits::ToFixed + fmt::Display + Copy> CheckedToFixedOr for T {}
