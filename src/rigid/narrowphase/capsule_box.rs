//! Capsule against box: the closest points of the capsule's segment and the box, two points
//! for a capsule lying on a face, and the separating axes when the segment enters the box.
//!
//! Everything is computed in the box's frame, where the box is −h ≤ x ≤ h.

use super::capsule_capsule::capsule_feature;
use super::segments::{Segment, closest_parameters};
use super::tolerance::{
    lying_sine, min_span, parallel_sine_squared, side, unit, unit_from_squared,
};
use crate::math::{Real, Vec3};
use crate::rigid::manifold::{Manifold, ManifoldPoint};
use crate::rigid::transform::Transform;

/// A contact point in the box frame: position (m), separation (m), id.
type LocalPoint<R> = (Vec3<R>, R, u32);

/// The contact of capsule A (segment `segment` in the world frame, radius `radius`, m) with
/// box B (half extents `half_extents`, m, placed by `xf_box`).
///
/// 1. The point of the segment closest to the box, by [`closest_to_box`], and the box's
///    point q closest to it. When they are apart (more than 0.24 mm), with d = p − q: the
///    normal (box to capsule) d/|d| and the separation |d| − r; empty beyond the margin.
/// 2. If that normal is within 1.8° of a face normal σe_k and the axis lies along the face
///    (|u_k| ≤ 2⁻⁵), the segment is clipped to the face's rectangle; the two ends of the
///    clipped part, when more than 1 mm apart, give two points with separations
///    σ p_k − h_k − r and the face normal (see [`on_face`]).
/// 3. When the segment touches or enters the box, the least-overlap axis among the three
///    face normals and the three u × e_k decides ([`through_box`]).
///
/// Points lie midway between the surfaces. The manifold normal (A to B) is minus the box's
/// outward normal, in the world frame.
///
/// Id: bits 0–1 the capsule feature ([`capsule_feature`]: 0 or 1 an end, 2 between), bits
/// 2–4 the face side that clipped the point (0 none, 1–4 the −/+ side of the face's first
/// then second tangent axis), bits 5 and up the box feature: face 2k (+) or 2k + 1 (−), or
/// 6 + 4k + (side bits) for the edge along axis k.
pub(super) fn capsule_box<R: Real>(
    segment: &Segment<R>,
    radius: R,
    half_extents: Vec3<R>,
    xf_box: &Transform<R>,
    margin: R,
) -> Manifold<R> {
    let local = Segment {
        centre: xf_box.inverse_point(segment.centre),
        axis: xf_box.inverse_vector(segment.axis),
        half_length: segment.half_length,
    };
    let h = half_extents;
    let s = closest_to_box(&local, h);
    let p = local.at(s);
    let d = p - clamp_to_box(p, h);
    let distance_squared = d.length_squared();
    let reach = radius + margin;
    if distance_squared > reach * reach {
        return Manifold::EMPTY;
    }
    let mut points: [LocalPoint<R>; 2] = [(Vec3::ZERO, R::ZERO, 0); 2];
    let (outward, count) = match unit_from_squared(d, distance_squared) {
        Some((n, distance)) => {
            let k = dominant_axis(n);
            let lying = lying_sine::<R>();
            let face_like = R::ONE - n[k] * n[k] <= lying * lying;
            let count = if face_like && local.axis[k].abs() <= lying {
                on_face(&local, radius, h, k, side(n[k]), margin, &mut points)
            } else {
                0
            };
            if count > 0 {
                (face_normal(k, side(n[k])), count)
            } else {
                let separation = distance - radius;
                let id = capsule_feature(s, local.half_length) | face_id(k, side(n[k])) << 5;
                points[0] = (p - n * (radius + separation * R::HALF), separation, id);
                (n, 1)
            }
        }
        None => through_box(&local, radius, h, margin, &mut points),
    };
    let mut manifold = Manifold {
        normal: -xf_box.vector(outward),
        ..Manifold::EMPTY
    };
    for &(point, separation, id) in &points[..count] {
        manifold.push(ManifoldPoint {
            point: xf_box.point(point),
            separation,
            id,
        });
    }
    manifold
}

/// clamp(p, −h, h) componentwise: the point of the box closest to p.
#[inline(always)]
fn clamp_to_box<R: Real>(p: Vec3<R>, h: Vec3<R>) -> Vec3<R> {
    Vec3::new(
        p.x.clamp(-h.x, h.x),
        p.y.clamp(-h.y, h.y),
        p.z.clamp(-h.z, h.z),
    )
}

/// The index k of the largest |v_k| (lowest on ties).
#[inline]
fn dominant_axis<R: Real>(v: Vec3<R>) -> usize {
    let a = v.abs();
    if a.x >= a.y && a.x >= a.z {
        0
    } else if a.y >= a.z {
        1
    } else {
        2
    }
}

