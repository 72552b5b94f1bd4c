//! Height-field water: a grid of surface heights stepped by the wave equation
//! ∂²u/∂t² = c²∇²u, the cheap water most games use, and the float force generator that
//! makes particles and rigid bodies float on it.
//!
//! Data flows one way: a scene's [`WaterDesc`] (its `water_surface` section) compiles into
//! a [`WaterSystem`] (heights at the cells, flows at the edges between them); each world
//! substep runs [`waves`]; inputs drop [`disturb`]ances on it; the world applies the
//! [`float`] forces to the particles and bodies on it at the start of each tick
//! (`world/water_coupling.rs`); the state is hashed for checksums ([`hashing`]).
//!
//! # Files
//!
//! [`desc`] scene types · [`build`] checks and compilation · [`system`] the state and the
//! surface's height anywhere · [`waves`] the wave step · [`disturb`] disturbances ·
//! [`float`] buoyancy and drag · [`hashing`] canonical state · `subsystem` the world's
//! contract.
//!
//! # Determinism
//!
//! Fixed point throughout, cells and edges visited in ascending slot order; every flow is
//! computed from the previous heights only and every height from the new flows (no
//! Gauss–Seidel order dependence). With reflective borders the sum of the heights' raw
//! integers is exactly constant ([`waves`]).

mod build;
pub mod desc;
mod disturb;
pub mod float;
mod hashing;
mod subsystem;
pub mod system;
pub mod waves;

pub use desc::{WaterBodiesDesc, WaterBorder, WaterDesc, WaterParticleFloat};
pub use system::{WaterSettings, WaterSystem};
