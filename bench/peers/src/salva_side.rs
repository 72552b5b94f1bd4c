//! salva3d's side: the fluid scene of fixstep's fluid benchmark, particle for particle.

use crate::{FluidScene, time_steps};
use salva3d::LiquidWorld;
use salva3d::math::Vector;
use salva3d::object::interaction_groups::InteractionGroups;
use salva3d::object::{Boundary, Fluid};
use salva3d::solver::DFSPHSolver;

/// The lattice sites `lo + (i + ½)·spacing` below `hi`.
fn sites(lo: f32, hi: f32, spacing: f32) -> Vec<f32> {
    let count = ((hi - lo) / spacing).round() as usize;
    (0..count)
        .map(|i| lo + (i as f32 + 0.5) * spacing)
        .collect()
}

/// The tank's boundary particles, as fixstep samples them (`src/fluid/boundary.rs`): two
/// layers one spacing apart outside the floor (under the walls too) and the four walls.
fn tank_walls(scene: &FluidScene) -> Vec<Vector<f32>> {
    let (dx, side, height) = (scene.spacing, scene.side(), scene.height());
    let thickness = 2.0 * dx;
    let outer = sites(-thickness, side + thickness, dx);
    let inner = sites(0.0, side, dx);
    let rise = sites(0.0, height, dx);
    let layers = sites(0.0, thickness, dx);
    let mut points = Vec::new();
    for &z in &outer {
        for &depth in &layers {
            for &x in &outer {
                points.push(Vector::new(x, -depth, z));
            }
        }
    }
    for &z in &outer {
        for &y in &rise {
            for &depth in &layers {
                points.push(Vector::new(-depth, y, z));
                points.push(Vector::new(side + depth, y, z));
            }
        }
    }
    for &depth in &layers {
        for &y in &rise {
            for &x in &inner {
                points.push(Vector::new(x, y, -depth));
                points.push(Vector::new(x, y, side + depth));
            }
        }
    }
    points
}

/// Mean ms per step of salva3d's DFSPH on `scene`, after its warm-up steps, and the
/// particle counts (fluid, boundary).
pub fn run(scene: &FluidScene) -> (f64, usize, usize) {
    let dx = scene.spacing;
    let radius = dx / 2.0;
    // h = radius · smoothing factor · 2 = 2 dx: the support of fixstep's kernel.
    let mut world = LiquidWorld::new(
        DFSPHSolver::<salva3d::kernel::CubicSplineKernel>::new(),
        radius,
        2.0,
        1.0,
    );
    let inner = sites(0.0, scene.side(), dx);
    let mut fluid = Vec::new();
    for &z in &inner {
        for &y in &inner {
            for &x in &inner {
                fluid.push(Vector::new(x, y, z));
            }
        }
    }
    let walls = tank_walls(scene);
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
    (ms, counts.0, counts.1)
}
