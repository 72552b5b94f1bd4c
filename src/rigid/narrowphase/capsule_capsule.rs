//! Capsule against capsule: the closest points of the two segments, and two points when the
//! capsules lie side by side.

use super::segments::{Segment, closest_parameters};
use super::tolerance::{lying_sine, min_span, unit, unit_from_squared};
use crate::math::{Real, Vec3};
use crate::rigid::manifold::{Manifold, ManifoldPoint};

/// Feature of a capsule at segment parameter `s`: 0 for the end at −h, 1 for the end at
/// +h, 2 for a point between them.
#[inline]
pub(super) fn capsule_feature<R: Real>(s: R, half_length: R) -> u32 {
    if s <= -half_length {
        0
    } else if s >= half_length {
        1
    } else {
        2
    }
}

/// The contact of capsule A (segment `a`, radius `radius_a`, m) with capsule B.
///
/// The closest points p_A, p_B of the two segments give the normal n = (p_B − p_A)/|p_B − p_A|
/// and the least separation |p_B − p_A| − r_A − r_B (m); empty when that exceeds `margin`.
/// Segments that cross within 0.24 mm get the normal ±u_A × u_B (towards B's centre), or
/// for parallel ones ± the fixed [`Vec3::any_orthonormal`] of u_A ([`crossing_normal`]).
///
/// When the axes are parallel to within a sine of 2⁻⁵ and B's segment, projected on A's
/// axis, overlaps A's by more than 1 mm, the contact has two points, one at each end of
/// that overlap: at A's parameter s, the point p_A(s) and B's point closest to it give the
/// separation (p_B − p_A)·n − r_A − r_B, measured along the common normal so that two
/// capsules crossing at a small angle keep the least separation at both points. Points
/// beyond the margin are dropped; otherwise there is one point at the closest pair. Each
/// point lies midway between the surfaces, p_A + n (r_A + separation/2).
///
/// Id: A's feature + 4 × B's feature, a feature being 0 or 1 for the segment's −h or +h
/// end and 2 for a point between ends ([`capsule_feature`]); an overlap end belongs to the
/// capsule whose end bounds it.
pub(super) fn capsule_capsule<R: Real>(
    a: &Segment<R>,
    radius_a: R,
    b: &Segment<R>,
    radius_b: R,
    margin: R,
) -> Manifold<R> {
    let (s, t) = closest_parameters(a, b);
    let (pa, pb) = (a.at(s), b.at(t));
    let d = pb - pa;
    let distance_squared = d.length_squared();
    let radii = radius_a + radius_b;
    let reach = radii + margin;
    if distance_squared > reach * reach {
        return Manifold::EMPTY;
    }
    let (normal, distance) =
        unit_from_squared(d, distance_squared).unwrap_or_else(|| (crossing_normal(a, b), R::ZERO));
    let mut manifold = Manifold {
        normal,
        ..Manifold::EMPTY
    };
    let cos = a.axis.dot(b.axis);
    let lying = lying_sine::<R>();
    if R::ONE - cos * cos <= lying * lying {
        side_by_side(a, radius_a, b, radius_b, cos, margin, &mut manifold);
        if manifold.count > 0 {
            return manifold;
        }
    }
    let separation = distance - radii;
    manifold.push(ManifoldPoint {
        point: pa + normal * (radius_a + separation * R::HALF),
        separation,
        id: capsule_feature(s, a.half_length) + 4 * capsule_feature(t, b.half_length),
    });
    manifold
}

/// The normal for segments that meet: u_A × u_B turned towards B's centre, or when the
/// axes are parallel (the capsules on one line) u⊥ = [`Vec3::any_orthonormal`] of u_A,
/// negated when B's centre is behind A's along u_A. Either way swapping A and B reverses
/// it, unless the two segments are the same.
fn crossing_normal<R: Real>(a: &Segment<R>, b: &Segment<R>) -> Vec3<R> {
    let offset = b.centre - a.centre;
    match unit(a.axis.cross(b.axis)) {
        Some((n, _)) if n.dot(offset) < R::ZERO => -n,
        Some((n, _)) => n,
        None if offset.dot(a.axis) < R::ZERO => -a.axis.any_orthonormal(),
        None => a.axis.any_orthonormal(),
    }
}

/// The two points of parallel capsules, pushed onto `manifold` (whose normal is set): the
/// ends of the overlap of A's parameter range [−h_A, h_A] with B's segment projected on A's
/// axis, c_B·u_A − c_A·u_A ± h_B |u_A·u_B|; nothing when the overlap is 1 mm or shorter.
fn side_by_side<R: Real>(
    a: &Segment<R>,
    radius_a: R,
    b: &Segment<R>,
    radius_b: R,
    cos: R,
    margin: R,
    manifold: &mut Manifold<R>,
) {
    let offset = (b.centre - a.centre).dot(a.axis);
    let half_b = b.half_length * cos.abs();
    let (low_b, high_b) = (offset - half_b, offset + half_b);
    // B's end that projects lowest on A's axis is its −h end when the axes agree.
    let (b_low_end, b_high_end) = if cos >= R::ZERO { (0, 1) } else { (1, 0) };
    let (low, low_id) = if -a.half_length >= low_b {
        (-a.half_length, 4 * 2)
    } else {
        (low_b, 2 + 4 * b_low_end)
    };
    let (high, high_id) = if a.half_length <= high_b {
        (a.half_length, 1 + 4 * 2)
    } else {
        (high_b, 2 + 4 * b_high_end)
    };
    if high - low <= min_span() {
        return;
    }
    let normal = manifold.normal;
    let radii = radius_a + radius_b;
    for (s, id) in [(low, low_id), (high, high_id)] {
        let pa = a.at(s);
        let pb = b.at(b.closest_parameter(pa));
        let separation = (pb - pa).dot(normal) - radii;
        if separation <= margin {
            manifold.push(ManifoldPoint {
                point: pa + normal * (radius_a + separation * R::HALF),
                separation,
                id,
            });
        }
    }
}
