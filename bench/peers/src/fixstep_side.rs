//! fixstep's side: its built-in rigid scenes, and the fluid scenes built from their
//! description.

use crate::queries::{
    Answers, BodyShape, MAX_DISTANCE, PlacedBody, Queries, QuerySet, RayAnswer, SETTLE_STEPS, UNIT,
};
use crate::scenes::{FixstepFluid, FluidRun, FluidScene, RigidRun, Scene};
use crate::time_steps;
use fixstep::fluid::{FluidBlock, FluidBox, FluidDesc, FluidSolver, FluidSystem};
use fixstep::math::{Fx, Quat, Real, Vec3};
use fixstep::rigid::{BodyKind, CollisionFilter, QueryFilter, RigidSystem, Shape};
use fixstep::world::{TickInput, World};
use fixstep_scenes::builtin_scene;
use std::time::Instant;

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
    run_with::<R>(scene, None)
}

/// [`run`], every body given `filter` when there is one.
fn run_with<R: Real>(scene: Scene, filter: Option<CollisionFilter>) -> RigidRun {
    let mut description = match scene.name {
        "hills" | "hills_mesh" => {
            let mut landing = fixstep::scene::Scene::empty(scene.name);
            landing.rigid = Some(fixstep_scenes::terrain::landing(scene.name == "hills_mesh"));
            landing
        }
        name => builtin_scene::<R>(name).expect("a built-in scene"),
    };
    if let Some(rigid) = &mut description.rigid {
        rigid.solver.sleeping = scene.sleeping;
        if let Some(filter) = filter {
            for body in &mut rigid.bodies {
                body.filter = filter;
            }
        }
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

/// The filter every body gets in [`run_filtered`]: on layer 1, interacting with every
/// layer. Every pair still interacts (the same bits), but the collide stage now filters
/// the pairs and looks for sensor overlaps.
pub const LAYER_ONE: CollisionFilter = CollisionFilter::new(1, u32::MAX);

/// [`run_fixed`] with every body's filter [`LAYER_ONE`].
pub fn run_filtered(scene: Scene) -> RigidRun {
    run_with::<Fx>(scene, Some(LAYER_ONE))
}

/// fixstep's world of `scene` after [`SETTLE_STEPS`] steps (sleeping off), with the query
/// set in its own types.
pub struct FixstepQueries {
    world: World<Fx>,
    rays: Vec<(Vec3<Fx>, Vec3<Fx>)>,
    spheres: Vec<(Shape<Fx>, Vec3<Fx>)>,
}

fn fx_point(v: [i32; 3]) -> Vec3<Fx> {
    let c = |k: usize| Fx::from_ratio(i64::from(v[k]), i64::from(UNIT));
    Vec3::new(c(0), c(1), c(2))
}

/// `scene` settled, ready for the queries of `set`.
pub fn queries(scene: &str, set: &QuerySet) -> FixstepQueries {
    let mut description = builtin_scene::<Fx>(scene).expect("a built-in scene");
    if let Some(rigid) = &mut description.rigid {
        rigid.solver.sleeping = false;
    }
    let mut world = description.build().expect("built-in scenes build");
    let input = TickInput::default();
    for _ in 0..SETTLE_STEPS {
        world.step(&input);
    }
    FixstepQueries {
        world,
        rays: set
            .rays
            .iter()
            .map(|r| {
                let origin = fx_point(r.origin);
                (origin, fx_point(r.target) - origin)
            })
            .collect(),
        spheres: set
            .spheres
            .iter()
            .map(|s| {
                let radius = Fx::from_ratio(i64::from(s.radius), i64::from(UNIT));
                (Shape::Sphere { radius }, fx_point(s.centre))
            })
            .collect(),
    }
}

impl Queries for FixstepQueries {
    fn rays(&self) -> Answers<RayAnswer> {
        let filter = QueryFilter::new();
        let max = Fx::from_int(MAX_DISTANCE);
        let mut hits = Vec::with_capacity(self.rays.len());
        let start = Instant::now();
        for &(origin, direction) in &self.rays {
            hits.push(self.world.cast_ray(origin, direction, max, &filter));
        }
        let seconds = start.elapsed().as_secs_f64();
        Answers {
            seconds,
            answers: hits
                .into_iter()
                .map(|hit| hit.map(|h| (h.body.index, h.distance.to_f64())))
                .collect(),
        }
    }

    fn overlaps(&self) -> Answers<Vec<u32>> {
        let filter = QueryFilter::new();
        let mut found = Vec::with_capacity(self.spheres.len());
        let start = Instant::now();
        for (shape, centre) in &self.spheres {
            found.push(self.world.overlap(shape, *centre, Quat::IDENTITY, &filter));
        }
        let seconds = start.elapsed().as_secs_f64();
        Answers {
            seconds,
            answers: found
                .into_iter()
                .map(|handles| handles.iter().map(|h| h.index).collect())
                .collect(),
        }
    }
}

/// The bodies of the settled world, in slot order, for another engine to copy.
pub fn bodies(queries: &FixstepQueries) -> Vec<PlacedBody> {
    let rigid = queries.world.rigid().expect("a rigid scene");
    let f = Fx::to_f64;
    rigid
        .handles()
        .enumerate()
        .map(|(slot, h)| {
            assert_eq!(h.index as usize, slot, "no free slots");
            let shape = match rigid.shape(h).expect("a live body") {
                Shape::Sphere { radius } => BodyShape::Ball(f(*radius)),
                Shape::Box { half_extents } => BodyShape::Cuboid(to_f64(*half_extents)),
                Shape::Plane { normal, offset } if *normal == Vec3::Y => {
                    BodyShape::Ground(f(*offset))
                }
                other => unimplemented!("no copy of {other:?}"),
            };
            let q = rigid.orientation(h).expect("a live body");
            PlacedBody {
                shape,
                position: to_f64(rigid.position(h).expect("a live body")),
                orientation: [f(q.w), f(q.x), f(q.y), f(q.z)],
                dynamic: rigid.kind(h) == Some(BodyKind::Dynamic),
            }
        })
        .collect()
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
