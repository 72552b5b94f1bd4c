//! The particle stage of a scene whose particle groups collide with the rigid bodies: each
//! substep is the particles' own step followed by their bounces off the bodies
//! ([`collisions`](crate::particles::collisions)), with pushes applied to awake bodies at
//! once, so that the rigid stage after it starts from the pushed velocities. A sleeping
//! body gathers its pushes over the tick and wakes only if together they would move it
//! faster than its sleep speed.
//!
//! A scene without colliding groups steps its particles as any other subsystem, and pays
//! nothing here.

use std::collections::BTreeMap;

use super::pipeline::Settings;
use crate::math::rng::Pcg32;
use crate::math::{Real, Vec3};
use crate::particles::ParticleSystem;
use crate::particles::collisions::{SurfaceHit, Surfaces};
use crate::rigid::query::BodiesInMotion;
use crate::rigid::{CollisionFilter, RigidSystem};
use crate::types::Subsystem;

/// The rigid bodies as the particles' surfaces, for one tick.
struct Bodies<'a, R: Real> {
    rigid: &'a mut RigidSystem<R>,
    /// Where the bodies are during the current substep.
    motion: BodiesInMotion<R>,
    /// The pushes on sleeping bodies so far this tick, by slot: total impulse (N·s) and
    /// total moment about the centre (N·m·s).
    sleeping: BTreeMap<usize, (Vec3<R>, Vec3<R>)>,
}

impl<R: Real> Surfaces<R> for Bodies<'_, R> {
    fn cast(
        &mut self,
        from: Vec3<R>,
        to: Vec3<R>,
        dt: R,
        filter: CollisionFilter,
    ) -> Option<SurfaceHit<R>> {
        let hit = self
            .rigid
            .cast_moving_point(&mut self.motion, from, to, dt, filter)?;
        Some(SurfaceHit {
            body: hit.slot as u32,
            fraction: hit.fraction,
            normal: hit.normal,
            velocity: hit.velocity,
        })
    }

    fn push(&mut self, body: u32, impulse: Vec3<R>, point: Vec3<R>) {
        let slot = body as usize;
        if let Some(centre) = self.rigid.push_body(slot, impulse, point) {
            let total = self
                .sleeping
                .entry(slot)
                .or_insert((Vec3::ZERO, Vec3::ZERO));
            total.0 += impulse;
            total.1 += (point - centre).cross(impulse);
        }
    }
}

/// One tick of the particle stage with collisions: per substep of `dt` seconds, the
/// particles' step, then their bounces off `rigid`'s bodies; at the end, the pushes gathered
/// by sleeping bodies, in ascending slot order
/// ([`RigidSystem::push_sleeping_body`]: enough of them wake the body).
pub(super) fn step_colliding_particles<R: Real>(
    particles: &mut ParticleSystem<R>,
    rigid: &mut RigidSystem<R>,
    settings: &Settings<R>,
    rng: &mut Pcg32,
    dt: R,
) {
    Subsystem::begin_tick(particles);
    let mut starts = Vec::new();
    let mut bodies = Bodies {
        rigid,
        motion: BodiesInMotion::default(),
        sleeping: BTreeMap::new(),
    };
    let mut elapsed = R::ZERO;
    for _ in 0..settings.substeps {
        particles.path_starts(&mut starts);
        particles.step(dt, settings.gravity, rng);
        bodies
            .rigid
            .place_in_motion(elapsed, dt, &mut bodies.motion);
        particles.collide(dt, &starts, &mut bodies);
        elapsed += dt;
    }
    for (slot, (impulse, moment)) in bodies.sleeping {
        bodies.rigid.push_sleeping_body(slot, impulse, moment);
    }
}