/// The outward normal σ e_k of face (k, σ).
#[inline]
fn face_normal<R: Real>(k: usize, sign: R) -> Vec3<R> {
    let mut n = Vec3::ZERO;
    match k {
        0 => n.x = sign,
        1 => n.y = sign,
        _ => n.z = sign,
    }
    n
}

/// The face number 2k for the + face along axis k, 2k + 1 for the − face.
#[inline]
fn face_id<R: Real>(k: usize, sign: R) -> u32 {
    2 * k as u32 + u32::from(sign < R::ZERO)
}

/// ½ d/ds of the squared distance from the segment point p(s) = c + u s to the box:
/// g(s) = Σ_k u_k (p_k − clamp(p_k, −h_k, h_k)). Continuous, piecewise linear and
/// non-decreasing, since the squared distance to a convex set is convex and C¹.
#[inline]
fn slope<R: Real>(segment: &Segment<R>, h: Vec3<R>, s: R) -> R {
    let p = segment.at(s);
    (p - clamp_to_box(p, h)).dot(segment.axis)
}

/// The parameter s in [−H, H] of a point of the segment closest to the box.
///
/// The squared distance f(s) is convex with derivative 2g(s) ([`slope`]), linear between
/// the breakpoints where p(s) crosses a face plane, s = (±h_k − c_k)/u_k. So: s = −H if
/// g(−H) ≥ 0, s = H if g(H) ≤ 0, otherwise the root of g on the first piece where g turns
/// non-negative, by linear interpolation between the ends of that piece (exact up to
/// rounding, since g is linear there). An axis with |u_k|² ≤ 2⁻²⁰ has no breakpoints:
/// its term of g is at most 2⁻¹⁰ of the distance. A segment that passes through the box
/// gets a parameter where f = 0.
fn closest_to_box<R: Real>(segment: &Segment<R>, h: Vec3<R>) -> R {
    let half = segment.half_length;
    let low_slope = slope(segment, h, -half);
    if low_slope >= R::ZERO {
        return -half;
    }
    let high_slope = slope(segment, h, half);
    if high_slope <= R::ZERO {
        return half;
    }
    let mut breaks = [R::ZERO; 6];
    let mut count = 0;
    for k in 0..3 {
        let u = segment.axis[k];
        if u * u <= parallel_sine_squared() {
            continue;
        }
        let inverse = u.recip();
        for bound in [-h[k], h[k]] {
            let s = (bound - segment.centre[k]) * inverse;
            if s > -half && s < half {
                let mut at = count;
                while at > 0 && breaks[at - 1] > s {
                    breaks[at] = breaks[at - 1];
                    at -= 1;
                }
                breaks[at] = s;
                count += 1;
            }
        }
    }
    let (mut a, mut ga) = (-half, low_slope);
    let (mut b, mut gb) = (half, high_slope);
    for &s in &breaks[..count] {
        let g = slope(segment, h, s);
        if g >= R::ZERO {
            (b, gb) = (s, g);
            break;
        }
        (a, ga) = (s, g);
    }
    // ga < 0 ≤ gb, so the fraction −ga/(gb − ga) lies in (0, 1].
    a + (b - a) * (-ga / (gb - ga))
}

/// The two points of a capsule lying along face (k, σ) (outward normal σ e_k), written to
/// `points`; returns how many (0 when the clipped part is 1 mm or shorter, or lies beyond
/// the margin).
///
/// The segment's parameter range [−H, H] is cut to where its tangent coordinates j ≠ k
/// stay within ±h_j (s = (±h_j − c_j)/u_j, or all or nothing when u_j is 0). At each end s
/// of what remains, the separation is σ p_k(s) − h_k − r and the point p − σ e_k (r +
/// separation/2). Ids as in [`capsule_box`].
fn on_face<R: Real>(
    segment: &Segment<R>,
    radius: R,
    h: Vec3<R>,
    k: usize,
    sign: R,
    margin: R,
    points: &mut [LocalPoint<R>; 2],
) -> usize {
    let (mut low, mut low_id) = (-segment.half_length, 0u32);
    let (mut high, mut high_id) = (segment.half_length, 1u32);
    for (m, j) in [(k + 1) % 3, (k + 2) % 3].into_iter().enumerate() {
        let (u, c) = (segment.axis[j], segment.centre[j]);
        if u * u <= parallel_sine_squared() {
            if c.abs() > h[j] {
                return 0;
            }
            continue;
        }
        let inverse = u.recip();
        // Sides 1 + 2m (the −h_j plane) and 2 + 2m (the +h_j plane).
        let mut enter = ((-h[j] - c) * inverse, 2 | (1 + 2 * m as u32) << 2);
        let mut exit = ((h[j] - c) * inverse, 2 | (2 + 2 * m as u32) << 2);
        if u < R::ZERO {
            core::mem::swap(&mut enter, &mut exit);
        }
        if enter.0 > low {
            (low, low_id) = enter;
        }
        if exit.0 < high {
            (high, high_id) = exit;
        }
    }
    if high - low <= min_span() {
        return 0;
    }
    let normal = face_normal(k, sign);
    let face = face_id(k, sign) << 5;
    let mut count = 0;
    for (s, id) in [(low, low_id), (high, high_id)] {
        let p = segment.at(s);
        let separation = sign * p[k] - h[k] - radius;
        if separation <= margin {
            points[count] = (
                p - normal * (radius + separation * R::HALF),
                separation,
                id | face,
            );
            count += 1;
        }
    }
    count
}

