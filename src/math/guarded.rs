//! Guarded arithmetic: range-check-free forms of the scalar operators, for batch kernels.
//!
//! The checked operators (`+`, `-`, `*` of [`Real`]) test every result against the range
//! and saturate and count on the spot. A batch kernel that wants straight-line code instead
//! computes a block of values with the guarded operators
//! ([`Real::guarded_add`], [`Real::guarded_sub`], [`Real::guarded_mul`]) and one [`Guard`]:
//!
//! * each guarded operator returns exactly the checked operator's result whenever that one
//!   does not saturate, and trips the guard whenever it might saturate (it may also trip in
//!   some cases where it would not: the guard is conservative, never lax);
//! * the kernel looks at the guard once per block. Clear: no operation of the block
//!   saturated, so every value equals the checked operators' value bit for bit. Tripped:
//!   the kernel throws the block's results away and computes the block again with the
//!   checked operators, which saturate and count as they always do.
//!
//! Results are therefore those of the checked operators in every case, and the saturation
//! counter sees every saturation of the checked computation.
//!
//! A [`Fraction`] is a factor c with 0 ≤ c < 1/2 (a step length under half a second, a drag
//! coefficient under 0.5 kg/s, …). `x · c` is never out of range, so
//! [`Real::mul_fraction`] needs neither a check nor a guard.

use super::real::Real;

/// Whether a block of guarded operations stayed clear of the range limits; see the
/// [module documentation](self).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Guard {
    tripped: bool,
}

impl Guard {
    /// A clear guard.
    #[inline(always)]
    pub const fn new() -> Self {
        Self { tripped: false }
    }

    /// True when no guarded operation since [`Guard::new`] could have saturated, so that
    /// every guarded result equals the checked operators' result.
    #[inline(always)]
    pub const fn is_clear(self) -> bool {
        !self.tripped
    }

    /// Trips the guard when `might_saturate` holds: a branch that is never taken in a
    /// block that stays in range.
    #[inline(always)]
    pub fn trip_if(&mut self, might_saturate: bool) {
        if might_saturate {
            self.trip();
        }
    }

    #[cold]
    #[inline(never)]
    fn trip(&mut self) {
        self.tripped = true;
    }
}

/// A factor c with 0 ≤ c < 1/2: its product with any value of the format is in range (and,
/// in fixed point, c·2⁶⁴⁻ᶠ fits in an `i64`, which makes the product one multiply).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Fraction<R: Real>(R);

impl<R: Real> Fraction<R> {
    /// 0.
    pub const ZERO: Self = Self(R::ZERO);

    /// `value` as a fraction, or `None` unless 0 ≤ value < 1/2.
    #[inline]
    pub fn new(value: R) -> Option<Self> {
        (R::ZERO <= value && value < R::HALF).then_some(Self(value))
    }

    /// The factor.
    #[inline(always)]
    pub fn get(self) -> R {
        self.0
    }
}
