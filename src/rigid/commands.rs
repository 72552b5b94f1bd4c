//! The command methods the world calls while applying a tick's inputs to rigid bodies.
//!
//! Each returns whether its target existed: `false` for a stale handle or a target that is
//! not a body or a joint. A command that acts on a body or a joint wakes its island. Forces
//! and impulses move only dynamic bodies; a static body accepts them and does not move.

use super::desc::BodyKind;
use super::events::EventKind;
use super::joints::desc::{JointKind, Motor};
use super::system::RigidSystem;
use crate::math::{Real, Vec3};
use crate::types::{Command, Target};

impl<R: Real> RigidSystem<R> {
    /// Applies a world command aimed at a rigid body or a joint; false when its target does
    /// not exist or the command does not act on it.
    pub fn apply_command(&mut self, command: &Command<R>) -> bool {
        match *command {
            Command::SpawnBody {
                template,
                position,
                orientation,
                velocity,
                angular_velocity,
            } => {
                return self
                    .spawn_body(template, position, orientation, velocity, angular_velocity)
                    .is_some();
            }
            Command::SpawnJoint {
                template,
                bodies,
                anchor,
                anchor_b,
                axis,
            } => {
                return self
                    .spawn_joint(template, bodies, anchor, anchor_b, axis)
                    .is_some();
            }
            _ => {}
        }
        let target = match command {
            Command::ApplyForce { target, .. }
            | Command::ApplyImpulse { target, .. }
            | Command::SetVelocity { target, .. }
            | Command::Remove { target }
            | Command::MoveKinematic { target, .. }
            | Command::SetMotor { target, .. } => *target,
            _ => return false,
        };
        if let Target::Joint(handle) = target {
            return self.apply_joint_command(handle, command);
        }
        let Target::Body(handle) = target else {
            return false;
        };
        let Some(i) = self.bodies.slot(handle) else {
            return false;
        };
        match *command {
            Command::ApplyForce { force, point, .. } => self.apply_force(i, force, point),
            Command::ApplyImpulse { impulse, point, .. } => self.apply_impulse(i, impulse, point),
            Command::SetVelocity { velocity, .. } => self.set_velocity(i, velocity),
            Command::Remove { .. } => self.remove(i),
            Command::MoveKinematic { position, .. } => self.move_kinematic(i, position),
            _ => return false,
        }
        true
    }

    /// A command aimed at joint `handle`: `Remove` removes it, `SetMotor` sets the motor of
    /// a hinge or slider; false for a stale handle or another command or kind.
    fn apply_joint_command(&mut self, handle: crate::types::Handle, command: &Command<R>) -> bool {
        let Some(i) = self.joints.slot(handle) else {
            return false;
        };
        match *command {
            Command::Remove { .. } => {
                self.remove_joint(i);
                true
            }
            Command::SetMotor {
                speed, max_force, ..
            } => {
                let motor = (max_force > R::ZERO).then_some(Motor { speed, max_force });
                match &mut self.joints.kind[i] {
                    JointKind::Hinge { motor: m, .. } | JointKind::Slider { motor: m, .. } => {
                        *m = motor;
                    }
                    _ => return false,
                }
                let (a, b) = (
                    self.joints.body_a[i] as usize,
                    self.joints.body_b[i] as usize,
                );
                self.wake_body(a);
                self.wake_body(b);
                true
            }
            _ => false,
        }
    }

    /// Adds force F (N) at world point p (m), or at the centre of mass when `point` is
    /// `None`, for the rest of the tick: F to the force and (p − x) × F to the torque.
    pub(crate) fn apply_force(&mut self, i: usize, force: Vec3<R>, point: Option<Vec3<R>>) {
        if self.bodies.kind[i] != BodyKind::Dynamic {
            return;
        }
        self.wake_body(i);
        self.bodies.force[i] += force;
        if let Some(p) = point {
            self.bodies.torque[i] += (p - self.bodies.position[i]).cross(force);
        }
    }

    /// Applies impulse J (N·s) at world point p: Δv = J/m, Δω = I⁻¹(p − x) × J with the
    /// world-frame inverse inertia R I⁻¹ Rᵀ.
    fn apply_impulse(&mut self, i: usize, impulse: Vec3<R>, point: Option<Vec3<R>>) {
        if self.bodies.kind[i] != BodyKind::Dynamic {
            return;
        }
        self.wake_body(i);
        let b = &mut self.bodies;
        b.linear_velocity[i] += impulse * b.inv_mass[i];
        if let Some(p) = point {
            let inv_inertia = b.orientation[i].to_mat3().rotate_inertia(b.inv_inertia[i]);
            b.angular_velocity[i] += inv_inertia * (p - b.position[i]).cross(impulse);
        }
    }

    /// A push from outside the rigid stage (a particle's bounce) on the awake dynamic body
    /// in slot `i`: impulse J (N·s) at world point p, applied at once as
    /// [`apply_impulse`](Self::apply_impulse) applies it. When the body sleeps nothing is
    /// applied and its centre of mass (m) is returned: the caller gathers the pushes about
    /// it and gives them to [`push_sleeping_body`](Self::push_sleeping_body) once the stage
    /// ends.
    pub(crate) fn push_body(
        &mut self,
        i: usize,
        impulse: Vec3<R>,
        point: Vec3<R>,
    ) -> Option<Vec3<R>> {
        let b = &self.bodies;
        if b.kind[i] != BodyKind::Dynamic {
            return None;
        }
        if b.asleep[i] {
            return Some(b.position[i]);
        }
        self.apply_impulse(i, impulse, Some(point));
        None
    }

