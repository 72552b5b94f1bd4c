//! Reporting figures of the rigid bodies, as `f64` (never fed back into the simulation).

use super::desc::BodyKind;
use super::system::RigidSystem;
use crate::math::{Real, Vec3};

/// Totals over the live dynamic bodies.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct RigidMetrics {
    /// Σ ½ m |v|² + ½ ωᵀ I_world ω, J.
    pub kinetic_energy: f64, // ok-det: reporting
    /// Σ −m g·x, J (zero at the origin).
    pub potential_energy: f64, // ok-det: reporting
    /// Σ m v, kg·m/s.
    pub momentum: [f64; 3], // ok-det: reporting
    /// The largest |v| of a body, m/s.
    pub max_speed: f64, // ok-det: reporting
    /// The deepest overlap in the current contacts, m (0 when none overlap).
    pub max_penetration: f64, // ok-det: reporting
    /// Σ m over the live dynamic bodies, kg.
    pub mass: f64, // ok-det: reporting
    /// Dynamic bodies awake.
    pub awake_bodies: u64,
    /// Dynamic bodies asleep.
    pub sleeping_bodies: u64,
    /// Live joints.
    pub joints: u64,
    /// The largest [`joint_error`](RigidSystem::joint_error), m.
    pub max_joint_error: f64, // ok-det: reporting
}

impl<R: Real> RigidSystem<R> {
    /// The reporting figures under `gravity` (m/s²). Each body's terms are computed in the
    /// scalar and summed in `f64`, so totals far beyond one body's range do not saturate.
    pub fn metrics(&self, gravity: Vec3<R>) -> RigidMetrics {
        let b = &self.bodies;
        let mut m = RigidMetrics::default();
        for i in 0..b.len() {
            if !b.alive[i] || b.kind[i] != BodyKind::Dynamic {
                continue;
            }
            if b.asleep[i] {
                m.sleeping_bodies += 1;
            } else {
                m.awake_bodies += 1;
            }
            let mass = b.mass[i];
            m.mass += mass.to_f64();
            let v = b.linear_velocity[i];
            let w = b.angular_velocity[i];
            let body_w = b.orientation[i].conjugate().rotate(w);
            let linear = (mass * v.length_squared()).to_f64() * 0.5; // ok-det: reporting
            let angular = (b.inertia[i] * body_w).dot(body_w).to_f64() * 0.5; // ok-det: reporting
            m.kinetic_energy += linear + angular;
            m.potential_energy -= (gravity.dot(b.position[i]) * mass).to_f64();
            for (total, part) in m.momentum.iter_mut().zip((v * mass).to_f64()) {
                *total += part;
            }
            m.max_speed = m.max_speed.max(v.length().to_f64());
        }
        for c in &self.contacts {
            for p in c.points() {
                m.max_penetration = m.max_penetration.max(-p.separation.to_f64());
            }
        }
        m.joints = self.joint_count() as u64;
        m.max_joint_error = self.max_joint_error().to_f64();
        m
    }
}
