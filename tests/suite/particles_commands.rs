//! The command methods: targets, stale handles, slot recycling and the lifetime of external
//! forces.

use fixstep::math::rng::Pcg32;
use fixstep::math::{Fx, Real, Vec3};
use fixstep::particles::{
    Integrator, ParticleDesc, ParticleSystem, ParticleTemplate, ParticlesDesc,
};
use fixstep::world::Handle;
use fixstep::world::Target;

fn particle(x: i32, mass: Fx, group: u16) -> ParticleDesc<Fx> {
    ParticleDesc {
        position: Vec3::new(Fx::from_int(x), Fx::ZERO, Fx::ZERO),
        velocity: Vec3::ZERO,
        mass,
        group,
        lifetime: Fx::ZERO,
    }
}

/// Five 1 kg particles in slots 0–4 (groups 0, 1, 0, 1, 0), a pinned one in slot 5, and one
/// template.
fn row(integrator: Integrator) -> ParticleSystem<Fx> {
    let mut particles: Vec<_> = (0..5)
        .map(|i| particle(i, Fx::ONE, (i % 2) as u16))
        .collect();
    particles.push(particle(10, Fx::ZERO, 7));
    ParticleSystem::from_desc(&ParticlesDesc {
        integrator,
        capacity: 8,
        particles,
        templates: vec![ParticleTemplate {
            mass: Fx::TWO,
            group: 3,
            lifetime: Fx::ZERO,
        }],
        ..ParticlesDesc::default()
    })
    .unwrap()
}

fn one(index: u32, generation: u32) -> Target {
    Target::Particle(Handle::new(index, generation))
}

/// Freed slots are reused lowest index first, with a new generation; only then does the
/// storage grow, up to the capacity.
#[test]
fn recycling_takes_the_lowest_free_slot() {
    let mut s = row(Integrator::SemiImplicitEuler);
    assert!(s.remove(one(3, 0)));
    assert!(s.remove(one(1, 0)));
    let spawn = |s: &mut ParticleSystem<Fx>| s.spawn(0, Vec3::ZERO, Vec3::ZERO);
    assert_eq!(spawn(&mut s), Some(Handle::new(1, 1)));
    assert_eq!(spawn(&mut s), Some(Handle::new(3, 1)));
    assert_eq!(spawn(&mut s), Some(Handle::new(6, 0)));
    assert_eq!(spawn(&mut s), Some(Handle::new(7, 0)));
    assert_eq!(spawn(&mut s), None, "capacity 8 reached");
    assert_eq!(s.live_count(), 8);
    assert_eq!(
        s.handles().map(|h| h.index).collect::<Vec<_>>(),
        (0..8).collect::<Vec<_>>()
    );
    assert_eq!(s.mass(Handle::new(1, 1)), Some(Fx::TWO));
    assert_eq!(s.group(Handle::new(3, 1)), Some(3));
}

/// Every command on a removed particle's handle reports that nothing matched, even after
/// its slot was reused.
#[test]
fn stale_handles_match_nothing() {
    let mut s = row(Integrator::SemiImplicitEuler);
    let stale = one(2, 0);
    assert!(s.remove(stale));
    assert!(!s.remove(stale));
    assert_eq!(s.spawn(0, Vec3::ZERO, Vec3::ZERO), Some(Handle::new(2, 1)));
    let v = Vec3::new(Fx::ONE, Fx::ZERO, Fx::ZERO);
    assert!(!s.apply_force(stale, v));
    assert!(!s.apply_impulse(stale, v));
    assert!(!s.set_velocity(stale, v));
    assert!(!s.move_pinned(stale, v));
    assert!(!s.remove(stale));
    assert!(!s.is_alive(Handle::new(2, 0)));
    assert_eq!(s.position(Handle::new(2, 0)), None);
    // Out of range and never allocated.
    assert!(!s.apply_force(one(40, 0), v));
    assert!(!s.set_velocity(Target::ParticleGroup(9), v));
    assert_eq!(s.spawn(1, Vec3::ZERO, Vec3::ZERO), None, "no template 1");
    assert!(!s.set_emitter(0, true), "no emitters");
}