    /// The pushes a sleeping dynamic body gathered during a stage: total impulse J (N·s) and
    /// total moment L = Σ (pₖ − c) × Jₖ (N·m·s) about its centre c. The body wakes and
    /// takes Δv = J/m, Δω = I⁻¹ L only when |J|/m reaches its linear sleep speed; weaker
    /// pushes leave it asleep and unmoved, so that particles resting on a crate do not
    /// keep it awake.
    pub(crate) fn push_sleeping_body(&mut self, i: usize, impulse: Vec3<R>, moment: Vec3<R>) {
        let b = &self.bodies;
        if b.kind[i] != BodyKind::Dynamic
            || impulse.length() * b.inv_mass[i] < self.settings.linear_sleep_speed
        {
            return;
        }
        self.wake_body(i);
        let b = &mut self.bodies;
        b.linear_velocity[i] += impulse * b.inv_mass[i];
        let inv_inertia = b.orientation[i].to_mat3().rotate_inertia(b.inv_inertia[i]);
        b.angular_velocity[i] += inv_inertia * moment;
    }

    /// A push from outside the rigid stage (a fluid's pressure over a world substep) on the
    /// dynamic body in slot `i`: impulse J (N·s) and moment L (N·m·s) about its centre of
    /// mass, Δv = J/m and Δω = I⁻¹ L when it is awake; on a sleeping body,
    /// [`push_sleeping_body`](Self::push_sleeping_body)'s rule. Other kinds do not move.
    pub(crate) fn push_body_about_centre(&mut self, i: usize, impulse: Vec3<R>, moment: Vec3<R>) {
        let b = &mut self.bodies;
        if b.kind[i] != BodyKind::Dynamic || !b.alive[i] {
            return;
        }
        if b.asleep[i] {
            self.push_sleeping_body(i, impulse, moment);
            return;
        }
        b.linear_velocity[i] = b.linear_velocity[i].add_scaled(impulse, b.inv_mass[i]);
        let inv_inertia = b.orientation[i].to_mat3().rotate_inertia(b.inv_inertia[i]);
        b.angular_velocity[i] += inv_inertia * moment;
    }

    /// Moves the awake dynamic body in slot `i` by `displacement` (m) and turns it by the
    /// rotation vector `rotation` (rad): what a push from outside the rigid stage did to it
    /// during a world substep whose motion the rigid step had already integrated. Other
    /// bodies do not move. Returns whether it moved; the caller then updates the query
    /// index.
    pub(crate) fn displace_body(
        &mut self,
        i: usize,
        displacement: Vec3<R>,
        rotation: Vec3<R>,
    ) -> bool {
        let b = &mut self.bodies;
        if !b.is_awake_dynamic(i) || (displacement == Vec3::ZERO && rotation == Vec3::ZERO) {
            return false;
        }
        b.position[i] += displacement;
        b.orientation[i] = b.orientation[i].integrate(rotation, R::ONE);
        true
    }

    /// Sets the linear velocity (m/s) of a dynamic or kinematic body.
    fn set_velocity(&mut self, i: usize, velocity: Vec3<R>) {
        if self.bodies.kind[i] == BodyKind::Static {
            return;
        }
        self.wake_body(i);
        self.bodies.linear_velocity[i] = velocity;
    }

    /// Moves a kinematic body's centre of mass to `position` (m) at once; bodies it now
    /// overlaps are pushed out by the solver. Other kinds do not move.
    fn move_kinematic(&mut self, i: usize, position: Vec3<R>) {
        if self.bodies.kind[i] != BodyKind::Kinematic {
            return;
        }
        self.bodies.position[i] = position;
        self.scratch.query.invalidate();
        self.wake_touching(i);
    }

    /// Removes the body: its contacts and joints go, and the islands it touched or was
    /// jointed to wake.
    fn remove(&mut self, i: usize) {
        self.wake_touching(i);
        self.wake_body(i);
        let slot = i as u32;
        let attached: Vec<usize> = self
            .joints
            .live()
            .filter(|&j| self.joints.body_a[j] == slot || self.joints.body_b[j] == slot)
            .collect();
        for j in attached {
            self.remove_joint(j);
        }
        self.end_events_of(slot);
        self.bodies.remove(i);
        self.contacts
            .retain(|c| c.key.body_a != slot && c.key.body_b != slot);
        self.sensor_overlaps
            .retain(|&(a, b)| a != slot && b != slot);
        self.scratch.cache_valid = false;
    }

    /// Before slot `slot`'s body is removed: a `contact_end` for each body it touches and a
    /// `sensor_exit` for each sensor overlap it is in, with the handles it had.
    fn end_events_of(&mut self, slot: u32) {
        let mut ended: Vec<(EventKind, u32, u32)> = self
            .contacts
            .iter()
            .filter(|c| c.key.body_a == slot || c.key.body_b == slot)
            .map(|c| (EventKind::ContactEnd, c.key.body_a, c.key.body_b))
            .collect();
        ended.dedup();
        ended.extend(
            self.sensor_overlaps
                .iter()
                .filter(|&&(a, b)| a == slot || b == slot)
                .map(|&(a, b)| (EventKind::SensorExit, a, b)),
        );
        for (kind, a, b) in ended {
            self.push_pair_event(kind, a, b);
        }
    }

    /// Wakes the islands of every body touching slot `i`.
    fn wake_touching(&mut self, i: usize) {
        let slot = i as u32;
        let bodies = &self.bodies;
        let mut islands: Vec<u32> = self
            .contacts
            .iter()
            .filter(|c| c.key.body_a == slot || c.key.body_b == slot)
            .map(|c| {
                let other = if c.key.body_a == slot {
                    c.key.body_b
                } else {
                    c.key.body_a
                };
                other as usize
            })
            .filter(|&j| bodies.asleep[j])
            .map(|j| bodies.island[j])
            .collect();
        self.wake_islands(&mut islands);
    }
}
