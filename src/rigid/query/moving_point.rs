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

use super::ray::{BoxProbe, Crossing, Ray, ray_shape};
use super::{prune_pad, unit_direction};
use crate::math::{Real, Vec3};
use crate::rigid::aabb::Aabb;
use crate::rigid::filter::CollisionFilter;
use crate::rigid::system::RigidSystem;
use crate::rigid::transform::Transform;

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
    /// How far any point of a moving body can travel in `time` seconds at the current
    /// velocities, m: the largest (|vᵢ| + |ωᵢ| rᵢ)·time, with rᵢ the half diagonal of the
    /// body's bounding box (0 for planes).
    pub(crate) fn moving_reach(&self, time: R) -> R {
        let b = &self.bodies;
        let mut reach = R::ZERO;
        for i in 0..b.len() {
            if !b.is_moving(i) {
                continue;
            }
            let xf = Transform::from_pose(b.position[i], b.orientation[i]);
            let radius = Aabb::of_shape(&b.shape[i], &xf)
                .map_or(R::ZERO, |a| (a.max - a.min).length() * R::HALF);
            let speed = b.linear_velocity[i].length() + b.angular_velocity[i].length() * radius;
            reach = reach.max(speed * time);
        }
        reach
    }

    /// The first non-sensor body `filter` interacts with that the point moving from `from`
    /// to `to` (m) in `dt` seconds enters, each body placed `elapsed` seconds into the tick
    /// and seen moving with its velocity at `from` (module documentation). `reach` (m)
    /// bounds how far any body moves by then ([`moving_reach`](Self::moving_reach) of
    /// `elapsed + dt`). Ties in fraction go to the lower handle.
    pub(crate) fn cast_moving_point(
        &self,
        from: Vec3<R>,
        to: Vec3<R>,
        dt: R,
        elapsed: R,
        reach: R,
        filter: CollisionFilter,
    ) -> Option<PathHit<R>> {
        let b = &self.bodies;
        let path = Aabb {
            min: from.min_elem(to),
            max: from.max_elem(to),
        }
        .expanded(reach + prune_pad::<R>());
        let mut best: Option<(PathHit<R>, crate::types::Handle)> = None;
        self.for_each_candidate(
            |aabb| aabb.overlaps(&path),
            |i| {
                if !b.alive[i] || b.sensor[i] || !filter.interacts(b.filter[i]) {
                    return;
                }
                let moving = b.is_moving(i);
                let (v, w) = if moving {
                    (b.linear_velocity[i], b.angular_velocity[i])
                } else {
                    (Vec3::ZERO, Vec3::ZERO)
                };
                let centre = b.position[i].add_scaled(v, elapsed);
                let velocity = v + w.cross(from - centre);
                let relative = to - velocity * dt - from;
                let Some(direction) = unit_direction(relative) else {
                    return;
                };
                let length = relative.length();
                let ray = Ray::new(from, direction, length);
                let xf = Transform::from_pose(centre, b.orientation[i]);
                let shape = &b.shape[i];
                let probe = BoxProbe::new(&ray, prune_pad::<R>());
                if !Aabb::of_shape(shape, &xf).is_none_or(|a| probe.reaches(&a, ray.max)) {
                    return;
                }
                let Some(Crossing::Enters { distance, normal }) = ray_shape(shape, &xf, &ray)
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
