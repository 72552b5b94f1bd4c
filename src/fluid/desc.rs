//! The scene description of a fluid: what a RON scene file says under `fluid: (...)`.
//!
//! Plain data; [`FluidSystem::from_desc`](super::FluidSystem::from_desc) checks it and
//! compiles it into simulation state. Units: metres, seconds, kilograms.
//!
//! ```ron
//! fluid: (
//!     solver: Wcsph,
//!     spacing: 0.01,
//!     tank: (min: (x: 0.0, y: 0.0, z: 0.0), max: (x: 0.4, y: 0.3, z: 0.04)),
//!     blocks: [(min: (x: 0.0, y: 0.0, z: 0.0), max: (x: 0.1, y: 0.2, z: 0.04))],
//! )
//! ```

use serde::{Deserialize, Serialize};

use crate::rigid::CollisionFilter;

use crate::math::{Fx, Real, Vec3};

/// The most fluid particles (initial and emitted together) a scene may ask for.
pub const MAX_FLUID_PARTICLES: u32 = 1 << 20;
/// The most boundary particles the tank's walls may need.
pub const MAX_BOUNDARY_PARTICLES: u32 = 1 << 21;
/// The most grid cells the tank may span (cells are half a kernel support wide).
pub const MAX_CELLS: u64 = 1 << 24;
/// The most fluid substeps per world substep.
pub const MAX_FLUID_SUBSTEPS: u32 = 1000;
/// The most iterations of the pressure solver per substep.
pub const MAX_SOLVER_ITERATIONS: u32 = 1000;

/// The pressure solver.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
pub enum FluidSolver {
    /// Weakly compressible SPH: pressure from the Tait equation of state, explicit.
    #[default]
    Wcsph,
    /// Divergence-free SPH: each substep a divergence-free solve, then the constant-density
    /// solve, velocities corrected by Jacobi iterations until the mean predicted density
    /// error is below a tolerance (and no particle's above 10 %).
    Dfsph,
}

impl FluidSolver {
    /// The code hashed into checksums.
    pub const fn code(self) -> u8 {
        match self {
            Self::Wcsph => 0,
            Self::Dfsph => 1,
        }
    }
}

/// An axis-aligned box, m.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(bound = "", deny_unknown_fields)]
pub struct FluidBox<R: Real = Fx> {
    /// The lower corner.
    pub min: Vec3<R>,
    /// The upper corner.
    pub max: Vec3<R>,
}

/// A block of fluid at tick 0: every lattice site `tank.min + (i + ½, j + ½, k + ½)·spacing`
/// inside the box gets a particle, created in the order i fastest, then j, then k.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(bound = "", deny_unknown_fields)]
pub struct FluidBlock<R: Real = Fx> {
    /// The region filled, m; it must lie inside the tank.
    pub region: FluidBox<R>,
    /// The initial velocity of its particles, m/s.
    #[serde(default)]
    pub velocity: Vec3<R>,
}

/// A nozzle that adds a square of `width × width` particles, `spacing` apart in the
/// horizontal plane, each time the fluid it emitted has moved on by one spacing.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(bound = "", deny_unknown_fields)]
pub struct FluidEmitter<R: Real = Fx> {
    /// Centre of the nozzle, m; it must lie inside the tank.
    pub position: Vec3<R>,
    /// Velocity of the emitted particles, m/s; not zero.
    pub velocity: Vec3<R>,
    /// Particles per side of the square nozzle (1 to 64).
    pub width: u32,
    /// How many particles the emitter adds in all.
    pub count: u32,
}

