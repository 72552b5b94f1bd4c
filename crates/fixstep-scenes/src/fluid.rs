//! The fluids of the built-in scenes.

use fixstep::fluid::{FluidBlock, FluidBox, FluidDesc, FluidEmitter, FluidSolver};
use fixstep::math::{Real, Vec3};

/// Martin & Moyce's column width a = 2.25 in = 0.05715 m.
pub fn dam_break_width<R: Real>() -> R {
    R::from_ratio(5715, 100_000)
}

/// Martin & Moyce's dam break (1952, n² = 2) in a thin 3D slab: a water column a wide and
/// 2a high at the back wall (x = 0) of a tank 0.3 m long and 0.15 m high, `layers`
/// particles deep (z) between two free-slip walls, `per_width` particles across a.
/// c = 20 m/s, ten times the fastest front. The fluid substeps suit a 60 Hz tick: 16 per
/// particle across a for WCSPH, 2 for DFSPH, within the limit 0.2 H / u.
pub fn dam_break<R: Real>(per_width: u32, layers: u32, solver: FluidSolver) -> FluidDesc<R> {
    let a = dam_break_width::<R>();
    let dx = a * R::from_ratio(1, i64::from(per_width));
    let depth = dx * R::from_int(layers as i32);
    let tank = FluidBox {
        min: Vec3::ZERO,
        max: Vec3::new(R::from_ratio(3, 10), R::from_ratio(15, 100), depth),
    };
    let mut desc = FluidDesc::new(solver, dx, tank);
    desc.substeps = per_width
        * match solver {
            FluidSolver::Wcsph => 16,
            FluidSolver::Dfsph => 2,
        };
    desc.blocks.push(FluidBlock {
        region: FluidBox {
            min: Vec3::ZERO,
            max: Vec3::new(a, a * R::TWO, depth),
        },
        velocity: Vec3::ZERO,
    });
    desc
}

/// Water at rest: a cube 0.1 m on a side, `per_side` particles along each edge, in a
/// tank that fits it. The fluid substeps suit a 60 Hz tick: 10 per particle along an edge
/// for WCSPH, 1 for DFSPH, within the limit 0.2 H / u.
pub fn tank<R: Real>(per_side: u32, solver: FluidSolver) -> FluidDesc<R> {
    let side = R::from_ratio(1, 10);
    let dx = side * R::from_ratio(1, i64::from(per_side));
    let tank = FluidBox {
        min: Vec3::ZERO,
        max: Vec3::new(side, R::from_ratio(15, 100), side),
    };
    let mut desc = FluidDesc::new(solver, dx, tank);
    desc.substeps = per_side
        * match solver {
            FluidSolver::Wcsph => 10,
            FluidSolver::Dfsph => 1,
        };
    desc.blocks.push(FluidBlock {
        region: FluidBox {
            min: Vec3::ZERO,
            max: Vec3::new(side, side, side),
        },
        velocity: Vec3::ZERO,
    });
    desc
}

/// The benchmark's fluid (`benches/fluid.rs`): a cube of `n`³ particles 1 cm apart on the
/// floor of a tank of the same footprint, 1.5 × as high, with default settings and
/// `substeps` fluid substeps per step.
pub fn cube<R: Real>(n: u32, solver: FluidSolver, substeps: u32) -> FluidDesc<R> {
    let dx = R::from_ratio(1, 100);
    let side = dx * R::from_int(n as i32);
    let tank = FluidBox {
        min: Vec3::ZERO,
        max: Vec3::new(side, side * R::from_ratio(3, 2), side),
    };
    let mut desc = FluidDesc::new(solver, dx, tank);
    desc.substeps = substeps;
    desc.blocks.push(FluidBlock {
        region: FluidBox {
            min: Vec3::ZERO,
            max: Vec3::splat(side),
        },
        velocity: Vec3::ZERO,
    });
    desc
}

/// A jet poured into an empty box under DFSPH: a 3 × 3 nozzle 2 cm apart, 0.2 m above
/// the floor of a box 0.2 m wide, 1 m/s downwards, `count` particles in all; 5 fluid
/// substeps per 60 Hz tick.
pub fn pour<R: Real>(count: u32) -> FluidDesc<R> {
    let dx = R::from_ratio(2, 100);
    let side = R::from_ratio(2, 10);
    let tank = FluidBox {
        min: Vec3::ZERO,
        max: Vec3::new(side, R::from_ratio(3, 10), side),
    };
    let mut desc = FluidDesc::new(FluidSolver::Dfsph, dx, tank);
    desc.substeps = 10;
    desc.emitters.push(FluidEmitter {
        position: Vec3::new(
            R::from_ratio(7, 100),
            R::from_ratio(2, 10),
            R::from_ratio(1, 10),
        ),
        velocity: Vec3::new(R::ZERO, -R::ONE, R::ZERO),
        width: 4,
        count,
    });
    desc
}

/// The showcase's water: the dam break of [`dam_break`] (5 particles across a, 2 deep,
/// DFSPH), its tank moved to x = 3.5 m, z = 1 m, beside the rigid bodies.
pub fn showcase<R: Real>() -> FluidDesc<R> {
    let mut desc = dam_break(5, 2, FluidSolver::Dfsph);
    let offset = Vec3::new(R::from_ratio(7, 2), R::ZERO, R::ONE);
    let moved = |b: FluidBox<R>| FluidBox {
        min: b.min + offset,
        max: b.max + offset,
    };
    desc.tank = moved(desc.tank);
    for block in &mut desc.blocks {
        block.region = moved(block.region);
    }
    desc
}
