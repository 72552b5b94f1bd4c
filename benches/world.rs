//! The cost of the tick itself: an empty world, and what an absent subsystem adds.
//!
//! `empty_world` steps a world with no subsystems and no inputs: the floor every scene pays
//! (target: under 100 ns per tick). `absent_particles` is the same world built from a scene
//! whose particle section is absent, through the scene loader, to show that an absent
//! subsystem costs nothing beyond that floor; `empty_particles` has a particle system with
//! no particles, the smallest cost of a present subsystem.

use std::hint::black_box;

use criterion::{Criterion, criterion_group, criterion_main};
use fixstep::math::Fx;
use fixstep::particles::ParticlesDesc;
use fixstep::scene::Scene;
use fixstep::world::{Settings, TickInput, World};

fn tick_cost(c: &mut Criterion) {
    let input = TickInput::<Fx>::default();
    let mut group = c.benchmark_group("tick");

    let settings = Scene::<Fx>::empty("empty");
    let mut empty = World::new(
        Settings {
            gravity: settings.gravity,
            tick_rate: 60,
            substeps: 1,
        },
        1,
    );
    group.bench_function("empty_world", |b| {
        b.iter(|| black_box(empty.step(black_box(&input))))
    });

    let mut absent = Scene::<Fx>::empty("absent").build().expect("valid scene");
    group.bench_function("absent_particles", |b| {
        b.iter(|| black_box(absent.step(black_box(&input))))
    });

    let mut scene = Scene::<Fx>::empty("present");
    scene.particles = Some(ParticlesDesc::default());
    let mut present = scene.build().expect("valid scene");
    group.bench_function("empty_particles", |b| {
        b.iter(|| black_box(present.step(black_box(&input))))
    });
    group.finish();
}

criterion_group!(benches, tick_cost);
criterion_main!(benches);
