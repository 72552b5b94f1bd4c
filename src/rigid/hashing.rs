//! The canonical state of the rigid bodies, for checksums.
//!
//! [`RigidSystem::hash_state`] writes, in order (integers little-endian, scalars as their
//! raw fixed-point bits, vectors x, y, z, quaternions w, x, y, z, matrices column by
//! column, flags as one byte 0 or 1):
//!
//! 1. the solver settings: substeps (`u32`), contact hertz, damping ratio, push velocity,
//!    restitution threshold, speculative distance, sleeping flag, time to sleep, linear and
//!    angular sleep speeds;
//! 2. the slot count (`u64`), then each slot in ascending index: its generation (`u32`),
//!    its alive flag, and for a live body: kind code (`u8`), position, orientation, linear
//!    and angular velocity, force, torque, inverse mass, mass, inertia, linear and angular
//!    damping, friction, restitution, sleep time, asleep flag, island (`u32`);
//! 3. the contact count (`u64`), then each contact in key order: body A, body B (`u32`),
//!    part A, part B (`u32`), normal, point count (`u8`), each point's position,
//!    separation, feature id (`u32`) and normal impulse, then the contact's two friction
//!    impulses and its twist impulse.
//!
//! Shapes do not change during a run and are part of the scene, which replays check by
//! its own hash; they are not hashed here.

use super::system::RigidSystem;
use crate::math::{Mat3, Quat, Real, StateHasher};
use crate::world::Handle;

fn write_flag(h: &mut StateHasher, flag: bool) {
    h.write_u8(u8::from(flag));
}

fn write_quat<R: Real>(h: &mut StateHasher, q: Quat<R>) {
    h.write_real(q.w);
    h.write_real(q.x);
    h.write_real(q.y);
    h.write_real(q.z);
}

fn write_mat3<R: Real>(h: &mut StateHasher, m: &Mat3<R>) {
    for c in m.cols {
        h.write_vec3(c);
    }
}

impl<R: Real> RigidSystem<R> {
    /// Writes the complete simulation state into `h` in the canonical order documented in
    /// [this module](self).
    pub fn hash_state(&self, h: &mut StateHasher) {
        let s = &self.settings;
        h.write_u32(s.substeps);
        h.write_real(s.contact_hertz);
        h.write_real(s.contact_damping_ratio);
        h.write_real(s.max_push_velocity);
        h.write_real(s.restitution_threshold);
        h.write_real(s.speculative_distance);
        write_flag(h, s.sleeping);
        h.write_real(s.time_to_sleep);
        h.write_real(s.linear_sleep_speed);
        h.write_real(s.angular_sleep_speed);

        h.write_len(self.bodies.len());
        for i in 0..self.bodies.len() {
            self.hash_slot(i, h);
        }

        h.write_len(self.contacts.len());
        for c in &self.contacts {
            h.write_u32(c.key.body_a);
            h.write_u32(c.key.body_b);
            h.write_u32(u32::from(c.key.part_a));
            h.write_u32(u32::from(c.key.part_b));
            h.write_vec3(c.normal);
            h.write_u8(c.count);
            for p in c.points() {
                h.write_vec3(p.point);
                h.write_real(p.separation);
                h.write_u32(p.id);
                h.write_real(p.normal_impulse);
            }
            h.write_real(c.friction_impulse[0]);
            h.write_real(c.friction_impulse[1]);
            h.write_real(c.twist_impulse);
        }
    }

    /// Item 2 of the [hash order](self) for slot `i`.
    fn hash_slot(&self, i: usize, h: &mut StateHasher) {
        let b = &self.bodies;
        h.write_u32(b.generation[i]);
        write_flag(h, b.alive[i]);
        if !b.alive[i] {
            return;
        }
        h.write_u8(b.kind[i].code());
        h.write_vec3(b.position[i]);
        write_quat(h, b.orientation[i]);
        h.write_vec3(b.linear_velocity[i]);
        h.write_vec3(b.angular_velocity[i]);
        h.write_vec3(b.force[i]);
        h.write_vec3(b.torque[i]);
        h.write_real(b.inv_mass[i]);
        h.write_real(b.mass[i]);
        write_mat3(h, &b.inertia[i]);
        h.write_real(b.linear_damping[i]);
        h.write_real(b.angular_damping[i]);
        h.write_real(b.material[i].friction);
        h.write_real(b.material[i].restitution);
        h.write_real(b.sleep_time[i]);
        write_flag(h, b.asleep[i]);
        h.write_u32(b.island[i]);
    }

    /// One 32-bit digest per slot, in ascending slot index: the low 32 bits of the XXH3-64
    /// of the slot's canonical bytes (item 2 of the [hash order](self)), so that a desync
    /// report can name the first differing body.
    pub fn slot_digests(&self) -> Vec<(Handle, u32)> {
        (0..self.bodies.len())
            .map(|i| {
                let mut h = StateHasher::new();
                self.hash_slot(i, &mut h);
                (self.bodies.handle(i), h.finish() as u32)
            })
            .collect()
    }
}
