//! Checking a [`FluidDesc`] and compiling it into a [`FluidSystem`], and the invariants of a
//! fluid state that comes from outside (a snapshot).

use super::boundary::boundary_count;
use super::desc::{
    FluidBodiesDesc, FluidBox, FluidDesc, MAX_BOUNDARY_PARTICLES, MAX_CELLS, MAX_FLUID_PARTICLES,
    MAX_FLUID_SUBSTEPS, MAX_SOLVER_ITERATIONS,
};
use super::emitter::EmitterState;
use super::grid::CellGrid;
use super::kernel::{Kernel, lattice_reach};
use super::settings::FluidSettings;
use super::system::{FluidSystem, Scratch};
use crate::math::{Real, Vec3};
use crate::types::SceneError;

/// The most lattice sites along one axis of the tank.
const MAX_SITES_PER_AXIS: u64 = 1 << 16;

/// An error unless `1 ≤ value ≤ hi`.
fn check_count(field: &str, value: u32, hi: u32) -> Result<(), SceneError> {
    if !(1..=hi).contains(&value) {
        return Err(SceneError::new(
            field,
            format!("must be 1 to {hi} (got {value})"),
        ));
    }
    Ok(())
}

/// The number of lattice sites `lo + (i + ½) spacing` below `hi`, counting at most past
/// `cap`.
fn sites_along<R: Real>(lo: R, hi: R, spacing: R, cap: u64) -> u64 {
    let mut n = 0;
    let mut at = lo + spacing * R::HALF;
    while at < hi && n <= cap {
        n += 1;
        at += spacing;
    }
    n
}

/// Whether `p` lies within `outer`.
fn contains<R: Real>(outer: &FluidBox<R>, p: Vec3<R>) -> bool {
    p.x >= outer.min.x
        && p.y >= outer.min.y
        && p.z >= outer.min.z
        && p.x <= outer.max.x
        && p.y <= outer.max.y
        && p.z <= outer.max.z
}

/// Checks a box: each extent at least one spacing and at most [`MAX_SITES_PER_AXIS`].
fn check_box<R: Real>(b: &FluidBox<R>, spacing: R) -> Result<[u64; 3], SceneError> {
    let mut counts = [0; 3];
    for (axis, (lo, hi)) in [(b.min.x, b.max.x), (b.min.y, b.max.y), (b.min.z, b.max.z)]
        .into_iter()
        .enumerate()
    {
        let name = ["x", "y", "z"][axis];
        if hi - lo < spacing {
            return Err(SceneError::new(
                format!("max.{name}"),
                format!("must exceed min.{name} by at least one spacing ({spacing} m)"),
            ));
        }
        counts[axis] = sites_along(lo, hi, spacing, MAX_SITES_PER_AXIS);
        if counts[axis] > MAX_SITES_PER_AXIS {
            return Err(SceneError::new(
                format!("max.{name}"),
                format!("the box spans more than {MAX_SITES_PER_AXIS} spacings along {name}"),
            ));
        }
    }
    Ok(counts)
}

