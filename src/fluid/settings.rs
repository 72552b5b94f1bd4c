//! `FluidSettings`: a fluid's description compiled into the values its step uses.

use serde::{Deserialize, Serialize};

use super::desc::{FluidBox, FluidSolver};
use super::kernel::Kernel;
use crate::math::{Fx, Real};
use crate::rigid::CollisionFilter;

/// The compiled settings of a fluid: the description's values and the constants derived
/// from them once.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(bound = "")]
pub struct FluidSettings<R: Real = Fx> {
    /// The pressure solver.
    pub solver: FluidSolver,
    /// Particle spacing at rest, m.
    pub spacing: R,
    /// Kernel support in spacings.
    pub support: R,
    /// Rest density ρ₀, kg/m³ (used only to report pressures; the solvers work in ρ/ρ₀).
    pub rest_density: R,
    /// WCSPH speed of sound c, m/s.
    pub speed_of_sound: R,
    /// WCSPH artificial viscosity α.
    pub viscosity: R,
    /// XSPH smoothing ε.
    pub xsph: R,
    /// Fluid substeps per world substep; with a CFL number, the most.
    pub substeps: u32,
    /// The CFL number C of adaptive substeps, in kernel supports; 0 for a fixed count.
    pub cfl: R,
    /// DFSPH tolerance on the mean predicted compression.
    pub max_density_error: R,
    /// DFSPH iteration cap.
    pub max_iterations: u32,
    /// The tank.
    pub tank: FluidBox<R>,
    /// The kernel constants.
    pub kernel: Kernel<R>,
    /// Tait stiffness over rest density, B/ρ₀ = c²/7, m²/s².
    pub stiffness: R,
    /// The layers of the rigid bodies the fluid meets, if it meets any.
    pub bodies: Option<CollisionFilter>,
}
