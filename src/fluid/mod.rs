//! Fluids: smoothed particle hydrodynamics with a deterministic neighbour search, a weakly
//! compressible solver and a constant-density solver, in a tank lined with boundary
//! particles.
//!
//! Data flows one way: a scene's [`FluidDesc`] compiles into a [`FluidSystem`] (particle
//! positions and velocities by id, emitters); each step runs the stages listed on
//! [`FluidSystem`]; the state is hashed for checksums ([`hashing`]) and reported as
//! [`FluidMetrics`].
//!
//! # Files
//!
//! Description and storage: [`desc`] scene types · [`build`] checks and compilation ·
//! [`system`] the system and its step · [`substeps`] adaptive substeps · [`hashing`] canonical state · [`metrics`]
//! reporting. The built-in scenes' fluids live in the `fixstep-scenes` crate.
//!
//! Neighbours: [`kernel`] the Wendland C2 kernel in normalised form · [`grid`] counting
//! sort into cells · [`neighbours`] neighbour lists with kernel values.
//!
//! Dynamics: [`emitter`] nozzles · [`density`] kernel sums · [`wcsph`] Tait pressure ·
//! [`dfsph`] the divergence-free and constant-density solves and [`row_sums`] their sums over the
//! neighbours · [`xsph`] velocity smoothing · [`boundary`] the
//! tank's boundary particles and walls · [`bodies`] rigid bodies in the fluid, two-way.
//!
//! # Determinism
//!
//! Particles are stored by id (creation order) and never removed. The grid lists each
//! cell's particles by id, neighbour lists follow (cell, id), every sum runs in that
//! order, and every solver pass is Jacobi (reads the previous pass only), so results do
//! not depend on anything but the state.

pub(crate) mod bodies;
mod boundary;
mod build;
mod density;
pub mod desc;
mod dfsph;
mod emitter;
pub mod grid;
mod hashing;
pub mod kernel;
mod metrics;
pub mod neighbours;
mod row_sums;
mod settings;
mod substeps;
mod subsystem;
mod system;
mod wcsph;
mod xsph;

pub use desc::{FluidBlock, FluidBodiesDesc, FluidBox, FluidDesc, FluidEmitter, FluidSolver};
pub use emitter::EmitterState;
pub use kernel::Kernel;
pub use metrics::FluidMetrics;
pub use settings::FluidSettings;
pub use system::FluidSystem;
