//! `Mat3`: a 3×3 matrix of [`Real`] scalars, stored as three columns.
//!
//! Column j is the image of the j-th basis vector, so element (row i, column j) is
//! `cols[j][i]` and M v = vₓ c₀ + v_y c₁ + v_z c₂ for columns cⱼ. The matrix serves as a
//! rotation (see [`Quat::to_mat3`](super::Quat::to_mat3)) and as an inertia tensor, for
//! which [`Mat3::safe_inverse_symmetric`] and [`Mat3::rotate_inertia`] exist.
//!
//! Inverses first scale the matrix so that its largest entry is about 1 and undo the scale
//! afterwards: in fixed point the determinant of a matrix of small entries would otherwise
//! keep only a few significant bits (entries of 10⁻³ give a determinant of 10⁻⁹, about four
//! ulp of I32F32), and the reciprocal of a large determinant would lose its relative
//! precision.

use core::ops::{Add, Mul, Sub};

use serde::{Deserialize, Serialize};

use super::fixed_scalar::Fx;
use super::real::Real;
use super::vec3::Vec3;

/// A 3×3 matrix as three columns (see the module documentation). The default is
/// [`Mat3::ZERO`]. Arithmetic follows the scalar's policy.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(bound = "")]
pub struct Mat3<R: Real = Fx> {
    /// The columns: `cols[j]` is M e_j, and element (i, j) is `cols[j][i]`.
    pub cols: [Vec3<R>; 3],
}

/// A normalised copy of a matrix: `scaled` = `scale` · M with the largest |entry| of
/// `scaled` about 1, so that the inverse is M⁻¹ = `scale` · `scaled`⁻¹.
struct Normalised<R: Real> {
    scaled: Mat3<R>,
    scale: R,
}

impl<R: Real> Mat3<R> {
    /// The zero matrix.
    pub const ZERO: Self = Self::from_cols(Vec3::ZERO, Vec3::ZERO, Vec3::ZERO);
    /// The identity matrix I.
    pub const IDENTITY: Self = Self::from_cols(Vec3::X, Vec3::Y, Vec3::Z);

    /// The matrix [c0 c1 c2] with the given columns.
    #[inline(always)]
    pub const fn from_cols(c0: Vec3<R>, c1: Vec3<R>, c2: Vec3<R>) -> Self {
        Self { cols: [c0, c1, c2] }
    }

    /// The matrix with the given rows: element (i, j) is `ri[j]`.
    #[inline]
    pub fn from_rows(r0: Vec3<R>, r1: Vec3<R>, r2: Vec3<R>) -> Self {
        Self::from_cols(r0, r1, r2).transpose()
    }

    /// diag(d) = [[dₓ, 0, 0], [0, d_y, 0], [0, 0, d_z]].
    #[inline]
    pub fn from_diagonal(d: Vec3<R>) -> Self {
        Self::from_cols(
            Vec3::new(d.x, R::ZERO, R::ZERO),
            Vec3::new(R::ZERO, d.y, R::ZERO),
            Vec3::new(R::ZERO, R::ZERO, d.z),
        )
    }

    /// The symmetric matrix [[xx, xy, xz], [xy, yy, yz], [xz, yz, zz]], exactly symmetric
    /// by construction.
    #[inline]
    pub fn from_symmetric(diagonal: Vec3<R>, xy: R, xz: R, yz: R) -> Self {
        Self::from_cols(
            Vec3::new(diagonal.x, xy, xz),
            Vec3::new(xy, diagonal.y, yz),
            Vec3::new(xz, yz, diagonal.z),
        )
    }

    /// From `f64` rows (`rows[i][j]` is element (i, j)), for scene loading and tests only.
    pub fn from_f64(rows: [[f64; 3]; 3]) -> Self {
        let row = |r: [f64; 3]| Vec3::from_f64(r[0], r[1], r[2]);
        Self::from_rows(row(rows[0]), row(rows[1]), row(rows[2]))
    }

    /// The elements as `f64` rows (`[i][j]` is element (i, j)), for reporting.
    pub fn to_f64(self) -> [[f64; 3]; 3] {
        [0, 1, 2].map(|i| self.row(i).to_f64())
    }

    /// The outer product a bᵀ, the matrix with element (i, j) = aᵢ b_j.
    #[inline]
    pub fn outer(a: Vec3<R>, b: Vec3<R>) -> Self {
        Self::from_cols(a * b.x, a * b.y, a * b.z)
    }

