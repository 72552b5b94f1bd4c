//! XPBD cloth step time: a 64×64 cloth (64·63·2 + 63² = 12 033 distance rows, plus 8 188
//! tethers to its two pins; no bending, as in the 12k-constraint case the issue names) at
//! 60 Hz with the default substeps (10) and iterations (1), pinned at two corners and
//! falling from horizontal. Each sample runs 120 ticks from the start and reports the time
//! per tick.
//!
//! The same generic code runs in I32F32 and in `f64`, measured in the same run.

mod support;

use criterion::{BenchmarkId, Criterion, criterion_group, criterion_main};
use fixstep::math::{Fx, Real};
use fixstep::scene::Scene;
use fixstep::soft::SoftModel;
use support::bench_ticks;

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

/// Times `ticks` ticks of the cloth from its start in format R.
fn bench_cloth<R: Real>(
    group: &mut criterion::BenchmarkGroup<'_, criterion::measurement::WallTime>,
    bending: bool,
    ticks: u32,
) {
    let label = if bending {
        "cloth64_bending"
    } else {
        "cloth64"
    };
    let id = BenchmarkId::new(label, R::NAME);
    bench_ticks(group, id, &cloth::<R>(bending), ticks);
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
