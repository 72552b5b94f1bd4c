//! `Vec3`: a 3-vector of [`Real`] scalars.

use core::ops::{Add, AddAssign, Div, DivAssign, Index, Mul, MulAssign, Neg, Sub, SubAssign};

use serde::{Deserialize, Serialize};

use super::fixed_scalar::Fx;
use super::real::Real;

/// A 3-vector. Arithmetic follows the scalar's policy (saturating for fixed point).
///
/// `repr(C)`: x, y, z in this order with no padding, so a slice of `Vec3<Fx>` is a run of
/// `i64` that SIMD kernels can load as it is.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(bound = "")]
pub struct Vec3<R: Real = Fx> {
    /// x component.
    pub x: R,
    /// y component.
    pub y: R,
    /// z component.
    pub z: R,
}

impl<R: Real> Vec3<R> {
    /// (0, 0, 0).
    pub const ZERO: Self = Self::new(R::ZERO, R::ZERO, R::ZERO);
    /// (1, 0, 0).
    pub const X: Self = Self::new(R::ONE, R::ZERO, R::ZERO);
    /// (0, 1, 0).
    pub const Y: Self = Self::new(R::ZERO, R::ONE, R::ZERO);
    /// (0, 0, 1).
    pub const Z: Self = Self::new(R::ZERO, R::ZERO, R::ONE);

    /// The vector (x, y, z).
    #[inline(always)]
    pub const fn new(x: R, y: R, z: R) -> Self {
        Self { x, y, z }
    }

    /// (v, v, v).
    #[inline(always)]
    pub const fn splat(v: R) -> Self {
        Self::new(v, v, v)
    }

    /// From `f64` components, for scene loading and tests only.
    pub fn from_f64(x: f64, y: f64, z: f64) -> Self {
        Self::new(R::from_f64(x), R::from_f64(y), R::from_f64(z))
    }

    /// The components as `f64`, for reporting.
    pub fn to_f64(self) -> [f64; 3] {
        [self.x.to_f64(), self.y.to_f64(), self.z.to_f64()]
    }

    /// a·b = aₓbₓ + a_yb_y + a_zb_z.
    #[inline(always)]
    pub fn dot(self, other: Self) -> R {
        self.x * other.x + self.y * other.y + self.z * other.z
    }

    /// a·b with the products summed exactly and rounded once ([`Real::dot3`]): for the
    /// rigid-body solver, whose results need not match [`Vec3::dot`] bit for bit.
    #[inline(always)]
    pub fn dot_fused(self, other: Self) -> R {
        R::dot3(self.to_array(), other.to_array())
    }

    /// a × b.
    #[inline(always)]
    pub fn cross(self, other: Self) -> Self {
        Self::new(
            self.y * other.z - self.z * other.y,
            self.z * other.x - self.x * other.z,
            self.x * other.y - self.y * other.x,
        )
    }

    /// |v|².
    #[inline(always)]
    pub fn length_squared(self) -> R {
        self.dot(self)
    }

    /// |v|.
    #[inline]
    pub fn length(self) -> R {
        self.length_squared().sqrt()
    }

    /// |a − b|.
    #[inline]
    pub fn distance(self, other: Self) -> R {
        (self - other).length()
    }

    /// Component-wise product.
    #[inline(always)]
    pub fn mul_elem(self, other: Self) -> Self {
        Self::new(self.x * other.x, self.y * other.y, self.z * other.z)
    }

    /// Component-wise minimum.
    #[inline]
    pub fn min_elem(self, other: Self) -> Self {
        Self::new(
            self.x.min(other.x),
            self.y.min(other.y),
            self.z.min(other.z),
        )
    }

    /// Component-wise maximum.
    #[inline]
    pub fn max_elem(self, other: Self) -> Self {
        Self::new(
            self.x.max(other.x),
            self.y.max(other.y),
            self.z.max(other.z),
        )
    }

    /// Component-wise |v|.
    #[inline]
    pub fn abs(self) -> Self {
        Self::new(self.x.abs(), self.y.abs(), self.z.abs())
    }

    /// The largest component.
    #[inline]
    pub fn max_component(self) -> R {
        self.x.max(self.y).max(self.z)
    }

