//! The cost of coupling (issue [coupling]): `debris` (an emitter keeping about 525 pellets
//! alive, sprayed at a stack of crates; 480 steps at 60 Hz, one thread) with its particles
//! colliding with the bodies and pushing them, against the same scene with the collisions
//! removed (the pellets then fly through everything). Each sample runs the whole sequence
//! from the scene's start; the figure is the time per step, in I32F32 and, with the same
//! generic code, in `f64`.
//!
//! And `flag` (a 13 × 9 cloth tied to a turning kinematic pole and touching the bodies, a
//! 10-link rope tied to a swinging crate; 600 steps), against the same scene with the soft
//! bodies untied and touching nothing (the cloth and rope then fall freely).
//!
//! And `harbour` (1200 water particles at 2.5 cm, a turning paddle, four floating bodies
//! and a sinking crate; 180 steps), against the same scene with the water ignoring the
//! bodies (they then fall through it onto the floor, and the rigid bodies step once a tick
//! instead of at the fluid's rate).

mod support;

use criterion::{BenchmarkId, Criterion, criterion_group, criterion_main};
use fixstep::math::{Fx, Real};
use fixstep::scene::Scene;
use fixstep_scenes::builtin_scene;
use support::bench_ticks;

const STEPS: u32 = 480;

/// `debris` in format R, with or without its particle collisions.
fn debris<R: Real>(collisions: bool) -> Scene<R> {
    let mut scene = builtin_scene::<R>("debris").expect("a built-in scene");
    if !collisions && let Some(particles) = &mut scene.particles {
        particles.collisions.clear();
    }
    scene
}

fn bench_debris<R: Real>(
    group: &mut criterion::BenchmarkGroup<'_, criterion::measurement::WallTime>,
    collisions: bool,
) {
    let label = if collisions {
        "debris"
    } else {
        "debris_without_collisions"
    };
    let id = BenchmarkId::new(label, R::NAME);
    bench_ticks(group, id, &debris::<R>(collisions), STEPS);
}

/// `flag` in format R, with or without its soft bodies' ties and contacts.
fn flag<R: Real>(coupled: bool) -> Scene<R> {
    let mut scene = builtin_scene::<R>("flag").expect("a built-in scene");
    if !coupled && let Some(soft) = &mut scene.soft {
        for body in &mut soft.bodies {
            body.body_attachments.clear();
            body.body_contacts = None;
        }
    }
    scene
}

fn bench_flag<R: Real>(
    group: &mut criterion::BenchmarkGroup<'_, criterion::measurement::WallTime>,
    coupled: bool,
) {
    let label = if coupled { "flag" } else { "flag_uncoupled" };
    let id = BenchmarkId::new(label, R::NAME);
    bench_ticks(group, id, &flag::<R>(coupled), 600);
}

/// `harbour` in format R, with or without the water meeting the bodies.
fn harbour<R: Real>(coupled: bool) -> Scene<R> {
    let mut scene = builtin_scene::<R>("harbour").expect("a built-in scene");
    if !coupled && let Some(fluid) = &mut scene.fluid {
        fluid.bodies = None;
    }
    scene
}

fn bench_harbour<R: Real>(
    group: &mut criterion::BenchmarkGroup<'_, criterion::measurement::WallTime>,
    coupled: bool,
) {
    let label = if coupled {
        "harbour"
    } else {
        "harbour_uncoupled"
    };
    let id = BenchmarkId::new(label, R::NAME);
    bench_ticks(group, id, &harbour::<R>(coupled), 180);
}

fn coupling(c: &mut Criterion) {
    let mut group = c.benchmark_group("coupling_step");
    group.sample_size(10);
    for collisions in [true, false] {
        bench_debris::<Fx>(&mut group, collisions);
        bench_debris::<f64>(&mut group, collisions);
    }
    for coupled in [true, false] {
        bench_flag::<Fx>(&mut group, coupled);
        bench_flag::<f64>(&mut group, coupled);
    }
    for coupled in [true, false] {
        bench_harbour::<Fx>(&mut group, coupled);
        bench_harbour::<f64>(&mut group, coupled);
    }
    group.finish();
}

criterion_group!(benches, coupling);
criterion_main!(benches);