/// An external force acts in every substep of the tick it was applied in and is gone after
/// `end_tick`: with F = 2 N on 1 kg, two substeps of 1/4 s give Δv = 2·(F/m)·h = 1 m/s, and
/// the next tick adds nothing. Exact up to the rounding of h/6 in RK4's weights (1/24 is not
/// dyadic: at most 12 × ½ ulp per step, two steps).
#[test]
fn external_forces_last_one_tick() {
    let close = |v: Fx| (v - Fx::ONE).abs() <= Fx::from_bits(12);
    for integrator in Integrator::ALL {
        let mut s = row(integrator);
        let h = Fx::from_ratio(1, 4);
        let mut rng = Pcg32::new(1, 1);
        assert!(s.apply_force(one(0, 0), Vec3::new(Fx::ONE, Fx::ZERO, Fx::ZERO)));
        assert!(s.apply_force(one(0, 0), Vec3::new(Fx::ONE, Fx::ZERO, Fx::ZERO)));
        s.step(h, Vec3::ZERO, &mut rng);
        s.step(h, Vec3::ZERO, &mut rng);
        s.end_tick();
        let after_force = s.velocity(Handle::new(0, 0)).unwrap().x;
        assert!(close(after_force), "{integrator}: {after_force}");
        s.step(h, Vec3::ZERO, &mut rng);
        s.step(h, Vec3::ZERO, &mut rng);
        s.end_tick();
        assert_eq!(
            s.velocity(Handle::new(0, 0)).unwrap().x,
            after_force,
            "{integrator}"
        );
        assert_eq!(
            s.velocity(Handle::new(1, 0)).unwrap(),
            Vec3::ZERO,
            "{integrator}"
        );
    }
}

/// Δv = J/m for an impulse; set_velocity on a group touches only that group; pinned
/// particles do not move under either but still count as matched.
#[test]
fn impulses_velocities_and_groups() {
    let mut s = row(Integrator::VelocityVerlet);
    let j = Vec3::new(Fx::ZERO, Fx::from_int(3), Fx::ZERO);
    assert!(s.apply_impulse(one(0, 0), j));
    assert_eq!(s.velocity(Handle::new(0, 0)), Some(j));
    let spawned = s.spawn(0, Vec3::ZERO, Vec3::ZERO).unwrap();
    assert!(s.apply_impulse(Target::Particle(spawned), j));
    assert_eq!(s.velocity(spawned), Some(j * Fx::HALF), "2 kg template");

    let v = Vec3::new(Fx::ONE, Fx::TWO, Fx::ZERO);
    assert!(s.set_velocity(Target::ParticleGroup(1), v));
    for i in 0..5 {
        let expected = if i % 2 == 1 {
            v
        } else if i == 0 {
            j
        } else {
            Vec3::ZERO
        };
        assert_eq!(s.velocity(Handle::new(i, 0)), Some(expected), "slot {i}");
    }
    let pinned = one(5, 0);
    assert!(s.set_velocity(pinned, v));
    assert!(s.apply_impulse(pinned, v));
    assert!(s.apply_force(pinned, v));
    let mut rng = Pcg32::new(1, 1);
    s.step(Fx::ONE, Vec3::ZERO, &mut rng);
    assert_eq!(s.velocity(Handle::new(5, 0)), Some(Vec3::ZERO));
    assert_eq!(
        s.position(Handle::new(5, 0)),
        Some(Vec3::new(Fx::from_int(10), Fx::ZERO, Fx::ZERO))
    );
}

/// move_pinned moves pinned particles only.
#[test]
fn moving_pinned_points() {
    let mut s = row(Integrator::StormerVerlet);
    let target = Vec3::new(Fx::ONE, Fx::ONE, Fx::ONE);
    assert!(!s.move_pinned(one(0, 0), target), "slot 0 is not pinned");
    assert!(s.move_pinned(Target::ParticleGroup(7), target));
    assert_eq!(s.position(Handle::new(5, 0)), Some(target));
    let mut rng = Pcg32::new(1, 1);
    s.step(Fx::ONE, Vec3::ZERO, &mut rng);
    assert_eq!(s.position(Handle::new(5, 0)), Some(target));
}

/// A removed group frees all its slots at once.
#[test]
fn removing_a_group() {
    let mut s = row(Integrator::Rk4);
    assert!(s.remove(Target::ParticleGroup(0)));
    assert_eq!(s.live_count(), 3);
    assert!(!s.remove(Target::ParticleGroup(0)));
    assert_eq!(s.spawn(0, Vec3::ZERO, Vec3::ZERO), Some(Handle::new(0, 1)));
    assert_eq!(Real::to_f64(s.kinetic_energy()), 0.0);
}
