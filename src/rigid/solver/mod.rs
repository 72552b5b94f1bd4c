//! The contact solver: sequential impulses with soft contacts and substeps, in Box2D v3's
//! stage order.
//!
//! [`Solver::run`] performs, for one step of length dt split into n substeps of h = dt/n:
//!
//! 1. **prepare**: one constraint per contact with a body to move (anchors, effective
//!    masses, approach velocities), stored [`LANES`] to a [`ContactBlock`];
//! 2. per substep: **integrate velocities** (gravity, forces, damping, gyroscopic torque),
//!    **warm start** (apply the accumulated impulses), **solve** (with the soft bias),
//!    **integrate positions**, **relax** (solve again without bias, removing the velocity
//!    the bias added, so pushing apart injects no energy);
//! 3. **restitution**;
//! 4. **store impulses** into the persistent contacts for the next step.
//!
//! Constraints are visited in contact-key order, bodies in slot order: the same on every
//! machine.

mod body;
mod contact_constraint;
mod integrate;
mod lanes;
mod softness;

pub(crate) use body::{STATIC_BODY, SolverBody};
pub(crate) use contact_constraint::{ContactBlock, SolvePass};
pub(crate) use softness::Softness;

use crate::math::{Real, Vec3};
use crate::rigid::contact::Contact;

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
}

impl<R: Real> Solver<R> {
    /// Forgets the constraints of the last step (keeping the blocks' memory).
    pub fn clear_constraints(&mut self) {
        self.block_count = 0;
    }

    /// Builds the constraint of `contact` (index `index` in the world's list) between solver
    /// bodies `a` and `b`, with centres of mass `centre_a`, `centre_b` (m) and the mixed
    /// `friction` and `restitution`, in the next free lane: that of the last block in use,
    /// or of a fresh block when that one is full.
    #[allow(clippy::too_many_arguments)]
    pub fn prepare_constraint(
        &mut self,
        contact: &Contact<R>,
        index: u32,
        a: (u32, Vec3<R>),
        b: (u32, Vec3<R>),
        friction: R,
        restitution: R,
    ) {
        let last_is_full = self.block_count == 0 || self.blocks[self.block_count - 1].is_full();
        if last_is_full {
            if self.block_count == self.blocks.len() {
                self.blocks.push(ContactBlock::empty());
            } else {
                self.blocks[self.block_count].clear();
            }
            self.block_count += 1;
        }
        self.blocks[self.block_count - 1].prepare_lane(
            contact,
            index,
            a,
            b,
            &self.bodies,
            friction,
            restitution,
        );
    }

    /// The blocks in use, in solving order.
    pub fn blocks(&self) -> &[ContactBlock<R>] {
        &self.blocks[..self.block_count]
    }

    /// The blocks in use, mutably, with the solver bodies.
    pub fn blocks_and_bodies(&mut self) -> (&mut [ContactBlock<R>], &mut [SolverBody<R>]) {
        (&mut self.blocks[..self.block_count], &mut self.bodies)
    }
}
