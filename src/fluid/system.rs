//! `FluidSystem`: the fluid particles of a world, and one step of their motion.

use serde::{Deserialize, Serialize};

use super::bodies::{BodiesInFluid, BodyView, FluidPushes};
use super::boundary::{advect, sample_walls};
use super::desc::FluidSolver;
use super::emitter::EmitterState;
use super::grid::CellGrid;
use super::kernel::lattice_reach;
use super::neighbours::NeighbourLists;
use super::neighbours::skin::{Reach, SkinLists};
use super::row_sums::GradientBits;
use super::settings::FluidSettings;
use crate::math::{Fx, Real, Vec3};

/// Particles a worker takes at a time in the fluid's per-particle loops
/// ([`crate::parallel`]); it sets which particles a partial sum covers, so it is a constant,
/// never derived from the thread count.
pub(crate) const PARTICLE_CHUNK: usize = 1024;

/// The fluid of a world: particle positions and velocities, in creation order (a
/// particle's index is its id; particles are never removed), and the emitters.
///
/// A step ([`FluidSystem::step`]) runs, per fluid substep:
/// 1. **emit** ([`emitter`](super::emitter)): nozzles add their due layers;
/// 2. **neighbours** ([`grid`](super::grid), [`neighbours`](super::neighbours)): the
///    neighbour lists with kernel values, fluid and boundary, from candidate lists with a
///    skin ([`skin`](super::neighbours::skin)) found by counting sort into cells whenever
///    the particles have moved too far for the last ones, or by a search within the
///    support alone when the flow is too fast (or an emitter too busy) for new candidates
///    to serve the next substep;
/// 3. **density** ([`density`](super::density)): ρ/ρ₀ by kernel sums;
/// 4. **solve**: [`wcsph`](super::wcsph) (Tait pressure, explicit) or
///    [`dfsph`](super::dfsph) (iterated velocity corrections to the rest density), with
///    gravity and [`xsph`](super::xsph) smoothing;
/// 5. **advect** ([`boundary`](super::boundary)): x ← x + Δt v, then the tank walls.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(bound = "")]
pub struct FluidSystem<R: Real = Fx> {
    pub(crate) settings: FluidSettings<R>,
    pub(crate) positions: Vec<Vec3<R>>,
    pub(crate) velocities: Vec<Vec3<R>>,
    pub(crate) emitters: Vec<EmitterState<R>>,
    #[serde(skip)]
    pub(crate) scratch: Scratch<R>,
}

/// Per-step working memory and the boundary derived from the settings: never part of the
/// state, rebuilt when missing, equal to any other scratch. A clone starts empty.
#[derive(Debug, Default)]
pub(crate) struct Scratch<R: Real> {
    /// Whether the boundary particles and grids below match the settings.
    pub ready: bool,
    /// Boundary particles lining the tank, fixed.
    pub boundary: Vec<Vec3<R>>,
    /// The boundary particles sorted into cells, once.
    pub boundary_grid: CellGrid<R>,
    /// The fluid particles sorted into cells when the candidates are found, and their cells
    /// located in the other substeps.
    pub grid: CellGrid<R>,
    /// The candidate radius of the settings' kernel.
    pub reach: Reach<R>,
    /// Candidate neighbours of each fluid particle, reused across substeps while they hold
    /// every neighbour.
    pub skin: SkinLists<R>,
    /// Fluid neighbours of each fluid particle.
    pub fluid: NeighbourLists<R>,
    /// Boundary neighbours of each fluid particle.
    pub walls: NeighbourLists<R>,
    /// ρ/ρ₀ of each fluid particle.
    pub density: Vec<R>,
    /// Pressure over rest density P̃ = p/ρ₀ of each fluid particle in the last substep,
    /// m²/s².
    pub pressure: Vec<R>,
    /// A per-particle scalar of the solver (WCSPH: P̃/ρ̃²; DFSPH: the stiffness k).
    pub scalar: Vec<R>,
    /// A per-particle scalar of the solver (DFSPH: the factor 1/(Δt² D)).
    pub factor: Vec<R>,
    /// ρ₀/ρ of each fluid particle.
    pub inv_density: Vec<R>,
    /// Σ_b V₀∇W_ib of each fluid particle, 1/m (DFSPH).
    pub wall_gradient: Vec<Vec3<R>>,
    /// A per-particle velocity change, m/s (DFSPH: first the pressure push, m/s²).
    pub delta: Vec<Vec3<R>>,
    /// Σⱼ (vᵢ − vⱼ)·V₀∇Wᵢⱼ of each fluid particle, 1/s (DFSPH).
    pub rate: Vec<R>,
    /// The bit length of the fluid lists' gradients, measured with DFSPH's factors for the
    /// iterations of the same substep.
    pub gradient_bits: GradientBits,
    /// Solver iterations of the last step, summed over its substeps (DFSPH), for reports.
    pub last_iterations: u32,
    /// Substeps of the last step, for reports.
    pub last_substeps: u32,
    /// The rigid bodies in the fluid, when it meets them.
    pub bodies: BodiesInFluid<R>,
}

