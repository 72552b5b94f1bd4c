//! Rays against shapes: where the ray x(t) = o + t·d (o in m, d a unit vector, t in m)
//! first meets a shape, taken as solid.
//!
//! Answers, for every shape:
//! - the origin inside the shape or on its surface: [`Crossing::Inside`] (distance 0);
//! - otherwise the smallest t in [0, max] at which x(t) lies in the shape, with the outward
//!   unit surface normal there; a ray that only touches the shape (grazing an edge, tangent
//!   to a sphere) hits at the touching distance when the rounded arithmetic finds the
//!   touch, and misses otherwise;
//! - no such t: `None`.
//!
//! Every quotient is formed by [`clamped_ratio`], so no input divides by zero or
//! overflows: huge inputs saturate.

use super::super::shape::Shape;
use super::super::transform::Transform;
use super::ray_hull::ray_hull;
use super::ray_mesh::ray_mesh;
use super::ray_round::{ray_cone, ray_cylinder};
use crate::math::{Real, Vec3};

/// A ray: origin (m), unit direction, and the farthest distance of interest (m).
#[derive(Clone, Copy, Debug)]
pub(super) struct Ray<R: Real> {
    /// Origin o, m.
    pub origin: Vec3<R>,
    /// Unit direction d.
    pub direction: Vec3<R>,
    /// Farthest distance t reported, m, in [0, MAX/2].
    pub max: R,
}

impl<R: Real> Ray<R> {
    /// The ray from `origin` along unit `direction` up to `max` (m), clamped to
    /// [0, MAX/2] so that `max + 1` is representable.
    pub fn new(origin: Vec3<R>, direction: Vec3<R>, max: R) -> Self {
        Self {
            origin,
            direction,
            max: max.clamp(R::ZERO, R::MAX * R::HALF),
        }
    }

    /// The bound quotients are clamped to: max + 1 m, past every distance of interest.
    pub fn limit(&self) -> R {
        self.max + R::ONE
    }

    /// The point o + t·d, m.
    pub fn at(&self, t: R) -> Vec3<R> {
        self.origin.add_scaled(self.direction, t)
    }

    /// The same ray in the frame of `xf` (the direction stays unit: `xf` is a rotation).
    fn local(&self, xf: &Transform<R>) -> Self {
        Self {
            origin: xf.inverse_point(self.origin),
            direction: xf.inverse_vector(self.direction),
            max: self.max,
        }
    }
}

/// Where a ray meets a shape.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) enum Crossing<R: Real> {
    /// The origin is in the shape (or on its surface).
    Inside,
    /// The ray enters the shape at `distance` (m) through the surface with outward unit
    /// normal `normal`.
    Enters { distance: R, normal: Vec3<R> },
}

impl<R: Real> Crossing<R> {
    /// The distance, m: 0 for [`Crossing::Inside`].
    pub fn distance(&self) -> R {
        match self {
            Self::Inside => R::ZERO,
            Self::Enters { distance, .. } => *distance,
        }
    }
}

/// num/den for den > 0, clamped to [−limit, limit] (limit > 0) without ever forming a
/// quotient that leaves the range: when den < 1 the quotient is compared through
/// num ≷ ±den·limit first (den·limit ≤ limit cannot overflow); when den ≥ 1 it is no
/// larger than num.
pub(super) fn clamped_ratio<R: Real>(num: R, den: R, limit: R) -> R {
    if den >= R::ONE {
        return (num / den).clamp(-limit, limit);
    }
    let cap = den * limit;
    if num >= cap {
        limit
    } else if num <= -cap {
        -limit
    } else {
        num / den
    }
}

/// The slab test: where the ray's line is within `min ≤ x ≤ max` on every axis.
#[derive(Clone, Copy, Debug)]
pub(super) struct Slabs<R: Real> {
    /// The largest entry distance over the axes, m (clamped to ±limit).
    pub enter: R,
    /// The axis of `enter` (the lowest on ties), 3 when no axis constrains the ray.
    pub axis: usize,
    /// The smallest exit distance over the axes, m (clamped to ±limit).
    pub exit: R,
}

