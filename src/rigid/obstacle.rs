//! Dynamic bodies against a kinematic obstacle that is not a body (a character): after the
//! rigid stage has moved the bodies, each awake dynamic body that overlaps the obstacle is
//! put back where it touches it and loses its approach, as against an immovable body.

use super::aabb::Aabb;
use super::filter::QueryFilter;
use super::query::{cast_shape, unit_direction};
use super::shape::Shape;
use super::system::RigidSystem;
use super::transform::Transform;
use crate::math::{Quat, Real, Vec3};
use crate::types::Handle;

/// How one body was knocked off an obstacle.
struct Knock<R: Real> {
    /// How far the body is moved, m.
    displacement: Vec3<R>,
    /// Unit contact normal, from the body towards the obstacle.
    normal: Vec3<R>,
    /// The contact point once the body is moved, m.
    point: Vec3<R>,
}

impl<R: Real> RigidSystem<R> {
    /// The obstacle `shape` (convex, unrotated) at `position` (m), moving at `velocity`
    /// (m/s), against the awake dynamic bodies `filter` accepts that overlap it, ascending by
    /// handle. Each such body is:
    ///
    /// 1. **moved back to touching** the obstacle: to where its motion d = v dt of the last
    ///    `dt` seconds first met it (a cast of the obstacle from x + d along −d against the
    ///    body, which undoes the rest of d), or, when it already touched it before that
    ///    motion, out along the contact normal n by the overlap's depth (a cast of the
    ///    obstacle from x + n L back along −n, L beyond both shapes' extents);
    /// 2. **stopped against it** at the contact point p (r = p − c): when its velocity there
    ///    relative to the obstacle approaches it, v_n = (v + ω × r − v_o)·n > 0, it takes
    ///    the impulse of a frictionless collision with an immovable body,
    ///    J = −(1 + e) v_n n / (1/m + (r × n)·I⁻¹(r × n)), e its material's restitution when
    ///    v_n exceeds the restitution threshold, 0 otherwise.
    ///
    /// A body knocked stays awake (its sleep timer restarts, as for a body touching a moving
    /// kinematic body), so that it falls once the obstacle leaves. Returns the handles of
    /// the bodies knocked, ascending; the query index is brought up to date when one moved.
    pub(crate) fn knock_off_obstacle(
        &mut self,
        shape: &Shape<R>,
        position: Vec3<R>,
        velocity: Vec3<R>,
        dt: R,
        filter: &QueryFilter,
    ) -> Vec<Handle> {
        let mut knocked = Vec::new();
        for handle in self.overlap(shape, position, Quat::IDENTITY, filter) {
            let Some(i) = self.bodies.slot(handle) else {
                continue;
            };
            if !self.bodies.is_awake_dynamic(i) {
                continue;
            }
            let Some(knock) = self.knock(i, shape, position, dt) else {
                continue;
            };
            self.displace_body(i, knock.displacement, Vec3::ZERO);
            self.stop_against(i, knock.normal, knock.point, velocity);
            self.bodies.sleep_time[i] = R::ZERO;
            knocked.push(handle);
        }
        if !knocked.is_empty() {
            self.update_query_index();
        }
        knocked
    }

    /// Where body `i` touches the obstacle (see [`knock_off_obstacle`](Self::knock_off_obstacle),
    /// step 1); `None` when no cast finds the contact.
    fn knock(&self, i: usize, shape: &Shape<R>, position: Vec3<R>, dt: R) -> Option<Knock<R>> {
        let b = &self.bodies;
        let xf = Transform::from_pose(b.position[i], b.orientation[i]);
        let body = &b.shape[i];
        let at = |p: Vec3<R>| Transform::from_pose(p, Quat::IDENTITY);
        // The body's motion d: the obstacle, seen from the body, moved by −d.
        let d = b.linear_velocity[i] * dt;
        if let Some(u) = unit_direction(d) {
            let len = d.length();
            if let Some(hit) = cast_shape(shape, &at(position + d), -u, len, body, &xf)
                && hit.distance > R::ZERO
            {
                let displacement = -u * (len - hit.distance);
                return Some(Knock {
                    displacement,
                    normal: hit.normal,
                    point: hit.point + displacement,
                });
            }
        }
        // Already touching before that motion: out along the contact normal.
        let touch = cast_shape(shape, &at(position), Vec3::Y, R::ZERO, body, &xf)?;
        let n = touch.normal;
        let reach = |a: Option<Aabb<R>>| a.map_or(R::ZERO, |a| (a.max - a.min).length());
        let l = reach(Aabb::of_shape(shape, &at(position))) + reach(Aabb::of_shape(body, &xf));
        let hit = cast_shape(shape, &at(position + n * l), -n, l, body, &xf)?;
        let displacement = -n * (l - hit.distance);
        Some(Knock {
            displacement,
            normal: n,
            point: hit.point + displacement,
        })
    }

    /// Body `i`'s approach to an immovable obstacle moving at `velocity` (m/s), along the
    /// unit `normal` (from the body towards the obstacle) at the contact `point` (m),
    /// removed (see [`knock_off_obstacle`](Self::knock_off_obstacle), step 2).
    fn stop_against(&mut self, i: usize, normal: Vec3<R>, point: Vec3<R>, velocity: Vec3<R>) {
        let b = &self.bodies;
        let r = point - b.position[i];
        let approach =
            (b.linear_velocity[i] + b.angular_velocity[i].cross(r) - velocity).dot(normal);
        if approach <= R::ZERO {
            return;
        }
        let inv_inertia = b.orientation[i].to_mat3().rotate_inertia(b.inv_inertia[i]);
        let rn = r.cross(normal);
        let k = b.inv_mass[i] + rn.dot(inv_inertia * rn);
        if k <= R::ZERO {
            return;
        }
        let e = if approach > self.settings.restitution_threshold {
            b.material[i].restitution
        } else {
            R::ZERO
        };
        let impulse = normal * (-(R::ONE + e) * approach / k);
        self.push_body(i, impulse, point);
    }
}