impl<R: Real> FluidSettings<R> {
    /// Checks every setting and the tank, and derives the constants. `dt` is the world
    /// substep, s, for the time-step limit (not checked without it).
    fn compile(desc: &FluidDesc<R>, dt: Option<R>) -> Result<Self, SceneError> {
        SceneError::check_range("spacing", desc.spacing, R::from_ratio(1, 1000), R::ONE, "m")?;
        SceneError::check_range(
            "support",
            desc.support,
            R::from_ratio(3, 2),
            R::from_int(4),
            "spacings",
        )?;
        SceneError::check_range(
            "rest_density",
            desc.rest_density,
            R::ONE,
            R::from_int(100_000),
            "kg/m³",
        )?;
        SceneError::check_range(
            "speed_of_sound",
            desc.speed_of_sound,
            R::from_ratio(1, 10),
            R::from_int(1000),
            "m/s",
        )?;
        SceneError::check_range("viscosity", desc.viscosity, R::ZERO, R::ONE, "")?;
        SceneError::check_range("xsph", desc.xsph, R::ZERO, R::ONE, "")?;
        check_count("substeps", desc.substeps, MAX_FLUID_SUBSTEPS)?;
        if desc.cfl != R::ZERO && !(R::from_ratio(1, 100) <= desc.cfl && desc.cfl <= R::ONE) {
            return Err(SceneError::new(
                "cfl",
                format!(
                    "must be 0 (a fixed count of substeps) or 0.01 to 1 (got {})",
                    desc.cfl
                ),
            ));
        }
        SceneError::check_range(
            "max_density_error",
            desc.max_density_error,
            R::from_ratio(1, 100_000),
            R::from_ratio(1, 10),
            "",
        )?;
        check_count("max_iterations", desc.max_iterations, MAX_SOLVER_ITERATIONS)?;
        let kernel = Kernel::calibrated(desc.spacing, desc.support);
        let settings = Self {
            solver: desc.solver,
            spacing: desc.spacing,
            support: desc.support,
            rest_density: desc.rest_density,
            speed_of_sound: desc.speed_of_sound,
            viscosity: desc.viscosity,
            xsph: desc.xsph,
            substeps: desc.substeps,
            cfl: desc.cfl,
            max_density_error: desc.max_density_error,
            max_iterations: desc.max_iterations,
            tank: desc.tank,
            kernel,
            stiffness: desc.speed_of_sound * desc.speed_of_sound * R::from_ratio(1, 7),
            bodies: desc.bodies.map(|b| b.filter),
        };
        settings.check_tank()?;
        let Some(dt) = dt else {
            return Ok(settings);
        };
        // Time-step limit: Δt ≤ 0.4 (H/2) / u with u = c for WCSPH, the fastest flow
        // c/10 for DFSPH.
        let h = dt * R::from_ratio(1, i64::from(desc.substeps));
        let speed = match desc.solver {
            super::desc::FluidSolver::Wcsph => desc.speed_of_sound,
            super::desc::FluidSolver::Dfsph => desc.speed_of_sound * R::from_ratio(1, 10),
        };
        let support = desc.spacing * desc.support;
        if h * speed * R::from_int(5) > support {
            return Err(SceneError::new(
                "substeps",
                format!(
                    "the fluid substep {h} s is above the time-step limit 0.2 H / u = {} s \
                     (H = {support} m, u = {speed} m/s); raise the substeps",
                    support * R::from_ratio(1, 5) / speed
                ),
            ));
        }
        Ok(settings)
    }

    /// Checks the tank's extents and the size of its grid and boundary.
    fn check_tank(&self) -> Result<(), SceneError> {
        check_box(&self.tank, self.spacing).map_err(|e| e.within("tank"))?;
        let support = self.spacing * self.support;
        let margin = self.spacing * R::from_int(lattice_reach(self.support) + 1);
        let lower = self.tank.min - Vec3::splat(margin);
        let upper = self.tank.max + Vec3::splat(margin);
        let cells = CellGrid::cells_along(lower.x, upper.x, support)
            * CellGrid::cells_along(lower.y, upper.y, support)
            * CellGrid::cells_along(lower.z, upper.z, support);
        if cells > MAX_CELLS {
            return Err(SceneError::new(
                "tank",
                format!("spans {cells} grid cells of half a kernel support; at most {MAX_CELLS}"),
            ));
        }
        let boundary = boundary_count(self, MAX_SITES_PER_AXIS);
        if boundary > u64::from(MAX_BOUNDARY_PARTICLES) {
            return Err(SceneError::new(
                "tank",
                format!(
                    "needs {boundary} boundary particles at this spacing; at most \
                     {MAX_BOUNDARY_PARTICLES}"
                ),
            ));
        }
        Ok(())
    }
}

