//! Shape casts: a convex shape translated along a unit direction d from a start
//! pose, against one body's shape: the first distance t (m) at which the two touch.
//!
//! A sphere against a sphere or a capsule is a ray against the target grown by the
//! sphere's radius (exact to rounding). Every other pair uses conservative advancement
//! with the narrowphase ([`collide`]): at distance t it gives the separation s (m) along
//! a separating direction n (from the cast shape towards the target); the shapes cannot
//! touch before t + s / (n·d), so the cast advances by that much (n·d ≤ 0: they never
//! meet). It stops at a gap of at most [`cast_tolerance`]. Should an advance overshoot
//! into overlap deeper than the tolerance (the narrowphase's separation of two boxes is
//! that of its clipped points, which can exceed their true gap), the cast bisects between
//! the last separated distance and the overlapping one. After [`MAX_ITERATIONS`] it reports
//! the distance reached.
//!
//! So the reported distance lies within the tolerance of a touching pose: the gap there
//! is at most 2⁻²⁰ m, or the overlap at most that deep (to rounding). Shapes that already
//! touch or overlap at the start hit at distance 0.

use super::super::aabb::Aabb;
use super::super::convex::Rounded;
use super::super::manifold::Manifold;
use super::super::mesh::TriMesh;
use super::super::narrowphase::{collide, collide_triangle};
use super::super::shape::Shape;
use super::super::transform::Transform;
use super::ray::{Crossing, Ray, clamped_ratio, ray_capsule, ray_sphere};
use crate::math::{Real, Vec3};

/// Most narrowphase calls one cast against one convex shape makes.
pub(super) const MAX_ITERATIONS: usize = 64;

/// The gap (m) at which a conservative advancement counts as touching: 2⁻²⁰ m ≈ 0.95 µm.
pub(crate) fn cast_tolerance<R: Real>() -> R {
    R::from_ratio(1, 1 << 20)
}

/// Where a cast shape first touches a target.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct CastHit<R: Real> {
    /// Travel along the unit direction at impact, m.
    pub distance: R,
    /// The contact point, m (midway between the two surfaces).
    pub point: Vec3<R>,
    /// Unit normal from the target towards the cast shape.
    pub normal: Vec3<R>,
}

/// The convex `cast` (any shape but a plane, a compound or a mesh) placed by `start`, moved
/// along unit `direction` by up to `max` (m), against `target` placed by `xf`: a compound
/// answers for its nearest part (the first on ties), a plane for its half-space, a mesh or
/// a heightfield for its nearest triangle (the lowest index on ties).
pub(crate) fn cast_shape<R: Real>(
    cast: &Shape<R>,
    start: &Transform<R>,
    direction: Vec3<R>,
    max: R,
    target: &Shape<R>,
    xf: &Transform<R>,
) -> Option<CastHit<R>> {
    match target {
        Shape::Compound { parts } => {
            let mut best: Option<CastHit<R>> = None;
            for part in parts {
                let local = Transform::from_pose(part.translation, part.rotation);
                let placed = xf.compose(&local);
                if let Some(hit) = cast_shape(cast, start, direction, max, &part.shape, &placed)
                    && best.is_none_or(|b| hit.distance < b.distance)
                {
                    best = Some(hit);
                }
            }
            best
        }
        Shape::TriMesh { .. } | Shape::HeightField { .. } => {
            let mesh = target.triangles()?;
            cast_against_triangles(cast, start, direction, max, mesh, xf, None)
        }
        _ => analytic(cast, start, direction, max, target, xf).unwrap_or_else(|| {
            advance(start, direction, max, |placed, margin| {
                collide(cast, placed, target, xf, margin)
            })
        }),
    }
}

