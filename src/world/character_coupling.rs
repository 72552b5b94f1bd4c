//! The character stage: once per tick, after the bodies have moved, each character moves
//! among them ([`crate::character::movement`]), seeing them through [`Bodies`], an
//! implementation of [`Surroundings`] over the rigid system; its pushes go to the bodies at
//! once (so a later character sees them), and its events join the tick's rigid events.

use crate::character::{BodyMotion, CharacterSystem, NoSurroundings, Surroundings};
use crate::math::{Quat, Real, Vec3};
use crate::rigid::{BodyKind, QueryFilter, RayHit, RigidSystem, Shape};
use crate::types::{Command, Handle, Target};

/// The rigid bodies as the characters see them.
struct Bodies<'a, R: Real> {
    rigid: &'a mut RigidSystem<R>,
}

impl<R: Real> Surroundings<R> for Bodies<'_, R> {
    fn cast(
        &self,
        shape: &Shape<R>,
        position: Vec3<R>,
        direction: Vec3<R>,
        max_distance: R,
        filter: &QueryFilter,
    ) -> Option<RayHit<R>> {
        self.rigid.cast_shape(
            shape,
            position,
            Quat::IDENTITY,
            direction,
            max_distance,
            filter,
        )
    }

    fn cast_ray(
        &self,
        origin: Vec3<R>,
        direction: Vec3<R>,
        max_distance: R,
        filter: &QueryFilter,
    ) -> Option<RayHit<R>> {
        self.rigid.cast_ray(origin, direction, max_distance, filter)
    }

    fn motion(&self, body: Handle) -> Option<BodyMotion<R>> {
        let r = &*self.rigid;
        let kind = r.kind(body)?;
        let inverse_mass = match (kind, r.mass(body)) {
            (BodyKind::Dynamic, Some(m)) if m > R::ZERO => R::ONE / m,
            _ => R::ZERO,
        };
        Some(BodyMotion {
            kind,
            centre: r.position(body)?,
            velocity: r.linear_velocity(body)?,
            angular_velocity: r.angular_velocity(body)?,
            inverse_mass,
        })
    }

    fn push(&mut self, body: Handle, impulse: Vec3<R>, point: Vec3<R>) {
        self.rigid.apply_command(&Command::ApplyImpulse {
            target: Target::Body(body),
            impulse,
            point: Some(point),
        });
    }

    fn knock_off(
        &mut self,
        shape: &Shape<R>,
        position: Vec3<R>,
        velocity: Vec3<R>,
        dt: R,
        filter: &QueryFilter,
    ) -> Vec<Handle> {
        self.rigid
            .knock_off_obstacle(shape, position, velocity, dt, filter)
    }
}

/// One tick (`dt` seconds, under `gravity`, m/s²) of every character, among `rigid`'s bodies
/// when the scene has any; their events are added to the rigid bodies' events of the tick.
pub(super) fn step_characters<R: Real>(
    characters: &mut CharacterSystem<R>,
    rigid: Option<&mut RigidSystem<R>>,
    dt: R,
    gravity: Vec3<R>,
) {
    let Some(rigid) = rigid else {
        characters.step_tick(dt, gravity, &mut NoSurroundings);
        return;
    };
    let events = characters.step_tick(dt, gravity, &mut Bodies { rigid: &mut *rigid });
    for e in events {
        rigid.push_character_event(e.kind, e.character, e.body);
    }
}
