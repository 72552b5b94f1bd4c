//! `Quat`: a rotation in 3D as a unit quaternion of [`Real`] scalars.
//!
//! # Convention
//!
//! Hamilton quaternions, q = w + x·i + y·j + z·k with i² = j² = k² = ijk = −1. `w` is the
//! scalar part and u = (x, y, z) the vector part. A unit quaternion represents the *active*
//! rotation v' = q v q* (v taken as the pure quaternion (0, v)); the rotation by angle θ
//! about the unit axis n is q = (cos θ/2, n sin θ/2), and q and −q are the same rotation.
//! Products compose like matrices: p ⊗ q rotates by q first, then by p.
//!
//! # Accuracy
//!
//! A normalised fixed-point quaternion is unit only to its rounding (|q|² − 1 of a few ulp),
//! and the textbook rotation formula, which assumes |q| = 1, scales every vector by |q|²:
//! for components up to 1000 that changes lengths by up to 4700 ulp (measured, I32F32).
//! [`Quat::rotate`], [`Quat::to_mat3`] and [`Quat::normalize`] therefore divide by the
//! exact |q|², recovered in the generic [`Real`] arithmetic by squaring components
//! pre-scaled by 2⁸ (see `norm_defect`). `rotate` then preserves lengths within 2.9 ulp
//! (measured over 10⁶ random unit quaternions and vectors with components up to 1000).

use core::ops::{Mul, Neg};

use serde::{Deserialize, Serialize};

use super::fixed_scalar::Fx;
use super::mat3::Mat3;
use super::real::Real;
use super::vec3::Vec3;

/// A quaternion w + x·i + y·j + z·k; unit quaternions are rotations (see the module
/// documentation for the convention). Arithmetic follows the scalar's policy.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(bound = "")]
pub struct Quat<R: Real = Fx> {
    /// Scalar part, cos θ/2 for a rotation by θ.
    pub w: R,
    /// i component of the vector part.
    pub x: R,
    /// j component of the vector part.
    pub y: R,
    /// k component of the vector part.
    pub z: R,
}

/// 2⁸. A value of magnitude ≤ 1 multiplied by it (exactly) before it is squared gives a
/// square 2¹⁶ times larger, rounded at the same absolute resolution: 16 more bits.
pub(crate) fn square_prescale<R: Real>() -> R {
    R::from_int(256)
}

/// 2⁻¹⁶ = 1/[`square_prescale`]², which takes such a square back to its true size.
pub(crate) fn square_unscale<R: Real>() -> R {
    R::from_ratio(1, 1 << 16)
}

/// 17: a Newton step on the length multiplies by ½·[`square_unscale`] = 2⁻¹⁷, applied
/// with [`Real::mul_pow2_recip`] so that formats with 16 fractional bits, which cannot hold
/// 2⁻¹⁷, still halve (rounding the factor would double the step).
const HALF_UNSCALE_SHIFT: u32 = 17;

/// 2⁻¹⁰: the largest |ε| = ||q|² − 1| that [`Quat::normalize_near_unit`] takes to unit
/// length in two Newton steps (the first leaves ¾ε² ≤ 2⁻²⁰, within the 2⁻¹⁶ that
/// `norm_defect` needs).
pub(crate) fn near_unit_excess<R: Real>() -> R {
    R::from_ratio(1, 1 << 10)
}

impl<R: Real> Quat<R> {
    /// The identity rotation, 1 + 0i + 0j + 0k.
    pub const IDENTITY: Self = Self::new(R::ONE, R::ZERO, R::ZERO, R::ZERO);

    /// The quaternion w + x·i + y·j + z·k.
    #[inline(always)]
    pub const fn new(w: R, x: R, y: R, z: R) -> Self {
        Self { w, x, y, z }
    }

    /// From `f64` components (w, x, y, z), for scene loading and tests only.
    pub fn from_f64(w: f64, x: f64, y: f64, z: f64) -> Self {
        Self::new(
            R::from_f64(w),
            R::from_f64(x),
            R::from_f64(y),
            R::from_f64(z),
        )
    }

    /// The components [w, x, y, z] as `f64`, for reporting.
    pub fn to_f64(self) -> [f64; 4] {
        [
            self.w.to_f64(),
            self.x.to_f64(),
            self.y.to_f64(),
            self.z.to_f64(),
        ]
    }

