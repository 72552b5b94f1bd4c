//! Canonical hashing of the particle state, and locating the first slot where two systems
//! differ.
//!
//! # Hash order
//!
//! [`ParticleSystem::hash_state`] writes, in this order (reals with `write_real`, vectors
//! with `write_vec3` as x, y, z, flags as `u32` 0/1, `Option<u16>` group restrictions as
//! `u32` with `u32::MAX` for none, counts with `write_len`):
//!
//! 1. the integrator code (`u32`, position in [`Integrator::ALL`](super::Integrator::ALL)),
//!    the capacity (`u32`), the slot count;
//! 2. every slot in ascending index: alive flag, generation (`u32`); then, for a live slot
//!    only, group (`u32`), remaining lifetime, mass, inverse mass, position, velocity,
//!    previous position, has-previous-position flag, stored acceleration, external force
//!    (a dead slot's other fields are overwritten before reuse, so they do not matter);
//! 3. the spawn templates: count, then each template's mass, inverse mass, group (`u32`),
//!    lifetime;
//! 4. the emitters: count, then each emitter's on flag, accumulator, position, rate, shape
//!    (`u32` tag 0 = cone: axis, tangent, bitangent, 1 − cos α; 1 = box: half extents,
//!    direction), speed min and max, lifetime min and max, mass, inverse mass, group (`u32`);
//! 5. the acceleration fields: count, then each one's tag (`u32` 0 = gravity: scale, group;
//!    1 = point gravity: centre, GM, ε², group);
//! 6. the force generators: count, then each one's tag (`u32` 0 = linear drag: coefficient,
//!    group; 1 = quadratic drag: coefficient, group; 2 = anchored spring: particle handle
//!    (index, generation as `u32`), anchor, stiffness, damping, rest length; 3 = spring: the
//!    two handles, stiffness, damping, rest length; 4 = user: name length, then its UTF-8
//!    bytes);
//! 7. the dampings: count, then each one's kept-per-second fraction and group;
//! 8. the accelerations-current flag, the external-forces-pending flag, the gravity of the
//!    last step;
//! 9. only when some group collides with the rigid bodies (so that a system without
//!    collisions hashes as before they existed): their count, then per group in ascending
//!    order the group (`u32`), restitution, friction, push flag, the filter's layers and
//!    mask (`u32`);
//! 10. only when the system has contacts (so that a system without them hashes as before
//!     they existed): the contact radius, the particle–particle restitution, the planes
//!     (count, then each one's unit normal, offset, restitution) and the links (count, then
//!     each one's kind (`u32` 0 = rod, 1 = cable), its two handles (index, generation as
//!     `u32`), length and restitution), then the resolutions per step (`u32`).
//!
//! Not hashed, because they do not influence the future: the lowest-free-slot cache and the
//! live count (functions of the alive flags), the dampings' cached d^Δt (a function of d and
//! Δt), the integrators' scratch arrays, the user-force registry (code, not state), and the
//! scene index of user forces (error messages only).

use super::contacts::LinkKind;
use super::desc::{Interval, SpringDesc};
use super::emitter::EmissionShape;
use super::forces::{AccelerationField, ForceGenerator};
use super::system::ParticleSystem;
use crate::math::state_hash::StateHasher;
use crate::math::{Real, Vec3};
use crate::types::Handle;

/// Everything that describes one live slot.
#[derive(Clone, Copy, PartialEq)]
struct LiveSlot<R: Real> {
    group: u16,
    lifetime: R,
    mass: R,
    inv_mass: R,
    position: Vec3<R>,
    velocity: Vec3<R>,
    previous_position: Vec3<R>,
    has_previous_position: bool,
    acceleration: Vec3<R>,
    external_force: Vec3<R>,
}

/// Everything that describes one slot: its generation, and its contents when alive.
#[derive(Clone, Copy, PartialEq)]
struct SlotState<R: Real> {
    generation: u32,
    live: Option<LiveSlot<R>>,
}

