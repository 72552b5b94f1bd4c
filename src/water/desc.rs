//! The scene description of a water surface: what a RON scene file says under
//! `water_surface: (...)`.
//!
//! Plain data; [`WaterSystem::from_desc`](super::WaterSystem::from_desc) checks it and
//! compiles it into simulation state. Units: metres, seconds, kilograms. The surface is
//! horizontal at rest, y up.
//!
//! ```ron
//! water_surface: (
//!     origin: (x: -4.0, y: 0.0, z: -4.0),
//!     cells: (64, 64),
//!     cell_size: 0.125,
//!     depth: 0.5,
//!     border: Open,
//!     particles: [(group: 0, volume: 0.002, height: 0.2, drag: 1.0)],
//!     bodies: Some((drag: 0.5, angular_drag: 0.5)),
//! )
//! ```

use serde::{Deserialize, Serialize};

use crate::math::{Fx, Real, Vec3};
use crate::rigid::CollisionFilter;

/// The most cells a water surface may have (columns × rows).
pub const MAX_WATER_CELLS: u64 = 1 << 22;
/// The most wave steps per world substep (the surface splits a substep into as many as
/// its wave speed and cell size need, [`super::waves`]).
pub const MAX_WATER_SUBSTEPS: u32 = 64;

/// What happens to a wave at the edge of the grid.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
pub enum WaterBorder {
    /// A wall: no water crosses the border, waves bounce back, the volume is kept.
    #[default]
    Reflective,
    /// Open water: a wave leaves through the border as if the surface went on (the
    /// radiation condition ∂u/∂t + c ∂u/∂n = 0), taking its volume with it.
    Open,
}

impl WaterBorder {
    /// The code hashed into checksums.
    pub const fn code(self) -> u8 {
        match self {
            Self::Reflective => 0,
            Self::Open => 1,
        }
    }
}

/// How the particles of one group float: each is a vertical column of `volume` (m³) and
/// `height` (m) centred on the particle, and the water pushes it up by the weight of the
/// water it displaces (ρ g V_submerged) and slows it by linear drag.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(bound = "", deny_unknown_fields)]
pub struct WaterParticleFloat<R: Real = Fx> {
    /// The particle group (of an emitter, template or particle) that floats so.
    pub group: u16,
    /// The column's volume, m³ (its cross-section is `volume / height`).
    pub volume: R,
    /// The column's height, m.
    pub height: R,
    /// Linear drag rate in the water, 1/s: F = −drag · m · f · v with f the submerged
    /// fraction. Default 0.
    #[serde(default)]
    pub drag: R,
}

/// How rigid bodies float: every dynamic body whose filter interacts with `filter`.
/// Spheres float as spheres (their submerged cap), boxes as boxes (eight octants, each a
/// horizontal slab), other shapes as the box that bounds them in their own frame.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(bound = "", deny_unknown_fields)]
pub struct WaterBodiesDesc<R: Real = Fx> {
    /// The layers of the bodies that float. Default: every body.
    #[serde(default)]
    pub filter: CollisionFilter,
    /// Linear drag rate in the water, 1/s: F = −drag · m · f · v with f the submerged
    /// fraction. Default 0.
    #[serde(default)]
    pub drag: R,
    /// Angular drag rate in the water, 1/s: τ = −angular_drag · f · I ω. Default 0.
    #[serde(default)]
    pub angular_drag: R,
}

/// A height-field water surface (the scene's `water_surface` section).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(bound = "", deny_unknown_fields)]
pub struct WaterDesc<R: Real = Fx> {
    /// The grid's corner at its lowest x and z; its y is the rest level of the surface, m.
    pub origin: Vec3<R>,
    /// Columns (along x) and rows (along z) of cells.
    pub cells: (u32, u32),
    /// The side of a square cell, m.
    pub cell_size: R,
    /// The still water's depth below the rest level, m: it sets the wave speed
    /// c = √(g · depth) unless `wave_speed` is given.
    pub depth: R,
    /// The wave speed c, m/s; absent: √(|g| · depth) with the scene's gravity.
    #[serde(default)]
    pub wave_speed: Option<R>,
    /// Damping rate of the flow, 1/s (a wave's height decays as e^(−damping·t/2)).
    /// Default 0.
    #[serde(default)]
    pub damping: R,
    /// The water's density ρ, kg/m³. Default 1000.
    #[serde(default = "default_density")]
    pub density: R,
    /// What the grid's edges do to waves. Default `Reflective`.
    #[serde(default)]
    pub border: WaterBorder,
    /// The particle groups that float, each at most once.
    #[serde(default)]
    pub particles: Vec<WaterParticleFloat<R>>,
    /// The rigid bodies that float, when any do.
    #[serde(default)]
    pub bodies: Option<WaterBodiesDesc<R>>,
}

fn default_density<R: Real>() -> R {
    R::from_int(1000)
}
