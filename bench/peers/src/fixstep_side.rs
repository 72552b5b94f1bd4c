//! fixstep's side: its built-in rigid scenes, with sleeping off, and the cube of water of
//! its fluid benchmark.

use crate::{FluidScene, Scene, time_steps};
use fixstep::fluid::{FluidBlock, FluidBox, FluidDesc, FluidSolver, FluidSystem};
use fixstep::math::{Fx, Real, Vec3};
use fixstep::scene::builtin_scene;
use fixstep::world::TickInput;

fn run<R: Real>(scene: Scene) -> f64 {
    let mut description = builtin_scene::<R>(scene.name).expect("a built-in scene");
    if let Some(rigid) = &mut description.rigid {
        rigid.solver.sleeping = false;
    }
    let mut world = description.build().expect("built-in scenes build");
    let input = TickInput::default();
    time_steps(scene.steps, || {
        world.step(&input);
    })
}

/// Mean ms per step of `scene` in I32F32.
pub fn run_fixed(scene: Scene) -> f64 {
    run::<Fx>(scene)
}

/// The same in `f64`, the same generic code: what fixed point costs inside fixstep.
pub fn run_f64(scene: Scene) -> f64 {
    run::<f64>(scene)
}

/// Mean ms per step of fixstep's DFSPH on `scene` in `R`, after its warm-up steps: the
/// cube of `benches/fluid.rs` with the scene's step.
fn run_fluid<R: Real>(scene: &FluidScene) -> f64 {
    let dx = R::from_f64(f64::from(scene.spacing));
    let side = dx * R::from_int(scene.n as i32);
    let tank = FluidBox {
        min: Vec3::ZERO,
        max: Vec3::new(side, side * R::from_ratio(3, 2), side),
    };
    let mut desc = FluidDesc::new(FluidSolver::Dfsph, dx, tank);
    // fixstep takes a fixed substep count and refuses one above 0.2 H/u (u = 2 m/s, the
    // fastest flow it is set for): 5 ms in 3 substeps of 1.67 ms.
    desc.substeps = 3;
    desc.blocks.push(FluidBlock {
        region: FluidBox {
            min: Vec3::ZERO,
            max: Vec3::splat(side),
        },
        velocity: Vec3::ZERO,
    });
    let dt = R::from_f64(f64::from(scene.dt));
    let gravity = Vec3::new(R::ZERO, R::from_f64(-9.81), R::ZERO);
    let mut fluid = FluidSystem::from_desc(&desc, dt).expect("the cube builds");
    for _ in 0..scene.warm_steps {
        fluid.step(dt, gravity);
    }
    time_steps(scene.steps, || fluid.step(dt, gravity))
}

/// [`run_fluid`] in I32F32.
pub fn run_fluid_fixed(scene: &FluidScene) -> f64 {
    run_fluid::<Fx>(scene)
}

/// [`run_fluid`] in `f64`.
pub fn run_fluid_f64(scene: &FluidScene) -> f64 {
    run_fluid::<f64>(scene)
}
