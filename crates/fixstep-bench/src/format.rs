// ok-det: benchmark code; it names the number formats, including the f64 reference, and never runs inside a tick.
//! The number formats a benchmark runs the same generic code in.

use fixstep::math::{Fx, FxI40F24, FxI48F16, Real};

/// A scalar type implementing [`Real`], chosen at run time.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum NumberFormat {
    /// IEEE binary64: the reference (its rounding is negligible next to the fixed formats').
    F64,
    /// I32F32 ([`Fx`]), the engine's format: ulp 2⁻³² ≈ 2.3·10⁻¹⁰.
    I32F32,
    /// I40F24 ([`FxI40F24`]): ulp 2⁻²⁴ ≈ 6.0·10⁻⁸.
    I40F24,
    /// I48F16 ([`FxI48F16`]): ulp 2⁻¹⁶ ≈ 1.5·10⁻⁵.
    I48F16,
}

impl NumberFormat {
    /// Every format, the f64 reference first.
    pub const ALL: [Self; 4] = [Self::F64, Self::I32F32, Self::I40F24, Self::I48F16];

    /// The format's name, as [`Real::NAME`] spells it (`"f64"`, `"I32F32"`, …).
    pub fn name(self) -> &'static str {
        match self {
            Self::F64 => <f64 as Real>::NAME,
            Self::I32F32 => <Fx as Real>::NAME,
            Self::I40F24 => <FxI40F24 as Real>::NAME,
            Self::I48F16 => <FxI48F16 as Real>::NAME,
        }
    }

    /// The smallest positive step of the format near 1 (its ulp for fixed point,
    /// machine epsilon for f64).
    pub fn epsilon(self) -> f64 {
        match self {
            Self::F64 => <f64 as Real>::EPSILON,
            Self::I32F32 => <Fx as Real>::EPSILON.to_f64(),
            Self::I40F24 => <FxI40F24 as Real>::EPSILON.to_f64(),
            Self::I48F16 => <FxI48F16 as Real>::EPSILON.to_f64(),
        }
    }
}
