//! Fluid step time per particle-step at 8k, 64k and 256k particles (docs/PERFORMANCE.md).
//!
//! The fluid is a cube of n³ particles (n = 20, 40, 64) on the floor of a tank of the same
//! footprint, 1 cm apart ([`presets::cube`]), one thread; the copy a sample steps is made
//! outside the timing.
//!
//! - Scaling: WCSPH, whose work per particle does not depend on the size, at 8k, 64k and
//!   256k particles, steps of 0.1 ms (one fluid substep), from the state after 5 steps.
//! - salva3d's setup (8000 fluid particles and a few thousand boundary particles, Δt =
//!   0.005 s): DFSPH at 8k particles, a whole step of 5 ms in the 3 fluid substeps the
//!   time-step limit asks for (0.2 H / u with u = c/10 = 2 m/s, H = 2 cm), from the state
//!   after 20 steps (water settling under gravity, 0.1 s in).
//!
//! Every case runs in I32F32 and, with the same generic code, in `f64`, measured in the
//! same run. Throughput is reported in particle-steps.

use std::hint::black_box;
use std::time::{Duration, Instant};

use criterion::{BenchmarkId, Criterion, Throughput, criterion_group, criterion_main};
use fixstep::fluid::{FluidSolver, FluidSystem, presets};
use fixstep::math::{Fx, Real, Vec3};

/// A case: the solver, the step (1/`rate` s) and its fluid substeps.
struct Case {
    solver: FluidSolver,
    rate: i64,
    substeps: u32,
}

/// WCSPH at Δt = 0.1 ms (c = 20 m/s), one substep.
const WCSPH: Case = Case {
    solver: FluidSolver::Wcsph,
    rate: 10_000,
    substeps: 1,
};

/// DFSPH at Δt = 5 ms, in three substeps.
const DFSPH: Case = Case {
    solver: FluidSolver::Dfsph,
    rate: 200,
    substeps: 3,
};

fn bench_cube<R: Real>(
    group: &mut criterion::BenchmarkGroup<'_, criterion::measurement::WallTime>,
    n: u32,
    case: &Case,
    warm_steps: u32,
) {
    let dt = R::from_ratio(1, case.rate);
    let gravity = Vec3::new(R::ZERO, R::from_f64(-9.81), R::ZERO);
    let desc = presets::cube::<R>(n, case.solver, case.substeps);
    let mut fluid = FluidSystem::from_desc(&desc, dt).expect("the cube builds");
    for _ in 0..warm_steps {
        fluid.step(dt, gravity);
    }
    let particles = u64::from(n * n * n);
    group.throughput(Throughput::Elements(particles));
    let name = format!("{:?}_{particles}_dt_1/{}", case.solver, case.rate);
    group.bench_function(BenchmarkId::new(name, R::NAME), |b| {
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
    });
}

fn fluid(c: &mut Criterion) {
    let mut group = c.benchmark_group("fluid_step");
    group.sample_size(10);
    group.warm_up_time(Duration::from_millis(500));
    group.measurement_time(Duration::from_secs(3));
    bench_cube::<Fx>(&mut group, 20, &DFSPH, 20);
    bench_cube::<f64>(&mut group, 20, &DFSPH, 20);
    for n in [20, 40, 64] {
        bench_cube::<Fx>(&mut group, n, &WCSPH, 5);
        bench_cube::<f64>(&mut group, n, &WCSPH, 5);
    }
    group.finish();
}

criterion_group!(benches, fluid);
criterion_main!(benches);
