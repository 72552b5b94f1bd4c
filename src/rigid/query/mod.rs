//! Scene queries against the rigid bodies: rays, shape casts, overlaps and the closest
//! point, for game code (line of sight, ground checks, area triggers, picking).
//!
//! Every query looks at the live bodies its [`QueryFilter`] accepts, tests each candidate
//! exactly with the shape's own function, and orders results by (distance, handle), so its
//! answer is a function of the state alone. Candidates come from the bounding-volume tree
//! of the query index ([`index`], [`tree`]) when it is current, and from every live body
//! otherwise (after a restore or an added body, until the next step): the same answers
//! either way. Planes, which have no box, are tested by every query. The user guide is
//! `docs/queries.md`.
//!
//! # Files
//!
//! [`ray`] rays against shapes · [`ray_round`] rays against cylinders and cones ·
//! [`ray_hull`] rays against convex hulls · [`ray_mesh`] and [`point_mesh`] rays and
//! closest points on meshes and heightfields · [`shape_cast`] swept shapes · [`overlap`]
//! shared points · [`point`] closest points · [`point_hull`] closest points of hulls ·
//! [`moving_point`] a particle's path against moving bodies · [`ball_contact`](mod@ball_contact) a soft
//! vertex against a shape · [`parts`] a compound's parts · [`tree`] the dynamic AABB tree · [`index`] the tree
//! kept current by the step.

mod ball_contact;
mod index;
mod moving_point;
mod overlap;
mod parts;
mod point;
mod point_hull;
mod point_mesh;
mod ray;
mod ray_hull;
mod ray_mesh;
mod ray_round;
mod shape_cast;
#[cfg(test)]
mod tests;
mod tree;

use core::cell::Cell;

pub(crate) use self::ball_contact::ball_contact;
pub(crate) use self::index::QueryIndex;
pub(crate) use self::moving_point::BodiesInMotion;
use self::overlap::shapes_overlap;
use self::point::project_point;
pub(crate) use self::point::shape_contains;
use self::ray::{BoxProbe, Crossing, Ray, ray_shape};
pub(crate) use self::shape_cast::{CastHit, cast_shape, cast_tolerance, sweep_shape};
use super::aabb::Aabb;
use super::filter::QueryFilter;
use super::shape::Shape;
use super::system::RigidSystem;
use super::transform::Transform;
use crate::math::{Fx, Quat, Real, Vec3};
use crate::types::Handle;

/// Where a ray or a cast shape first meets a body.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RayHit<R: Real = Fx> {
    /// The body hit.
    pub body: Handle,
    /// Distance travelled along the unit direction, m.
    pub distance: R,
    /// The hit point in the world frame, m (for a shape cast, the contact point).
    pub point: Vec3<R>,
    /// Unit surface normal at the hit, pointing out of the body hit (towards the ray's
    /// origin side, or towards the cast shape).
    pub normal: Vec3<R>,
}

/// The point of a body closest to a query point.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PointProjection<R: Real = Fx> {
    /// The body.
    pub body: Handle,
    /// The closest point of the body's surface, m; the query point itself when `inside`.
    pub point: Vec3<R>,
    /// Whether the query point lies in the body (solid shapes, surface included).
    pub inside: bool,
    /// Distance from the query point to `point`, m; 0 when `inside`.
    pub distance: R,
}

/// How far past rounding the tree's pruning boxes are grown, m: 2⁻¹⁶ m.
fn prune_pad<R: Real>() -> R {
    R::from_ratio(1, 1 << 16)
}

/// The unit vector along `v`, or `None` for the zero vector. `v` is first scaled by a power
/// of two so that its largest component lies in [½, 2¹⁴): tiny and huge directions then
/// normalise as precisely as unit ones, and |v|² never saturates. Each component is then
/// divided by |v|.
pub(crate) fn unit_direction<R: Real>(v: Vec3<R>) -> Option<Vec3<R>> {
    let largest = |v: Vec3<R>| v.abs().max_component();
    if largest(v) == R::ZERO {
        return None;
    }
    let mut v = v;
    let large = R::from_int(1 << 14);
    for _ in 0..128 {
        let m = largest(v);
        if m >= large {
            v = Vec3::new(
                v.x.mul_pow2_recip(1),
                v.y.mul_pow2_recip(1),
                v.z.mul_pow2_recip(1),
            );
        } else if m < R::HALF {
            v *= R::TWO;
        } else {
            break;
        }
    }
    // Three correctly rounded quotients: an axis direction comes out exact.
    let length = v.length();
    (length > R::ZERO).then(|| Vec3::new(v.x / length, v.y / length, v.z / length))
}

