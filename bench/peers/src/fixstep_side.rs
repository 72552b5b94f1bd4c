//! fixstep's side: its built-in rigid scenes, and the cube of water of its fluid
//! benchmark.

use crate::scenes::{FluidRun, FluidScene, RigidRun, Scene};
use crate::time_steps;
use fixstep::fluid::{FluidBlock, FluidBox, FluidDesc, FluidSolver, FluidSystem};
use fixstep::math::{Fx, Real, Vec3};
use fixstep::rigid::{BodyKind, RigidSystem};
use fixstep::scene::builtin_scene;
use fixstep::world::TickInput;

fn to_f64<R: Real>(v: Vec3<R>) -> [f64; 3] {
    [v.x.to_f64(), v.y.to_f64(), v.z.to_f64()]
}

/// The positions of the dynamic bodies, in the order they were created.
fn positions<R: Real>(rigid: Option<&RigidSystem<R>>) -> Vec<[f64; 3]> {
    let Some(rigid) = rigid else {
        return Vec::new();
    };
    rigid
        .handles()
        .filter(|&h| rigid.kind(h) == Some(BodyKind::Dynamic))
        .filter_map(|h| rigid.position(h).map(to_f64))
        .collect()
}

fn run<R: Real>(scene: Scene) -> RigidRun {
    let mut description = builtin_scene::<R>(scene.name).expect("a built-in scene");
    if let Some(rigid) = &mut description.rigid {
        rigid.solver.sleeping = scene.sleeping;
    }
    let mut world = description.build().expect("built-in scenes build");
    let input = TickInput::default();
    let start = positions(world.rigid());
    let ms = time_steps(scene.steps, || {
        world.step(&input);
    });
    RigidRun {
        ms,
        start,
        end: positions(world.rigid()),
    }
}

/// `scene` in I32F32: mean ms per step and the bodies' positions before and after.
pub fn run_fixed(scene: Scene) -> RigidRun {
    run::<Fx>(scene)
}

/// The same in `f64`, the same generic code: what fixed point costs inside fixstep.
pub fn run_f64(scene: Scene) -> RigidRun {
    run::<f64>(scene)
}

/// fixstep's DFSPH on `scene` in `R`, timed after its warm-up steps: the cube of
/// `benches/fluid.rs` with the scene's step.
fn run_fluid<R: Real>(scene: &FluidScene) -> FluidRun {
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
    let ms = time_steps(scene.steps, || fluid.step(dt, gravity));
    FluidRun {
        ms,
        positions: fluid.positions().iter().map(|&p| to_f64(p)).collect(),
    }
}

/// [`run_fluid`] in I32F32.
pub fn run_fluid_fixed(scene: &FluidScene) -> FluidRun {
    run_fluid::<Fx>(scene)
}

/// [`run_fluid`] in `f64`.
pub fn run_fluid_f64(scene: &FluidScene) -> FluidRun {
    run_fluid::<f64>(scene)
}
