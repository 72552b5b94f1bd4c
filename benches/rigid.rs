//! Rigid-body step time on the scenes Rapier 0.36 was measured on (docs/PERFORMANCE.md):
//! `pyramid` (210 boxes, 500 steps), `balls` (4096 spheres in a box, 500 steps) and
//! `falling` (1000 free spheres, 1000 steps), and `terrain` (48 bodies down a heightfield
//! into a triangle-mesh bowl, 600 steps), at 60 Hz, one thread. Each sample runs the
//! whole sequence from the scene's start, so settling, piling and sleeping are all in the
//! mean; the figure is the time per step.
//!
//! Every scene runs in I32F32 and, with the same generic code, in `f64`: the baseline
//! measured in the same run. Sleeping is off (as in the Rapier runs) unless the case is
//! named `sleeping`.

mod support;

use criterion::{BenchmarkId, Criterion, criterion_group, criterion_main};
use fixstep::math::{Fx, Real};
use fixstep::scene::Scene;
use fixstep_scenes::builtin_scene;
use support::bench_ticks;

/// The built-in scene `name` in format R, with sleeping on or off.
fn scene<R: Real>(name: &str, sleeping: bool) -> Scene<R> {
    let mut scene = builtin_scene::<R>(name).expect("a built-in scene");
    if let Some(rigid) = &mut scene.rigid {
        rigid.solver.sleeping = sleeping;
    }
    scene
}

/// Times `steps` ticks of `name` from its start in format R, sleeping on or off.
fn bench_scene<R: Real>(
    group: &mut criterion::BenchmarkGroup<'_, criterion::measurement::WallTime>,
    name: &str,
    steps: u32,
    sleeping: bool,
) {
    let label = if sleeping {
        format!("{name}_sleeping")
    } else {
        name.to_owned()
    };
    let id = BenchmarkId::new(label, R::NAME);
    bench_ticks(group, id, &scene::<R>(name, sleeping), steps);
}

fn rigid(c: &mut Criterion) {
    let mut group = c.benchmark_group("rigid_step");
    group.sample_size(10);
    for (name, steps) in [
        ("pyramid", 500),
        ("balls", 500),
        ("falling", 1000),
        ("terrain", 600),
    ] {
        bench_scene::<Fx>(&mut group, name, steps, false);
        bench_scene::<f64>(&mut group, name, steps, false);
    }
    bench_scene::<Fx>(&mut group, "pyramid", 500, true);
    bench_scene::<Fx>(&mut group, "balls", 500, true);
    group.finish();
}

criterion_group!(benches, rigid);
criterion_main!(benches);