/// Whether (distance, handle) comes before the best so far.
fn precedes<R: Real>(distance: R, handle: Handle, best: Option<(R, Handle)>) -> bool {
    best.is_none_or(|(d, h)| distance < d || (distance == d && handle < h))
}

impl<R: Real> RigidSystem<R> {
    /// First hit along the ray from `origin` (m) along `direction` (any nonzero length; it
    /// is normalised) within `max_distance` (m along the unit direction), among the bodies
    /// `filter` accepts; ties in distance go to the lower handle.
    ///
    /// Shapes are solid: a ray starting inside a body (or on its surface) hits it at
    /// distance 0 with point = origin and normal = −direction. A ray that only grazes a
    /// shape (an edge, a tangent sphere) hits at the touching distance or misses, as the
    /// rounding falls. `None` for a zero direction, a negative `max_distance` or no hit.
    pub fn cast_ray(
        &self,
        origin: Vec3<R>,
        direction: Vec3<R>,
        max_distance: R,
        filter: &QueryFilter,
    ) -> Option<RayHit<R>> {
        let ray = self.query_ray(origin, direction, max_distance)?;
        let reach = Cell::new(ray.max);
        let probe = BoxProbe::new(&ray, prune_pad::<R>());
        let mut best: Option<(R, Handle, Crossing<R>)> = None;
        let mut visit = |i: usize| {
            if let Some((handle, crossing)) = self.ray_against(i, &ray, &probe, filter) {
                let distance = crossing.distance();
                if precedes(distance, handle, best.map(|(d, h, _)| (d, h))) {
                    best = Some((distance, handle, crossing));
                    reach.set(distance);
                }
            }
        };
        let index = &self.scratch.query;
        if index.is_current(self.bodies.len()) {
            // Nearest boxes first, so that a hit soon cuts off the farther subtrees; a box
            // entered at exactly the best distance is still visited (ties go by handle).
            index.candidates_nearest(
                |aabb| probe.enter(aabb).filter(|&e| e <= reach.get()),
                || reach.get(),
                &mut visit,
            );
        } else {
            for i in 0..self.bodies.len() {
                visit(i);
            }
        }
        best.map(|(_, handle, crossing)| ray_hit(&ray, handle, crossing))
    }

    /// Every body the ray hits (its nearest hit each, with the answers of
    /// [`cast_ray`](Self::cast_ray)), sorted by (distance, handle).
    pub fn cast_ray_all(
        &self,
        origin: Vec3<R>,
        direction: Vec3<R>,
        max_distance: R,
        filter: &QueryFilter,
    ) -> Vec<RayHit<R>> {
        let Some(ray) = self.query_ray(origin, direction, max_distance) else {
            return Vec::new();
        };
        let probe = BoxProbe::new(&ray, prune_pad::<R>());
        let mut hits = Vec::new();
        self.for_each_candidate(
            |aabb| probe.reaches(aabb, ray.max),
            |i| {
                if let Some((handle, crossing)) = self.ray_against(i, &ray, &probe, filter) {
                    hits.push(ray_hit(&ray, handle, crossing));
                }
            },
        );
        hits.sort_by(|a, b| a.distance.total_cmp(&b.distance).then(a.body.cmp(&b.body)));
        hits
    }

