//! The rigid and soft stages of a scene whose soft bodies touch or are tied to rigid
//! bodies: per world substep, the rigid step, then the soft step with the bodies in view
//! as proxies that take the soft constraints' corrections two-way
//! ([`rigid::proxies`](crate::rigid::proxies),
//! [`soft::body_coupling`](crate::soft::body_coupling)). At the end of the tick, the
//! pushes sleeping bodies gathered.
//!
//! A scene without such soft bodies steps each stage alone, and pays nothing here.

use super::pipeline::{Settings, step_context};
use crate::math::rng::Pcg32;
use crate::math::{Real, Vec3};
use crate::rigid::proxies::Proxies;
use crate::rigid::{Aabb, CollisionFilter, RigidSystem, Transform};
use crate::soft::SoftSystem;
use crate::soft::rigid_bodies::{BodyFrames, RigidBodies};
use crate::types::{Handle, Subsystem};

/// The scene's rigid bodies while its soft bodies are built, by index.
pub(crate) struct SceneBodies<'a, R: Real>(pub Option<&'a RigidSystem<R>>);

impl<R: Real> BodyFrames<R> for SceneBodies<'_, R> {
    fn frame(&self, index: u32) -> Option<(Handle, Transform<R>)> {
        let b = &self.0?.bodies;
        let i = index as usize;
        (i < b.len() && b.alive[i]).then(|| {
            (
                b.handle(i),
                Transform::from_pose(b.position[i], b.orientation[i]),
            )
        })
    }

    fn count(&self) -> usize {
        self.0.map_or(0, |r| r.bodies.len())
    }
}

/// The rigid bodies as the soft solver sees them during one world substep.
struct Bodies<'a, R: Real> {
    rigid: &'a mut RigidSystem<R>,
    proxies: &'a mut Proxies<R>,
}

impl<R: Real> RigidBodies<R> for Bodies<'_, R> {
    fn begin(&mut self, dt: R, substeps: u32) {
        self.proxies.begin(self.rigid, dt, substeps);
    }

    fn near(&mut self, aabb: &Aabb<R>, filter: CollisionFilter, out: &mut Vec<u32>) {
        self.proxies.near(self.rigid, aabb, filter, out);
    }

    fn of_body(&mut self, body: Handle) -> Option<u32> {
        self.proxies.of_body(self.rigid, body)
    }

    fn advance(&mut self) {
        self.proxies.advance(self.rigid);
    }

    fn may_touch(&self, i: u32, x: Vec3<R>, margin: R) -> bool {
        self.proxies.may_touch(i, x, margin)
    }

    fn contact(&self, i: u32, x: Vec3<R>, previous: Vec3<R>, r: R) -> Option<(Vec3<R>, R)> {
        self.proxies.contact(self.rigid, i, x, previous, r)
    }

    fn point(&self, i: u32, local: Vec3<R>) -> Vec3<R> {
        self.proxies.point(i, local)
    }

    fn velocity_at(&self, i: u32, p: Vec3<R>) -> Vec3<R> {
        self.proxies.velocity_at(i, p)
    }

    fn inverse_mass(&self, i: u32, p: Vec3<R>, n: Vec3<R>) -> R {
        self.proxies.inverse_mass(i, p, n)
    }

    fn correct(&mut self, i: u32, p: Vec3<R>, impulse: Vec3<R>) {
        self.proxies.correct(i, p, impulse);
    }

    fn push(&mut self, i: u32, p: Vec3<R>, impulse: Vec3<R>) {
        self.proxies.push(i, p, impulse);
    }

    fn finish(&mut self) {
        self.proxies.finish_substep(self.rigid);
    }
}

/// One tick of the rigid and soft stages together: per substep of `dt` seconds the rigid
/// step, then the soft step with the bodies in view; at the end, the pushes gathered by
/// sleeping bodies ([`RigidSystem::push_sleeping_body`]: enough of them wake the body).
/// `time` wraps each stage's part for the stage timings.
pub(super) fn step_rigid_and_soft<R: Real>(
    rigid: &mut RigidSystem<R>,
    soft: &mut SoftSystem<R>,
    proxies: &mut Proxies<R>,
    (settings, rng, dt): (&Settings<R>, &mut Pcg32, R),
    mut time: impl FnMut(crate::types::Stage, &mut dyn FnMut()),
) {
    Subsystem::begin_tick(rigid);
    Subsystem::begin_tick(soft);
    let mut context = step_context(settings, rng, dt);
    for substep in 0..settings.substeps {
        context.substep = substep;
        time(crate::types::Stage::Rigid, &mut || {
            Subsystem::step(rigid, &mut context)
        });
        time(crate::types::Stage::Soft, &mut || {
            let mut bodies = Bodies {
                rigid: &mut *rigid,
                proxies: &mut *proxies,
            };
            soft.step_with_bodies(
                dt,
                settings.gravity,
                (substep, settings.substeps),
                Some(&mut bodies),
            );
        });
    }
    proxies.finish_tick(rigid);
}
