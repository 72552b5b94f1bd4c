//! Joints between rigid bodies: ball-and-socket, cone-twist, hinge, slider, fixed, rod,
//! rope and spring, solved in the rigid solver's passes with the contacts.
//!
//! Data flows as for bodies: a scene's [`JointsDesc`] is checked and compiled by
//! [`RigidSystem::add_joints`](super::RigidSystem::add_joints) into [`storage`] (frames
//! fixed in each body, accumulated impulses); each step the solver builds the joints'
//! constraints ([`crate::rigid::solver`]'s joint rows), solves them with warm starting and
//! soft position correction, and stores the impulses back; joints that transmitted more
//! than their break force or torque are removed and reported ([`breaking`]).
//!
//! Joints link islands: jointed dynamic bodies sleep and wake together ([`sleep`]), and a
//! joint's bodies do not collide with each other unless it says so.
//!
//! [`sleep`]: super::sleep
//!
//! # Files
//!
//! [`desc`] scene types · [`build`] checks and compilation · [`storage`] slots and state ·
//! [`breaking`] break thresholds and events · [`queries`] what the API reports.

pub(crate) mod breaking;
mod build;
pub mod desc;
mod queries;
pub(crate) mod storage;

pub use breaking::JointEvent;
pub(crate) use build::check_joint;
pub use desc::{JointDesc, JointGrid, JointKind, JointsDesc, Limits, Motor, Spring};
