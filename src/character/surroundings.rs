//! What a character sees of the world: shape casts against the bodies, how the body it
//! hits or stands on moves, and a way to push it. The world implements it over the rigid
//! bodies (`world/character_coupling.rs`), so the characters know nothing of the rigid
//! system.

use crate::math::{Real, Vec3};
use crate::rigid::{BodyKind, QueryFilter, RayHit, Shape};
use crate::types::Handle;

/// How a body moves, at the moment a character looks at it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BodyMotion<R: Real> {
    /// Static, kinematic or dynamic.
    pub kind: BodyKind,
    /// Its centre of mass, m.
    pub centre: Vec3<R>,
    /// Linear velocity, m/s.
    pub velocity: Vec3<R>,
    /// Angular velocity, rad/s.
    pub angular_velocity: Vec3<R>,
    /// 1 / mass, 1/kg (0 for a body that is not dynamic).
    pub inverse_mass: R,
}

impl<R: Real> BodyMotion<R> {
    /// The velocity of the body's point `p` (m): v + ω × (p − c), m/s.
    pub fn velocity_at(&self, p: Vec3<R>) -> Vec3<R> {
        self.velocity + self.angular_velocity.cross(p - self.centre)
    }
}

/// The world as a character sees it.
pub trait Surroundings<R: Real> {
    /// The first body `shape` (at `position`, unrotated) touches when moved along
    /// `direction` (any nonzero length) by up to `max_distance` (m), among those `filter`
    /// accepts: as [`RigidSystem::cast_shape`](crate::rigid::RigidSystem::cast_shape).
    fn cast(
        &self,
        shape: &Shape<R>,
        position: Vec3<R>,
        direction: Vec3<R>,
        max_distance: R,
        filter: &QueryFilter,
    ) -> Option<RayHit<R>>;

    /// The first body the ray from `origin` along `direction` meets within `max_distance`
    /// (m), among those `filter` accepts: as
    /// [`RigidSystem::cast_ray`](crate::rigid::RigidSystem::cast_ray).
    fn cast_ray(
        &self,
        origin: Vec3<R>,
        direction: Vec3<R>,
        max_distance: R,
        filter: &QueryFilter,
    ) -> Option<RayHit<R>>;

    /// How `body` moves now; `None` when it does not exist.
    fn motion(&self, body: Handle) -> Option<BodyMotion<R>>;

    /// Adds `impulse` (N·s) to the dynamic `body` at the world point `point` (m).
    fn push(&mut self, body: Handle, impulse: Vec3<R>, point: Vec3<R>);

    /// The character `shape` at `position` (m), moving at `velocity` (m/s), as an
    /// immovable obstacle to the dynamic bodies `filter` accepts that the last `dt` seconds
    /// moved into it: each is put back where it touches it and loses its approach, as
    /// [`RigidSystem::knock_off_obstacle`](crate::rigid::RigidSystem) does. The bodies
    /// knocked, ascending.
    fn knock_off(
        &mut self,
        shape: &Shape<R>,
        position: Vec3<R>,
        velocity: Vec3<R>,
        dt: R,
        filter: &QueryFilter,
    ) -> Vec<Handle>;
}

/// A world with no bodies: casts hit nothing.
#[derive(Clone, Copy, Debug, Default)]
pub struct NoSurroundings;

impl<R: Real> Surroundings<R> for NoSurroundings {
    fn cast(
        &self,
        _: &Shape<R>,
        _: Vec3<R>,
        _: Vec3<R>,
        _: R,
        _: &QueryFilter,
    ) -> Option<RayHit<R>> {
        None
    }

    fn cast_ray(&self, _: Vec3<R>, _: Vec3<R>, _: R, _: &QueryFilter) -> Option<RayHit<R>> {
        None
    }

    fn motion(&self, _: Handle) -> Option<BodyMotion<R>> {
        None
    }

    fn push(&mut self, _: Handle, _: Vec3<R>, _: Vec3<R>) {}

    fn knock_off(
        &mut self,
        _: &Shape<R>,
        _: Vec3<R>,
        _: Vec3<R>,
        _: R,
        _: &QueryFilter,
    ) -> Vec<Handle> {
        Vec::new()
    }
}