/// [`cast_shape`] for continuous collision: against a mesh or a heightfield, only the
/// triangles whose plane the body's centre crosses or touches on its way from
/// `centre_path.0` to `centre_path.1` (m) are swept, as Box2D v3 sweeps a fast body
/// against a segment only when its centroid passes through it: a body whose centre stays
/// on one side of a triangle's plane cannot end past the triangle. Any other target as
/// [`cast_shape`].
pub(crate) fn sweep_shape<R: Real>(
    cast: &Shape<R>,
    start: &Transform<R>,
    direction: Vec3<R>,
    max: R,
    target: &Shape<R>,
    xf: &Transform<R>,
    centre_path: (Vec3<R>, Vec3<R>),
) -> Option<CastHit<R>> {
    match target.triangles() {
        Some(mesh) => {
            cast_against_triangles(cast, start, direction, max, mesh, xf, Some(centre_path))
        }
        None => cast_shape(cast, start, direction, max, target, xf),
    }
}

/// The convex `cast` against the triangles of `mesh` placed by `xf` whose boxes overlap
/// the box swept by the cast (its boxes at the start and at `max`): conservative
/// advancement against each, with the triangle's manifold as a lone triangle (every edge
/// active: its separation is then the true distance, which the advancement needs); the
/// nearest hit, the lowest triangle index on ties. With a `centre_path`, only the triangles
/// whose plane it crosses or touches (see [`sweep_shape`]).
fn cast_against_triangles<R: Real>(
    cast: &Shape<R>,
    start: &Transform<R>,
    direction: Vec3<R>,
    max: R,
    mesh: &TriMesh<R>,
    xf: &Transform<R>,
    centre_path: Option<(Vec3<R>, Vec3<R>)>,
) -> Option<CastHit<R>> {
    let end = Transform {
        translation: start.translation.add_scaled(direction, max),
        ..*start
    };
    let swept = Aabb::of_shape(cast, start)?
        .union(&Aabb::of_shape(cast, &end)?)
        .expanded(cast_tolerance::<R>() * R::TWO);
    let mut triangles = Vec::new();
    mesh.for_each_triangle_in(&swept.seen_from(xf), |t| triangles.push(t));
    triangles.sort_unstable();
    let rounded = Rounded::of(cast)?;
    let tolerance = cast_tolerance::<R>();
    let mut best: Option<CastHit<R>> = None;
    for t in triangles {
        if !crosses_plane(&rounded, start, direction, max, mesh, t, xf, tolerance) {
            continue;
        }
        if let Some((from, to)) = centre_path {
            let n = xf.vector(mesh.normal(t));
            let v0 = xf.point(mesh.corners(t)[0]);
            let (a, b) = (n.dot(from - v0), n.dot(to - v0));
            if (a > R::ZERO && b > R::ZERO) || (a < R::ZERO && b < R::ZERO) {
                continue;
            }
        }
        let hit = advance(start, direction, max, |placed, margin| {
            collide_triangle(mesh, t, xf, cast, placed, margin, false).flipped()
        });
        if let Some(hit) = hit
            && best.is_none_or(|b| hit.distance < b.distance)
        {
            best = Some(hit);
        }
    }
    best
}

/// A sphere of radius ρ against a sphere or capsule of radius r: the ray of the sphere's
/// centre against the target grown to radius r + ρ; the contact point is the centre at
/// impact moved ρ against the normal. `None` when the pair is not one of these or the
/// centre starts in the grown shape (left to [`advance`], which answers distance 0 with
/// the narrowphase's normal); `Some(None)` for a miss.
#[allow(clippy::option_option)] // "not analytic" and "analytic miss" differ
fn analytic<R: Real>(
    cast: &Shape<R>,
    start: &Transform<R>,
    direction: Vec3<R>,
    max: R,
    target: &Shape<R>,
    xf: &Transform<R>,
) -> Option<Option<CastHit<R>>> {
    let Shape::Sphere { radius: rho } = cast else {
        return None;
    };
    let ray = Ray::new(start.translation, direction, max);
    let crossing = match target {
        Shape::Sphere { radius } => ray_sphere(xf.translation, *radius + *rho, &ray),
        Shape::Capsule {
            radius,
            half_height,
        } => {
            let local = Ray::new(
                xf.inverse_point(ray.origin),
                xf.inverse_vector(direction),
                max,
            );
            ray_capsule(*radius + *rho, *half_height, &local).map(|c| match c {
                Crossing::Enters { distance, normal } => Crossing::Enters {
                    distance,
                    normal: xf.vector(normal),
                },
                Crossing::Inside => Crossing::Inside,
            })
        }
        _ => return None,
    };
    match crossing {
        None => Some(None),
        Some(Crossing::Inside) => None,
        Some(Crossing::Enters { distance, normal }) => Some(Some(CastHit {
            distance,
            point: ray.at(distance) - normal * *rho,
            normal,
        })),
    }
}

