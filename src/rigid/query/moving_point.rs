//! A point's path against moving bodies: where a particle moving from x₀ to x₁ during Δt
//! first enters a body, with each body seen moving with its own velocity (the world's
//! particle coupling).
//!
//! Body `i` moves with the velocity field u(x) = vᵢ + ωᵢ × (x − cᵢ) (m/s). Over a short
//! step the point's path relative to the body is x₀ → x₁ − u(x₀) Δt, and that segment is
//! cast as a ray against the body's shape. The body is placed where its velocity carries it
//! `elapsed` seconds into the tick, cᵢ + vᵢ·elapsed with its orientation at the tick's
//! start (the particle stage runs before the rigid stage, so the bodies have not moved yet
//! this tick). A path that starts inside a body ([`Crossing::Inside`]) does not hit it, so
//! a particle that a body has overtaken leaves it freely.

use core::cell::OnceCell;

use super::ray::{Crossing, Ray, ray_shape};
use super::{prune_pad, unit_direction};
use crate::math::{Real, Vec3};
use crate::rigid::aabb::Aabb;
use crate::rigid::filter::CollisionFilter;
use crate::rigid::system::RigidSystem;
use crate::rigid::transform::Transform;

/// Every body's placement `elapsed` seconds into the tick (its centre carried by its
/// velocity, its orientation at the tick's start), by slot, and how far any point of a
/// moving body travels by the end of the path's step: the largest (|vᵢ| + |ωᵢ| rᵢ)·(elapsed +
/// Δt), with rᵢ the half diagonal of the body's bounding box (0 for planes), m. It keeps
/// its memory, and the tree traversal's, from one substep and one cast to the next.
pub(crate) struct BodiesInMotion<R: Real> {
    placements: Vec<Transform<R>>,
    reach: R,
    stack: Vec<u32>,
}

impl<R: Real> Default for BodiesInMotion<R> {
    /// No bodies placed yet.
    fn default() -> Self {
        Self {
            placements: Vec::new(),
            reach: R::ZERO,
            stack: Vec::new(),
        }
    }
}

/// Where a point's path first enters a body.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct PathHit<R: Real> {
    /// The body's slot.
    pub slot: usize,
    /// Where along the relative path, in [0, 1].
    pub fraction: R,
    /// Unit normal out of the body at the hit.
    pub normal: Vec3<R>,
    /// The body's velocity u(x₀) at the path's start, m/s.
    pub velocity: Vec3<R>,
}

impl<R: Real> RigidSystem<R> {
    /// Places the bodies in `motion` as a particle stage sees them `elapsed` seconds into
    /// the tick, for paths of up to `dt` seconds ([`cast_moving_point`](Self::cast_moving_point)).
    pub(crate) fn place_in_motion(&self, elapsed: R, dt: R, motion: &mut BodiesInMotion<R>) {
        let b = &self.bodies;
        let placements = &mut motion.placements;
        placements.clear();
        let mut reach = R::ZERO;
        for i in 0..b.len() {
            if !b.is_moving(i) {
                placements.push(Transform::from_pose(b.position[i], b.orientation[i]));
                continue;
            }
            let v = b.linear_velocity[i];
            reach = reach.max(b.point_speed_bound(i) * (elapsed + dt));
            placements.push(Transform::from_pose(
                b.position[i].add_scaled(v, elapsed),
                b.orientation[i],
            ));
        }
        motion.reach = reach;
    }

    /// The first non-sensor body `filter` interacts with that the point moving from `from`
    /// to `to` (m) in `dt` seconds enters, each body placed as in `motion` and seen moving
    /// with its velocity at `from` (module documentation). Ties in fraction go to the lower
    /// handle.
    pub(crate) fn cast_moving_point(
        &self,
        motion: &mut BodiesInMotion<R>,
        from: Vec3<R>,
        to: Vec3<R>,
        dt: R,
        filter: CollisionFilter,
    ) -> Option<PathHit<R>> {
        let b = &self.bodies;
        let BodiesInMotion {
            placements,
            reach,
            stack,
        } = motion;
        let path = Aabb {
            min: from.min_elem(to),
            max: from.max_elem(to),
        }
        .expanded(*reach + prune_pad::<R>());
        // The path itself, for the bodies that do not move (most of a level): formed once,
        // when the first of them is met.
        let still = OnceCell::new();
        let mut best: Option<(PathHit<R>, crate::types::Handle)> = None;
        self.for_each_candidate_with(
            stack,
            |aabb| aabb.overlaps(&path),
            |i| {
                if !b.alive[i] || b.sensor[i] || !filter.interacts(b.filter[i]) {
                    return;
                }
                let Some(xf) = placements.get(i) else {
                    return;
                };
                let (velocity, ray) = if b.is_moving(i) {
                    let (v, w) = (b.linear_velocity[i], b.angular_velocity[i]);
                    let velocity = v + w.cross(from - xf.translation);
                    (velocity, ray_along(from, to - velocity * dt - from))
                } else {
                    (
                        Vec3::ZERO,
                        *still.get_or_init(|| ray_along(from, to - from)),
                    )
                };
                let Some((ray, length)) = ray else {
                    return;
                };
                let Some(Crossing::Enters { distance, normal }) = ray_shape(&b.shape[i], xf, &ray)
                else {
                    return;
                };
                let fraction = (distance / length).min(R::ONE);
                let handle = b.handle(i);
                if best.is_none_or(|(h, best_handle)| {
                    fraction < h.fraction || (fraction == h.fraction && handle < best_handle)
                }) {
                    let hit = PathHit {
                        slot: i,
                        fraction,
                        normal,
                        velocity,
                    };
                    best = Some((hit, handle));
                }
            },
        );
        best.map(|(hit, _)| hit)
    }
}

/// The ray along `path` from `from` and the path's length (m), or `None` for no motion.
fn ray_along<R: Real>(from: Vec3<R>, path: Vec3<R>) -> Option<(Ray<R>, R)> {
    let direction = unit_direction(path)?;
    let length = path.length();
    Some((Ray::new(from, direction, length), length))
}
