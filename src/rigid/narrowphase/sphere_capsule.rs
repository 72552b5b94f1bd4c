//! Sphere against capsule: a sphere against the closest point of the capsule's segment.

use super::segments::Segment;
use super::sphere_sphere::ball_contact;
use crate::math::{Real, Vec3};
use crate::rigid::manifold::Manifold;

/// The contact of sphere A (centre `centre`, radius `radius`, m) with capsule B (segment
/// `segment`, radius `capsule_radius`, m). One point, id 0.
///
/// With q the point of the segment closest to the centre c (parameter
/// clamp((c − c_B)·u, −h, h)) and d = q − c: the normal is d/|d|, the separation
/// |d| − r − r_B (m), and the point c + n (r + separation/2), midway between the
/// surfaces. Empty when |d|² > (r + r_B + margin)². A centre within 0.24 mm of the
/// segment (`tiny_length_squared`) gets the fixed normal −u⊥, u⊥ =
/// [`Vec3::any_orthonormal`] of the axis, and the separation −r − r_B.
pub(super) fn sphere_capsule<R: Real>(
    centre: Vec3<R>,
    radius: R,
    segment: &Segment<R>,
    capsule_radius: R,
    margin: R,
) -> Manifold<R> {
    let q = segment.at(segment.closest_parameter(centre));
    ball_contact(centre, radius, q, capsule_radius, margin, || {
        -segment.axis.any_orthonormal()
    })
}
