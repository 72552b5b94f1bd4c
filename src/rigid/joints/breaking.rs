//! Breakable joints: a joint whose transmitted force or torque exceeds its threshold at the
//! end of a step is removed, its bodies wake, and the break is reported as an event.

use crate::math::Real;
use crate::rigid::system::RigidSystem;
use crate::types::Handle;

/// A joint that broke during the last tick.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct JointEvent<R: Real> {
    /// The joint's handle (stale from now on).
    pub joint: Handle,
    /// The force it transmitted when it broke, N.
    pub force: R,
    /// The torque it transmitted when it broke, N·m.
    pub torque: R,
}

impl<R: Real> RigidSystem<R> {
    /// After a step's solve with substep `h` (s): removes every joint whose transmitted
    /// force |Σ linear impulses|/h exceeds its `break_force` or whose torque
    /// |Σ angular impulses|/h exceeds its `break_torque`, in slot order, waking its bodies
    /// and recording a [`JointEvent`].
    pub(crate) fn break_overloaded_joints(&mut self, h: R) {
        let joints = &self.joints;
        let broken: Vec<(u32, R, R)> = self
            .scratch
            .solver
            .joint_loads(h, |i| {
                joints.break_force[i].is_some() || joints.break_torque[i].is_some()
            })
            .filter(|&(i, force, torque)| {
                let i = i as usize;
                joints.break_force[i].is_some_and(|limit| force > limit)
                    || joints.break_torque[i].is_some_and(|limit| torque > limit)
            })
            .collect();
        for (i, force, torque) in broken {
            let joint = self.joints.handle(i as usize);
            self.remove_joint(i as usize);
            self.push_joint_break(joint);
            self.scratch.joint_events.push(JointEvent {
                joint,
                force,
                torque,
            });
        }
    }

    /// Removes joint slot `i`, waking its bodies' islands.
    pub(crate) fn remove_joint(&mut self, i: usize) {
        let (a, b) = (
            self.joints.body_a[i] as usize,
            self.joints.body_b[i] as usize,
        );
        self.joints.remove(i);
        self.scratch.joint_filter_valid = false;
        for body in [a, b] {
            if self.bodies.alive[body] {
                self.wake_body(body);
            }
        }
    }

    /// The joints that broke during the last tick, in the order they broke.
    pub fn joint_events(&self) -> &[JointEvent<R>] {
        &self.scratch.joint_events
    }

    /// Forgets the last tick's joint events (the world calls it as a tick starts).
    pub(crate) fn clear_joint_events(&mut self) {
        self.scratch.joint_events.clear();
    }
}
