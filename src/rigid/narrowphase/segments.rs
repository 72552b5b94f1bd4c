//! Closest points on segments: a point to a segment, and a segment to a segment.
//!
//! A segment is written as its centre c, a unit direction u and a half length h (m): the
//! points c + u s for s in [−h, h]. Capsules are segments with a radius, box edges are
//! segments, so the capsule pairs and box–box edge contacts share these.

use super::tolerance::parallel_sine_squared;
use crate::math::{Real, Vec3};

/// A segment {c + u s : −h ≤ s ≤ h} with unit direction u.
#[derive(Clone, Copy, Debug)]
pub(super) struct Segment<R: Real> {
    /// Centre c, m.
    pub centre: Vec3<R>,
    /// Unit direction u.
    pub axis: Vec3<R>,
    /// Half length h, m.
    pub half_length: R,
}

impl<R: Real> Segment<R> {
    /// The point c + u s (m).
    #[inline(always)]
    pub fn at(&self, s: R) -> Vec3<R> {
        self.centre + self.axis * s
    }

    /// The parameter s of the point of the segment closest to `point`:
    /// s = clamp((p − c)·u, −h, h).
    #[inline]
    pub fn closest_parameter(&self, point: Vec3<R>) -> R {
        (point - self.centre)
            .dot(self.axis)
            .clamp(-self.half_length, self.half_length)
    }
}

/// The parameters (s, t) of a closest pair of points a.at(s), b.at(t) of two segments.
///
/// Minimising |r + u_a s − u_b t|² with r = c_a − c_b, b = u_a·u_b, c = u_a·r, f = u_b·r
/// gives s = b t − c and t = b s + f, so s = (b f − c)/(1 − b²) on the lines. s is clamped
/// to its segment, t follows from s and is clamped, and if t was clamped s is recomputed
/// from t and clamped (Ericson, *Real-Time Collision Detection*, 5.1.9). When
/// 1 − b² ≤ [`parallel_sine_squared`] the segments are parallel to the format's precision
/// and s starts at 0 instead: the result is still a closest pair (the distance between
/// parallel segments is the same along their overlap), with no division by a tiny number.
pub(super) fn closest_parameters<R: Real>(a: &Segment<R>, b: &Segment<R>) -> (R, R) {
    let r = a.centre - b.centre;
    let cos = a.axis.dot(b.axis);
    let c = a.axis.dot(r);
    let f = b.axis.dot(r);
    let denominator = R::ONE - cos * cos;
    let mut s = if denominator > parallel_sine_squared() {
        ((cos * f - c) / denominator).clamp(-a.half_length, a.half_length)
    } else {
        R::ZERO
    };
    let mut t = cos * s + f;
    if t < -b.half_length || t > b.half_length {
        t = t.clamp(-b.half_length, b.half_length);
        s = (cos * t - c).clamp(-a.half_length, a.half_length);
    }
    (s, t)
}
