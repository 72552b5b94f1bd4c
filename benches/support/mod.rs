//! What the step benchmarks share: timing a scene's first ticks from a fresh world.

use std::hint::black_box;
use std::time::{Duration, Instant};

use criterion::BenchmarkId;
use criterion::measurement::WallTime;
use fixstep::math::Real;
use fixstep::scene::Scene;
use fixstep::world::{TickInput, World};

/// Benchmarks `scene` as `id`: each iteration builds a fresh world (not timed) and runs
/// `ticks` ticks without inputs; the figure is the time per tick.
pub fn bench_ticks<R: Real>(
    group: &mut criterion::BenchmarkGroup<'_, WallTime>,
    id: BenchmarkId,
    scene: &Scene<R>,
    ticks: u32,
) {
    let empty = TickInput::default();
    group.bench_function(id, |b| {
        b.iter_custom(|iterations| {
            let mut total = Duration::ZERO;
            for _ in 0..iterations {
                let mut world: World<R> = scene.build().expect("the scene builds");
                let start = Instant::now();
                for _ in 0..ticks {
                    black_box(world.step(&empty));
                }
                total += start.elapsed() / ticks;
            }
            total
        })
    });
}