    /// `shape` (any convex shape: sphere, box, capsule, cylinder, cone or hull) at `position` (m) and `orientation`, translated
    /// along `direction` (normalised) by up to `max_distance` (m): the first accepted body
    /// it touches, ties to the lower handle. `distance` is the travel along the unit
    /// direction at impact (within 2⁻²⁰ m of touching: see `shape_cast.rs`), `point` the
    /// contact point, `normal` the unit normal from the body hit towards the cast shape.
    /// A shape that already touches or overlaps a body hits it at distance 0 with the
    /// narrowphase's contact normal. `None` for a plane or compound `shape`, a zero
    /// direction, a negative `max_distance` or no hit.
    pub fn cast_shape(
        &self,
        shape: &Shape<R>,
        position: Vec3<R>,
        orientation: Quat<R>,
        direction: Vec3<R>,
        max_distance: R,
        filter: &QueryFilter,
    ) -> Option<RayHit<R>> {
        if matches!(shape, Shape::Plane { .. } | Shape::Compound { .. }) {
            return None;
        }
        let ray = self.query_ray(position, direction, max_distance)?;
        let start = Transform::from_pose(position, orientation.normalize());
        let own = Aabb::of_shape(shape, &start)?;
        // The shape's box centre moves along the ray; a body's box is reached when it
        // meets the body's box grown by the shape's half extents (and the tolerance).
        let centre = Ray::new((own.min + own.max) * R::HALF, ray.direction, ray.max);
        let half = (own.max - own.min) * R::HALF;
        let probe = BoxProbe::new(&centre, prune_pad::<R>() + cast_tolerance::<R>());
        let reach = Cell::new(ray.max);
        let mut best: Option<(R, Handle)> = None;
        let mut found = None;
        self.for_each_candidate(
            |aabb| {
                let grown = Aabb {
                    min: aabb.min - half,
                    max: aabb.max + half,
                };
                probe.reaches(&grown, reach.get())
            },
            |i| {
                if !self.query_accepts(i, filter) {
                    return;
                }
                let handle = self.bodies.handle(i);
                let xf = self.query_placement(i);
                let body = &self.bodies.shape[i];
                // The same tight-box test on both paths (tree or every body).
                let near = Aabb::of_shape(body, &xf).is_none_or(|b| {
                    let grown = Aabb {
                        min: b.min - half,
                        max: b.max + half,
                    };
                    probe.reaches(&grown, ray.max)
                });
                if !near {
                    return;
                }
                let Some(hit) = cast_shape(shape, &start, ray.direction, ray.max, body, &xf) else {
                    return;
                };
                if precedes(hit.distance, handle, best) {
                    best = Some((hit.distance, handle));
                    reach.set(hit.distance);
                    found = Some(RayHit {
                        body: handle,
                        distance: hit.distance,
                        point: hit.point,
                        normal: hit.normal,
                    });
                }
            },
        );
        found
    }

    /// Handles of the accepted bodies that overlap or touch `shape` at `position` (m) and
    /// `orientation`, ascending. `shape` may be a sphere, box, capsule or compound; a
    /// plane gives an empty list.
    pub fn overlap(
        &self,
        shape: &Shape<R>,
        position: Vec3<R>,
        orientation: Quat<R>,
        filter: &QueryFilter,
    ) -> Vec<Handle> {
        let xf = Transform::from_pose(position, orientation.normalize());
        let Some(own) = Aabb::of_shape(shape, &xf) else {
            return Vec::new();
        };
        let mut found = Vec::new();
        self.for_each_candidate(
            |aabb| aabb.overlaps(&own),
            |i| {
                if !self.query_accepts(i, filter) {
                    return;
                }
                let body_xf = self.query_placement(i);
                let body = &self.bodies.shape[i];
                // The same tight-box test on both paths (tree or every body).
                let near = Aabb::of_shape(body, &body_xf).is_none_or(|b| b.overlaps(&own));
                if near && shapes_overlap(shape, &xf, body, &body_xf) {
                    found.push(self.bodies.handle(i));
                }
            },
        );
        found.sort_unstable();
        found
    }

    /// The closest point of any accepted body to `point` (m) within `max_distance` (m),
    /// ties to the lower handle. A point inside a body (surface included) answers that
    /// body with `inside`, distance 0 and the query point itself. `None` when no accepted
    /// body is within `max_distance` (or it is negative).
    pub fn project_point(
        &self,
        point: Vec3<R>,
        max_distance: R,
        filter: &QueryFilter,
    ) -> Option<PointProjection<R>> {
        if max_distance < R::ZERO {
            return None;
        }
        let max = max_distance.min(R::MAX * R::HALF);
        let reach = Cell::new(max);
        let pad = prune_pad::<R>();
        let within = |aabb: &Aabb<R>, reach: R| aabb.expanded(reach + pad).contains_point(point);
        let mut best: Option<(R, Handle)> = None;
        let mut found = None;
        self.for_each_candidate(
            |aabb| within(aabb, reach.get()),
            |i| {
                if !self.query_accepts(i, filter) {
                    return;
                }
                let handle = self.bodies.handle(i);
                let xf = self.query_placement(i);
                let body = &self.bodies.shape[i];
                // The same tight-box test on both paths (tree or every body).
                if !Aabb::of_shape(body, &xf).is_none_or(|b| within(&b, max)) {
                    return;
                }
                let p = project_point(body, &xf, point);
                if p.distance <= max && precedes(p.distance, handle, best) {
                    best = Some((p.distance, handle));
                    reach.set(p.distance);
                    found = Some(PointProjection {
                        body: handle,
                        point: p.point,
                        inside: p.inside,
                        distance: p.distance,
                    });
                }
            },
        );
        found
    }

