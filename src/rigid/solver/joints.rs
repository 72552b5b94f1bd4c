//! The joints' part of the solver: one constraint per joint with a body to move, solved in
//! the same passes as the contacts and before them (Box2D v3's order), in joint slot order.
//!
//! Per step, [`Solver::prepare_joints`] builds each joint's point block and rows from the
//! poses at the step's start, with the stored impulses; per substep,
//! [`Solver::update_joints`] rebuilds them from the current poses, keeping the accumulated
//! impulses. The effective masses are recomputed with the Jacobians: a row about an axis
//! that turns with its body, solved with the mass of the step's start, would meet an
//! effective mass off by the body's anisotropy (20 times for a thin capsule), and a
//! Gauss–Seidel step that overshoots more than twice diverges (measured: a chain of 20
//! hinged capsules blew up within 100 ticks). Keeping the step's Jacobians instead lets the
//! anchors lag their bodies' turn, and a fast chain then drifts apart by centimetres.
//! Impulses are carried from step to step in the joint storage, for warm starting.

use super::Solver;
use super::body::{STATIC_BODY, pair};
use super::joint_point::PointBlock;
use super::joint_pose::JointPose;
use super::joint_row::{JointPass, JointRow};
use super::joint_rows::{JointRows, RowInputs};
use super::softness::Softness;
use crate::math::{Real, Vec3};
use crate::rigid::bodies::Bodies;
use crate::rigid::joints::desc::JointKind;
use crate::rigid::joints::storage::Joints;

/// One joint in the solver for a step.
#[derive(Clone, Debug)]
pub(crate) struct JointConstraint<R: Real> {
    /// The joint's slot.
    pub joint: u32,
    /// Solver indices of bodies A and B.
    pub a: u32,
    pub b: u32,
    /// The point block, for the kinds that have one.
    pub point: Option<PointBlock<R>>,
    /// The joint's rows: `rows[first..first + count]` of the solver's row list; the point
    /// block is solved after the first `locks_from` of them.
    pub first: u32,
    pub count: u32,
    pub locks_from: u32,
    /// The softness of the joint's spring for the step's substep (zero without one).
    pub spring: Softness<R>,
}

/// The spring of a joint kind, if it has one: (natural frequency Hz, damping ratio).
fn spring_of<R: Real>(kind: &JointKind<R>) -> Option<(R, R)> {
    match kind {
        JointKind::Hinge {
            spring: Some(s), ..
        }
        | JointKind::Spring { spring: s, .. } => Some((s.hertz, s.damping_ratio)),
        _ => None,
    }
}

impl<R: Real> Solver<R> {
    /// Builds the step's joint constraints for substep `h` (s), for the solver bodies
    /// already set up from `bodies`: every live joint with a body to move, in slot order,
    /// with its impulses from the last step.
    pub fn prepare_joints(&mut self, joints: &Joints<R>, bodies: &Bodies<R>, h: R) {
        self.joints.clear();
        self.joint_rows.clear();
        for i in joints.live() {
            let a = self.index_of_slot[joints.body_a[i] as usize];
            let b = self.index_of_slot[joints.body_b[i] as usize];
            if a == STATIC_BODY && b == STATIC_BODY {
                continue;
            }
            let spring = spring_of(&joints.kind[i])
                .map_or(Softness::new(R::ZERO, R::ZERO, h), |(f, z)| {
                    Softness::new(f, z, h)
                });
            let (ba, bb) = (&self.bodies[a as usize], &self.bodies[b as usize]);
            let inputs = RowInputs {
                kind: &joints.kind[i],
                length: joints.length[i],
                h,
                spring,
            };
            let pose = JointPose::of(joints, i, bodies);
            let first = self.joint_rows.len();
            let built = JointRows::build(&inputs, &pose, (ba, bb), &mut self.joint_rows);
            let (count, locks_from) = (built.count(), built.locks_from);
            let stored = &joints.impulses[i];
            let point = built.point.map(|mut p| {
                p.mass = p.effective_mass(ba, bb);
                p.impulse = Vec3::new(stored[0], stored[1], stored[2]);
                p
            });
            for row in &mut self.joint_rows[first..] {
                row.mass = row.effective_mass(ba, bb);
                row.impulse = stored[usize::from(row.slot)];
            }
            self.joints.push(JointConstraint {
                joint: i as u32,
                a,
                b,
                point,
                first: first as u32,
                count: count as u32,
                locks_from: locks_from as u32,
                spring,
            });
        }
    }