/// For each axis k with d_k ≠ 0 the line is in the slab for t between
/// (lo_k − o_k)/d_k and (hi_k − o_k)/d_k; with d_k = 0 it is in it everywhere or nowhere.
/// `None` when the intervals do not meet (enter > exit) or a parallel slab misses. Distances
/// beyond `limit` (m) are clamped to ±`limit`, which keeps every comparison with a
/// distance below `limit` exact.
pub(super) fn slabs<R: Real>(
    min: Vec3<R>,
    max: Vec3<R>,
    ray: &Ray<R>,
    limit: R,
) -> Option<Slabs<R>> {
    let mut out = Slabs {
        enter: -limit,
        axis: 3,
        exit: limit,
    };
    for k in 0..3 {
        let (o, d, lo, hi) = (ray.origin[k], ray.direction[k], min[k], max[k]);
        if d == R::ZERO {
            if o < lo || o > hi {
                return None;
            }
            continue;
        }
        // With |d|: entering through the face the ray faces, leaving through the other.
        let (near, far) = if d > R::ZERO {
            (lo - o, hi - o)
        } else {
            (o - hi, o - lo)
        };
        let speed = d.abs();
        let t_near = clamped_ratio(near, speed, limit);
        let t_far = clamped_ratio(far, speed, limit);
        if t_near > out.enter {
            out.enter = t_near;
            out.axis = k;
        }
        out.exit = out.exit.min(t_far);
    }
    (out.enter <= out.exit).then_some(out)
}

/// The tree's pruning test for one ray, with the per-axis reciprocals formed once: a box
/// is tested by multiplications, not divisions. Conservative: it may pass a box the ray
/// misses by a hair, never fail one the ray meets within the distance asked.
///
/// On an axis with |d_k| ≥ 2⁻¹⁰ whose slab offsets are below 2¹⁶ m, the distance is
/// offset × (1/|d_k|): the reciprocal is off by at most 2⁻³³ (correctly rounded), so the
/// product is off by at most 2¹⁶·2⁻³³ + 2⁻³³ < 2⁻¹⁶ m, less than the `pad` (≥ 2⁻¹⁶ m, which
/// moves the distance by pad/|d_k| ≥ pad) covers. Every other axis divides as [`slabs`]
/// does. So the test passes every box the exact quotients say the ray meets (the test
/// `box_probe_is_never_stricter_than_exact_quotients`).
#[derive(Clone, Copy, Debug)]
pub(super) struct BoxProbe<R: Real> {
    origin: Vec3<R>,
    /// |d_k|, 0 for an axis the ray does not move along.
    speed: [R; 3],
    /// 1/|d_k| where the fast path applies (|d_k| ≥ 2⁻¹⁰), else 0.
    inverse: [R; 3],
    /// Whether d_k > 0.
    ahead: [bool; 3],
    pad: R,
    limit: R,
}

impl<R: Real> BoxProbe<R> {
    /// The probe of `ray` for boxes grown by `pad` (m, ≥ 2⁻¹⁶ m).
    pub fn new(ray: &Ray<R>, pad: R) -> Self {
        let slow = R::from_ratio(1, 1 << 10);
        let mut speed = [R::ZERO; 3];
        let mut inverse = [R::ZERO; 3];
        let mut ahead = [false; 3];
        for k in 0..3 {
            let d = ray.direction[k];
            speed[k] = d.abs();
            ahead[k] = d > R::ZERO;
            if speed[k] >= slow {
                inverse[k] = speed[k].recip();
            }
        }
        Self {
            origin: ray.origin,
            speed,
            inverse,
            ahead,
            pad,
            limit: ray.limit(),
        }
    }