impl<R: Real> SlotState<R> {
    fn hash(&self, h: &mut StateHasher) {
        write_flag(h, self.live.is_some());
        h.write_u32(self.generation);
        if let Some(s) = &self.live {
            h.write_u32(u32::from(s.group));
            h.write_real(s.lifetime);
            h.write_real(s.mass);
            h.write_real(s.inv_mass);
            h.write_vec3(s.position);
            h.write_vec3(s.velocity);
            h.write_vec3(s.previous_position);
            write_flag(h, s.has_previous_position);
            h.write_vec3(s.acceleration);
            h.write_vec3(s.external_force);
        }
    }
}

fn write_flag(h: &mut StateHasher, flag: bool) {
    h.write_u32(u32::from(flag));
}

fn write_group(h: &mut StateHasher, group: Option<u16>) {
    h.write_u32(group.map_or(u32::MAX, u32::from));
}

fn write_handle(h: &mut StateHasher, handle: Handle) {
    h.write_u32(handle.index);
    h.write_u32(handle.generation);
}

fn write_interval<R: Real>(h: &mut StateHasher, interval: Interval<R>) {
    h.write_real(interval.min);
    h.write_real(interval.max);
}

fn write_spring<R: Real>(h: &mut StateHasher, spring: &SpringDesc<R>) {
    h.write_real(spring.stiffness);
    h.write_real(spring.damping);
    h.write_real(spring.rest_length);
}

impl<R: Real> ParticleSystem<R> {
    /// Writes the complete simulation state into `h` in the canonical order documented in
    /// [this module](self).
    pub fn hash_state(&self, h: &mut StateHasher) {
        h.write_u32(self.integrator.code());
        h.write_u32(self.storage.capacity());
        h.write_len(self.slot_count());
        for i in 0..self.slot_count() {
            self.slot_state(i).hash(h);
        }

        h.write_len(self.templates.len());
        for t in &self.templates {
            h.write_real(t.mass);
            h.write_real(t.inv_mass);
            h.write_u32(u32::from(t.group));
            h.write_real(t.lifetime);
        }

        h.write_len(self.emitters.len());
        for e in &self.emitters {
            write_flag(h, e.on);
            h.write_real(e.accumulator);
            h.write_vec3(e.position);
            h.write_real(e.rate);
            match e.shape {
                EmissionShape::Cone {
                    axis,
                    tangent,
                    bitangent,
                    one_minus_cos_half_angle,
                } => {
                    h.write_u32(0);
                    h.write_vec3(axis);
                    h.write_vec3(tangent);
                    h.write_vec3(bitangent);
                    h.write_real(one_minus_cos_half_angle);
                }
                EmissionShape::Box {
                    half_extents,
                    direction,
                } => {
                    h.write_u32(1);
                    h.write_vec3(half_extents);
                    h.write_vec3(direction);
                }
            }
            write_interval(h, e.speed);
            write_interval(h, e.lifetime);
            h.write_real(e.mass);
            h.write_real(e.inv_mass);
            h.write_u32(u32::from(e.group));
        }

        h.write_len(self.forces.fields.len());
        for field in &self.forces.fields {
            match *field {
                AccelerationField::Gravity { scale, group } => {
                    h.write_u32(0);
                    h.write_real(scale);
                    write_group(h, group);
                }
                AccelerationField::PointGravity {
                    centre,
                    gm,
                    softening_squared,
                    group,
                } => {
                    h.write_u32(1);
                    h.write_vec3(centre);
                    h.write_real(gm);
                    h.write_real(softening_squared);
                    write_group(h, group);
                }
            }
        }

        h.write_len(self.forces.generators.len());
        for generator in &self.forces.generators {
            match *generator {
                ForceGenerator::LinearDrag { coefficient, group } => {
                    h.write_u32(0);
                    h.write_real(coefficient);
                    write_group(h, group);
                }
                ForceGenerator::QuadraticDrag { coefficient, group } => {
                    h.write_u32(1);
                    h.write_real(coefficient);
                    write_group(h, group);
                }
                ForceGenerator::AnchoredSpring {
                    particle,
                    anchor,
                    ref spring,
                } => {
                    h.write_u32(2);
                    write_handle(h, particle);
                    h.write_vec3(anchor);
                    write_spring(h, spring);
                }
                ForceGenerator::Spring {
                    first,
                    second,
                    ref spring,
                } => {
                    h.write_u32(3);
                    write_handle(h, first);
                    write_handle(h, second);
                    write_spring(h, spring);
                }
                ForceGenerator::User { ref name, .. } => {
                    h.write_u32(4);
                    h.write_len(name.len());
                    h.write_bytes(name.as_bytes());
                }
            }
        }

        h.write_len(self.forces.dampings.len());
        for damping in &self.forces.dampings {
            h.write_real(damping.kept_per_second);
            write_group(h, damping.group);
        }

        write_flag(h, self.accelerations_current);
        write_flag(h, self.external_forces_pending);
        h.write_vec3(self.last_gravity);

        if !self.collisions.is_empty() {
            h.write_len(self.collisions.len());
            for c in &self.collisions {
                h.write_u32(u32::from(c.group));
                h.write_real(c.restitution);
                h.write_real(c.friction);
                write_flag(h, c.push);
                h.write_u32(c.filter.layers);
                h.write_u32(c.filter.mask);
            }
        }

        if let Some(contacts) = &self.contacts {
            h.write_real(contacts.radius);
            h.write_real(contacts.restitution);
            h.write_len(contacts.planes.len());
            for plane in &contacts.planes {
                h.write_vec3(plane.normal);
                h.write_real(plane.offset);
                h.write_real(plane.restitution);
            }
            h.write_len(contacts.links.len());
            for link in &contacts.links {
                h.write_u32(match link.kind {
                    LinkKind::Rod => 0,
                    LinkKind::Cable => 1,
                });
                for end in [link.a, link.b] {
                    h.write_u32(end.index);
                    h.write_u32(end.generation);
                }
                h.write_real(link.length);
                h.write_real(link.restitution);
            }
            h.write_u32(contacts.iterations);
        }
    }

