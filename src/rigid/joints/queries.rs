//! What the API reports about joints: handles, bodies, anchors, errors and coordinates,
//! from the current poses.

use super::desc::JointKind;
use crate::math::{Real, Vec3};
use crate::rigid::solver::{JointPose, twist_angle};
use crate::rigid::system::RigidSystem;
use crate::types::Handle;

impl<R: Real> RigidSystem<R> {
    /// Number of live joints.
    pub fn joint_count(&self) -> usize {
        self.joints.live().count()
    }

    /// Handles of the live joints, in slot order.
    pub fn joint_handles(&self) -> impl Iterator<Item = Handle> + '_ {
        self.joints.live().map(|i| self.joints.handle(i))
    }

    /// A live joint's kind, with its limits, motor and spring as they are now.
    pub fn joint_kind(&self, joint: Handle) -> Option<&JointKind<R>> {
        self.joints.slot(joint).map(|i| &self.joints.kind[i])
    }

    /// The handles of a live joint's bodies A and B.
    pub fn joint_bodies(&self, joint: Handle) -> Option<(Handle, Handle)> {
        self.joints.slot(joint).map(|i| {
            (
                self.bodies.handle(self.joints.body_a[i] as usize),
                self.bodies.handle(self.joints.body_b[i] as usize),
            )
        })
    }

    /// A live joint's anchors on A and on B, world frame, m.
    pub fn joint_anchors(&self, joint: Handle) -> Option<(Vec3<R>, Vec3<R>)> {
        let i = self.joints.slot(joint)?;
        let pose = JointPose::of(&self.joints, i, &self.bodies);
        let a = self.bodies.position[self.joints.body_a[i] as usize] + pose.r_a;
        Some((a, a + pose.d))
    }

    /// How far a live joint is from holding, m: the distance between the anchors (ball,
    /// cone-twist, hinge, fixed), the anchors' distance off the axis (slider), |ℓ − L| for a
    /// rod and max(ℓ − L, 0) for a rope (ℓ the anchors' distance); 0 for a spring, which
    /// holds nothing.
    pub fn joint_error(&self, joint: Handle) -> Option<R> {
        let i = self.joints.slot(joint)?;
        let pose = JointPose::of(&self.joints, i, &self.bodies);
        let length = self.joints.length[i];
        Some(match self.joints.kind[i] {
            JointKind::Ball
            | JointKind::ConeTwist { .. }
            | JointKind::Hinge { .. }
            | JointKind::Fixed => pose.d.length(),
            JointKind::Slider { .. } => {
                let (a, _) = pose.axes();
                (pose.d - a[0] * pose.d.dot(a[0])).length()
            }
            JointKind::Rod { .. } => (pose.d.length() - length).abs(),
            JointKind::Rope { .. } => (pose.d.length() - length).max(R::ZERO),
            JointKind::Spring { .. } => R::ZERO,
        })
    }

    /// A live joint's free coordinate: the hinge angle or the cone-twist's twist (rad, in
    /// (−π, π], 0 at tick 0), the slider's translation (m, 0 at tick 0), the anchors'
    /// distance for a rod, rope or spring (m); 0 for ball and fixed joints.
    pub fn joint_coordinate(&self, joint: Handle) -> Option<R> {
        let i = self.joints.slot(joint)?;
        let pose = JointPose::of(&self.joints, i, &self.bodies);
        Some(match self.joints.kind[i] {
            JointKind::Ball | JointKind::Fixed => R::ZERO,
            JointKind::ConeTwist { .. } | JointKind::Hinge { .. } => twist_angle(pose.relative()),
            JointKind::Slider { .. } => pose.d.dot(pose.axes().0[0]),
            JointKind::Rod { .. } | JointKind::Rope { .. } | JointKind::Spring { .. } => {
                pose.d.length()
            }
        })
    }

    /// The largest [`joint_error`](Self::joint_error) of the live joints, m (0 without
    /// joints).
    pub fn max_joint_error(&self) -> R {
        self.joint_handles()
            .filter_map(|h| self.joint_error(h))
            .fold(R::ZERO, R::max)
    }
}