    /// The rotation by `angle` radians about the unit vector `axis` (right-handed):
    /// q = (cos ½θ, n̂ sin ½θ), from one `sin_cos`.
    ///
    /// `axis` must be unit length; the result is then unit to the rounding of `sin_cos`.
    pub fn from_axis_angle(axis: Vec3<R>, angle: R) -> Self {
        let (sin, cos) = (angle * R::HALF).sin_cos();
        Self::new(cos, axis.x * sin, axis.y * sin, axis.z * sin)
    }

    /// The vector part u = (x, y, z).
    #[inline(always)]
    pub fn vector(self) -> Vec3<R> {
        Vec3::new(self.x, self.y, self.z)
    }

    /// The conjugate q* = (w, −u). For a unit quaternion this is the inverse rotation.
    #[inline(always)]
    pub fn conjugate(self) -> Self {
        Self::new(self.w, -self.x, -self.y, -self.z)
    }

    /// The inverse q⁻¹ = q* / |q|², or `None` when |q|² = 0.
    ///
    /// For a unit quaternion this equals [`Quat::conjugate`], which is exact and cheaper:
    /// rotation code should use that.
    pub fn inverse(self) -> Option<Self> {
        let norm_squared = self.length_squared();
        if norm_squared <= R::ZERO {
            return None;
        }
        Some(self.conjugate() * norm_squared.recip())
    }

    /// p·q = p_w q_w + p_x q_x + p_y q_y + p_z q_z.
    #[inline(always)]
    pub fn dot(self, other: Self) -> R {
        self.w * other.w + self.x * other.x + self.y * other.y + self.z * other.z
    }

    /// |q|² = w² + x² + y² + z².
    #[inline(always)]
    pub fn length_squared(self) -> R {
        self.dot(self)
    }

    /// (1 − 1/|q|²)·2¹⁶ for a quaternion near unit length: how far the exact |q|², not its
    /// rounded value, is from 1, scaled up so that it keeps its precision.
    ///
    /// With ε = |q|² − 1 this is (ε − ε²)·2¹⁶, and 1 − 1/(1 + ε) = ε − ε² + O(ε³). The
    /// components are scaled by 2⁸ (exactly) before they are squared, so each square
    /// (2⁸qᵢ)² = 2¹⁶qᵢ² is rounded to the format's resolution, which is qᵢ² rounded to
    /// 2⁻¹⁶ of it: ε·2¹⁶ = Σ(2⁸qᵢ)² − 2¹⁶ is correct to about 2⁻¹⁵ ulp (exact for
    /// I48F16). That is what lets [`Quat::rotate`] scale vectors of length ~10³ by 1/|q|²
    /// to a fraction of an ulp.
    ///
    /// Valid for |q|² < 2¹⁵ in I32F32 (beyond, the sum saturates) and accurate for
    /// |ε| ≲ 2⁻¹⁶ (the neglected ε³ term); every quaternion from [`Quat::normalize`],
    /// [`Quat::integrate`] or [`Quat::from_axis_angle`] with a unit axis qualifies. Formats
    /// with fewer than 16 fractional bits get no correction.
    fn norm_defect(self) -> R {
        let k = square_prescale::<R>();
        let (w, x, y, z) = (self.w * k, self.x * k, self.y * k, self.z * k);
        let excess = (w * w + x * x + y * y + z * z) - k * k;
        excess - excess * (excess * square_unscale::<R>())
    }

    /// q / |q|, or `None` when |q|² = 0.
    ///
    /// Two stages:
    ///
    /// 1. q₁ = q / √(|q|²), four correctly rounded divisions. (Not q · rsqrt(|q|²): for
    ///    fixed point that small reciprocal is rounded absolutely, so for a long q its
    ///    relative error, about ε·|q|, would reach 3 % at |q| = 2000 in I48F16.) The
    ///    direction is right to half an ulp per component; the length is off by the
    ///    rounding of |q|², which for a short q can be many ulp.
    /// 2. One Newton step on the length with the exact defect of `norm_defect`:
    ///    q₂ = q₁ (1 − ½(1 − 1/|q₁|²)) = q₁/|q₁| + O(δ²), which leaves each component
    ///    within about an ulp of q/|q| and |q₂|² within a few ulp of 1.
    ///
    /// Any nonzero q works: q/|q| does not depend on q's scale, so a q whose largest
    /// component lies outside [½, 2¹⁴) is first scaled by powers of two into that range
    /// (see `scaled_for_length`), where |q|² neither saturates (at 2³¹ in I32F32) nor is
    /// rounded too coarsely for the Newton step.
    pub fn try_normalize(self) -> Option<Self> {
        let q = self.scaled_for_length()?;
        let norm_squared = q.length_squared();
        if norm_squared <= R::ZERO {
            return None;
        }
        let length = norm_squared.sqrt();
        let estimate = Self::new(q.w / length, q.x / length, q.y / length, q.z / length);
        let defect = estimate.norm_defect();
        let step = |c: R| c - (c * defect).mul_pow2_recip(HALF_UNSCALE_SHIFT);
        Some(Self::new(
            step(estimate.w),
            step(estimate.x),
            step(estimate.y),
            step(estimate.z),
        ))
    }

