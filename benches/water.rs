//! Height-field water step time: a 256 × 256 surface (65 536 cells, 130 560 edges), 8 cm
//! cells, 0.5 m deep (one wave step per tick at 60 Hz), reflective borders, nothing
//! floating. Each sample runs 60 ticks from the start and reports the time per tick.
//!
//! The same generic code runs in I32F32 and in `f64`, measured in the same run.

mod support;

use criterion::{BenchmarkId, Criterion, criterion_group, criterion_main};
use fixstep::math::{Fx, Real, Vec3};
use fixstep::scene::Scene;
use fixstep::water::{WaterBorder, WaterDesc};
use support::bench_ticks;

/// The 256 × 256 surface in format R.
fn surface<R: Real>() -> Scene<R> {
    let mut scene = Scene::empty("water256");
    scene.water_surface = Some(WaterDesc {
        origin: Vec3::new(-R::from_int(10), R::ZERO, -R::from_int(10)),
        cells: (256, 256),
        cell_size: R::from_ratio(2, 25),
        depth: R::HALF,
        wave_speed: None,
        damping: R::from_ratio(1, 10),
        density: R::from_int(1000),
        border: WaterBorder::Reflective,
        particles: Vec::new(),
        bodies: None,
    });
    scene
}

fn water(c: &mut Criterion) {
    let mut group = c.benchmark_group("water_step");
    group.sample_size(10);
    bench_ticks(
        &mut group,
        BenchmarkId::new("surface256", Fx::NAME),
        &surface::<Fx>(),
        60,
    );
    bench_ticks(
        &mut group,
        BenchmarkId::new("surface256", f64::NAME),
        &surface::<f64>(),
        60,
    );
    group.finish();
}

criterion_group!(benches, water);
criterion_main!(benches);
