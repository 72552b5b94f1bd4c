//! fixstep's side: its built-in rigid scenes, and the fluid scenes built from their
//! description.

use crate::scenes::{FixstepFluid, FluidRun, FluidScene, RigidRun, Scene};
use crate::time_steps;
use fixstep::fluid::{FluidBlock, FluidBox, FluidDesc, FluidSolver, FluidSystem};
use fixstep::math::{Fx, Real, Vec3};
use fixstep::rigid::{BodyKind, RigidSystem};
use fixstep_scenes::builtin_scene;
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

/// fixstep's DFSPH on `scene` in `R` with `settings`, timed after its warm-up steps.
fn run_fluid<R: Real>(scene: &FluidScene, settings: FixstepFluid) -> FluidRun {
    let dx = R::from_f64(f64::from(scene.spacing));
    let corner = |c: [f32; 3]| {
        Vec3::new(
            R::from_f64(f64::from(c[0])),
            R::from_f64(f64::from(c[1])),
            R::from_f64(f64::from(c[2])),
        )
    };
    let tank = FluidBox {
        min: Vec3::ZERO,
        max: corner(scene.tank),
    };
    let mut desc = FluidDesc::new(FluidSolver::Dfsph, dx, tank);
    desc.substeps = settings.substeps;
    desc.max_density_error = R::from_f64(f64::from(settings.tolerance));
    desc.cfl = R::from_f64(f64::from(settings.cfl));
    desc.blocks.push(FluidBlock {
        region: FluidBox {
            min: Vec3::ZERO,
            max: corner(scene.block),
        },
        velocity: Vec3::ZERO,
    });
    let dt = R::from_f64(f64::from(scene.dt));
    let gravity = Vec3::new(R::ZERO, R::from_f64(-9.81), R::ZERO);
    let mut fluid = FluidSystem::from_desc(&desc, dt).expect("the fluid scene builds");
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
pub fn run_fluid_fixed(scene: &FluidScene, settings: FixstepFluid) -> FluidRun {
    run_fluid::<Fx>(scene, settings)
}

/// [`run_fluid`] in `f64`.
pub fn run_fluid_f64(scene: &FluidScene, settings: FixstepFluid) -> FluidRun {
    run_fluid::<f64>(scene, settings)
}