impl<R: Real> Clone for Scratch<R> {
    fn clone(&self) -> Self {
        Self::default()
    }
}

impl<R: Real> PartialEq for Scratch<R> {
    fn eq(&self, _: &Self) -> bool {
        true
    }
}

impl<R: Real> FluidSystem<R> {
    /// The settings.
    pub fn settings(&self) -> &FluidSettings<R> {
        &self.settings
    }

    /// Fluid particle positions, by id, m.
    pub fn positions(&self) -> &[Vec3<R>] {
        &self.positions
    }

    /// Fluid particle velocities, by id, m/s.
    pub fn velocities(&self) -> &[Vec3<R>] {
        &self.velocities
    }

    /// ρ/ρ₀ of each fluid particle at the last substep, by id (empty before the first
    /// step; shorter than [`positions`](Self::positions) for particles emitted since).
    pub fn densities(&self) -> &[R] {
        &self.scratch.density
    }

    /// The number of fluid particles.
    pub fn len(&self) -> usize {
        self.positions.len()
    }

    /// Whether there is no fluid particle (yet).
    pub fn is_empty(&self) -> bool {
        self.positions.is_empty()
    }

    /// Pressure solver iterations in the last step, summed over its substeps (0 for WCSPH).
    pub fn last_iterations(&self) -> u32 {
        self.scratch.last_iterations
    }

    /// Fluid substeps the last step took (0 before the first step).
    pub fn last_substeps(&self) -> u32 {
        self.scratch.last_substeps
    }

    /// Puts the state of `restored` in place, keeping this system's scratch memory.
    pub fn restore_from(&mut self, restored: Self) {
        let same_settings = restored.settings == self.settings;
        self.settings = restored.settings;
        self.positions = restored.positions;
        self.velocities = restored.velocities;
        self.emitters = restored.emitters;
        self.scratch.ready &= same_settings;
    }

    /// Advances the fluid by `dt` seconds under `gravity` (m/s²), in
    /// [`FluidSettings::substeps`] equal substeps, or with a CFL number as many as the flow
    /// needs ([`substeps`](super::substeps)).
    pub fn step(&mut self, dt: R, gravity: Vec3<R>) {
        let substeps = self.begin_step(dt, gravity);
        let h = dt * R::from_ratio(1, i64::from(substeps));
        for _ in 0..substeps {
            self.substep_with_bodies(h, gravity, &[]);
        }
    }

    /// Starts a step of `dt` seconds under `gravity`: readies the scratch and returns the
    /// substeps it takes, each of `dt`/substeps seconds.
    pub(crate) fn begin_step(&mut self, dt: R, gravity: Vec3<R>) -> u32 {
        self.prepare();
        self.scratch.last_iterations = 0;
        let substeps = self.substep_count(dt, gravity);
        self.scratch.last_substeps = substeps;
        substeps
    }

    /// One substep of `h` seconds with the rigid bodies of `views` in the fluid, two-way
    /// ([`bodies`](super::bodies)): emit, neighbours, the bodies' samples, density, solve,
    /// advect. Returns, per view, the impulse (N·s) and moment about its centre (N·m·s)
    /// the fluid gave it, and how far those moved (m) and turned it (rotation vector, rad).
    pub(crate) fn substep_with_bodies(
        &mut self,
        h: R,
        gravity: Vec3<R>,
        views: &[BodyView<'_, R>],
    ) -> FluidPushes<'_, R> {
        self.scratch.bodies.begin(views);
        for emitter in &mut self.emitters {
            let spacing = self.settings.spacing;
            emitter.emit(h, spacing, &mut self.positions, &mut self.velocities);
        }
        if !self.positions.is_empty() {
            self.find_neighbours(h);
            if !views.is_empty() {
                self.place_bodies(views);
            }
            self.compute_density();
            match self.settings.solver {
                FluidSolver::Wcsph => self.wcsph_velocities(h, gravity),
                FluidSolver::Dfsph => self.dfsph_velocities(h, gravity),
            }
            advect(&self.settings, &mut self.positions, &mut self.velocities, h);
            if !views.is_empty() {
                self.scratch.bodies.drift(h);
            }
        }
        let bodies = &self.scratch.bodies;
        FluidPushes {
            pushes: &bodies.pushes,
            drifts: &bodies.drifts,
        }
    }

