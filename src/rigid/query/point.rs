//! The point of a shape closest to a query point.

use super::super::shape::Shape;
use super::super::transform::Transform;
use super::parts::for_each_part;
use super::point_hull::project_hull;
use super::point_mesh::project_mesh;
use super::ray_round::{Slant, cone_contains, cylinder_contains};
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

/// Whether the point `p` (m, in the shape's own frame) lies in `shape`, taken as solid,
/// surface included: [`project_point`]'s `inside` (never for a mesh or a heightfield, which
/// are surfaces).
pub(crate) fn shape_contains<R: Real>(shape: &Shape<R>, p: Vec3<R>) -> bool {
    project_point(shape, &Transform::IDENTITY, p).inside
}

/// One convex shape or a plane:
/// - ball (centre c, radius r): with v = p − c, inside when |v| ≤ r, else the point
///   c + v·r/|v| at distance |v| − r;
/// - box (half extents h, box frame): q = p clamped to [−h, h]; inside when q = p, else q
///   at distance |p − q|;
/// - capsule: the ball rule around the segment point (0, clamp(p_y, −h, h), 0);
/// - cylinder (cylinder frame): inside when p_x² + p_z² ≤ r² and |p_y| ≤ h, else the point
///   with y clamped to [−h, h] and (x, z) pulled in to radius r when farther out;
/// - cone: [`project_cone`]; convex hull: [`project_hull`]; mesh or heightfield: the
///   nearest point of its triangles ([`project_mesh`]), never inside (a surface);
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
        Shape::TriMesh { .. } | Shape::HeightField { .. } => {
            let Some(mesh) = shape.triangles() else {
                return Projected {
                    point: p,
                    inside: false,
                    distance: R::MAX,
                };
            };
            let (q, d2) = project_mesh(mesh, xf.inverse_point(p));
            Projected {
                point: xf.point(q),
                inside: false,
                distance: if d2 == R::MAX { R::MAX } else { d2.sqrt() },
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
        Shape::Cylinder {
            radius,
            half_height,
        } => {
            let local = xf.inverse_point(p);
            if cylinder_contains(*radius, *half_height, local) {
                return inside;
            }
            let y = local.y.clamp(-*half_height, *half_height);
            let level = Vec3::new(local.x, y, local.z);
            let q = ball(Vec3::new(R::ZERO, y, R::ZERO), *radius, level).map_or(level, |b| b.0);
            outside(xf.point(q), (local - q).length())
        }
        Shape::Cone {
            radius,
            half_height,
        } => {
            let local = xf.inverse_point(p);
            match project_cone(*radius, *half_height, local) {
                Some(q) => outside(xf.point(q), (local - q).length()),
                None => inside,
            }
        }
        Shape::ConvexHull { hull } => {
            let local = xf.inverse_point(p);
            match project_hull(hull, local) {
                Some(q) => outside(xf.point(q), (local - q).length()),
                None => inside,
            }
        }
        Shape::Compound { .. } => outside(p, R::MAX),
    }
}

/// The point of the solid cone (base radius r at y = −h, apex (0, h, 0), m; cone frame)
/// closest to `p`, or `None` when `p` is in it ([`cone_contains`]).
///
/// In the half-plane of p, at radius ρ = √(p_x² + p_z²) and height y, the cone is the
/// triangle (0, −h), (r, −h), (0, h), and an outside point is nearest to one of the two
/// edges it can see: the base (ρ clamped to [0, r], −h), and the slant from the apex
/// (0, h) down along g = (sin α, −cos α) (the [`Slant`]) to the rim, at
/// τ = (ρ, y − h)·g clamped to [0, L], L = r sin α + 2h cos α = √(r² + 4h²) the slant's
/// length. The nearer wins (the base on ties), and is turned back into 3D along the
/// radial direction (p_x, 0, p_z)/ρ (+x on the axis, where the point is on it anyway).
pub(super) fn project_cone<R: Real>(radius: R, half_height: R, p: Vec3<R>) -> Option<Vec3<R>> {
    let slant = Slant::of(radius, half_height)?;
    if cone_contains(&slant, half_height, p) {
        return None;
    }
    let (e, rho) = Vec3::new(p.x, R::ZERO, p.z)
        .try_normalize()
        .unwrap_or((Vec3::X, R::ZERO));
    let base = (rho.clamp(R::ZERO, radius), -half_height);
    let length = radius * slant.sin + (half_height + half_height) * slant.cos;
    let tau = (rho * slant.sin - (p.y - half_height) * slant.cos).clamp(R::ZERO, length);
    let side = (tau * slant.sin, half_height - tau * slant.cos);
    let gap = |(r, y): (R, R)| (rho - r) * (rho - r) + (p.y - y) * (p.y - y);
    let (r, y) = if gap(side) < gap(base) { side } else { base };
    Some(Vec3::new(e.x * r, y, e.z * r))
}
