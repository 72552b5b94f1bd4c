//! The scene queries of the rigid bodies, asked of the world: each forwards to the
//! [`RigidSystem`](crate::rigid::RigidSystem) method of the same name, and answers `None`
//! or an empty list when the scene has no rigid bodies. See `docs/queries.md`.

use super::pipeline::World;
use crate::math::{Quat, Real, Vec3};
use crate::rigid::{PointProjection, QueryFilter, RayHit, Shape};
use crate::types::Handle;

impl<R: Real> World<R> {
    /// [`RigidSystem::cast_ray`](crate::rigid::RigidSystem::cast_ray): the first body hit
    /// along the ray from `origin` (m) along `direction` within `max_distance` (m).
    pub fn cast_ray(
        &self,
        origin: Vec3<R>,
        direction: Vec3<R>,
        max_distance: R,
        filter: &QueryFilter,
    ) -> Option<RayHit<R>> {
        self.rigid()?
            .cast_ray(origin, direction, max_distance, filter)
    }

    /// [`RigidSystem::cast_ray_all`](crate::rigid::RigidSystem::cast_ray_all): every body
    /// the ray hits, sorted by (distance, handle).
    pub fn cast_ray_all(
        &self,
        origin: Vec3<R>,
        direction: Vec3<R>,
        max_distance: R,
        filter: &QueryFilter,
    ) -> Vec<RayHit<R>> {
        self.rigid().map_or_else(Vec::new, |rigid| {
            rigid.cast_ray_all(origin, direction, max_distance, filter)
        })
    }

    /// [`RigidSystem::cast_shape`](crate::rigid::RigidSystem::cast_shape): the first body
    /// `shape` touches when swept from its pose along `direction` by up to `max_distance`
    /// (m).
    pub fn cast_shape(
        &self,
        shape: &Shape<R>,
        position: Vec3<R>,
        orientation: Quat<R>,
        direction: Vec3<R>,
        max_distance: R,
        filter: &QueryFilter,
    ) -> Option<RayHit<R>> {
        self.rigid()?.cast_shape(
            shape,
            position,
            orientation,
            direction,
            max_distance,
            filter,
        )
    }

    /// [`RigidSystem::overlap`](crate::rigid::RigidSystem::overlap): the bodies that
    /// overlap `shape` at the pose, ascending.
    pub fn overlap(
        &self,
        shape: &Shape<R>,
        position: Vec3<R>,
        orientation: Quat<R>,
        filter: &QueryFilter,
    ) -> Vec<Handle> {
        self.rigid().map_or_else(Vec::new, |rigid| {
            rigid.overlap(shape, position, orientation, filter)
        })
    }

    /// [`RigidSystem::project_point`](crate::rigid::RigidSystem::project_point): the
    /// closest point of any body to `point` (m) within `max_distance` (m).
    pub fn project_point(
        &self,
        point: Vec3<R>,
        max_distance: R,
        filter: &QueryFilter,
    ) -> Option<PointProjection<R>> {
        self.rigid()?.project_point(point, max_distance, filter)
    }
}