    /// The first slot, in ascending index, whose state (as hashed) differs between `self`
    /// and `other`: its handle in `self`, or in `other` when `self` has no such slot. `None`
    /// when every slot agrees; system-wide state (emitters, forces, flags) is not a slot and
    /// is not compared here.
    pub fn first_difference(&self, other: &Self) -> Option<Handle> {
        let common = self.slot_count().min(other.slot_count());
        let differing = (0..common)
            .find(|&i| self.slot_state(i) != other.slot_state(i))
            .or_else(|| (self.slot_count() != other.slot_count()).then_some(common))?;
        Some(if differing < self.slot_count() {
            self.storage.handle(differing)
        } else {
            other.storage.handle(differing)
        })
    }

    /// One 32-bit digest per slot, in ascending slot index: the low 32 bits of the XXH3-64
    /// of the slot's canonical bytes (item 2 of the [hash order](self)). Replays store them
    /// at each checkpoint, so that a desync report can name the first differing particle.
    pub fn slot_digests(&self) -> Vec<(Handle, u32)> {
        (0..self.slot_count())
            .map(|i| {
                let mut h = StateHasher::new();
                self.slot_state(i).hash(&mut h);
                (self.storage.handle(i), h.finish() as u32)
            })
            .collect()
    }

    /// The state of slot `i`.
    fn slot_state(&self, i: usize) -> SlotState<R> {
        let k = &self.storage.kinematics;
        let a = &self.storage.attributes;
        SlotState {
            generation: a.generations[i],
            live: a.alive[i].then(|| LiveSlot {
                group: a.groups[i],
                lifetime: a.lifetimes[i],
                mass: a.masses[i],
                inv_mass: a.inv_masses[i],
                position: k.positions[i],
                velocity: k.velocities[i],
                previous_position: k.previous_positions[i],
                has_previous_position: k.has_previous_position[i],
                acceleration: k.accelerations[i],
                external_force: a.external_forces[i],
            }),
        }
    }
}
