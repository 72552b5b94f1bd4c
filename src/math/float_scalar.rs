// ok-det: this whole file is the f64 reference format (benchmarks, accuracy); it is never in a replay or a checksum.
//! `f64` as a [`Real`]: the reference format for accuracy and speed comparisons.
//!
//! It follows IEEE 754 (x / 0 is ±∞ or NaN) and is not deterministic across targets for
//! the transcendental functions, which come from the platform's math library. It is never
//! used by a replay or a checksum; it lets the same generic algorithms be measured against
//! the fixed-point formats in one run.

use core::cmp::Ordering;

use super::Fx;
use super::over_real::OverReal;
use super::real::{ParseRealError, Real};

impl Real for f64 {
    const NAME: &'static str = "f64"; // ok-det: f64 reference format
    const ZERO: Self = 0.0;
    const ONE: Self = 1.0;
    const TWO: Self = 2.0;
    const HALF: Self = 0.5;
    const PI: Self = core::f64::consts::PI; // ok-det: f64 reference format
    const FRAC_PI_2: Self = core::f64::consts::FRAC_PI_2; // ok-det: f64 reference format
    const TAU: Self = core::f64::consts::TAU; // ok-det: f64 reference format
    const MAX: Self = f64::MAX; // ok-det: f64 reference format
    const MIN: Self = f64::MIN; // ok-det: f64 reference format
    const EPSILON: Self = f64::EPSILON; // ok-det: f64 reference format

    #[inline(always)]
    fn as_fixed<T: OverReal>(_: &T::Of<Self>) -> Option<&T::Of<Fx>> {
        None
    }

    #[inline(always)]
    fn as_fixed_mut<T: OverReal>(_: &mut T::Of<Self>) -> Option<&mut T::Of<Fx>> {
        None
    }

    #[inline]
    fn from_int(value: i32) -> Self {
        value as f64 // ok-det: f64 reference format
    }

    #[inline]
    fn from_ratio(num: i64, den: i64) -> Self {
        num as f64 / den as f64 // ok-det: f64 reference format
    }

    #[inline]
    fn from_f64(value: f64) -> Self {
        value
    }

    #[inline]
    fn to_f64(self) -> f64 {
        self
    }

    fn parse_decimal(text: &str) -> Result<Self, ParseRealError> {
        let parsed = text.trim().parse::<f64>(); // ok-det: f64 reference format
        parsed.map_err(|e| ParseRealError {
            text: text.to_owned(),
            reason: e.to_string(),
        })
    }

    #[inline]
    fn canonical_bits(self) -> u64 {
        self.to_bits()
    }

    #[inline]
    fn total_cmp(&self, other: &Self) -> Ordering {
        f64::total_cmp(self, other) // ok-det: f64 reference format
    }

    #[inline]
    fn abs(self) -> Self {
        f64::abs(self) // ok-det: f64 reference format
    }

    #[inline]
    fn sqrt(self) -> Self {
        if self <= 0.0 { 0.0 } else { f64::sqrt(self) } // ok-det: f64 reference format
    }

    #[inline]
    fn rsqrt(self) -> Self {
        if self <= 0.0 {
            f64::MAX // ok-det: f64 reference format
        } else {
            1.0 / f64::sqrt(self) // ok-det: f64 reference format
        }
    }

    #[inline]
    fn sin(self) -> Self {
        f64::sin(self) // ok-det: f64 reference format
    }

    #[inline]
    fn cos(self) -> Self {
        f64::cos(self) // ok-det: f64 reference format
    }

    #[inline]
    fn sin_cos(self) -> (Self, Self) {
        f64::sin_cos(self) // ok-det: f64 reference format
    }

    #[inline]
    fn atan2(self, x: Self) -> Self {
        f64::atan2(self, x) // ok-det: f64 reference format
    }

    #[inline]
    fn asin(self) -> Self {
        f64::asin(self.clamp(-1.0, 1.0)) // ok-det: f64 reference format
    }

    #[inline]
    fn acos(self) -> Self {
        f64::acos(self.clamp(-1.0, 1.0)) // ok-det: f64 reference format
    }

    #[inline]
    fn exp(self) -> Self {
        f64::exp(self) // ok-det: f64 reference format
    }

    #[inline]
    fn ln(self) -> Self {
        if self <= 0.0 { f64::MIN } else { f64::ln(self) } // ok-det: f64 reference format
    }

    #[inline]
    fn powf(self, y: Self) -> Self {
        f64::powf(self, y) // ok-det: f64 reference format
    }

    #[inline]
    fn powi(self, n: i32) -> Self {
        f64::powi(self, n) // ok-det: f64 reference format
    }
}
