//! The contact solver: sequential impulses with soft contacts and substeps, in Box2D v3's
//! stage order.
//!
//! [`Solver::run`] performs, for one step of length dt split into n substeps of h = dt/n:
//!
//! 1. **prepare**: one [`ContactConstraint`] per contact with a body to move (anchors,
//!    effective masses, approach velocities);
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
mod softness;

pub(crate) use body::{STATIC_BODY, SolverBody};
pub(crate) use contact_constraint::{ContactConstraint, prepare as prepare_constraint};
pub(crate) use softness::Softness;

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
    pub constraints: Vec<ContactConstraint<R>>,
}
