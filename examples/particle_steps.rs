//! The particle benchmark's system (`benches/particles.rs`) stepped a given number of times,
//! for `perf stat`: `particle_steps FORMAT STEPS [COUNT]`, FORMAT `I32F32` or `f64`, COUNT
//! particles (10⁶ by default, as in the benchmark). The cost of one step is the difference
//! between two step counts, so that setup cancels out:
//!
//! ```text
//! perf stat -e instructions:u,cycles:u target/release/examples/particle_steps I32F32 60
//! perf stat -e instructions:u,cycles:u target/release/examples/particle_steps I32F32 10
//! ```
//!
//! It prints a digest of the final positions and velocities, the same for every build that
//! gives the same bits.

use fixstep::math::rng::Pcg32;
use fixstep::math::{Fx, Real, Vec3};
use fixstep::particles::{ForceDesc, Integrator, ParticleDesc, ParticleSystem, ParticlesDesc};

/// The benchmark's system: `count` particles of 1 kg under gravity and linear drag.
fn system<R: Real>(count: u32) -> ParticleSystem<R> {
    let mut rng = Pcg32::new(7, 11);
    let mut within = |half: i32| {
        let (lo, hi) = (R::from_int(-half), R::from_int(half));
        Vec3::new(rng.range(lo, hi), rng.range(lo, hi), rng.range(lo, hi))
    };
    let particles = (0..count)
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
        capacity: count,
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

fn run<R: Real>(steps: u32, count: u32) {
    let mut particles = system::<R>(count);
    let dt = R::from_ratio(1, 60);
    let gravity = Vec3::new(R::ZERO, R::from_ratio(-981, 100), R::ZERO);
    let mut rng = Pcg32::new(1, 1);
    for _ in 0..steps {
        std::hint::black_box(particles.step(std::hint::black_box(dt), gravity, &mut rng));
    }
    let digest = particles
        .positions()
        .iter()
        .chain(particles.velocities())
        .fold(0u64, |digest, v| {
            [v.x, v.y, v.z]
                .iter()
                .fold(digest, |d, c| d.rotate_left(5) ^ c.canonical_bits())
        });
    println!("{steps} steps of {}: {digest:016x}", R::NAME);
}

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let steps = args.get(2).and_then(|s| s.parse().ok()).unwrap_or(10);
    let count = args
        .get(3)
        .and_then(|s| s.parse().ok())
        .unwrap_or(1_000_000);
    match args.get(1).map(String::as_str) {
        Some("f64") => run::<f64>(steps, count),
        _ => run::<Fx>(steps, count),
    }
}
