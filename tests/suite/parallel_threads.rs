//! Multithreaded stepping gives the bits of one thread ([`fixstep::parallel`]): the committed
//! replays verify at 2, 3, 4 and 8 threads (1 is `replay_committed`), random scenes give the
//! same checksums at every count and through mid-run changes of the count and snapshot
//! restores, and a debug build with the pool oversubscribed (8 threads on a 2-core CI
//! machine) gives them too.

use std::path::Path;
#[cfg(not(debug_assertions))]
use std::path::PathBuf;

use fixstep::fluid::FluidSolver;
use fixstep::math::rng::Pcg32;
use fixstep::math::{Fx, Real, Vec3};
use fixstep::particles::{ForceDesc, Integrator, ParticleDesc, ParticlesDesc};
use fixstep::replay::{Replay, VerifyOutcome, verify_on_threads};
use fixstep::rigid::Shape;
use fixstep::scene::Scene;
use proptest::prelude::*;

use super::property_cases::fixed_cases;

fn replay(name: &str) -> Replay {
    let path = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("replays")
        .join(format!("{name}.replay"));
    Replay::read(&path).unwrap_or_else(|e| panic!("{e}"))
}

#[cfg(not(debug_assertions))]
fn committed_replays() -> Vec<PathBuf> {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("replays");
    let mut files: Vec<PathBuf> = std::fs::read_dir(dir)
        .expect("replays/ exists")
        .map(|entry| entry.expect("readable entry").path())
        .filter(|path| path.extension().is_some_and(|e| e == "replay"))
        .collect();
    files.sort();
    files
}

fn assert_verifies(replay: &Replay, name: &str, threads: usize) {
    let outcome = verify_on_threads(replay, threads).unwrap_or_else(|e| panic!("{name}: {e}"));
    assert_eq!(
        outcome,
        VerifyOutcome::Ok {
            ticks: replay.ticks(),
            checksum: replay.final_checksum(),
        },
        "{name} on {threads} threads"
    );
}

/// Every committed replay at 2 and 8 threads (release only: the debug run has the
/// oversubscribed case below, and one thread is `replay_committed`'s).
#[cfg(not(debug_assertions))]
#[test]
fn every_committed_replay_verifies_at_2_and_8_threads() {
    for path in committed_replays() {
        let replay = Replay::read(&path).unwrap_or_else(|e| panic!("{e}"));
        for threads in [2, 8] {
            assert_verifies(&replay, &path.display().to_string(), threads);
        }
    }
}

/// The replays whose stages split their loops (over 256 contact pairs, or many files) at 3
/// and 4 threads, where chunks fall unevenly on the workers.
#[cfg(not(debug_assertions))]
#[test]
fn split_loops_verify_at_3_and_4_threads() {
    for name in [
        "balls", "pyramid", "falling", "harbour", "cloth", "curtain", "flag", "jelly",
    ] {
        let replay = replay(name);
        for threads in [3, 4] {
            assert_verifies(&replay, name, threads);
        }
    }
}

/// The debug build (its overflow checks on) with 8 threads, more than CI's 2 cores: the
/// recorded bits of `balls` (a pile of a thousand contact pairs and more).
#[cfg(debug_assertions)]
#[test]
fn an_oversubscribed_debug_run_gives_the_recorded_bits() {
    assert_verifies(&replay("balls"), "balls", 8);
}

/// A pile of `n`³ bodies of one random shape dropped into the `balls` box from a lattice of
/// random spacing (close enough to start touching); or, when `fluid` gives a number, a
/// cube of water with that many particles along a side (DFSPH).
fn random_scene(shape: u8, n: u32, spacing: i64, seed: u64, fluid: Option<u32>) -> Scene<Fx> {
    let mut rigid = fixstep_scenes::rigid::balls::<Fx>(n);
    let lattice = rigid.bodies.last_mut().expect("the lattice");
    lattice.shape = match shape {
        0 => Shape::Sphere { radius: Fx::HALF },
        1 => Shape::Box {
            half_extents: Vec3::splat(Fx::from_ratio(45, 100)),
        },
        _ => Shape::Capsule {
            radius: Fx::from_ratio(3, 10),
            half_height: Fx::from_ratio(2, 10),
        },
    };
    if let Some(grid) = &mut lattice.grid {
        grid.spacing = Vec3::splat(Fx::from_ratio(spacing, 100));
    }
    let mut scene = Scene::empty("random");
    scene.seed = seed;
    scene.rigid = Some(rigid);
    if let Some(per_side) = fluid {
        scene.fluid = Some(fixstep_scenes::fluid::tank::<Fx>(
            per_side,
            FluidSolver::Dfsph,
        ));
        scene.rigid = None;
    }
    scene
}