/// Whether the cast can touch triangle `t`'s plane at all: with the plane's world normal
/// n and a point v₀ on it, the gap of the shape's lowest point below the plane's front,
/// g(s) = n · (x_B(−n) − v₀) + s (n · d) − r at travel s, and of its highest point behind
/// it, likewise with x_B(+n), are linear in s; a shape whose front gap stays above
/// `tolerance` (m), or whose back gap stays below −`tolerance`, over s ∈ [0, max] never
/// meets the plane, so neither the triangle: the advancement is skipped.
#[allow(clippy::too_many_arguments)]
fn crosses_plane<R: Real>(
    cast: &Rounded<R>,
    start: &Transform<R>,
    direction: Vec3<R>,
    max: R,
    mesh: &TriMesh<R>,
    t: u32,
    xf: &Transform<R>,
    tolerance: R,
) -> bool {
    let n = xf.vector(mesh.normal(t));
    let v0 = xf.point(mesh.corners(t)[0]);
    let travel = n.dot(direction) * max;
    let reach = |towards: Vec3<R>| {
        let core = start.point(cast.core.support(start.inverse_vector(towards)));
        n.dot(core - v0)
    };
    let front = reach(-n) - cast.radius;
    let back = reach(n) + cast.radius;
    let front_min = front.min(front + travel);
    let back_max = back.max(back + travel);
    front_min <= tolerance && back_max >= -tolerance
}

/// Conservative advancement (see the [module](self)), with `contact(placement, margin)`
/// the manifold of the cast shape at that placement against the target (normal from the
/// cast shape towards the target).
fn advance<R: Real>(
    start: &Transform<R>,
    direction: Vec3<R>,
    max: R,
    contact: impl Fn(&Transform<R>, R) -> Manifold<R>,
) -> Option<CastHit<R>> {
    let tolerance = cast_tolerance::<R>();
    let max = max.clamp(R::ZERO, R::MAX * R::HALF);
    let limit = max + R::ONE;
    let mut t = R::ZERO;
    // The last distance found separated, and the first found overlapping.
    let mut separated = R::ZERO;
    let mut overlapping: Option<R> = None;
    for iteration in 0..MAX_ITERATIONS {
        let placed = Transform {
            rotation: start.rotation,
            translation: start.translation.add_scaled(direction, t),
        };
        // Points farther apart than the rest of the travel cannot be reached.
        let margin = (max - t) + tolerance;
        let manifold = contact(&placed, margin);
        let (separation, point) = deepest(&manifold)?;
        let touching = separation <= tolerance && (separation >= -tolerance || t == R::ZERO);
        if touching || iteration + 1 == MAX_ITERATIONS {
            return Some(CastHit {
                distance: t,
                point,
                normal: -manifold.normal,
            });
        }
        if separation < -tolerance {
            overlapping = Some(t);
        } else {
            separated = t;
        }
        t = match overlapping {
            Some(deep) => (separated + deep) * R::HALF,
            None => {
                let closing = manifold.normal.dot(direction);
                if closing <= R::ZERO {
                    return None;
                }
                t + clamped_ratio(separation, closing, limit)
            }
        };
        if t > max {
            return None;
        }
    }
    None
}

/// The smallest separation of a manifold's points and its point (the first on ties);
/// `None` for an empty manifold.
fn deepest<R: Real>(manifold: &Manifold<R>) -> Option<(R, Vec3<R>)> {
    let mut best: Option<(R, Vec3<R>)> = None;
    for p in manifold.points() {
        if best.is_none_or(|(s, _)| p.separation < s) {
            best = Some((p.separation, p.point));
        }
    }
    best
}