    /// 2ᵏ·q, with the integer k chosen so that the largest |component| lies in [½, 2¹⁴);
    /// `None` for the zero quaternion. Quaternions already in that range (every rotation,
    /// and every q that integration or a scene gives a world that has not diverged) are
    /// returned unchanged.
    ///
    /// Scaling up (by doubling) is exact. Each scaling down by 2⁻⁸ moves every component by
    /// at most half an ulp and leaves the largest at least 2⁶, so it turns q by at most
    /// 2⁻⁶ ulp (one ulp over a length of 2⁶); I32F32 needs at most three of them: far below
    /// what the normalisation itself rounds. This keeps a world whose angular velocities
    /// have saturated (components of q + ½ω dt ⊗ q near 10⁷, whose |q|² saturates) on unit
    /// orientations.
    fn scaled_for_length(self) -> Option<Self> {
        let large = R::from_int(1 << 14);
        let largest = |q: Self| q.w.abs().max(q.x.abs()).max(q.y.abs()).max(q.z.abs());
        let mut q = self;
        if largest(q) == R::ZERO {
            return None;
        }
        // 64 steps span any 64-bit fixed-point format; floats, which neither saturate nor
        // round absolutely, may stop short.
        for _ in 0..64 {
            let m = largest(q);
            if m >= large {
                let down = |c: R| c.mul_pow2_recip(8);
                q = Self::new(down(q.w), down(q.x), down(q.y), down(q.z));
            } else if m < R::HALF {
                q = q * R::TWO;
            } else {
                break;
            }
        }
        Some(q)
    }

    /// q / |q| (see [`Quat::try_normalize`]); the zero quaternion gives [`Quat::IDENTITY`].
    pub fn normalize(self) -> Self {
        self.try_normalize().unwrap_or(Self::IDENTITY)
    }

    /// The vector v rotated by q: v' = q v q* / |q|², the rotation by the unit quaternion
    /// q/|q|.
    ///
    /// With u the vector part, t = 2 u × v and c = w t + u × t, q v q* = |q|² v + c, so
    /// v' = v + c / |q|². The scalars that multiply vector-sized quantities are the exact
    /// inputs w, u (never a rounded product), and 1/|q|² is applied as
    /// c − c·(1 − 1/|q|²) with the defect from `norm_defect`; the length of v is
    /// then preserved to a few ulp of the format whatever the rounding left in |q|
    /// (measured: within 2.9 ulp, and each component within 2.9 ulp of the exact rotation,
    /// for components up to 1000 in I32F32).
    ///
    /// `self` must be unit to within about 2⁻¹⁶ (see `norm_defect`), and |v| below half the
    /// format's range.
    pub fn rotate(self, v: Vec3<R>) -> Vec3<R> {
        let u = self.vector();
        let t = (u + u).cross(v);
        let c = t * self.w + u.cross(t);
        let scaled_defect = self.norm_defect();
        v + c - (c * scaled_defect) * square_unscale::<R>()
    }

