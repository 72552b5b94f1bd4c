//! Fluid step time per particle-step at 8k, 64k and 256k particles (docs/PERFORMANCE.md).
//!
//! The fluid is a cube of n³ particles (n = 20, 40, 64) on the floor of a tank of the same
//! footprint, 1 cm apart ([`presets::cube`]), one thread. Each sample copies a state
//! reached beforehand, outside the timing, and then:
//!
//! - **running** (every case): steps the copy once untimed, then times [`RUN`] steps in a
//!   row and reports their mean: steps of a running simulation, which keeps its boundary
//!   particles, grids and candidate lists from step to step;
//! - **after a restore** (the 8k cubes, cases named `…_after_restore`): times the copy's
//!   first step. A copy, like a state restored from a snapshot (a GGRS rollback), starts
//!   without that working memory, and its first step rebuilds it: what each rollback pays
//!   once.
//!
//! The cases:
//!
//! - Scaling: WCSPH, whose work per particle does not depend on the size, at 8k, 64k and
//!   256k particles, steps of 0.1 ms (one fluid substep), from the state after 5 steps.
//! - salva3d's setup (8000 fluid particles and a few thousand boundary particles, Δt =
//!   0.005 s): DFSPH at 8k particles, a whole step of 5 ms in the 3 fluid substeps the
//!   time-step limit asks for (0.2 H / u with u = c/10 = 2 m/s, H = 2 cm), from the state
//!   after 20 steps (water settling under gravity, 0.1 s in).
//! - A puddle in a large tank: 1000 particles (a cube of 10³ in a corner, [`presets::cube`],
//!   spreading over the floor) in a tank 2 and 16 times as wide and deep as the cube (64
//!   times the floor in the second; the far walls beyond the water's reach in both), DFSPH,
//!   5 ms in 3 substeps, from the state after 5 steps. A scene pays for the water, not for
//!   the tank: the two should take about the same time.
//!
//! Every case but the puddle runs in I32F32 and, with the same generic code, in `f64`,
//! measured in the same run. Throughput is reported in particle-steps.

use std::hint::black_box;
use std::time::{Duration, Instant};

use criterion::{BenchmarkId, Criterion, Throughput, criterion_group, criterion_main};
use fixstep::fluid::{FluidDesc, FluidSolver, FluidSystem};
use fixstep::math::{Fx, Real, Vec3};
use fixstep_scenes::fluid as presets;

/// Steps timed in a row per sample of a running simulation.
const RUN: u32 = 5;

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

/// What a sample times.
#[derive(Clone, Copy, PartialEq, Eq)]
enum Timing {
    /// [`RUN`] steps of a running simulation.
    Running,
    /// The first step after a restore.
    AfterRestore,
}

/// The cube of `n`³ particles under `case`, from the state after `warm_steps` steps.
fn bench_cube<R: Real>(
    group: &mut criterion::BenchmarkGroup<'_, criterion::measurement::WallTime>,
    n: u32,
    case: &Case,
    warm_steps: u32,
    timing: Timing,
) {
    let desc = presets::cube::<R>(n, case.solver, case.substeps);
    let mut name = format!("{:?}_{}_dt_1/{}", case.solver, n * n * n, case.rate);
    if timing == Timing::AfterRestore {
        name += "_after_restore";
    }
    bench_desc(group, &name, desc, case, warm_steps, timing);
}

/// The puddle: a cube of 10³ particles in a tank `widen` times as wide and deep as the
/// cube's own.
fn bench_puddle(
    group: &mut criterion::BenchmarkGroup<'_, criterion::measurement::WallTime>,
    widen: i32,
) {
    let mut desc = presets::cube::<Fx>(10, DFSPH.solver, DFSPH.substeps);
    desc.tank.max.x *= Fx::from_int(widen);
    desc.tank.max.z *= Fx::from_int(widen);
    let name = format!("puddle_1000_in_tank_{widen}x");
    bench_desc(group, &name, desc, &DFSPH, 5, Timing::Running);
}

/// Steps `desc` `warm_steps` times, then times copies of that state as `timing` says.
fn bench_desc<R: Real>(
    group: &mut criterion::BenchmarkGroup<'_, criterion::measurement::WallTime>,
    name: &str,
    desc: FluidDesc<R>,
    case: &Case,
    warm_steps: u32,
    timing: Timing,
) {
    let dt = R::from_ratio(1, case.rate);
    let gravity = Vec3::new(R::ZERO, R::from_f64(-9.81), R::ZERO);
    let mut fluid = FluidSystem::from_desc(&desc, dt).expect("the cube builds");
    for _ in 0..warm_steps {
        fluid.step(dt, gravity);
    }
    let particles = fluid.positions().len() as u64;
    group.throughput(Throughput::Elements(particles));
    group.bench_function(BenchmarkId::new(name, R::NAME), |b| {
        b.iter_custom(|iterations| {
            let mut total = Duration::ZERO;
            for _ in 0..iterations {
                let mut copy = fluid.clone();
                let steps = match timing {
                    Timing::Running => {
                        copy.step(dt, gravity);
                        RUN
                    }
                    Timing::AfterRestore => 1,
                };
                let start = Instant::now();
                for _ in 0..steps {
                    copy.step(dt, gravity);
                }
                total += start.elapsed() / steps;
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
    for timing in [Timing::Running, Timing::AfterRestore] {
        bench_cube::<Fx>(&mut group, 20, &DFSPH, 20, timing);
        bench_cube::<f64>(&mut group, 20, &DFSPH, 20, timing);
    }
    for n in [20, 40, 64] {
        bench_cube::<Fx>(&mut group, n, &WCSPH, 5, Timing::Running);
        bench_cube::<f64>(&mut group, n, &WCSPH, 5, Timing::Running);
    }
    bench_cube::<Fx>(&mut group, 20, &WCSPH, 5, Timing::AfterRestore);
    bench_cube::<f64>(&mut group, 20, &WCSPH, 5, Timing::AfterRestore);
    bench_puddle(&mut group, 2);
    bench_puddle(&mut group, 16);
    group.finish();
}

criterion_group!(benches, fluid);
criterion_main!(benches);