    /// Places the samples of `views` and lists them as the particles' neighbours.
    fn place_bodies(&mut self, views: &[BodyView<'_, R>]) {
        let s = &self.settings;
        let margin = s.spacing * R::from_int(lattice_reach(s.support) + 1);
        let bounds = (
            s.tank.min - Vec3::splat(margin),
            s.tank.max + Vec3::splat(margin),
        );
        self.scratch
            .bodies
            .place(views, &self.positions, bounds, &s.kernel, s.spacing);
    }

    /// The mass of a fluid particle, ρ₀V₀ (kg).
    pub(crate) fn particle_mass(&self) -> R {
        let dx = self.settings.spacing;
        self.settings.rest_density * dx * dx * dx
    }

    /// Builds the boundary particles and grids when the scratch does not have them.
    pub(crate) fn prepare(&mut self) {
        if self.scratch.ready {
            return;
        }
        let s = &self.settings;
        let support = s.spacing * s.support;
        let margin = s.spacing * R::from_int(lattice_reach(s.support) + 1);
        let lower = s.tank.min - Vec3::splat(margin);
        let upper = s.tank.max + Vec3::splat(margin);
        self.scratch.boundary = sample_walls(s);
        self.scratch.boundary_grid = CellGrid::new(lower, upper, support);
        self.scratch.boundary_grid.fill(&self.scratch.boundary);
        self.scratch.grid = CellGrid::new(lower, upper, support);
        self.scratch.reach = Reach::new(&s.kernel, &self.scratch.grid);
        self.scratch.skin = SkinLists::default();
        self.scratch.ready = true;
    }

    /// Stage 2: lists every particle's fluid and boundary neighbours with their kernel
    /// values, from the candidates of the last substep when they still hold every
    /// neighbour (the fluid's cells located for the lists' order); else, with the fluid
    /// sorted into cells, from new candidates selected and evaluated in one pass of the
    /// grid when the next substep (of `h` seconds) can reuse them
    /// ([`SkinLists::may_last`], and no emitter adds particles), and otherwise by a search
    /// within the support alone ([`FluidSystem::search_neighbours`]), which costs less than
    /// one within the candidate radius. The same lists in every case; only the cost
    /// differs.
    pub(crate) fn find_neighbours(&mut self, h: R) {
        let Scratch {
            boundary,
            boundary_grid,
            grid,
            reach,
            skin,
            fluid,
            walls,
            ..
        } = &mut self.scratch;
        let kernel = &self.settings.kernel;
        let positions = &self.positions;
        if skin.covers(positions, reach) {
            grid.locate(positions);
            skin.fluid.order_by_cells(grid.cells());
            fluid.evaluate(&skin.fluid, positions, positions, kernel);
            walls.evaluate(&skin.walls, positions, boundary, kernel);
        } else if skin.may_last(&self.velocities, h, reach)
            && !adds_particles(&self.emitters, self.settings.spacing, h)
        {
            grid.fill(positions);
            let lists = [fluid, walls];
            skin.build(
                positions,
                grid,
                boundary,
                boundary_grid,
                reach,
                kernel,
                lists,
            );
        } else {
            skin.discard();
            self.search_neighbours();
        }
    }

    /// The neighbour lists of stage 2 by a search of the grid within the support, the
    /// fluid sorted into cells anew, keeping no candidates.
    pub(crate) fn search_neighbours(&mut self) {
        let s = &mut self.scratch;
        let (positions, kernel) = (&self.positions, &self.settings.kernel);
        s.grid.fill(positions);
        NeighbourLists::build_both(
            [&mut s.fluid, &mut s.walls],
            positions,
            &s.grid,
            (&s.boundary, &s.boundary_grid),
            kernel,
        );
    }
}

/// Whether an emitter adds particles in the next substep (of `h` seconds): one with
/// particles left whose travel then reaches the `spacing` (m), as [`emit`] finds it. The
/// particle count changes, so no candidate list outlives that.
///
/// [`emit`]: EmitterState::emit
fn adds_particles<R: Real>(emitters: &[EmitterState<R>], spacing: R, h: R) -> bool {
    emitters
        .iter()
        .any(|e| e.remaining > 0 && e.travelled.add_product(e.speed, h) >= spacing)
}