/// The contact of a segment that touches or enters the box: the axis of least overlap.
///
/// Separations along the candidate axes (box frame): face k, |c_k| − h_k − H|u_k| − r;
/// edge L = unit(u × e_k), |c·L| − Σ_j h_j |L_j| − r (the segment spans nothing along L).
/// An edge axis wins only if it beats the best face by more than 1 mm + 1/16 of the face's
/// depth, for a face normal that does not flicker. On a face axis the capsule, if lying
/// along the face, gets its two clipped points ([`on_face`]), and otherwise one at its
/// deeper end; on an edge axis the closest points of the segment and that box edge give one
/// point. Returns the outward normal (box frame) and the number of points.
fn through_box<R: Real>(
    segment: &Segment<R>,
    radius: R,
    h: Vec3<R>,
    margin: R,
    points: &mut [LocalPoint<R>; 2],
) -> (Vec3<R>, usize) {
    let (c, u, half) = (segment.centre, segment.axis, segment.half_length);
    let mut face = (0, R::MIN);
    for k in 0..3 {
        let separation = c[k].abs() - h[k] - half * u[k].abs() - radius;
        if separation > face.1 {
            face = (k, separation);
        }
    }
    let mut edge: Option<(usize, Vec3<R>, R)> = None;
    for (k, e) in [Vec3::X, Vec3::Y, Vec3::Z].into_iter().enumerate() {
        let Some((axis, _)) = unit(u.cross(e)) else {
            continue;
        };
        let separation = c.dot(axis).abs() - h.dot(axis.abs()) - radius;
        if edge.is_none_or(|(_, _, best)| separation > best) {
            edge = Some((k, axis, separation));
        }
    }
    let bias = R::from_ratio(1, 1 << 10) + face.1.abs() * R::from_ratio(1, 16);
    if let Some((k, axis, separation)) = edge
        && separation > face.1 + bias
    {
        let n = if c.dot(axis) < R::ZERO { -axis } else { axis };
        let sides = [side(n.x), side(n.y), side(n.z)];
        let mut centre = h.mul_elem(Vec3::new(sides[0], sides[1], sides[2]));
        match k {
            0 => centre.x = R::ZERO,
            1 => centre.y = R::ZERO,
            _ => centre.z = R::ZERO,
        }
        let box_edge = Segment {
            centre,
            axis: face_normal(k, R::ONE),
            half_length: h[k],
        };
        let (s, t) = closest_parameters(segment, &box_edge);
        let (ps, pe) = (segment.at(s), box_edge.at(t));
        let separation = (ps - pe).dot(n) - radius;
        let (j1, j2) = ((k + 1) % 3, (k + 2) % 3);
        let edge_index =
            4 * k as u32 + u32::from(sides[j1] > R::ZERO) + 2 * u32::from(sides[j2] > R::ZERO);
        let id = capsule_feature(s, half) | (6 + edge_index) << 5;
        points[0] = (ps - n * (radius + separation * R::HALF), separation, id);
        return (n, 1);
    }
    let k = face.0;
    let sign = side(c[k]);
    let normal = face_normal(k, sign);
    if u[k].abs() <= lying_sine() {
        let count = on_face(segment, radius, h, k, sign, margin, points);
        if count > 0 {
            return (normal, count);
        }
    }
    // The deeper end: the one with the smaller σ p_k.
    let s = if sign * u[k] > R::ZERO { -half } else { half };
    let p = segment.at(s);
    let separation = sign * p[k] - h[k] - radius;
    let mut surface = clamp_to_box(p, h);
    match k {
        0 => surface.x = p.x,
        1 => surface.y = p.y,
        _ => surface.z = p.z,
    }
    let id = capsule_feature(s, half) | face_id(k, sign) << 5;
    points[0] = (
        surface - normal * (radius + separation * R::HALF),
        separation,
        id,
    );
    (normal, 1)
}
