//! The narrowphase's named thresholds, in metres or as dimensionless sines, and the guarded
//! normalisation every pair uses for its normal.
//!
//! All are powers of two, so they are exact in every format. A vector of length 2⁻¹² m has
//! components of about 2²⁰ ulp in I32F32, so its direction is known to about 10⁻⁶; shorter
//! ones are treated as having no direction and get a fixed fallback.

use crate::math::{Real, Vec3};

/// Squared length (m²) at or below which a direction is undefined: 2⁻²⁴ m², a length of
/// 2⁻¹² m ≈ 0.24 mm. Centres closer than this, or a sphere centre this close to a box
/// surface, use the deep-penetration fallback.
#[inline(always)]
pub(crate) fn tiny_length_squared<R: Real>() -> R {
    R::from_ratio(1, 1 << 24)
}

/// Squared sine at or below which two unit directions count as parallel for a cross
/// product to be meaningless: 2⁻²⁰ (an angle of about 0.001 rad). Box edge axes this close
/// to parallel are skipped (the face axes cover them), and the closest points of two such
/// segments are found without the 1/sin² solve.
#[inline(always)]
pub(super) fn parallel_sine_squared<R: Real>() -> R {
    R::from_ratio(1, 1 << 20)
}

/// Sine (dimensionless) up to which a capsule's axis counts as lying along a face or along
/// another capsule, so that the contact gets two points: 2⁻⁵ ≈ 0.031 (1.8°). Each of the
/// two points gets its own separation, so a slightly tilted capsule still gets the right
/// depths; only points within the margin are kept.
#[inline(always)]
pub(super) fn lying_sine<R: Real>() -> R {
    R::from_ratio(1, 1 << 5)
}

/// Shortest overlap (m) of a lying capsule with a face or another capsule that gives two
/// points rather than one: 2⁻¹⁰ m ≈ 1 mm.
#[inline(always)]
pub(super) fn min_span<R: Real>() -> R {
    R::from_ratio(1, 1 << 10)
}

/// v / |v| and |v| computed from the already known squared length `length_squared` = v·v
/// (m²): with y = 1/√(v·v) ([`Real::rsqrt`], correctly rounded, no division), v̂ = v y and
/// |v| = (v·v) y. `None` when v·v ≤ [`tiny_length_squared`], where the direction would be
/// mostly rounding. (Equivalent to [`Vec3::try_normalize`] with its √ and reciprocal, and
/// a little cheaper.)
///
/// A vector shorter than 1/16 m is first scaled by 2⁸ (exact): v·v of a short vector has
/// few significant bits in fixed point (at |v| = 7 mm, I32F32 keeps it to 6·10⁻⁶), and the
/// scaled one brings the unit vector back to about 10⁻⁹.
#[inline]
pub(crate) fn unit_from_squared<R: Real>(v: Vec3<R>, length_squared: R) -> Option<(Vec3<R>, R)> {
    if length_squared <= tiny_length_squared() {
        return None;
    }
    if length_squared >= R::from_ratio(1, 1 << 8) {
        let inverse = length_squared.rsqrt();
        return Some((v * inverse, length_squared * inverse));
    }
    let scaled = v * R::from_int(1 << 8);
    let scaled_squared = scaled.length_squared();
    let inverse = scaled_squared.rsqrt();
    Some((
        scaled * inverse,
        scaled_squared * inverse * R::from_ratio(1, 1 << 8),
    ))
}

/// v / |v| and |v|, or `None` when |v|² ≤ [`tiny_length_squared`].
#[inline]
pub(crate) fn unit<R: Real>(v: Vec3<R>) -> Option<(Vec3<R>, R)> {
    unit_from_squared(v, v.length_squared())
}

/// +1 for x ≥ 0, −1 otherwise: the side of a box face or edge, with 0 sent to the positive
/// side so that exact ties are resolved the same way every time.
#[inline(always)]
pub(super) fn side<R: Real>(x: R) -> R {
    if x >= R::ZERO { R::ONE } else { -R::ONE }
}