    /// The cross-product matrix \[v\]ₓ, with \[v\]ₓ w = v × w:
    /// [[0, −v_z, v_y], [v_z, 0, −vₓ], [−v_y, vₓ, 0]].
    #[inline]
    pub fn skew(v: Vec3<R>) -> Self {
        Self::from_cols(
            Vec3::new(R::ZERO, v.z, -v.y),
            Vec3::new(-v.z, R::ZERO, v.x),
            Vec3::new(v.y, -v.x, R::ZERO),
        )
    }

    /// Row i, (M_i0, M_i1, M_i2). Panics for i > 2.
    #[inline]
    pub fn row(self, i: usize) -> Vec3<R> {
        Vec3::new(self.cols[0][i], self.cols[1][i], self.cols[2][i])
    }

    /// The diagonal (M₀₀, M₁₁, M₂₂).
    #[inline]
    pub fn diagonal(self) -> Vec3<R> {
        Vec3::new(self.cols[0].x, self.cols[1].y, self.cols[2].z)
    }

    /// tr M = M₀₀ + M₁₁ + M₂₂.
    #[inline]
    pub fn trace(self) -> R {
        self.cols[0].x + self.cols[1].y + self.cols[2].z
    }

    /// Mᵀ, element (i, j) = M_ji.
    #[inline]
    pub fn transpose(self) -> Self {
        Self::from_cols(self.row(0), self.row(1), self.row(2))
    }

    /// det M = c₀ · (c₁ × c₂), the scalar triple product of the columns.
    #[inline]
    pub fn determinant(self) -> R {
        let [c0, c1, c2] = self.cols;
        c0.dot(c1.cross(c2))
    }

    /// The largest |element|.
    fn max_abs_element(self) -> R {
        let [c0, c1, c2] = self.cols;
        c0.abs()
            .max_component()
            .max(c1.abs().max_component())
            .max(c2.abs().max_component())
    }

    /// The matrix scaled by s = 1/max|Mᵢⱼ|, or `None` for the zero matrix.
    fn normalised(self) -> Option<Normalised<R>> {
        let largest = self.max_abs_element();
        if largest <= R::ZERO {
            return None;
        }
        let scale = largest.recip();
        Some(Normalised {
            scaled: self * scale,
            scale,
        })
    }

    /// M⁻¹, or `None` when M is singular to the format's precision.
    ///
    /// With A = s M scaled so that max|Aᵢⱼ| ≈ 1 and columns a, b, c of A, A⁻¹ has rows
    /// (b × c, c × a, a × b) / det A with det A = a · (b × c), and M⁻¹ = s A⁻¹. M counts as
    /// singular when it is zero or |det A| ≤ 8 ε (ε = [`Real::EPSILON`]), the rounding error
    /// of det A itself: such a determinant carries no information.
    ///
    /// Entries of M⁻¹ beyond the format's range saturate.
    pub fn inverse(self) -> Option<Self> {
        let Normalised { scaled, scale } = self.normalised()?;
        let det = scaled.determinant();
        if det.abs() <= R::EPSILON * R::from_int(8) {
            return None;
        }
        Some(Self::adjugate(scaled).scale_each(det.recip(), scale))
    }

    /// A safe inverse for an inertia tensor (symmetric positive semi-definite): never
    /// divides by a negligible value, so a degenerate tensor cannot blow up.
    ///
    /// With A = s M scaled so that max|Aᵢⱼ| = 1 and the threshold τ = √ε (2⁻¹⁶ for
    /// I32F32, where ε = [`Real::EPSILON`]):
    ///
    /// - det A ≥ τ: the full inverse s·adj(A)/det A, mirrored from its upper triangle so it
    ///   is exactly symmetric. Below τ the inverse would lose more than half of the
    ///   format's bits (det A has an absolute rounding error of a few ε).
    /// - otherwise: diag(1/M_ii) over the diagonal entries with M_ii ≥ τ·max|Mᵢⱼ|, and 0
    ///   for the others and for every off-diagonal entry. A zero in the inverse is an
    ///   infinite moment of inertia: the body does not turn about that axis.
    /// - M = 0 (a point mass): the zero matrix.
    ///
    /// The fallback is exact for a diagonal tensor (a body-frame tensor in principal axes):
    /// each moment below τ times the largest is treated as infinite, e.g. the axial moment
    /// of a solid rod whose radius is below about 1/600 of its length. For a non-diagonal
    /// degenerate tensor it only guarantees a bounded result; diagonalise first. A negative
    /// or non-symmetric input gets the same safe treatment.
    ///
    /// Entries of the result reach at most about 1/(τ·max|Mᵢⱼ|), exceeded only by the
    /// rounding of the scaled diagonal and of the reciprocal; only where that exceeds
    /// the format's range (max|Mᵢⱼ| below about 2⁻¹⁵ in I32F32) can they saturate, counted
    /// like any other overflow.
    pub fn safe_inverse_symmetric(self) -> Self {
        let Some(Normalised { scaled, scale }) = self.normalised() else {
            return Self::ZERO;
        };
        let threshold = R::EPSILON.sqrt();
        let det = scaled.determinant();
        if det >= threshold {
            let full = Self::adjugate(scaled).scale_each(det.recip(), scale);
            let [_, c1, c2] = full.cols;
            return Self::from_symmetric(full.diagonal(), c1.x, c2.x, c2.y);
        }
        let invert = |moment: R, scaled_moment: R| {
            if scaled_moment >= threshold {
                moment.recip()
            } else {
                R::ZERO
            }
        };
        let (d, ds) = (self.diagonal(), scaled.diagonal());
        Self::from_diagonal(Vec3::new(
            invert(d.x, ds.x),
            invert(d.y, ds.y),
            invert(d.z, ds.z),
        ))
    }

