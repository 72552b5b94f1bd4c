//! Particle throughput: one semi-implicit Euler step of 10⁶ particles under gravity and
//! linear drag, through the engine's own `ParticleSystem::step`, in I32F32 and, with the same
//! generic code, in `f64`. Reported as particle-steps per second (criterion's element
//! throughput); the I32F32 / `f64` time ratio is the figure in docs/PERFORMANCE.md (goal
//! ≤ 1.5).
//!
//! The particles start spread over a cube with varied velocities, so that no value is a
//! constant the compiler could fold; the drag keeps speeds bounded over the benchmark's
//! thousands of steps.

use std::hint::black_box;

use criterion::{BenchmarkId, Criterion, Throughput, criterion_group, criterion_main};
use fixstep::math::rng::Pcg32;
use fixstep::math::{Fx, Real, Vec3};
use fixstep::particles::{ForceDesc, Integrator, ParticleDesc, ParticleSystem, ParticlesDesc};

/// Particles per system.
const PARTICLES: u32 = 1_000_000;

/// A system of [`PARTICLES`] 1 kg particles with gravity and linear drag (k = 0.1 kg/s).
fn system<R: Real>() -> ParticleSystem<R> {
    let mut rng = Pcg32::new(7, 11);
    let mut within = |half: i32| {
        let (lo, hi) = (R::from_int(-half), R::from_int(half));
        Vec3::new(rng.range(lo, hi), rng.range(lo, hi), rng.range(lo, hi))
    };
    let particles = (0..PARTICLES)
        .map(|_| ParticleDesc {
            position: within(50),
            velocity: within(5),
            mass: R::ONE,
            group: 0,
            lifetime: R::ZERO,
        })
        .collect();
    let desc = ParticlesDesc {
        integrator: Integrator::SemiImplicitEuler,
        capacity: PARTICLES,
        particles,
        forces: vec![
            ForceDesc::Gravity {
                scale: R::ONE,
                group: None,
            },
            ForceDesc::LinearDrag {
                coefficient: R::from_ratio(1, 10),
                group: None,
            },
        ],
        ..ParticlesDesc::default()
    };
    ParticleSystem::from_desc(&desc).expect("valid system")
}

fn bench_format<R: Real>(
    group: &mut criterion::BenchmarkGroup<'_, criterion::measurement::WallTime>,
) {
    let mut particles = system::<R>();
    let dt = R::from_ratio(1, 60);
    let gravity = Vec3::new(R::ZERO, R::from_ratio(-981, 100), R::ZERO);
    let mut rng = Pcg32::new(1, 1);
    group.bench_function(
        BenchmarkId::new("semi_implicit_euler_gravity_drag", R::NAME),
        |b| b.iter(|| black_box(particles.step(black_box(dt), gravity, &mut rng))),
    );
}

fn throughput(c: &mut Criterion) {
    let mut group = c.benchmark_group("particles_1e6");
    group.throughput(Throughput::Elements(u64::from(PARTICLES)));
    group.sample_size(20);
    bench_format::<Fx>(&mut group);
    bench_format::<f64>(&mut group);
    group.finish();
}

criterion_group!(benches, throughput);
criterion_main!(benches);