impl<R: Real> FluidSystem<R> {
    /// Checks `desc` and builds the fluid at tick 0: the blocks' particles in block order,
    /// each block's lattice sites x fastest, then y, then z. `dt` is the world substep, s.
    /// The error names the offending field, as a path from `fluid`.
    pub fn from_desc(desc: &FluidDesc<R>, dt: R) -> Result<Self, SceneError> {
        let settings = FluidSettings::compile(desc, Some(dt))?;
        let dx = desc.spacing;
        let tank = &desc.tank;
        let mut total = 0u64;
        for (i, block) in desc.blocks.iter().enumerate() {
            let at = format!("blocks[{i}].region");
            let counts = check_box(&block.region, dx).map_err(|e| e.within(&at))?;
            if !contains(tank, block.region.min) || !contains(tank, block.region.max) {
                return Err(SceneError::new(at, "must lie inside the tank"));
            }
            total += counts.iter().product::<u64>();
        }
        for (i, e) in desc.emitters.iter().enumerate() {
            let at = format!("emitters[{i}]");
            if !contains(tank, e.position) {
                return Err(SceneError::new("position", "must lie inside the tank").within(&at));
            }
            if e.velocity == Vec3::ZERO {
                return Err(SceneError::new("velocity", "must not be zero").within(&at));
            }
            check_count("width", e.width, 64).map_err(|err| err.within(&at))?;
            check_count("count", e.count, MAX_FLUID_PARTICLES).map_err(|err| err.within(&at))?;
            total += u64::from(e.count);
        }
        if total > u64::from(MAX_FLUID_PARTICLES) {
            return Err(SceneError::new(
                "blocks",
                format!(
                    "the blocks and emitters make {total} particles; at most \
                     {MAX_FLUID_PARTICLES}"
                ),
            ));
        }
        let mut positions = Vec::new();
        let mut velocities = Vec::new();
        for block in &desc.blocks {
            let r = &block.region;
            let along = |lo: R, hi: R, origin: R| {
                // Tank lattice sites origin + (i + ½) dx within [lo, hi].
                let mut out = Vec::new();
                let mut at = origin + dx * R::HALF;
                while at < hi {
                    if at >= lo {
                        out.push(at);
                    }
                    at += dx;
                }
                out
            };
            let xs = along(r.min.x, r.max.x, tank.min.x);
            let ys = along(r.min.y, r.max.y, tank.min.y);
            let zs = along(r.min.z, r.max.z, tank.min.z);
            for &z in &zs {
                for &y in &ys {
                    for &x in &xs {
                        positions.push(Vec3::new(x, y, z));
                        velocities.push(block.velocity);
                    }
                }
            }
        }
        let emitters = desc
            .emitters
            .iter()
            .map(|e| {
                let speed = e.velocity.length();
                EmitterState {
                    position: e.position,
                    velocity: e.velocity,
                    speed,
                    direction: e.velocity * speed.recip(),
                    width: e.width,
                    remaining: e.count,
                    travelled: R::ZERO,
                }
            })
            .collect();
        Ok(Self {
            settings,
            positions,
            velocities,
            emitters,
            scratch: Scratch::default(),
        })
    }
}

impl<R: Real> FluidSystem<R> {
    /// Checks the invariants the step relies on, for a state from outside (a snapshot): the
    /// settings as a scene would give them (the derived constants included), one velocity
    /// per position, and emitters within the particle budget. The error names the field,
    /// as a path from `fluid`.
    pub fn validate(&self) -> Result<(), SceneError> {
        let s = &self.settings;
        let mut desc = FluidDesc::new(s.solver, s.spacing, s.tank);
        desc.support = s.support;
        desc.rest_density = s.rest_density;
        desc.speed_of_sound = s.speed_of_sound;
        desc.viscosity = s.viscosity;
        desc.xsph = s.xsph;
        desc.substeps = s.substeps;
        desc.cfl = s.cfl;
        desc.max_density_error = s.max_density_error;
        desc.max_iterations = s.max_iterations;
        desc.bodies = s.bodies.map(|filter| FluidBodiesDesc { filter });
        let compiled = FluidSettings::compile(&desc, None).map_err(|e| e.within("settings"))?;
        if compiled != *s {
            return Err(SceneError::new(
                "settings",
                "the kernel constants or the stiffness do not follow from the settings",
            ));
        }
        if self.velocities.len() != self.positions.len() {
            return Err(SceneError::new(
                "velocities",
                format!(
                    "{} velocities for {} positions",
                    self.velocities.len(),
                    self.positions.len()
                ),
            ));
        }
        let mut total = self.positions.len() as u64;
        for (i, e) in self.emitters.iter().enumerate() {
            check_count("width", e.width, 64)
                .map_err(|err| err.within(&format!("emitters[{i}]")))?;
            total += u64::from(e.remaining);
        }
        if total > u64::from(MAX_FLUID_PARTICLES) {
            return Err(SceneError::new(
                "positions",
                format!(
                    "{total} particles with those still to emit; at most {MAX_FLUID_PARTICLES}"
                ),
            ));
        }
        Ok(())
    }
}
