//! Fluid step time per particle-step at 8k, 64k and 256k particles (docs/PERFORMANCE.md).
//!
//! The fluid is a cube of n³ particles (n = 20, 40, 64) on the floor of a tank of the same
//! footprint, 1 cm apart, one fluid substep per step, one thread; the copy a sample steps
//! is made outside the timing.
//!
//! - Scaling: WCSPH, whose work per particle does not depend on the size, at 8k, 64k and
//!   256k particles, from the state after 5 steps.
//! - The solver salva3d's quoted figure is for: DFSPH at 8k particles, from the state after
//!   100 steps (water settling under gravity).
//!
//! Every case runs in I32F32 and, with the same generic code, in `f64`, measured in the
//! same run. Throughput is reported in particle-steps.

use std::hint::black_box;
use std::time::{Duration, Instant};

use criterion::{BenchmarkId, Criterion, Throughput, criterion_group, criterion_main};
use fixstep::fluid::{FluidBlock, FluidBox, FluidDesc, FluidSolver, FluidSystem};
use fixstep::math::{Fx, Real, Vec3};

/// A cube of `n`³ particles 1 cm apart in a tank of the same footprint, 1.5 × as high.
fn cube<R: Real>(n: u32, solver: FluidSolver) -> FluidDesc<R> {
    let dx = R::from_ratio(1, 100);
    let side = dx * R::from_int(n as i32);
    let tank = FluidBox {
        min: Vec3::ZERO,
        max: Vec3::new(side, side * R::from_ratio(3, 2), side),
    };
    let mut desc = FluidDesc::new(solver, dx, tank);
    desc.blocks.push(FluidBlock {
        region: FluidBox {
            min: Vec3::ZERO,
            max: Vec3::splat(side),
        },
        velocity: Vec3::ZERO,
    });
    desc
}

/// The step of the solver: 1 ms for DFSPH, 0.1 ms for WCSPH (c = 20 m/s).
fn step_of<R: Real>(solver: FluidSolver) -> R {
    match solver {
        FluidSolver::Dfsph => R::from_ratio(1, 1000),
        FluidSolver::Wcsph => R::from_ratio(1, 10_000),
    }
}

fn bench_cube<R: Real>(
    group: &mut criterion::BenchmarkGroup<'_, criterion::measurement::WallTime>,
    n: u32,
    solver: FluidSolver,
    warm_steps: u32,
) {
    let dt = step_of::<R>(solver);
    let gravity = Vec3::new(R::ZERO, R::from_f64(-9.81), R::ZERO);
    let mut fluid = FluidSystem::from_desc(&cube::<R>(n, solver), dt).expect("the cube builds");
    for _ in 0..warm_steps {
        fluid.step(dt, gravity);
    }
    let particles = u64::from(n * n * n);
    group.throughput(Throughput::Elements(particles));
    group.bench_function(
        BenchmarkId::new(format!("{solver:?}_{particles}"), R::NAME),
        |b| {
            b.iter_custom(|iterations| {
                let mut total = Duration::ZERO;
                for _ in 0..iterations {
                    let mut copy = fluid.clone();
                    let start = Instant::now();
                    copy.step(dt, gravity);
                    total += start.elapsed();
                    black_box(&copy);
                }
                total
            })
        },
    );
}

fn fluid(c: &mut Criterion) {
    let mut group = c.benchmark_group("fluid_step");
    group.sample_size(10);
    group.warm_up_time(Duration::from_millis(500));
    group.measurement_time(Duration::from_secs(3));
    for n in [20, 40, 64] {
        bench_cube::<Fx>(&mut group, n, FluidSolver::Wcsph, 5);
        bench_cube::<f64>(&mut group, n, FluidSolver::Wcsph, 5);
    }
    bench_cube::<Fx>(&mut group, 20, FluidSolver::Dfsph, 100);
    bench_cube::<f64>(&mut group, 20, FluidSolver::Dfsph, 100);
    group.finish();
}

criterion_group!(benches, fluid);
criterion_main!(benches);