    /// `self + t·(other − self)`.
    #[inline]
    pub fn lerp(self, other: Self, t: R) -> Self {
        self + (other - self) * t
    }

    /// `self + v·s`: the fused update used by integrators (x += v·dt), per component with
    /// [`Real::add_product`].
    #[inline(always)]
    pub fn add_scaled(self, v: Self, s: R) -> Self {
        Self::new(
            self.x.add_product(v.x, s),
            self.y.add_product(v.y, s),
            self.z.add_product(v.z, s),
        )
    }

    /// The unit vector along `self` and the length, or `None` for the zero vector.
    ///
    /// v̂ = v / |v|, computed with one reciprocal and three multiplies.
    #[inline]
    pub fn try_normalize(self) -> Option<(Self, R)> {
        let length = self.length();
        if length == R::ZERO {
            return None;
        }
        Some((self * length.recip(), length))
    }

    /// The unit vector along `self`, or zero for the zero vector.
    #[inline]
    pub fn normalize_or_zero(self) -> Self {
        self.try_normalize().map_or(Self::ZERO, |(n, _)| n)
    }

    /// A unit vector perpendicular to `self` (which must be unit length): the
    /// [`any_orthogonal`](Self::any_orthogonal) vector normalised.
    pub fn any_orthonormal(self) -> Self {
        self.any_orthogonal().normalize_or_zero()
    }

    /// A vector perpendicular to `self`, not normalised: v × h for the axis h = x̂ when
    /// |v_x| < 0.577 (as a unit v's x component is for some axis) and h = ŷ otherwise, so
    /// that for a unit v, |v × h| ≥ 0.577.
    pub fn any_orthogonal(self) -> Self {
        let helper = if self.x.abs() < R::from_ratio(577, 1000) {
            Self::X
        } else {
            Self::Y
        };
        self.cross(helper)
    }

    /// The components as an array.
    #[inline(always)]
    pub fn to_array(self) -> [R; 3] {
        [self.x, self.y, self.z]
    }
}

impl<R: Real> Index<usize> for Vec3<R> {
    type Output = R;
    #[inline(always)]
    fn index(&self, i: usize) -> &R {
        match i {
            0 => &self.x,
            1 => &self.y,
            2 => &self.z,
            _ => panic!("Vec3 index {i} out of range 0..3"),
        }
    }
}

impl<R: Real> Add for Vec3<R> {
    type Output = Self;
    #[inline(always)]
    fn add(self, rhs: Self) -> Self {
        Self::new(self.x + rhs.x, self.y + rhs.y, self.z + rhs.z)
    }
}

impl<R: Real> Sub for Vec3<R> {
    type Output = Self;
    #[inline(always)]
    fn sub(self, rhs: Self) -> Self {
        Self::new(self.x - rhs.x, self.y - rhs.y, self.z - rhs.z)
    }
}

impl<R: Real> Neg for Vec3<R> {
    type Output = Self;
    #[inline(always)]
    fn neg(self) -> Self {
        Self::new(-self.x, -self.y, -self.z)
    }
}

impl<R: Real> Mul<R> for Vec3<R> {
    type Output = Self;
    #[inline(always)]
    fn mul(self, s: R) -> Self {
        Self::new(self.x * s, self.y * s, self.z * s)
    }
}

impl<R: Real> Div<R> for Vec3<R> {
    type Output = Self;
    /// Divides by `s` through one reciprocal (one division, three multiplies).
    #[inline]
    #[allow(clippy::suspicious_arithmetic_impl)] // v / s = v · (1/s), on purpose
    fn div(self, s: R) -> Self {
        self * s.recip()
    }
}

impl<R: Real> AddAssign for Vec3<R> {
    #[inline(always)]
    fn add_assign(&mut self, rhs: Self) {
        *self = *self + rhs;
    }
}

impl<R: Real> SubAssign for Vec3<R> {
    #[inline(always)]
    fn sub_assign(&mut self, rhs: Self) {
        *self = *self - rhs;
    }
}

impl<R: Real> MulAssign<R> for Vec3<R> {
    #[inline(always)]
    fn mul_assign(&mut self, s: R) {
        *self = *self * s;
    }
}

impl<R: Real> DivAssign<R> for Vec3<R> {
    #[inline]
    fn div_assign(&mut self, s: R) {
        *self = *self / s;
    }
}
