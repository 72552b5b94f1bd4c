//! salva3d's side: the fluid scene of fixstep's fluid benchmark, particle for particle.

use crate::scenes::{FluidRun, FluidScene};
use crate::time_steps;
use salva3d::LiquidWorld;
use salva3d::math::Vector;
use salva3d::object::interaction_groups::InteractionGroups;
use salva3d::object::{Boundary, Fluid};
use salva3d::solver::DFSPHSolver;

fn vectors(points: Vec<[f32; 3]>) -> Vec<Vector<f32>> {
    points
        .into_iter()
        .map(|p| Vector::new(p[0], p[1], p[2]))
        .collect()
}

/// salva3d's DFSPH on `scene`, timed after its warm-up steps, stopping its pressure
/// iterations at a mean predicted compression of `tolerance` (salva3d's default, 0.05,
/// is a fraction: 5 %, although its documentation says percent), and the particle counts
/// (fluid, boundary).
pub fn run(scene: &FluidScene, tolerance: Option<f32>) -> (FluidRun, usize, usize) {
    let dx = scene.spacing;
    let radius = dx / 2.0;
    let mut solver = DFSPHSolver::<salva3d::kernel::CubicSplineKernel>::new();
    if let Some(tolerance) = tolerance {
        solver.max_density_error = tolerance;
    }
    // h = radius · smoothing factor · 2 = 2 dx: the support of fixstep's kernel.
    let mut world = LiquidWorld::new(solver, radius, 2.0, 1.0);
    let fluid = vectors(scene.fluid());
    let walls = vectors(scene.walls());
    let counts = (fluid.len(), walls.len());
    world.add_fluid(Fluid::new(
        fluid,
        radius,
        1000.0,
        InteractionGroups::default(),
    ));
    world.add_boundary(Boundary::new(walls, InteractionGroups::default()));
    let gravity = Vector::new(0.0, -9.81, 0.0);
    for _ in 0..scene.warm_steps {
        world.step(scene.dt, &gravity);
    }
    let ms = time_steps(scene.steps, || world.step(scene.dt, &gravity));
    let positions = world
        .fluids()
        .iter()
        .flat_map(|(_, fluid)| fluid.positions.iter())
        .map(|p| [f64::from(p.x), f64::from(p.y), f64::from(p.z)])
        .collect();
    (FluidRun { ms, positions }, counts.0, counts.1)
}
