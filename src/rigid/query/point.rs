//! The point of a shape closest to a query point.

use super::super::shape::Shape;
use super::super::transform::Transform;
use super::parts::for_each_part;
use crate::math::{Real, Vec3};

/// The answer for one shape.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) struct Projected<R: Real> {
    /// The closest point of the shape's surface, m; the query point itself when inside.
    pub point: Vec3<R>,
    /// Whether the query point is in the (solid) shape, surface included.
    pub inside: bool,
    /// Distance from the query point to `point`, m; 0 when inside.
    pub distance: R,
}

/// The point of `shape` placed by `xf` closest to `p` (m). A compound answers for its
/// nearest part (the first on ties; inside when inside any part), a plane for its
/// half-space.
pub(super) fn project_point<R: Real>(
    shape: &Shape<R>,
    xf: &Transform<R>,
    p: Vec3<R>,
) -> Projected<R> {
    let mut best: Option<Projected<R>> = None;
    for_each_part(shape, xf, |part, placed| {
        let found = project_convex(part, placed, p);
        let nearer = |b: Projected<R>| {
            found.distance < b.distance
                || (found.distance == b.distance && found.inside && !b.inside)
        };
        if best.is_none_or(nearer) {
            best = Some(found);
        }
    });
    best.unwrap_or(Projected {
        point: p,
        inside: false,
        distance: R::MAX,
    })
}

/// One convex shape or a plane:
/// - ball (centre c, radius r): with v = p − c, inside when |v| ≤ r, else the point
///   c + v·r/|v| at distance |v| − r;
/// - box (half extents h, box frame): q = p clamped to [−h, h]; inside when q = p, else q
///   at distance |p − q|;
/// - capsule: the ball rule around the segment point (0, clamp(p_y, −h, h), 0);
/// - half-space n·x ≤ c: with s = n·p − c, inside when s ≤ 0, else p − s·n at distance s.
fn project_convex<R: Real>(shape: &Shape<R>, xf: &Transform<R>, p: Vec3<R>) -> Projected<R> {
    let inside = Projected {
        point: p,
        inside: true,
        distance: R::ZERO,
    };
    let outside = |point: Vec3<R>, distance: R| Projected {
        point,
        inside: false,
        distance,
    };
    let ball = |centre: Vec3<R>, radius: R, q: Vec3<R>| -> Option<(Vec3<R>, R)> {
        let v = q - centre;
        let length = v.length();
        (length > radius).then(|| (centre + v * (radius / length), length - radius))
    };
    match shape {
        Shape::Sphere { radius } => match ball(xf.translation, *radius, p) {
            Some((point, distance)) => outside(point, distance),
            None => inside,
        },
        Shape::Box { half_extents: h } => {
            let local = xf.inverse_point(p);
            let q = Vec3::new(
                local.x.clamp(-h.x, h.x),
                local.y.clamp(-h.y, h.y),
                local.z.clamp(-h.z, h.z),
            );
            if q == local {
                inside
            } else {
                outside(xf.point(q), (local - q).length())
            }
        }
        Shape::Capsule {
            radius,
            half_height,
        } => {
            let local = xf.inverse_point(p);
            let axis = Vec3::new(R::ZERO, local.y.clamp(-*half_height, *half_height), R::ZERO);
            match ball(axis, *radius, local) {
                Some((point, distance)) => outside(xf.point(point), distance),
                None => inside,
            }
        }
        Shape::Plane { normal, offset } => {
            let n = xf.vector(*normal);
            let s = n.dot(p) - (*offset + n.dot(xf.translation));
            if s <= R::ZERO {
                inside
            } else {
                outside(p - n * s, s)
            }
        }
        Shape::Cylinder { .. } | Shape::Cone { .. } | Shape::ConvexHull { .. } => {
            outside(p, R::MAX)
        }
        Shape::Compound { .. } => outside(p, R::MAX),
    }
}