    /// Rebuilds every joint constraint from the bodies' current poses (Jacobians, errors and
    /// effective masses), keeping the accumulated impulses.
    pub fn update_joints(&mut self, joints: &Joints<R>, bodies: &Bodies<R>, h: R) {
        for c in &mut self.joints {
            let i = c.joint as usize;
            let (ba, bb) = (&self.bodies[c.a as usize], &self.bodies[c.b as usize]);
            let inputs = RowInputs {
                kind: &joints.kind[i],
                length: joints.length[i],
                h,
                spring: c.spring,
            };
            let pose = JointPose::of(joints, i, bodies);
            let scratch = &mut self.joint_row_scratch;
            scratch.clear();
            let built = JointRows::build(&inputs, &pose, (ba, bb), scratch);
            if let (Some(point), Some(new)) = (&mut c.point, built.point) {
                *point = PointBlock {
                    mass: new.effective_mass(ba, bb),
                    impulse: point.impulse,
                    ..new
                };
            }
            let rows = &mut self.joint_rows[c.first as usize..(c.first + c.count) as usize];
            for (row, new) in rows.iter_mut().zip(scratch.iter()) {
                *row = JointRow {
                    mass: new.effective_mass(ba, bb),
                    impulse: row.impulse,
                    ..*new
                };
            }
        }
    }

    /// Applies every joint's accumulated impulses (warm starting).
    pub fn warm_start_joints(&mut self) {
        for c in &self.joints {
            let (ba, bb) = pair(&mut self.bodies, c.a, c.b);
            if let Some(point) = &c.point {
                point.warm_start(ba, bb);
            }
            for row in &self.joint_rows[c.first as usize..(c.first + c.count) as usize] {
                row.warm_start(ba, bb);
            }
        }
    }

    /// One pass over the joints, in slot order: each joint's springs, motors and limits,
    /// then its point block, then its locks.
    pub fn solve_joints(&mut self, pass: &JointPass<R>) {
        for c in &mut self.joints {
            let (ba, bb) = pair(&mut self.bodies, c.a, c.b);
            let rows = &mut self.joint_rows[c.first as usize..(c.first + c.count) as usize];
            let (drives, locks) = rows.split_at_mut(c.locks_from as usize);
            for row in drives {
                row.solve(ba, bb, pass);
            }
            if let Some(point) = &mut c.point {
                point.solve(ba, bb, pass);
            }
            for row in locks {
                row.solve(ba, bb, pass);
            }
        }
    }

    /// Moves every joint constraint's position errors on by the substep just integrated:
    /// C ← C + h (Ċ + ½ h κ) with the velocities the positions were integrated with (h in s;
    /// κ the rows' drift, zero for most), to second order the errors at the new positions,
    /// so that the relax pass's limits stop exactly at the limit instead of letting one more
    /// substep of motion through (contacts do the same with their separations).
    ///
    /// A point block's drift ½ h κ is first taken again from those velocities (it was built
    /// from the velocities before the gyroscopic update and the solve pass), so that the
    /// relax pass holds the anchors' velocity at the lever the bodies actually turned to
    /// (see [`PointBlock::drift_of`]).
    pub fn advance_joint_errors(&mut self, h: R) {
        for c in &mut self.joints {
            let (ba, bb) = (&self.bodies[c.a as usize], &self.bodies[c.b as usize]);
            if let Some(point) = &mut c.point {
                point.drift = PointBlock::drift_of(point.r_a, point.r_b, ba, bb, h);
                point.error += point.velocity(ba, bb) * h;
            }
            for row in &mut self.joint_rows[c.first as usize..(c.first + c.count) as usize] {
                row.error += row.velocity(ba, bb) * h;
            }
        }
    }

    /// Copies the accumulated impulses back into the joint storage.
    pub fn store_joint_impulses(&self, joints: &mut Joints<R>) {
        for c in &self.joints {
            let stored = &mut joints.impulses[c.joint as usize];
            if let Some(point) = &c.point {
                stored[..3].copy_from_slice(&point.impulse.to_array());
            }
            for row in &self.joint_rows[c.first as usize..(c.first + c.count) as usize] {
                stored[usize::from(row.slot)] = row.impulse;
            }
        }
    }

    /// The force (N) and torque (N·m) that the joint constraints of the slots `wanted`
    /// accepts transmitted in the last substep of length `h` (s): |Σ linear impulses| / h
    /// and |Σ angular impulses| / h, with the point block's impulse counted as linear.
    pub fn joint_loads<'a>(
        &'a self,
        h: R,
        wanted: impl Fn(usize) -> bool + 'a,
    ) -> impl Iterator<Item = (u32, R, R)> + 'a {
        let inv_h = h.recip();
        self.joints
            .iter()
            .filter(move |c| wanted(c.joint as usize))
            .map(move |c| {
                let mut linear = c.point.map_or(Vec3::ZERO, |p| p.impulse);
                let mut angular = Vec3::ZERO;
                for row in &self.joint_rows[c.first as usize..(c.first + c.count) as usize] {
                    if row.linear == Vec3::ZERO {
                        angular += row.angular_b * row.impulse;
                    } else {
                        linear += row.linear * row.impulse;
                    }
                }
                (c.joint, linear.length() * inv_h, angular.length() * inv_h)
            })
    }
}