    /// q' = normalize(q + ½·dt·(0, ω) ⊗ q): one explicit Euler step of dq/dt = ½ (0, ω) ⊗ q,
    /// with ω the angular velocity in the **world** frame (rad/s), followed by
    /// renormalisation.
    ///
    /// With a = ½ ω dt, (0, a) ⊗ (w, u) = (−a·u, w a + a × u). For constant ω each step is
    /// exactly a rotation about ω̂ by 2·atan(½|ω| dt) instead of |ω| dt, an angle error of
    /// |ω|³dt³/12 per step.
    ///
    /// For a unit q, |q + (0, a) ⊗ q|² = 1 + |a|²: while that is within 2⁻¹⁰ of 1 (|ω| dt
    /// up to about 0.06 rad, 15 rad/s at 240 Hz) the renormalisation is
    /// [`Quat::normalize_near_unit`], two Newton steps with neither square root nor
    /// division; beyond, [`Quat::normalize`].
    pub fn integrate(self, omega: Vec3<R>, dt: R) -> Self {
        let a = omega * (dt * R::HALF);
        let u = self.vector();
        let du = a * self.w + a.cross(u);
        let q = Self::new(self.w - a.dot(u), u.x + du.x, u.y + du.y, u.z + du.z);
        let excess = q.length_squared() - R::ONE;
        if excess.abs() <= near_unit_excess::<R>() {
            q.normalize_near_unit(excess)
        } else {
            q.normalize()
        }
    }

    /// q/|q| for a quaternion with ε = |q|² − 1 (`excess`, as rounded) within 2⁻¹⁰ of 0,
    /// by two Newton steps on the length:
    ///
    /// 1. q₁ = q (1 − ½ε). Then |q₁|² = (1 + ε)(1 − ½ε)² = 1 − ¾ε² + ¼ε³: within 2⁻²⁰ of 1
    ///    for |ε| ≤ 2⁻¹⁰, plus the rounding of ε and of the products (a few ulp).
    /// 2. The second stage of [`Quat::try_normalize`]: q₂ = q₁ (1 − ½(1 − 1/|q₁|²)) with the
    ///    exact defect of `norm_defect`, accurate for |q₁|² within 2⁻¹⁶ of 1, which leaves
    ///    each component within about an ulp of q/|q| and |q₂|² within a few ulp of 1.
    ///
    /// No square root and no division: about 20 products against a square root and four
    /// divisions for [`Quat::normalize`].
    fn normalize_near_unit(self, excess: R) -> Self {
        let first = R::ONE - excess * R::HALF;
        let estimate = Self::new(
            self.w * first,
            self.x * first,
            self.y * first,
            self.z * first,
        );
        let defect = estimate.norm_defect();
        let step = |c: R| c - (c * defect).mul_pow2_recip(HALF_UNSCALE_SHIFT);
        Self::new(
            step(estimate.w),
            step(estimate.x),
            step(estimate.y),
            step(estimate.z),
        )
    }

    /// The rotation matrix of q/|q|: with s = 2/|q|²,
    ///
    /// ```text
    /// ⎡ 1 − s(y² + z²)   s(xy − wz)       s(xz + wy)     ⎤
    /// ⎢ s(xy + wz)       1 − s(x² + z²)   s(yz − wx)     ⎥
    /// ⎣ s(xz − wy)       s(yz + wx)       1 − s(x² + y²) ⎦
    /// ```
    ///
    /// s = 2 − 2(1 − 1/|q|²) uses the exact defect from `norm_defect`, so the
    /// matrix is orthonormal to the rounding of its entries (a few ulp) even when |q| is
    /// not exactly 1. Entries are rounded to the format, so `to_mat3() * v` does not
    /// preserve length as precisely as [`Quat::rotate`] for long vectors.
    pub fn to_mat3(self) -> Mat3<R> {
        let s = R::TWO - self.norm_defect() * (square_unscale::<R>() * R::TWO);
        let (w, x, y, z) = (self.w, self.x, self.y, self.z);
        let (xs, ys, zs) = (x * s, y * s, z * s);
        let (xx, yy, zz) = (x * xs, y * ys, z * zs);
        let (xy, xz, yz) = (x * ys, x * zs, y * zs);
        let (wx, wy, wz) = (w * xs, w * ys, w * zs);
        Mat3::from_rows(
            Vec3::new(R::ONE - (yy + zz), xy - wz, xz + wy),
            Vec3::new(xy + wz, R::ONE - (xx + zz), yz - wx),
            Vec3::new(xz - wy, yz + wx, R::ONE - (xx + yy)),
        )
    }

