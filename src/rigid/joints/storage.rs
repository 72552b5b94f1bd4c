//! Structure-of-arrays joint storage: one `Vec` per attribute, indexed by joint slot.
//!
//! Slots are never freed, as for bodies: removing or breaking a joint marks its slot dead
//! and bumps its generation, so every [`Handle`] to it goes stale at once. A new joint (a
//! scene's, in order, or a spawned one) takes the lowest dead slot, or a new slot at the
//! end.

use serde::{Deserialize, Serialize};

use super::desc::JointKind;
use crate::math::{Quat, Real, Vec3};
use crate::types::Handle;

/// The most scalar impulses a joint accumulates: a hinge's three point rows, two angular
/// locks, two limits, a motor and a spring.
pub const MAX_JOINT_ROWS: usize = 9;

/// A frame fixed in a body: its origin (m, from the body's centre of mass, body frame) and
/// its orientation (body frame → joint frame: the joint axis is the frame's x axis).
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(bound = "")]
pub struct LocalFrame<R: Real> {
    /// Origin, m, body frame, from the centre of mass.
    pub origin: Vec3<R>,
    /// Orientation of the joint frame in the body frame (a unit quaternion).
    pub rotation: Quat<R>,
}

/// What a new joint is made of, already checked.
#[derive(Clone, Debug)]
pub(crate) struct NewJoint<R: Real> {
    pub kind: JointKind<R>,
    pub body_a: u32,
    pub body_b: u32,
    pub frame_a: LocalFrame<R>,
    pub frame_b: LocalFrame<R>,
    pub length: R,
    pub collide: bool,
    pub break_force: Option<R>,
    pub break_torque: Option<R>,
}

/// Every joint attribute, one array each, indexed by slot.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(bound = "")]
pub(crate) struct Joints<R: Real> {
    /// What the joint keeps, with its limits, motor and spring (commands change motors).
    pub kind: Vec<JointKind<R>>,
    /// Body slots of A and B.
    pub body_a: Vec<u32>,
    pub body_b: Vec<u32>,
    /// The joint frame in each body.
    pub frame_a: Vec<LocalFrame<R>>,
    pub frame_b: Vec<LocalFrame<R>>,
    /// Rod length, rope maximum or spring rest length, m (0 for the other kinds).
    pub length: Vec<R>,
    /// Whether A and B collide with each other.
    pub collide: Vec<bool>,
    /// Break thresholds: force (N) and torque (N·m).
    pub break_force: Vec<Option<R>>,
    pub break_torque: Vec<Option<R>>,
    /// Accumulated impulses of the joint's rows at the end of the last step, for warm
    /// starting (row order: [`crate::rigid::solver`]'s joint rows).
    pub impulses: Vec<[R; MAX_JOINT_ROWS]>,
    /// Whether the slot holds a joint.
    pub alive: Vec<bool>,
    /// Bumped every time the slot's joint is removed or breaks.
    pub generation: Vec<u32>,
    /// Softness of every joint's position correction: frequency (Hz) and damping ratio.
    pub hertz: R,
    pub damping_ratio: R,
    /// Gauss–Seidel passes over the joints per solver pass (0 without joints).
    pub iterations: u32,
}

impl<R: Real> Joints<R> {
    /// Number of slots, alive or dead.
    pub fn len(&self) -> usize {
        self.alive.len()
    }

    /// Whether there are no slots at all.
    pub fn is_empty(&self) -> bool {
        self.alive.is_empty()
    }

    /// The handle of slot `i`.
    pub fn handle(&self, i: usize) -> Handle {
        Handle::new(i as u32, self.generation[i])
    }

    /// The slot of a live joint, or `None` for a stale or unknown handle.
    pub fn slot(&self, handle: Handle) -> Option<usize> {
        let i = handle.index as usize;
        (i < self.len() && self.alive[i] && self.generation[i] == handle.generation).then_some(i)
    }

    /// Adds a joint in the lowest dead slot, or a new slot at the end.
    pub fn insert(&mut self, joint: NewJoint<R>) -> Handle {
        if let Some(i) = self.alive.iter().position(|&alive| !alive) {
            self.kind[i] = joint.kind;
            self.body_a[i] = joint.body_a;
            self.body_b[i] = joint.body_b;
            self.frame_a[i] = joint.frame_a;
            self.frame_b[i] = joint.frame_b;
            self.length[i] = joint.length;
            self.collide[i] = joint.collide;
            self.break_force[i] = joint.break_force;
            self.break_torque[i] = joint.break_torque;
            self.impulses[i] = [R::ZERO; MAX_JOINT_ROWS];
            self.alive[i] = true;
            return self.handle(i);
        }
        self.kind.push(joint.kind);
        self.body_a.push(joint.body_a);
        self.body_b.push(joint.body_b);
        self.frame_a.push(joint.frame_a);
        self.frame_b.push(joint.frame_b);
        self.length.push(joint.length);
        self.collide.push(joint.collide);
        self.break_force.push(joint.break_force);
        self.break_torque.push(joint.break_torque);
        self.impulses.push([R::ZERO; MAX_JOINT_ROWS]);
        self.alive.push(true);
        self.generation.push(0);
        self.handle(self.len() - 1)
    }

    /// Marks slot `i` dead and makes its handles stale; its impulses are cleared.
    pub fn remove(&mut self, i: usize) {
        self.alive[i] = false;
        self.generation[i] = self.generation[i].wrapping_add(1);
        self.impulses[i] = [R::ZERO; MAX_JOINT_ROWS];
    }

    /// The live joints' slots, in ascending order.
    pub fn live(&self) -> impl Iterator<Item = usize> + '_ {
        (0..self.len()).filter(|&i| self.alive[i])
    }

    /// The sorted (lower slot, higher slot) body pairs of the live joints whose bodies do
    /// not collide, without repeats.
    pub fn non_colliding_pairs(&self) -> Vec<(u32, u32)> {
        let mut pairs: Vec<(u32, u32)> = self
            .live()
            .filter(|&i| !self.collide[i])
            .map(|i| {
                let (a, b) = (self.body_a[i], self.body_b[i]);
                (a.min(b), a.max(b))
            })
            .collect();
        pairs.sort_unstable();
        pairs.dedup();
        pairs
    }
}