    /// Brings the query index up to date at the end of a step: the bodies that moved
    /// (those the step moved, `scratch.active`, and those moving now), bodies added or
    /// removed; a full rebuild after a restore.
    pub(crate) fn update_query_index(&mut self) {
        let scratch = &mut self.scratch;
        let bodies = &self.bodies;
        let active = &scratch.active;
        scratch.query.sync(bodies, |i| {
            bodies.is_moving(i) || active.get(i).copied().unwrap_or(true)
        });
    }

    /// The ray of a query, or `None` for a zero direction or a negative distance.
    fn query_ray(&self, origin: Vec3<R>, direction: Vec3<R>, max_distance: R) -> Option<Ray<R>> {
        if max_distance < R::ZERO {
            return None;
        }
        Some(Ray::new(origin, unit_direction(direction)?, max_distance))
    }

    /// Whether slot `i` holds a live body that `filter` accepts.
    fn query_accepts(&self, i: usize, filter: &QueryFilter) -> bool {
        let b = &self.bodies;
        b.alive[i] && filter.accepts(b.filter[i], b.sensor[i], b.handle(i))
    }

    /// The current placement of slot `i`'s body.
    fn query_placement(&self, i: usize) -> Transform<R> {
        Transform::from_pose(self.bodies.position[i], self.bodies.orientation[i])
    }

    /// The ray against slot `i`'s body, when `filter` accepts it.
    fn ray_against(
        &self,
        i: usize,
        ray: &Ray<R>,
        probe: &BoxProbe<R>,
        filter: &QueryFilter,
    ) -> Option<(Handle, Crossing<R>)> {
        if !self.query_accepts(i, filter) {
            return None;
        }
        let xf = self.query_placement(i);
        let shape = &self.bodies.shape[i];
        // The same tight-box test on both paths (tree or every body).
        let near = Aabb::of_shape(shape, &xf).is_none_or(|b| probe.reaches(&b, ray.max));
        if !near {
            return None;
        }
        Some((self.bodies.handle(i), ray_shape(shape, &xf, ray)?))
    }

    /// Calls `visit(slot)` for every candidate slot: from the tree when the index is
    /// current (`keep` prunes by box), otherwise every slot.
    fn for_each_candidate(&self, keep: impl FnMut(&Aabb<R>) -> bool, visit: impl FnMut(usize)) {
        self.for_each_candidate_with(&mut Vec::new(), keep, visit);
    }

    /// [`for_each_candidate`](Self::for_each_candidate) with `stack` as the tree traversal's
    /// memory.
    pub(crate) fn for_each_candidate_with(
        &self,
        stack: &mut Vec<u32>,
        keep: impl FnMut(&Aabb<R>) -> bool,
        mut visit: impl FnMut(usize),
    ) {
        let index = &self.scratch.query;
        if index.is_current(self.bodies.len()) {
            index.candidates_with(stack, keep, visit);
        } else {
            for i in 0..self.bodies.len() {
                visit(i);
            }
        }
    }
}

/// The public hit of a ray crossing.
fn ray_hit<R: Real>(ray: &Ray<R>, body: Handle, crossing: Crossing<R>) -> RayHit<R> {
    match crossing {
        Crossing::Inside => RayHit {
            body,
            distance: R::ZERO,
            point: ray.origin,
            normal: -ray.direction,
        },
        Crossing::Enters { distance, normal } => RayHit {
            body,
            distance,
            point: ray.at(distance),
            normal,
        },
    }
}
