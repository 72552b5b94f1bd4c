//! Joint solver time on Box2D's joint-grid benchmark in 3D
//! ([`joint_grid`](fixstep_scenes::joints::joint_grid)): 100 × 100 balls on
//! 19,800 ball joints hanging from seven static balls, 60 Hz, one thread, sleeping off,
//! timed over its first 60 steps from rest (each sample builds the grid afresh). Box2D v3
//! reports about 3.95 ms per step for its 2D revolute version on a Ryzen 9950X3D, with the
//! grid's collisions filtered out; here the balls collide once the grid folds.
//!
//! The baseline in the same run is the same generic code instantiated for `f64`.

mod support;

use criterion::{BenchmarkId, Criterion, criterion_group, criterion_main};
use fixstep::math::{Fx, Real};
use fixstep::scene::Scene;
use fixstep_scenes::joints::joint_grid;
use support::bench_ticks;

fn grid<R: Real>(n: u32) -> Scene<R> {
    let (mut rigid, joints) = joint_grid::<R>(n);
    rigid.solver.sleeping = false;
    let mut scene = Scene::empty("joint_grid");
    scene.rigid = Some(rigid);
    scene.joints = Some(joints);
    scene
}

fn bench_grid<R: Real>(
    group: &mut criterion::BenchmarkGroup<'_, criterion::measurement::WallTime>,
    n: u32,
    steps: u32,
) {
    let id = BenchmarkId::new(format!("grid_{n}x{n}"), R::NAME);
    bench_ticks(group, id, &grid::<R>(n), steps);
}

fn joints(c: &mut Criterion) {
    let mut group = c.benchmark_group("joint_step");
    group.sample_size(10);
    bench_grid::<Fx>(&mut group, 100, 60);
    bench_grid::<f64>(&mut group, 100, 60);
    group.finish();
}

criterion_group!(benches, joints);
criterion_main!(benches);
