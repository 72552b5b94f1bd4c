//! The rigid and fluid stages of a scene whose fluid meets the rigid bodies, stepped
//! together at the fluid's substep rate: after each rigid substep, the bodies the fluid's
//! filter accepts are given to the fluid's substep as views, and the impulses and moments
//! the fluid gave them, with the motion those caused, are applied
//! ([`fluid::bodies`](crate::fluid::bodies), [`RigidSystem::push_body_about_centre`],
//! [`RigidSystem::displace_body`]).
//!
//! Why at the fluid's rate: stepped once per world substep, a body took its weight's
//! impulse at once and the fluid's over the fluid's substeps, so a floating box at rest
//! ended every tick at g Δt/2 (8 cm/s at 60 Hz) under WCSPH, whose push follows the
//! position; the rigid step costs little beside the fluid's.
//!
//! A scene whose fluid ignores the bodies steps it as any other subsystem, and pays
//! nothing here.

use super::pipeline::{Settings, step_context};
use crate::fluid::FluidSystem;
use crate::fluid::bodies::BodyView;
use crate::math::Real;
use crate::math::Vec3;
use crate::math::rng::Pcg32;
use crate::rigid::{CollisionFilter, RigidSystem, Shape};
use crate::types::Stage;
use crate::types::Subsystem;

/// The views of the bodies `filter` accepts: alive, not sensors, of a shape with a volume;
/// each where it was `dt` seconds ago, before the rigid step that moved it (back along its
/// velocities).
fn views<'a, R: Real>(
    rigid: &'a RigidSystem<R>,
    filter: CollisionFilter,
    dt: R,
) -> Vec<BodyView<'a, R>> {
    let b = &rigid.bodies;
    (0..b.len())
        .filter(|&i| {
            b.alive[i]
                && !b.sensor[i]
                && filter.interacts(b.filter[i])
                && !matches!(b.shape[i], Shape::Plane { .. })
                && b.shape[i].triangles().is_none()
        })
        .map(|i| {
            let moved = b.is_awake_dynamic(i);
            let (velocity, angular_velocity) = (b.linear_velocity[i], b.angular_velocity[i]);
            BodyView {
                handle: b.handle(i),
                shape: &b.shape[i],
                position: b.position[i].add_scaled(velocity, -dt),
                orientation: if angular_velocity == Vec3::ZERO {
                    b.orientation[i]
                } else {
                    b.orientation[i].integrate(angular_velocity, -dt)
                },
                velocity,
                angular_velocity,
                inv_mass: if moved { b.inv_mass[i] } else { R::ZERO },
                inv_inertia: if moved {
                    b.orientation[i].to_mat3().rotate_inertia(b.inv_inertia[i])
                } else {
                    crate::math::Mat3::ZERO
                },
            }
        })
        .collect()
}

/// One tick of the rigid and fluid stages together, `filter` choosing the bodies in the
/// fluid. Per world substep of `dt` seconds the fluid decides its substeps, and for each
/// substep of h = `dt`/n seconds the rigid bodies step h, then the fluid steps h with the
/// bodies in view (where they were before that rigid step, moving at their new
/// velocities), then the fluid's pushes move the bodies in ascending slot order. So the
/// rigid bodies step at the fluid's rate: gravity and the fluid's pressure meet in every
/// fluid substep, and a floating body is at rest at the end of each. `time` wraps each
/// stage's part for the stage timings.
pub(super) fn step_fluid_with_bodies<R: Real>(
    fluid: &mut FluidSystem<R>,
    rigid: &mut RigidSystem<R>,
    filter: CollisionFilter,
    (settings, rng, dt): (&Settings<R>, &mut Pcg32, R),
    mut time: impl FnMut(Stage, &mut dyn FnMut()),
) {
    Subsystem::begin_tick(fluid);
    Subsystem::begin_tick(rigid);
    for _ in 0..settings.substeps {
        let substeps = fluid.begin_step(dt, settings.gravity);
        let h = dt * R::from_ratio(1, i64::from(substeps));
        let mut context = step_context(settings, &mut *rng, h);
        for _ in 0..substeps {
            time(Stage::Rigid, &mut || Subsystem::step(rigid, &mut context));
            time(Stage::Fluid, &mut || {
                let views = views(rigid, filter, h);
                let slots: Vec<usize> = views.iter().map(|v| v.handle.index as usize).collect();
                let done = fluid.substep_with_bodies(h, settings.gravity, &views);
                let mut moved = false;
                for (k, slot) in slots.into_iter().enumerate() {
                    let (impulse, moment) = done.pushes[k];
                    let (displacement, rotation) = done.drifts[k];
                    moved |= rigid.displace_body(slot, displacement, rotation);
                    rigid.push_body_about_centre(slot, impulse, moment);
                }
                if moved {
                    rigid.update_query_index();
                }
            });
        }
    }
}
