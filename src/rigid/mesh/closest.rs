//! The closest point of a triangle to a point, and the feature it lies on.

use crate::math::{Real, Vec3};

/// Where on a triangle a closest point lies.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum TriangleFeature {
    /// Inside the triangle.
    Face,
    /// On edge k, from corner k to corner k + 1 mod 3, between its ends.
    Edge(usize),
    /// At corner k.
    Corner(usize),
}

/// The point q of the triangle with `corners` v_k and unit `normal` n (its winding's)
/// closest to p (all in m, one frame), and its feature: p's projection p − n (n · (p − v₀))
/// when it lies inside all three edges ((v_{k+1} − v_k) × (q − v_k) · n ≥ 0), else the
/// nearest of the closest points on the three edges, v_k + t e_k with
/// t = clamp((p − v_k) · e_k / (e_k · e_k), 0, 1) (a corner at t = 0 or 1), the lowest k on
/// ties. No division by zero: a valid mesh has no zero-length edge, and t's division only
/// runs strictly between the ends (0 < (p − v_k) · e_k < e_k · e_k).
pub(crate) fn closest_point<R: Real>(
    corners: &[Vec3<R>; 3],
    normal: Vec3<R>,
    p: Vec3<R>,
) -> (Vec3<R>, TriangleFeature) {
    let projected = p - normal * normal.dot(p - corners[0]);
    let inside = (0..3).all(|k| {
        let edge = corners[(k + 1) % 3] - corners[k];
        edge.cross(projected - corners[k]).dot(normal) >= R::ZERO
    });
    if inside {
        return (projected, TriangleFeature::Face);
    }
    let mut best: Option<(R, Vec3<R>, TriangleFeature)> = None;
    for k in 0..3 {
        let (a, b) = (corners[k], corners[(k + 1) % 3]);
        let e = b - a;
        let along = (p - a).dot(e);
        let length2 = e.length_squared();
        let (point, feature) = if along <= R::ZERO {
            (a, TriangleFeature::Corner(k))
        } else if along >= length2 {
            (b, TriangleFeature::Corner((k + 1) % 3))
        } else {
            (a + e * (along / length2), TriangleFeature::Edge(k))
        };
        let distance2 = (p - point).length_squared();
        if best.is_none_or(|(d2, _, _)| distance2 < d2) {
            best = Some((distance2, point, feature));
        }
    }
    best.map_or((corners[0], TriangleFeature::Corner(0)), |(_, q, f)| (q, f))
}
