//! Where a joint's frames are now: its anchors and axes in the world frame from the
//! current poses of its bodies, and the joint's angles.

use crate::math::{Quat, Real, Vec3};
use crate::rigid::bodies::Bodies;
use crate::rigid::joints::storage::{Joints, LocalFrame};

/// A joint's current geometry.
#[derive(Clone, Copy, Debug)]
pub(crate) struct JointPose<R: Real> {
    /// Anchors from the centres of mass, world frame, m.
    pub r_a: Vec3<R>,
    pub r_b: Vec3<R>,
    /// From A's anchor to B's, m: (x_b + r_b) − (x_a + r_a).
    pub d: Vec3<R>,
    /// The joint frame of each body: its rotation, world frame.
    pub frame_a: Quat<R>,
    pub frame_b: Quat<R>,
}

impl<R: Real> JointPose<R> {
    /// The geometry of joint `i` for the bodies' current positions and orientations.
    pub fn of(joints: &Joints<R>, i: usize, bodies: &Bodies<R>) -> Self {
        let place = |slot: u32, frame: &LocalFrame<R>| {
            let slot = slot as usize;
            let q = bodies.orientation[slot];
            let r = q.rotate(frame.origin);
            (r, bodies.position[slot] + r, q * frame.rotation)
        };
        let (r_a, p_a, frame_a) = place(joints.body_a[i], &joints.frame_a[i]);
        let (r_b, p_b, frame_b) = place(joints.body_b[i], &joints.frame_b[i]);
        Self {
            r_a,
            r_b,
            d: p_b - p_a,
            frame_a,
            frame_b,
        }
    }

    /// The axes (x, y, z) of A's and B's joint frames, world frame.
    pub fn axes(&self) -> ([Vec3<R>; 3], [Vec3<R>; 3]) {
        let columns = |q: Quat<R>| {
            let m = q.to_mat3();
            [m.cols[0], m.cols[1], m.cols[2]]
        };
        (columns(self.frame_a), columns(self.frame_b))
    }

    /// B's joint frame seen from A's, q = q_A* ⊗ q_B, in the half-space w ≥ 0: the
    /// identity when the frames agree.
    pub fn relative(&self) -> Quat<R> {
        let q = self.frame_a.conjugate() * self.frame_b;
        if q.w < R::ZERO { -q } else { q }
    }
}

/// The twist of a relative rotation q (w ≥ 0) about the joint's x axis, rad, in (−π, π]:
/// 2·atan2(q_x, q_w), the angle of the twist factor of q = swing ⊗ twist.
pub(crate) fn twist_angle<R: Real>(q: Quat<R>) -> R {
    R::TWO * q.x.atan2(q.w)
}
