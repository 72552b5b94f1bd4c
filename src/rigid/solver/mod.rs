//! The contact and joint solver: sequential impulses with soft constraints and substeps, in
//! Box2D v3's stage order.
//!
//! The [solve stage](super::solve) performs, for one step of length dt split into n
//! substeps of h = dt/n:
//!
//! 1. **prepare**: one constraint per contact with a body to move (anchors, effective
//!    masses, approach velocities), stored [`LANES`] to a [`ContactBlock`], and one per
//!    joint with a body to move ([`joints`]: a point block and scalar rows);
//! 2. per substep: **integrate velocities** (gravity, forces, damping, gyroscopic torque),
//!    **update joints** (their Jacobians and errors from the current poses), **warm start**
//!    (apply the accumulated impulses), **solve** (with the soft bias), **integrate
//!    positions**, **relax** (solve again without bias, removing the velocity the bias
//!    added, so pushing apart injects no energy; jointed bodies' gyroscopic terms are
//!    solved with their joints there, [`joint_gyroscopic`], and the joints' point blocks
//!    take their drift from the velocities the positions moved with); joints before contacts in
//!    every pass; in a step where a contact may bounce, each point's impulse over the step
//!    is summed;
//! 3. **restitution**: chains of touching bodies that a bounce reaches are resolved one
//!    contact at a time, the largest closing speed first (the notes' iterative resolver,
//!    [`contact_constraint::BounceChains`]), every other bouncing contact by itself
//!    ([`bounce`]);
//! 4. **store impulses** into the persistent contacts and joints for the next step.
//!
//! Contact constraints are visited block by block in the order of [`batching`], close to
//! contact-key order; joints in slot order; bodies in slot order: the same on every
//! machine.

mod batching;
mod body;
mod bounce;
mod contact_constraint;
mod integrate;
mod joint_gyroscopic;
mod joint_point;
mod joint_pose;
mod joint_row;
mod joint_rows;
mod joints;
mod lanes;
mod mixed_materials;
mod prepare;
mod softness;
#[cfg(vector_kernels)]
pub(crate) mod wide_bodies;

pub(crate) use body::{STATIC_BODY, SolverBody};
pub(crate) use bounce::BouncePass;
pub(crate) use contact_constraint::{ContactBlock, SolvePass};
pub(crate) use joint_pose::{JointPose, twist_angle};
pub(crate) use joint_row::JointPass;
pub(crate) use lanes::LANES;
pub(crate) use softness::Softness;

use crate::math::Real;
use batching::Batching;

/// Buffers the solver reuses from step to step. They hold no state between steps, only
/// capacity.
#[derive(Clone, Debug, Default)]
pub(crate) struct Solver<R: crate::math::Real> {
    /// Index 0 is the static body; then the moving bodies in slot order.
    pub bodies: Vec<SolverBody<R>>,
    /// The body slot of each solver body (entry 0 unused).
    pub slots: Vec<u32>,
    /// The solver index of each body slot ([`STATIC_BODY`] for bodies it does not move).
    pub index_of_slot: Vec<u32>,
    /// The step's constraints: the first `block_count` blocks, in solving order. Blocks
    /// past those keep their memory for later steps.
    blocks: Vec<ContactBlock<R>>,
    block_count: usize,
    /// The batching of the step's constraints into blocks.
    batching: Batching,
    /// The step's joint constraints, in joint slot order, and their scalar rows.
    joints: Vec<joints::JointConstraint<R>>,
    joint_rows: Vec<joint_row::JointRow<R>>,
    /// One joint's rows as rebuilt for a substep, before they replace the step's.
    joint_row_scratch: Vec<joint_row::JointRow<R>>,
    /// The jointed bodies whose gyroscopic term is solved with their joints, and which
    /// solver bodies a joint holds.
    spinning: Vec<joint_gyroscopic::Spinning<R>>,
    joined: Vec<bool>,
    /// The restitution pass's buffers for chains of touching bodies.
    chains: contact_constraint::BounceChains<R>,
}

impl<R: Real> Solver<R> {
    /// The blocks in use, in solving order.
    pub fn blocks(&self) -> &[ContactBlock<R>] {
        &self.blocks[..self.block_count]
    }

    /// The blocks in use, mutably, with the solver bodies.
    pub fn blocks_and_bodies(&mut self) -> (&mut [ContactBlock<R>], &mut [SolverBody<R>]) {
        (&mut self.blocks[..self.block_count], &mut self.bodies)
    }
}
