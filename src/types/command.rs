//! Inputs: typed commands, per player, per tick.
//!
//! The world applies a tick's inputs once, at the start of the tick (stage
//! [`Stage::ApplyInputs`](crate::world::Stage::ApplyInputs)), in ascending player index and, within
//! a player, in the order the commands were given. A command whose target does not exist
//! (a stale handle, a subsystem absent from the scene, an emitter index out of range) is
//! skipped and counted in [`TickReport::ignored_commands`](crate::world::TickReport); it never
//! fails the tick.

use serde::{Deserialize, Serialize};

use super::Handle;
use crate::math::{Fx, Quat, Real, Vec3};

/// What a command acts on.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub enum Target {
    /// One particle.
    Particle(Handle),
    /// Every live particle of a group (the `group` of an emitter or particle template).
    ParticleGroup(u16),
    /// One rigid body.
    Body(Handle),
    /// A kinematic attachment target of the soft bodies, numbered over the scene's
    /// attachments body after body (only [`Command::MoveKinematic`] acts on it).
    SoftAttachment(u32),
    /// One rigid-body joint (only [`Command::Remove`] and [`Command::SetMotor`] act on it).
    Joint(Handle),
}

/// One command from one player.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(bound = "")]
pub enum Command<R: Real = Fx> {
    /// Adds a force (N) for this tick. `point` is the world point it acts at; point masses
    /// ignore it.
    ApplyForce {
        /// What receives the force.
        target: Target,
        /// Force in newtons.
        force: Vec3<R>,
        /// Point of application in metres, world frame.
        point: Option<Vec3<R>>,
    },
    /// Changes momentum at once: Δv = J / m.
    ApplyImpulse {
        /// What receives the impulse.
        target: Target,
        /// Impulse in N·s.
        impulse: Vec3<R>,
        /// Point of application in metres, world frame.
        point: Option<Vec3<R>>,
    },
    /// Sets the velocity (m/s).
    SetVelocity {
        /// What gets the velocity.
        target: Target,
        /// Velocity in m/s.
        velocity: Vec3<R>,
    },
    /// Creates an object from the scene's template number `template`.
    Spawn {
        /// Index into the scene's particle templates.
        template: u32,
        /// Position in metres.
        position: Vec3<R>,
        /// Velocity in m/s.
        velocity: Vec3<R>,
    },
    /// Removes an object.
    Remove {
        /// What to remove.
        target: Target,
    },
    /// Moves a kinematic object or a pinned point to a position (m).
    MoveKinematic {
        /// What to move.
        target: Target,
        /// New position in metres.
        position: Vec3<R>,
    },
    /// Switches emitter number `emitter` on or off.
    SetEmitter {
        /// Index into the scene's emitters.
        emitter: u32,
        /// On or off.
        on: bool,
    },
    /// Sets the world's gravity (m/s²).
    SetGravity {
        /// Gravitational acceleration in m/s².
        gravity: Vec3<R>,
    },
    /// An opaque value for game logic. The world hashes it into the state so that peers
    /// that disagree on game logic inputs also disagree on the checksum.
    Payload(u32),
    /// Sets (or adds) the motor of a hinge or slider joint: it drives the joint's relative
    /// speed to `speed` (rad/s or m/s) with at most `max_force` (N·m or N); a `max_force`
    /// of 0 switches it off. Wakes the joint's bodies.
    SetMotor {
        /// The joint.
        target: Target,
        /// Target relative speed, rad/s for a hinge, m/s for a slider.
        speed: R,
        /// The largest torque (N·m) or force (N), at least 0.
        max_force: R,
    },
    /// Creates a rigid body from the scene's body template number `template`
    /// ([`RigidDesc::templates`](crate::rigid::RigidDesc::templates)). The body takes the
    /// lowest free slot ([`RigidSystem::spawned`](crate::rigid::RigidSystem::spawned) lists
    /// the handles a tick created).
    SpawnBody {
        /// Index into the scene's body templates.
        template: u32,
        /// Position of the centre of mass, m.
        position: Vec3<R>,
        /// Orientation (normalised).
        orientation: Quat<R>,
        /// Linear velocity, m/s.
        velocity: Vec3<R>,
        /// Angular velocity, world frame, rad/s.
        angular_velocity: Vec3<R>,
    },
    /// Creates a joint from the scene's joint template number `template`
    /// ([`RigidDesc::joint_templates`](crate::rigid::RigidDesc::joint_templates)) between
    /// two live bodies.
    SpawnJoint {
        /// Index into the scene's joint templates.
        template: u32,
        /// Bodies A and B.
        bodies: (Handle, Handle),
        /// A's anchor, world frame, m.
        anchor: Vec3<R>,
        /// B's anchor, world frame, m; absent: the same point as `anchor`.
        anchor_b: Option<Vec3<R>>,
        /// The joint axis, world frame, unit length.
        axis: Vec3<R>,
    },
    /// Drives a kinematic character ([`crate::character`]): from this tick on it walks at
    /// the horizontal part of `desired_velocity` (m/s) until told otherwise, and it jumps
    /// this tick when `jump` is set and it stands on the ground.
    MoveCharacter {
        /// The character (index, generation 0).
        target: Handle,
        /// Walking velocity, m/s; its y component is ignored.
        desired_velocity: Vec3<R>,
        /// Jump now (with the character's `jump_speed`), if grounded.
        jump: bool,
    },
    /// Drops a disturbance on the water surface: a smooth bump of `height` (m, negative
    /// for a dip) and `radius` (m) centred at (x, z)
    /// ([`WaterSystem::disturb`](crate::water::WaterSystem::disturb)). Ignored (counted)
    /// without a water surface.
    DisturbWater {
        /// Centre along x, m.
        x: R,
        /// Centre along z, m.
        z: R,
        /// Height of the bump at its centre, m.
        height: R,
        /// Radius of the bump, m.
        radius: R,
    },
}

/// The commands of one player for one tick.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(bound = "")]
pub struct PlayerInput<R: Real = Fx> {
    /// Player index; the world applies players in ascending index.
    pub player: u8,
    /// Commands in the order the player gave them.
    pub commands: Vec<Command<R>>,
}

/// All inputs for one tick.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(bound = "")]
pub struct TickInput<R: Real = Fx> {
    /// The tick these inputs are applied at (the world's tick counter before the step).
    pub tick: u64,
    /// Per-player commands, in ascending player index, at most one entry per player.
    pub players: Vec<PlayerInput<R>>,
}

impl<R: Real> TickInput<R> {
    /// Puts the players in the canonical order (ascending index) and merges duplicate
    /// entries for a player in the order they appeared.
    pub fn canonicalize(&mut self) {
        self.players.sort_by_key(|p| p.player);
        let mut merged: Vec<PlayerInput<R>> = Vec::with_capacity(self.players.len());
        for p in self.players.drain(..) {
            match merged.last_mut() {
                Some(last) if last.player == p.player => last.commands.extend(p.commands),
                _ => merged.push(p),
            }
        }
        self.players = merged;
    }

    /// True when no player gave a command.
    pub fn is_empty(&self) -> bool {
        self.players.iter().all(|p| p.commands.is_empty())
    }
}
