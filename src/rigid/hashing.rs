//! The canonical state of the rigid bodies, for checksums.
//!
//! [`RigidSystem::hash_state`] writes, in order (integers little-endian, scalars as their
//! raw fixed-point bits, vectors x, y, z, quaternions w, x, y, z, matrices column by
//! column, flags as one byte 0 or 1):
//!
//! 1. the solver settings: substeps (`u32`), contact hertz, damping ratio, push velocity,
//!    restitution threshold, speculative distance, sleeping flag, time to sleep, linear and
//!    angular sleep speeds, contact recycle distance;
//! 2. the slot count (`u64`), then each slot in ascending index: its generation (`u32`),
//!    its alive flag, and for a live body: kind code (`u8`), position, orientation, linear
//!    and angular velocity, force, torque, inverse mass, mass, inertia, linear and angular
//!    damping, friction, restitution, sleep time, asleep flag, island (`u32`);
//! 3. the contact count (`u64`), then each contact in key order: body A, body B (`u32`),
//!    part A, part B (`u32`), normal, point count (`u8`), each point's position,
//!    separation, feature id (`u32`) and normal impulse, then the contact's two friction
//!    impulses and its twist impulse, then its recycling frame as an option (a byte 0 for
//!    none; else 1, the translation, rotation and normal of the frame, and each point's
//!    anchors on A and on B);
//! 4. when there are joints, the joints (see `hash_joints`);
//! 5. when some sensor overlaps a body, the overlap count (`u64`), then each overlapping
//!    pair in ascending order: lower slot, higher slot (`u32`). A scene without sensors
//!    hashes as it did before sensors existed.
//!
//! Collision filters, sensor flags and bullet flags, like shapes, do not change during a run and are
//! part of the scene (or of the template a spawn names). Shapes do not change during a run and are part of the scene, which replays check by
//! its own hash; they are not hashed here.

use super::joints::desc::{JointKind, Limits, Motor, Spring};
use super::system::RigidSystem;
use crate::math::{Mat3, Quat, Real, StateHasher};
use crate::types::Handle;

fn write_flag(h: &mut StateHasher, flag: bool) {
    h.write_u8(u8::from(flag));
}

fn write_option<T: Copy>(
    h: &mut StateHasher,
    value: Option<T>,
    write: impl Fn(&mut StateHasher, T),
) {
    match value {
        None => h.write_u8(0),
        Some(v) => {
            h.write_u8(1);
            write(h, v);
        }
    }
}

/// A joint kind: its code, then its parameters in declaration order.
fn write_kind<R: Real>(h: &mut StateHasher, kind: &JointKind<R>) {
    let limits = |h: &mut StateHasher, l: Limits<R>| {
        h.write_real(l.lower);
        h.write_real(l.upper);
    };
    let motor = |h: &mut StateHasher, m: Motor<R>| {
        h.write_real(m.speed);
        h.write_real(m.max_force);
    };
    let spring = |h: &mut StateHasher, s: Spring<R>| {
        h.write_real(s.hertz);
        h.write_real(s.damping_ratio);
    };
    let real = |h: &mut StateHasher, v: R| h.write_real(v);
    h.write_u8(kind.code());
    match *kind {
        JointKind::Ball | JointKind::Fixed => {}
        JointKind::ConeTwist {
            swing,
            twist_lower,
            twist_upper,
            friction,
        } => {
            h.write_real(swing);
            h.write_real(twist_lower);
            h.write_real(twist_upper);
            h.write_real(friction);
        }
        JointKind::Hinge {
            limits: l,
            motor: m,
            spring: s,
        } => {
            write_option(h, l, limits);
            write_option(h, m, motor);
            write_option(h, s, spring);
        }
        JointKind::Slider {
            limits: l,
            motor: m,
        } => {
            write_option(h, l, limits);
            write_option(h, m, motor);
        }
        JointKind::Rod { length } => write_option(h, length, real),
        JointKind::Rope { max_length } => write_option(h, max_length, real),
        JointKind::Spring {
            rest_length,
            spring: s,
        } => {
            write_option(h, rest_length, real);
            spring(h, s);
        }
    }
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
        h.write_real(s.contact_recycle_distance);

        h.write_len(self.bodies.len());
        for i in 0..self.bodies.len() {
            self.hash_slot(i, h);
        }

        h.write_len(self.contacts.len());
        for c in &self.contacts {
            h.write_u32(c.key.body_a);
            h.write_u32(c.key.body_b);
            h.write_u32(c.key.part_a);
            h.write_u32(c.key.part_b);
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
            let frame = self.frames.get(c.frame as usize).copied();
            write_option(h, frame, |h, frame| {
                h.write_vec3(frame.translation);
                write_quat(h, frame.rotation);
                h.write_vec3(frame.normal);
                for [on_a, on_b] in &frame.anchors[..usize::from(c.count)] {
                    h.write_vec3(*on_a);
                    h.write_vec3(*on_b);
                }
            });
        }

        if !self.joints.is_empty() {
            self.hash_joints(h);
        }

        if !self.sensor_overlaps.is_empty() {
            h.write_len(self.sensor_overlaps.len());
            for &(a, b) in &self.sensor_overlaps {
                h.write_u32(a);
                h.write_u32(b);
            }
        }
    }

    /// Item 4 of the [hash order](self).
    fn hash_joints(&self, h: &mut StateHasher) {
        let j = &self.joints;
        h.write_real(j.hertz);
        h.write_real(j.damping_ratio);
        h.write_u32(j.iterations);
        h.write_len(j.len());
        for i in 0..j.len() {
            h.write_u32(j.generation[i]);
            write_flag(h, j.alive[i]);
            if !j.alive[i] {
                continue;
            }
            write_kind(h, &j.kind[i]);
            h.write_u32(j.body_a[i]);
            h.write_u32(j.body_b[i]);
            for frame in [&j.frame_a[i], &j.frame_b[i]] {
                h.write_vec3(frame.origin);
                write_quat(h, frame.rotation);
            }
            h.write_real(j.length[i]);
            write_flag(h, j.collide[i]);
            write_option(h, j.break_force[i], |h, v| h.write_real(v));
            write_option(h, j.break_torque[i], |h, v| h.write_real(v));
            for &impulse in &j.impulses[i] {
                h.write_real(impulse);
            }
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