    /// The unit quaternion of a rotation matrix, by Shepperd's method: the largest of
    /// 4w² = 1 + tr, 4x² = 1 + 2m₀₀ − tr, 4y² = 1 + 2m₁₁ − tr, 4z² = 1 + 2m₂₂ − tr is taken
    /// by a square root and the other three components from sums and differences of
    /// off-diagonal entries divided by it, e.g. for w: s = 2√(1 + tr) = 4w,
    /// x = (m₂₁ − m₁₂)/s, y = (m₀₂ − m₂₀)/s, z = (m₁₀ − m₀₁)/s. The result is normalised.
    ///
    /// `m` must be a rotation (orthonormal, determinant 1). The sign of the result is
    /// whichever makes the chosen component positive.
    pub fn from_mat3(m: Mat3<R>) -> Self {
        let (r0, r1, r2) = (m.row(0), m.row(1), m.row(2));
        let trace = r0.x + r1.y + r2.z;
        let largest = trace.max(r0.x).max(r1.y).max(r2.z);
        // (c, 1/(4c)) for the component c with 4c² = `four_sq`.
        let quarter = |four_sq: R| {
            let twice = four_sq.sqrt();
            (twice * R::HALF, (twice + twice).recip())
        };
        let q = if largest == trace {
            let (w, inv) = quarter(R::ONE + trace);
            Self::new(
                w,
                (r2.y - r1.z) * inv,
                (r0.z - r2.x) * inv,
                (r1.x - r0.y) * inv,
            )
        } else if largest == r0.x {
            let (x, inv) = quarter(R::ONE + r0.x + r0.x - trace);
            Self::new(
                (r2.y - r1.z) * inv,
                x,
                (r0.y + r1.x) * inv,
                (r0.z + r2.x) * inv,
            )
        } else if largest == r1.y {
            let (y, inv) = quarter(R::ONE + r1.y + r1.y - trace);
            Self::new(
                (r0.z - r2.x) * inv,
                (r0.y + r1.x) * inv,
                y,
                (r1.z + r2.y) * inv,
            )
        } else {
            let (z, inv) = quarter(R::ONE + r2.z + r2.z - trace);
            Self::new(
                (r1.x - r0.y) * inv,
                (r0.z + r2.x) * inv,
                (r1.z + r2.y) * inv,
                z,
            )
        };
        q.normalize()
    }

    /// The rotation as (unit axis n̂, angle θ) with θ in [0, π]: with q taken in the
    /// half-space w ≥ 0, θ = 2·atan2(|u|, w) and n̂ = u/|u|. The identity gives (x̂, 0).
    ///
    /// |u| is computed as |2⁸u|/2⁸, so that small angles keep their relative precision,
    /// and n̂ as u · (1/|u|), a reciprocal of a value ≤ 1 that keeps its precision too.
    pub fn to_axis_angle(self) -> (Vec3<R>, R) {
        let q = if self.w < R::ZERO { -self } else { self };
        let u = q.vector();
        let sin_half = (u * square_prescale::<R>()).length() * R::from_ratio(1, 256);
        if sin_half <= R::ZERO {
            return (Vec3::X, R::ZERO);
        }
        (u * sin_half.recip(), R::TWO * sin_half.atan2(q.w))
    }
}

impl<R: Real> Default for Quat<R> {
    /// [`Quat::IDENTITY`], the rotation that does nothing.
    fn default() -> Self {
        Self::IDENTITY
    }
}

impl<R: Real> Mul for Quat<R> {
    type Output = Self;
    /// The Hamilton product p ⊗ q = (p_w q_w − p_u·q_u, p_w q_u + q_w p_u + p_u × q_u):
    /// the rotation by q followed by the rotation by p.
    #[inline]
    fn mul(self, q: Self) -> Self {
        let p = self;
        Self::new(
            p.w * q.w - p.x * q.x - p.y * q.y - p.z * q.z,
            p.w * q.x + p.x * q.w + p.y * q.z - p.z * q.y,
            p.w * q.y - p.x * q.z + p.y * q.w + p.z * q.x,
            p.w * q.z + p.x * q.y - p.y * q.x + p.z * q.w,
        )
    }
}

impl<R: Real> Mul<R> for Quat<R> {
    type Output = Self;
    /// s·q = (s w, s x, s y, s z).
    #[inline(always)]
    fn mul(self, s: R) -> Self {
        Self::new(self.w * s, self.x * s, self.y * s, self.z * s)
    }
}

impl<R: Real> Neg for Quat<R> {
    type Output = Self;
    /// −q = (−w, −x, −y, −z): the same rotation as q.
    #[inline(always)]
    fn neg(self) -> Self {
        Self::new(-self.w, -self.x, -self.y, -self.z)
    }
}