/// The fluid part of a scene: one fluid in one open-topped tank.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(bound = "", deny_unknown_fields)]
pub struct FluidDesc<R: Real = Fx> {
    /// The pressure solver. Default WCSPH.
    #[serde(default)]
    pub solver: FluidSolver,
    /// Particle spacing at rest, m (0.001 to 1).
    pub spacing: R,
    /// Kernel support radius in spacings, H / spacing (1.5 to 4). Default 2.
    #[serde(default = "default_support")]
    pub support: R,
    /// Rest density ρ₀, kg/m³ (1 to 100 000). Default 1000 (water).
    #[serde(default = "default_rest_density")]
    pub rest_density: R,
    /// WCSPH speed of sound c, m/s (0.1 to 1000): at least 10 × the fastest flow, so that
    /// the density varies by less than 1 %. Default 20.
    #[serde(default = "default_speed_of_sound")]
    pub speed_of_sound: R,
    /// WCSPH artificial viscosity α (0 to 1). Default 0: XSPH alone keeps the dam break
    /// on Martin & Moyce's front (α = 0.05 already slows it by 10 %).
    #[serde(default = "default_viscosity")]
    pub viscosity: R,
    /// XSPH velocity smoothing ε (0 to 1), the artificial viscosity. Default 0.05.
    #[serde(default = "default_xsph")]
    pub xsph: R,
    /// Fluid substeps per world substep (1 to 1000). Default 1. With a [`cfl`](Self::cfl)
    /// number, the most substeps a step may take.
    #[serde(default = "default_substeps")]
    pub substeps: u32,
    /// Adaptive substeps: the CFL number C (0.01 to 1), the most a particle may travel in one
    /// substep, in kernel supports H. Each world substep then takes the fewest fluid substeps
    /// n ≤ [`substeps`](Self::substeps) with Δt (u + |g| Δt) / n ≤ C H, u the fastest
    /// particle's (or due emitter's) speed at its start, plus c for WCSPH (the acoustic
    /// limit). 0.2 is the limit the fixed count is checked against. Default 0: always
    /// `substeps`.
    #[serde(default = "default_cfl")]
    pub cfl: R,
    /// DFSPH: iterate until the mean predicted compression (ρ − ρ₀)/ρ₀ is below this
    /// (0.000 01 to 0.1). Default 0.0005.
    #[serde(default = "default_max_density_error")]
    pub max_density_error: R,
    /// DFSPH: the most iterations per substep (1 to 1000). Default 100.
    #[serde(default = "default_max_iterations")]
    pub max_iterations: u32,
    /// The tank: a floor at `min.y` and four walls, open at the top. Boundary particles
    /// line it on the outside; no fluid particle passes a wall.
    pub tank: FluidBox<R>,
    /// Fluid present at tick 0.
    #[serde(default)]
    pub blocks: Vec<FluidBlock<R>>,
    /// Nozzles adding fluid during the run.
    #[serde(default)]
    pub emitters: Vec<FluidEmitter<R>>,
    /// Whether the fluid meets the rigid bodies, two-way, and which: their surfaces are
    /// sampled as boundary particles, and the fluid's pressure pushes them back (Akinci et
    /// al. 2012). Absent: the fluid ignores them.
    #[serde(default)]
    pub bodies: Option<FluidBodiesDesc>,
}

/// The rigid bodies a fluid meets.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct FluidBodiesDesc {
    /// The layers of the bodies the fluid meets (as a body's filter). Default all.
    #[serde(default)]
    pub filter: CollisionFilter,
}

fn default_support<R: Real>() -> R {
    R::TWO
}
fn default_rest_density<R: Real>() -> R {
    R::from_int(1000)
}
fn default_speed_of_sound<R: Real>() -> R {
    R::from_int(20)
}
fn default_viscosity<R: Real>() -> R {
    R::ZERO
}
fn default_xsph<R: Real>() -> R {
    R::from_ratio(5, 100)
}
fn default_substeps() -> u32 {
    1
}
fn default_cfl<R: Real>() -> R {
    R::ZERO
}
fn default_max_density_error<R: Real>() -> R {
    R::from_ratio(5, 10_000)
}
fn default_max_iterations() -> u32 {
    100
}

impl<R: Real> FluidDesc<R> {
    /// A fluid of the given solver and spacing in `tank`, with default settings and no
    /// fluid yet.
    pub fn new(solver: FluidSolver, spacing: R, tank: FluidBox<R>) -> Self {
        Self {
            solver,
            spacing,
            support: default_support(),
            rest_density: default_rest_density(),
            speed_of_sound: default_speed_of_sound(),
            viscosity: default_viscosity(),
            xsph: default_xsph(),
            substeps: default_substeps(),
            cfl: default_cfl(),
            max_density_error: default_max_density_error(),
            max_iterations: default_max_iterations(),
            tank,
            blocks: Vec::new(),
            emitters: Vec::new(),
            bodies: None,
        }
    }
}