    /// The world-frame inertia tensor R I Rᵀ of a body-frame tensor I, with `self` = R the
    /// body's rotation matrix (body → world). Also maps an inverse inertia: R I⁻¹ Rᵀ.
    ///
    /// Computed as A = R I, then element (i, j) = row i of A · row j of R for the upper
    /// triangle i ≤ j, mirrored into the lower one: the result is exactly symmetric.
    pub fn rotate_inertia(self, inertia: Self) -> Self {
        let a = self * inertia;
        let (a0, a1, a2) = (a.row(0), a.row(1), a.row(2));
        let (r0, r1, r2) = (self.row(0), self.row(1), self.row(2));
        Self::from_symmetric(
            Vec3::new(a0.dot(r0), a1.dot(r1), a2.dot(r2)),
            a0.dot(r1),
            a0.dot(r2),
            a1.dot(r2),
        )
    }

    /// adj(M) = the matrix with rows (c₁ × c₂, c₂ × c₀, c₀ × c₁) for columns c₀, c₁, c₂:
    /// M adj(M) = adj(M) M = det(M) I.
    fn adjugate(self) -> Self {
        let [c0, c1, c2] = self.cols;
        Self::from_rows(c1.cross(c2), c2.cross(c0), c0.cross(c1))
    }

    /// Every element times `first`, then times `second`: (Mᵢⱼ·first)·second, two roundings
    /// but no precision lost to a small product `first·second`.
    fn scale_each(self, first: R, second: R) -> Self {
        let scale = |c: Vec3<R>| c * first * second;
        Self::from_cols(
            scale(self.cols[0]),
            scale(self.cols[1]),
            scale(self.cols[2]),
        )
    }
}

impl<R: Real> Add for Mat3<R> {
    type Output = Self;
    /// Element-wise sum A + B.
    #[inline]
    fn add(self, rhs: Self) -> Self {
        Self::from_cols(
            self.cols[0] + rhs.cols[0],
            self.cols[1] + rhs.cols[1],
            self.cols[2] + rhs.cols[2],
        )
    }
}

impl<R: Real> Sub for Mat3<R> {
    type Output = Self;
    /// Element-wise difference A − B.
    #[inline]
    fn sub(self, rhs: Self) -> Self {
        Self::from_cols(
            self.cols[0] - rhs.cols[0],
            self.cols[1] - rhs.cols[1],
            self.cols[2] - rhs.cols[2],
        )
    }
}

impl<R: Real> Mul<R> for Mat3<R> {
    type Output = Self;
    /// s M, every element times s.
    #[inline]
    fn mul(self, s: R) -> Self {
        Self::from_cols(self.cols[0] * s, self.cols[1] * s, self.cols[2] * s)
    }
}

impl<R: Real> Mul<Vec3<R>> for Mat3<R> {
    type Output = Vec3<R>;
    /// M v = vₓ c₀ + v_y c₁ + v_z c₂.
    #[inline]
    fn mul(self, v: Vec3<R>) -> Vec3<R> {
        let [c0, c1, c2] = self.cols;
        Vec3::new(
            c0.x * v.x + c1.x * v.y + c2.x * v.z,
            c0.y * v.x + c1.y * v.y + c2.y * v.z,
            c0.z * v.x + c1.z * v.y + c2.z * v.z,
        )
    }
}

impl<R: Real> Mul for Mat3<R> {
    type Output = Self;
    /// A B, column j = A (column j of B).
    #[inline]
    fn mul(self, rhs: Self) -> Self {
        Self::from_cols(self * rhs.cols[0], self * rhs.cols[1], self * rhs.cols[2])
    }
}
