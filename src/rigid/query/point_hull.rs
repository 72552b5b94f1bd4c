//! The point of a convex hull closest to a query point, in the hull's frame, by brute
//! force over its faces and edges.

use super::super::convex::ConvexHull;
use super::ray::clamped_ratio;
use crate::math::{Real, Vec3};

/// The point of the solid `hull` closest to `p` (hull frame, m), or `None` when `p` is in
/// it: n_f · p ≤ c_f for every face f (outward unit normal n_f, offset c_f in m).
///
/// Otherwise the nearest point is on a face that p is above, or on an edge. Candidates,
/// in order: for each face with s = n_f · p − c_f > 0, the foot p − s n_f when it lies in
/// the face polygon (on the inner side of every edge (a, b) taken counter-clockwise seen
/// from outside: ((b − a) × (q − a)) · n_f ≥ 0), at distance s; then for each edge (a, b)
/// the segment point a + u (b − a), u = ((p − a)·(b − a)) / |b − a|² clamped to [0, 1]
/// (a vertex when they coincide). The first of the smallest distance wins.
pub(super) fn project_hull<R: Real>(hull: &ConvexHull<R>, p: Vec3<R>) -> Option<Vec3<R>> {
    let vertices = hull.vertices();
    if hull
        .faces()
        .iter()
        .all(|f| f.normal.dot(p) - f.offset <= R::ZERO)
    {
        return None;
    }
    let mut best: Option<(R, Vec3<R>)> = None;
    let mut offer = |q: Vec3<R>| {
        let gap = (p - q).length_squared();
        if best.is_none_or(|(g, _)| gap < g) {
            best = Some((gap, q));
        }
    };
    for face in hull.faces() {
        let s = face.normal.dot(p) - face.offset;
        if s <= R::ZERO {
            continue;
        }
        let foot = p - face.normal * s;
        let ring = hull.face_indices(face);
        let within = ring
            .iter()
            .zip(ring.iter().cycle().skip(1))
            .all(|(&i, &j)| {
                let (a, b) = (vertices[usize::from(i)], vertices[usize::from(j)]);
                (b - a).cross(foot - a).dot(face.normal) >= R::ZERO
            });
        if within {
            offer(foot);
        }
    }
    for &[i, j] in hull.edges() {
        let (a, b) = (vertices[usize::from(i)], vertices[usize::from(j)]);
        let edge = b - a;
        let span = edge.length_squared();
        let u = if span > R::ZERO {
            clamped_ratio((p - a).dot(edge), span, R::ONE).max(R::ZERO)
        } else {
            R::ZERO
        };
        offer(a.add_scaled(edge, u));
    }
    best.map(|(_, q)| q)
}