    /// The entry distance (m, possibly negative) of the ray into `aabb` grown by the pad,
    /// when the ray's forward half meets it; `None` when it surely does not.
    #[inline]
    pub fn enter(&self, aabb: &crate::rigid::aabb::Aabb<R>) -> Option<R> {
        let near_bound = R::from_int(1 << 16);
        let mut enter = -self.limit;
        let mut exit = self.limit;
        for k in 0..3 {
            let (o, lo, hi) = (
                self.origin[k],
                aabb.min[k] - self.pad,
                aabb.max[k] + self.pad,
            );
            let speed = self.speed[k];
            if speed == R::ZERO {
                if o < lo || o > hi {
                    return None;
                }
                continue;
            }
            let (near, far) = if self.ahead[k] {
                (lo - o, hi - o)
            } else {
                (o - hi, o - lo)
            };
            let inverse = self.inverse[k];
            let (t_near, t_far) =
                if inverse != R::ZERO && near.abs() < near_bound && far.abs() < near_bound {
                    (near * inverse, far * inverse)
                } else {
                    (
                        clamped_ratio(near, speed, self.limit),
                        clamped_ratio(far, speed, self.limit),
                    )
                };
            enter = enter.max(t_near);
            exit = exit.min(t_far);
        }
        (exit >= R::ZERO && enter <= exit).then_some(enter)
    }

    /// Whether the ray meets the grown `aabb` within `reach` (m).
    #[inline]
    pub fn reaches(&self, aabb: &crate::rigid::aabb::Aabb<R>, reach: R) -> bool {
        self.enter(aabb).is_some_and(|e| e <= reach)
    }
}

/// Whether the ray can meet the box `aabb` grown by `pad` (m) within `reach` (m): the
/// pruning test with exact quotients, the reference [`BoxProbe`] is checked against. Rounding moves the slab distances by ulps; `pad` covers it.
#[cfg(test)]
pub(super) fn ray_reaches_box<R: Real>(
    aabb: &crate::rigid::aabb::Aabb<R>,
    pad: R,
    ray: &Ray<R>,
    reach: R,
) -> bool {
    let grown = aabb.expanded(pad);
    slabs(grown.min, grown.max, ray, ray.limit())
        .is_some_and(|s| s.exit >= R::ZERO && s.enter <= reach)
}

/// The ray against `shape` placed by `xf` (m): see the [module](self) for the answers
/// (cylinders and cones: [`ray_round`](super::ray_round), hulls:
/// [`ray_hull`](super::ray_hull); meshes and heightfields:
/// [`ray_mesh`](super::ray_mesh)). A compound answers for its nearest part (the first on ties); a plane body is the
/// half-space below its plane.
pub(super) fn ray_shape<R: Real>(
    shape: &Shape<R>,
    xf: &Transform<R>,
    ray: &Ray<R>,
) -> Option<Crossing<R>> {
    match shape {
        Shape::Sphere { radius } => ray_sphere(xf.translation, *radius, ray),
        Shape::Box { half_extents } => local_to_world(xf, ray_box(*half_extents, &ray.local(xf))),
        Shape::Capsule {
            radius,
            half_height,
        } => local_to_world(xf, ray_capsule(*radius, *half_height, &ray.local(xf))),
        Shape::Cylinder {
            radius,
            half_height,
        } => local_to_world(xf, ray_cylinder(*radius, *half_height, &ray.local(xf))),
        Shape::Cone {
            radius,
            half_height,
        } => local_to_world(xf, ray_cone(*radius, *half_height, &ray.local(xf))),
        Shape::ConvexHull { hull } => local_to_world(xf, ray_hull(hull, &ray.local(xf))),
        Shape::TriMesh { .. } | Shape::HeightField { .. } => {
            local_to_world(xf, ray_mesh(shape.triangles()?, &ray.local(xf)))
        }
        Shape::Plane { normal, offset } => {
            let n = xf.vector(*normal);
            ray_plane(n, *offset + n.dot(xf.translation), ray)
        }
        Shape::Compound { parts } => {
            let mut best: Option<Crossing<R>> = None;
            for part in parts {
                let local = Transform::from_pose(part.translation, part.rotation);
                if let Some(hit) = ray_shape(&part.shape, &xf.compose(&local), ray)
                    && best.is_none_or(|b| hit.distance() < b.distance())
                {
                    best = Some(hit);
                }
            }
            best
        }
    }
}

