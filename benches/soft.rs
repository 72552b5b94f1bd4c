//! XPBD cloth step time: a 64×64 cloth (64·63·2 + 63² = 12 033 distance rows, plus 8 188
//! tethers to its two pins; no bending, as in the 12k-constraint case the issue names) at
//! 60 Hz with the default substeps (10) and iterations (1), pinned at two corners and
//! falling from horizontal. Each sample runs 120 ticks from the start and reports the time
//! per tick.
//!
//! The same generic code runs in I32F32 and in `f64`, measured in the same run.

use std::hint::black_box;
use std::time::{Duration, Instant};

use criterion::{BenchmarkId, Criterion, criterion_group, criterion_main};
use fixstep::math::{Fx, Real};
use fixstep::scene::Scene;
use fixstep::soft::SoftModel;
use fixstep::world::{TickInput, World};

/// The 64×64 cloth scene in format R, with or without its bending rows.
fn cloth<R: Real>(bending: bool) -> Scene<R> {
    let mut scene = Scene::empty("cloth64");
    let mut soft = fixstep_scenes::soft::cloth::<R>(64);
    if !bending
        && let SoftModel::Xpbd {
            bend_compliance, ..
        } = &mut soft.bodies[0].model
    {
        *bend_compliance = None;
    }
    scene.soft = Some(soft);
    scene
}

/// Runs `ticks` ticks of a fresh world per iteration; reports the time per tick.
fn bench_cloth<R: Real>(
    group: &mut criterion::BenchmarkGroup<'_, criterion::measurement::WallTime>,
    bending: bool,
    ticks: u64,
) {
    let scene = cloth::<R>(bending);
    let empty = TickInput::default();
    let label = if bending {
        "cloth64_bending"
    } else {
        "cloth64"
    };
    group.bench_function(BenchmarkId::new(label, R::NAME), |b| {
        b.iter_custom(|iterations| {
            let mut total = Duration::ZERO;
            for _ in 0..iterations {
                let mut world: World<R> = scene.build().expect("the scene builds");
                let start = Instant::now();
                for _ in 0..ticks {
                    black_box(world.step(&empty));
                }
                total += start.elapsed() / ticks as u32;
            }
            total
        })
    });
}

fn soft(c: &mut Criterion) {
    let mut group = c.benchmark_group("soft_step");
    group.sample_size(10);
    for bending in [false, true] {
        bench_cloth::<Fx>(&mut group, bending, 120);
        bench_cloth::<f64>(&mut group, bending, 120);
    }
    group.finish();
}

criterion_group!(benches, soft);
criterion_main!(benches);