/// The checksums after each of `ticks` ticks of `scene`, stepping on `schedule[t %
/// schedule.len()]` threads at tick t, and, at tick `restore_at`, restoring the snapshot
/// taken at tick `restore_at / 2` and running those ticks again.
fn checksums(scene: &Scene<Fx>, ticks: u64, schedule: &[usize], restore_at: u64) -> Vec<u64> {
    let mut world = scene.build().unwrap_or_else(|e| panic!("{e}"));
    let mut sums = Vec::new();
    let mut snapshot = None;
    let mut restored = false;
    let empty = Default::default();
    while world.tick() < ticks {
        let tick = world.tick();
        if tick == restore_at / 2 && !restored {
            snapshot = Some(world.snapshot());
        }
        if tick == restore_at
            && let Some(state) = snapshot.take()
        {
            world.restore(&state);
            restored = true;
            sums.truncate(world.tick() as usize);
            continue;
        }
        world.set_threads(schedule[tick as usize % schedule.len()]);
        world.step(&empty);
        sums.push(world.checksum().total);
    }
    sums
}

proptest! {
    #![proptest_config(fixed_cases(if cfg!(debug_assertions) { 2 } else { 5 }))]

    /// Random scenes give one thread's checksum after every tick at 2, 3, 4 and 8 threads,
    /// with the count changed at every tick and a snapshot restored mid-run.
    #[test]
    fn random_scenes_give_the_same_checksums_at_every_thread_count(
        shape in 0u8..3,
        n in 7u32..10,
        spacing in 90i64..110,
        seed in any::<u64>(),
        fluid in prop::option::weighted(0.3, 11u32..14),
        schedule in prop::collection::vec(prop::sample::select(vec![1usize, 2, 3, 4, 8]), 1..5),
        restore_at in 2u64..12,
    ) {
        let scene = random_scene(shape, n, spacing, seed, fluid);
        let ticks = if cfg!(debug_assertions) { 5 } else { 12 };
        let reference = checksums(&scene, ticks, &[1], u64::MAX);
        for threads in [2, 3, 4, 8] {
            prop_assert_eq!(&checksums(&scene, ticks, &[threads], u64::MAX), &reference);
        }
        prop_assert_eq!(&checksums(&scene, ticks, &schedule, restore_at), &reference);
    }
}

/// An `n` × `n` XPBD cloth (its rows split into runs solved side by side, its vertices
/// predicted in chunks) beside `particles` particles under gravity and linear drag (the
/// fused Euler step, in chunks of blocks), seeded by `seed`.
fn soft_and_particles(n: u32, particles: u32, seed: u64) -> Scene<Fx> {
    let mut rng = Pcg32::new(seed, 3);
    let mut within = |half: i32| {
        let (lo, hi) = (Fx::from_int(-half), Fx::from_int(half));
        Vec3::new(rng.range(lo, hi), rng.range(lo, hi), rng.range(lo, hi))
    };
    let particles = ParticlesDesc {
        integrator: Integrator::SemiImplicitEuler,
        capacity: particles,
        particles: (0..particles)
            .map(|_| ParticleDesc {
                position: within(50),
                velocity: within(5),
                mass: Fx::ONE,
                group: 0,
                lifetime: Fx::ZERO,
            })
            .collect(),
        forces: vec![
            ForceDesc::Gravity {
                scale: Fx::ONE,
                group: None,
            },
            ForceDesc::LinearDrag {
                coefficient: Fx::from_ratio(1, 10),
                group: None,
            },
        ],
        ..ParticlesDesc::default()
    };
    let mut scene = Scene::empty("soft and particles");
    scene.seed = seed;
    let mut cloth = fixstep_scenes::soft::cloth::<Fx>(n);
    cloth.solver.substeps = 4;
    scene.soft = Some(cloth);
    scene.particles = Some(particles);
    scene
}

proptest! {
    #![proptest_config(fixed_cases(if cfg!(debug_assertions) { 1 } else { 3 }))]

    /// A cloth and a cloud of particles give one thread's checksum after every tick at 2,
    /// 3, 4 and 8 threads, with the count changed at every tick and a snapshot restored
    /// mid-run.
    #[test]
    fn soft_and_particles_give_the_same_checksums_at_every_thread_count(
        n in 40u32..64,
        particles in 1500u32..5000,
        seed in any::<u64>(),
        schedule in prop::collection::vec(prop::sample::select(vec![1usize, 2, 3, 4, 8]), 1..5),
        restore_at in 2u64..8,
    ) {
        let scene = soft_and_particles(n, particles, seed);
        let ticks = if cfg!(debug_assertions) { 3 } else { 8 };
        let reference = checksums(&scene, ticks, &[1], u64::MAX);
        for threads in [2, 3, 4, 8] {
            prop_assert_eq!(&checksums(&scene, ticks, &[threads], u64::MAX), &reference);
        }
        prop_assert_eq!(&checksums(&scene, ticks, &schedule, restore_at), &reference);
    }
}