/// A crossing found in the frame of `xf`, with its normal turned to the world frame.
fn local_to_world<R: Real>(xf: &Transform<R>, hit: Option<Crossing<R>>) -> Option<Crossing<R>> {
    hit.map(|hit| match hit {
        Crossing::Inside => Crossing::Inside,
        Crossing::Enters { distance, normal } => Crossing::Enters {
            distance,
            normal: xf.vector(normal),
        },
    })
}

/// Ray against the ball |x − c| ≤ r (c and r in m).
///
/// With m = o − c the origin is inside when |m|² ≤ r². Otherwise, with b = m·d, the ray
/// misses when b ≥ 0 (it moves away); no point before t₀ = max(0, −b − r) can lie in the
/// ball, so the ray first skips to t₀ (a far origin then never squares a large m). From
/// there, with m' = m + t₀d, b' = m'·d and k = |m'|² − r², |x − c|² = r² reads
/// t² + 2b't + k = 0, and the ray enters (when b'² − k ≥ 0) at the smaller root written
/// as t = k / (−b' + √(b'² − k)), which does not lose digits to cancellation near the
/// surface. Distance t₀ + t; normal (x − c)/|x − c|.
pub(super) fn ray_sphere<R: Real>(centre: Vec3<R>, radius: R, ray: &Ray<R>) -> Option<Crossing<R>> {
    let d = ray.direction;
    let m = ray.origin - centre;
    if m.length_squared() <= radius * radius {
        return Some(Crossing::Inside);
    }
    let b = m.dot(d);
    if b >= R::ZERO {
        return None;
    }
    let skip = (-b - radius).max(R::ZERO);
    if skip > ray.max {
        return None;
    }
    let m = m.add_scaled(d, skip);
    let k = m.length_squared() - radius * radius;
    let b = m.dot(d);
    let t = if k <= R::ZERO {
        R::ZERO
    } else {
        let discriminant = b * b - k;
        if b >= R::ZERO || discriminant < R::ZERO {
            return None;
        }
        clamped_ratio(k, discriminant.sqrt() - b, ray.limit())
    };
    let distance = skip + t;
    if distance > ray.max {
        return None;
    }
    let normal = (m.add_scaled(d, t)).try_normalize().map_or(-d, |(n, _)| n);
    Some(Crossing::Enters { distance, normal })
}

/// Ray (in the box frame) against the box |x_k| ≤ h_k (m): inside when |o_k| ≤ h_k on
/// every axis; otherwise the [slab test](slabs) enters at t = max_k of the entry distances
/// through the face of that axis (the lowest axis on ties, at an edge or a corner), normal
/// −sign(d_k) e_k.
pub(super) fn ray_box<R: Real>(half: Vec3<R>, ray: &Ray<R>) -> Option<Crossing<R>> {
    let o = ray.origin;
    if o.x.abs() <= half.x && o.y.abs() <= half.y && o.z.abs() <= half.z {
        return Some(Crossing::Inside);
    }
    let s = slabs(-half, half, ray, ray.limit())?;
    if s.exit < R::ZERO || s.enter > ray.max || s.axis > 2 {
        return None;
    }
    let mut normal = Vec3::ZERO;
    let sign = -ray.direction[s.axis].signum();
    match s.axis {
        0 => normal.x = sign,
        1 => normal.y = sign,
        _ => normal.z = sign,
    }
    Some(Crossing::Enters {
        distance: s.enter.max(R::ZERO),
        normal,
    })
}

