//! Scene queries as a system parameter: the world's ray, shape, overlap and point queries,
//! answering with the entities of the bodies found.

use bevy::ecs::system::SystemParam;
use bevy::prelude::{Entity, Query, Res};
use fixstep::math::{Fx, Quat, Vec3};
use fixstep::rigid::{PointProjection, QueryFilter, RayHit, Shape};
use fixstep::world::Handle;

use super::components::BodyLink;
use super::world::FixstepWorld;

/// The world's scene queries (`docs/queries.md`) from a system, in fixed point: the same
/// answer on every machine. Each answer's bodies come with their entity, when linked.
/// Without a world yet (before `PostStartup`) every query answers nothing.
#[derive(SystemParam)]
pub struct PhysicsQuery<'w, 's> {
    world: Option<Res<'w, FixstepWorld>>,
    links: Query<'w, 's, (Entity, &'static BodyLink)>,
}

impl PhysicsQuery<'_, '_> {
    /// The entity linked to body `handle`.
    pub fn entity(&self, handle: Handle) -> Option<Entity> {
        self.links
            .iter()
            .find(|(_, l)| l.0 == handle)
            .map(|(e, _)| e)
    }

    /// The first body hit along the ray from `origin` (m) along the unit `direction` within
    /// `max_distance` (m), and its entity.
    pub fn cast_ray(
        &self,
        origin: Vec3<Fx>,
        direction: Vec3<Fx>,
        max_distance: Fx,
        filter: &QueryFilter,
    ) -> Option<(RayHit<Fx>, Option<Entity>)> {
        let hit = self
            .world
            .as_ref()?
            .world()
            .cast_ray(origin, direction, max_distance, filter)?;
        Some((hit, self.entity(hit.body)))
    }

    /// Every body the ray hits, sorted by (distance, handle).
    pub fn cast_ray_all(
        &self,
        origin: Vec3<Fx>,
        direction: Vec3<Fx>,
        max_distance: Fx,
        filter: &QueryFilter,
    ) -> Vec<RayHit<Fx>> {
        self.world.as_ref().map_or_else(Vec::new, |w| {
            w.world()
                .cast_ray_all(origin, direction, max_distance, filter)
        })
    }

    /// The first body `shape` touches when swept from its pose along the unit `direction`
    /// by up to `max_distance` (m), and its entity.
    pub fn cast_shape(
        &self,
        shape: &Shape<Fx>,
        position: Vec3<Fx>,
        orientation: Quat<Fx>,
        direction: Vec3<Fx>,
        max_distance: Fx,
        filter: &QueryFilter,
    ) -> Option<(RayHit<Fx>, Option<Entity>)> {
        let hit = self.world.as_ref()?.world().cast_shape(
            shape,
            position,
            orientation,
            direction,
            max_distance,
            filter,
        )?;
        Some((hit, self.entity(hit.body)))
    }

    /// The bodies overlapping `shape` at the pose, ascending by handle, with their entities.
    pub fn overlap(
        &self,
        shape: &Shape<Fx>,
        position: Vec3<Fx>,
        orientation: Quat<Fx>,
        filter: &QueryFilter,
    ) -> Vec<(Handle, Option<Entity>)> {
        let Some(world) = self.world.as_ref() else {
            return Vec::new();
        };
        world
            .world()
            .overlap(shape, position, orientation, filter)
            .into_iter()
            .map(|h| (h, self.entity(h)))
            .collect()
    }

    /// The closest point of any body to `point` (m) within `max_distance` (m).
    pub fn project_point(
        &self,
        point: Vec3<Fx>,
        max_distance: Fx,
        filter: &QueryFilter,
    ) -> Option<PointProjection<Fx>> {
        self.world
            .as_ref()?
            .world()
            .project_point(point, max_distance, filter)
    }
}