/// Ray (in the capsule frame) against the points within r (m) of the segment from
/// (0, −h, 0) to (0, h, 0).
///
/// Inside when the origin's distance to the segment is ≤ r. Otherwise the ray first skips
/// to t₀ = max(0, −o·d − (h + r)), before which it is farther than h + r from the centre
/// (as for [`ray_sphere`]), and the first hit is the nearest of: the side, the cylinder
/// x² + z² = r², entered at t₀ + k / (−b + √(b² − ak)) with a = d_x² + d_z²,
/// b = o_x d_x + o_z d_z, k = o_x² + o_z² − r² at the skipped-to origin o (when k > 0,
/// b < 0, b² ≥ ak) provided |y| ≤ h there, normal (x, 0, z)/r; and the two end balls.
pub(super) fn ray_capsule<R: Real>(radius: R, half_height: R, ray: &Ray<R>) -> Option<Crossing<R>> {
    let axis_point = Vec3::new(
        R::ZERO,
        ray.origin.y.clamp(-half_height, half_height),
        R::ZERO,
    );
    if (ray.origin - axis_point).length_squared() <= radius * radius {
        return Some(Crossing::Inside);
    }
    let skip = (-ray.origin.dot(ray.direction) - (half_height + radius)).max(R::ZERO);
    if skip > ray.max {
        return None;
    }
    let near = Ray {
        origin: ray.at(skip),
        direction: ray.direction,
        max: ray.max - skip,
    };
    let d = near.direction;
    let mut best: Option<Crossing<R>> = ray_tube(radius, half_height, &near)
        .map(|(distance, normal)| Crossing::Enters { distance, normal });
    for end in [-half_height, half_height] {
        let centre = Vec3::new(R::ZERO, end, R::ZERO);
        if let Some(hit) = ray_sphere(centre, radius, &near)
            && best.is_none_or(|b| hit.distance() < b.distance())
        {
            best = Some(hit);
        }
    }
    best.map(|hit| match hit {
        Crossing::Inside => Crossing::Enters {
            distance: skip,
            normal: -d,
        },
        Crossing::Enters { distance, normal } => Crossing::Enters {
            distance: skip + distance,
            normal,
        },
    })
}

/// Where a ray from outside the infinite cylinder x² + z² ≤ r² (m) enters its side between
/// y = −h and y = h: (o_x + t d_x)² + (o_z + t d_z)² = r², i.e. a t² + 2b t + k = 0 with
/// a = d_x² + d_z², b = o_x d_x + o_z d_z, k = o_x² + o_z² − r² (m²), entered when k > 0,
/// b < 0 and b² ≥ a k, at t = k / (−b + √(b² − a k)) (m, the form that does not cancel),
/// kept when t is within the ray and |y| ≤ h there; the normal (x, 0, z)/r (−d when that
/// is too short to normalise). The side of capsules and cylinders.
pub(super) fn ray_tube<R: Real>(radius: R, half_height: R, ray: &Ray<R>) -> Option<(R, Vec3<R>)> {
    let (o, d) = (ray.origin, ray.direction);
    let a = d.x * d.x + d.z * d.z;
    let b = o.x * d.x + o.z * d.z;
    let k = o.x * o.x + o.z * o.z - radius * radius;
    if k <= R::ZERO || b >= R::ZERO {
        return None;
    }
    let discriminant = b * b - a * k;
    if discriminant < R::ZERO {
        return None;
    }
    let t = clamped_ratio(k, discriminant.sqrt() - b, ray.limit());
    let p = ray.at(t);
    (t <= ray.max && p.y.abs() <= half_height).then(|| {
        let normal = Vec3::new(p.x, R::ZERO, p.z)
            .try_normalize()
            .map_or(-d, |(n, _)| n);
        (t, normal)
    })
}

/// Ray against the half-space n·x ≤ c (n unit, c in m, world frame). With s = n·o − c the
/// origin is inside when s ≤ 0; otherwise the ray enters when n·d < 0, at t = s / (−n·d),
/// normal n.
pub(super) fn ray_plane<R: Real>(normal: Vec3<R>, offset: R, ray: &Ray<R>) -> Option<Crossing<R>> {
    let s = normal.dot(ray.origin) - offset;
    if s <= R::ZERO {
        return Some(Crossing::Inside);
    }
    let approach = -normal.dot(ray.direction);
    if approach <= R::ZERO {
        return None;
    }
    let t = clamped_ratio(s, approach, ray.limit());
    (t <= ray.max).then_some(Crossing::Enters {
        distance: t,
        normal,
    })
}
