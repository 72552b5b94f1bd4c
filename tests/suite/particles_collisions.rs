//! Particles colliding with rigid bodies (issue [coupling]): a dropped particle rebounds to
//! e²h (Newton's restitution: the rebound speed is e times the impact speed, and
//! h = v²/2g), on a box and on a level mesh alike; with `push`, particles and bodies
//! exchange momentum and the total is conserved; without it, bodies do not move.

use fixstep::math::{Fx, Real, Vec3};
use fixstep::particles::{CollisionDesc, ForceDesc, Integrator, ParticleDesc, ParticlesDesc};
use fixstep::rigid::{BodyDesc, BodyKind, RigidDesc, Shape, TriMesh};
use fixstep::scene::Scene;
use fixstep::world::{Handle, TickInput, World};

fn v(x: f64, y: f64, z: f64) -> Vec3<Fx> {
    Vec3::new(Fx::from_f64(x), Fx::from_f64(y), Fx::from_f64(z))
}

/// A static floor whose top face is y = 0: a box, or a two-triangle mesh.
fn floor(mesh: bool) -> BodyDesc<Fx> {
    let mut body = if mesh {
        let mesh = TriMesh::new(
            vec![
                v(-2.0, 0.0, -2.0),
                v(2.0, 0.0, -2.0),
                v(2.0, 0.0, 2.0),
                v(-2.0, 0.0, 2.0),
            ],
            vec![[0, 2, 1], [0, 3, 2]],
        )
        .expect("a valid mesh");
        BodyDesc::new(Shape::TriMesh { mesh }, Vec3::ZERO)
    } else {
        BodyDesc::new(
            Shape::Box {
                half_extents: v(2.0, 0.5, 2.0),
            },
            v(0.0, -0.5, 0.0),
        )
    };
    body.kind = BodyKind::Static;
    body
}

/// One particle at height `h` (m) above `body`'s floor, falling under gravity, colliding
/// with restitution `e` and friction 0.
fn drop_scene(h: f64, e: f64, mesh: bool, integrator: Integrator) -> Scene<Fx> {
    let mut scene = Scene::empty("drop");
    scene.ticks = 120;
    let mut collision = CollisionDesc::new(0);
    collision.restitution = Fx::from_f64(e);
    collision.friction = Fx::ZERO;
    scene.particles = Some(ParticlesDesc {
        integrator,
        particles: vec![ParticleDesc {
            position: v(0.1, h, 0.2),
            velocity: Vec3::ZERO,
            mass: Fx::ONE,
            group: 0,
            lifetime: Fx::ZERO,
        }],
        forces: vec![ForceDesc::Gravity {
            scale: Fx::ONE,
            group: None,
        }],
        collisions: vec![collision],
        contacts: None,
        ..ParticlesDesc::default()
    });
    scene.rigid = Some(RigidDesc {
        bodies: vec![floor(mesh)],
        ..RigidDesc::default()
    });
    scene
}

fn particle(world: &World<Fx>) -> (Vec3<Fx>, Vec3<Fx>) {
    let p = world.particles().expect("particles");
    let h = Handle::new(0, 0);
    (p.position(h).expect("alive"), p.velocity(h).expect("alive"))
}

/// The highest point the particle reaches after its first bounce, m.
fn rebound_height(scene: &Scene<Fx>) -> f64 {
    let mut world = scene.build().expect("builds");
    let mut bounced = false;
    let mut highest = f64::NEG_INFINITY;
    for _ in 0..scene.ticks {
        world.step(&TickInput::default());
        let (x, velocity) = particle(&world);
        assert!(x.y >= Fx::ZERO, "the particle passed into the floor: {x:?}");
        if velocity.y > Fx::ZERO {
            bounced = true;
        }
        if bounced {
            highest = highest.max(x.y.to_f64());
            if velocity.y < Fx::ZERO && x.y.to_f64() < highest - 0.05 {
                break;
            }
        }
    }
    assert!(bounced, "the particle never bounced");
    highest
}

#[test]
fn a_dropped_particle_rebounds_to_e_squared_h() {
    let h = 1.0;
    for mesh in [false, true] {
        for e in [0.25, 0.5, 0.8] {
            // Second- and fourth-order schemes follow a parabola exactly, so what is measured
            // is the bounce; a first-order scheme's apex lags by v Δt/2 on its own.
            for integrator in [Integrator::VelocityVerlet, Integrator::Rk4] {
                let got = rebound_height(&drop_scene(h, e, mesh, integrator));
                let want = e * e * h;
                eprintln!("e = {e}, mesh {mesh}, {integrator:?}: rebound {got:.5} m, e²h {want} m");
                assert!(
                    (got - want).abs() <= 0.02 * want,
                    "e = {e}, mesh {mesh}, {integrator:?}: rebound {got} m, e²h = {want} m"
                );
            }
        }
    }
}

#[test]
fn an_inelastic_particle_comes_to_rest_on_the_floor() {
    let mut scene = drop_scene(0.5, 0.0, true, Integrator::SemiImplicitEuler);
    scene.ticks = 90;
    let mut world = scene.build().expect("builds");
    for _ in 0..scene.ticks {
        world.step(&TickInput::default());
    }
    let (x, velocity) = particle(&world);
    assert!(x.y >= Fx::ZERO && x.y.to_f64() < 1e-3, "resting at {x:?}");
    assert!(
        velocity.y.to_f64().abs() < 0.2,
        "still moving: {velocity:?}"
    );
}

/// `count` particles of 0.1 kg in zero gravity flying at 5 m/s into a free 2 kg box, the
/// group pushing bodies or not.
fn stream_scene(push: bool) -> Scene<Fx> {
    let mut scene = Scene::empty("stream");
    scene.gravity = Vec3::ZERO;
    scene.ticks = 60;
    let mut collision = CollisionDesc::new(0);
    collision.push = push;
    collision.restitution = Fx::from_f64(0.5);
    let particles = (0..20)
        .map(|k| ParticleDesc {
            position: v(
                -1.0 - 0.05 * f64::from(k),
                0.1 * f64::from(k % 5) - 0.2,
                0.0,
            ),
            velocity: v(5.0, 0.0, 0.0),
            mass: Fx::from_f64(0.1),
            group: 0,
            lifetime: Fx::ZERO,
        })
        .collect();
    scene.particles = Some(ParticlesDesc {
        particles,
        collisions: vec![collision],
        contacts: None,
        ..ParticlesDesc::default()
    });
    let mut target = BodyDesc::new(
        Shape::Box {
            half_extents: v(0.25, 0.5, 0.5),
        },
        Vec3::ZERO,
    );
    target.density = Fx::from_f64(4.0); // 0.5 × 1 × 1 m³ at 4 kg/m³: 2 kg
    scene.rigid = Some(RigidDesc {
        bodies: vec![target],
        ..RigidDesc::default()
    });
    scene
}

/// The total momentum of particles and bodies, kg·m/s.
fn momentum(world: &World<Fx>) -> [f64; 3] {
    let metrics = world.metrics();
    metrics.momentum
}

#[test]
fn pushing_particles_conserve_momentum_with_the_body() {
    let scene = stream_scene(true);
    let mut world = scene.build().expect("builds");
    let before = momentum(&world);
    for _ in 0..scene.ticks {
        world.step(&TickInput::default());
    }
    let after = momentum(&world);
    let box_velocity = world
        .rigid()
        .expect("rigid bodies")
        .linear_velocity(Handle::new(0, 0))
        .expect("alive");
    // 20 particles × 0.1 kg × 5 m/s = 10 kg·m/s; the box took a share of it.
    assert!(
        box_velocity.x.to_f64() > 1.0,
        "the box was barely pushed: {box_velocity:?}"
    );
    for k in 0..3 {
        assert!(
            (after[k] - before[k]).abs() < 1e-3 * 10.0,
            "momentum {k}: {} before, {} after",
            before[k],
            after[k]
        );
    }
}

#[test]
fn particles_that_do_not_push_leave_the_body_still() {
    let scene = stream_scene(false);
    let mut world = scene.build().expect("builds");
    for _ in 0..scene.ticks {
        world.step(&TickInput::default());
    }
    let rigid = world.rigid().expect("rigid bodies");
    assert_eq!(
        rigid.linear_velocity(Handle::new(0, 0)).expect("alive"),
        Vec3::ZERO
    );
    // ...and every particle bounced back off it.
    let particles = world.particles().expect("particles");
    for (k, velocity) in particles.velocities().iter().enumerate() {
        assert!(
            velocity.x < Fx::ZERO,
            "particle {k} did not bounce: {velocity:?}"
        );
    }
}

#[test]
fn debris_restored_mid_contact_continues_like_an_uninterrupted_run() {
    // At tick 70 pellets have been striking the crates for a few ticks.
    let reference = crate::restore_support::restored_mid_run_continues("debris", 150, 70);
    let particles = reference.particles().expect("particles");
    assert!(particles.alive().iter().filter(|&&a| a).count() > 100);
}

/// A kinematic wall moving at u = 2 m/s meets a particle at rest (no gravity): the particle
/// leaves at u + e u = (1 + e) u, Newton's restitution in the wall's frame, and stays ahead
/// of the wall.
#[test]
fn a_moving_kinematic_wall_bats_a_particle_away_at_one_plus_e_times_its_speed() {
    let e = 0.5;
    let mut scene = Scene::empty("bat");
    scene.gravity = Vec3::ZERO;
    scene.ticks = 60;
    let mut collision = CollisionDesc::new(0);
    collision.restitution = Fx::from_f64(e);
    scene.particles = Some(ParticlesDesc {
        particles: vec![ParticleDesc {
            position: v(1.0, 0.0, 0.0),
            velocity: Vec3::ZERO,
            mass: Fx::ONE,
            group: 0,
            lifetime: Fx::ZERO,
        }],
        collisions: vec![collision],
        contacts: None,
        ..ParticlesDesc::default()
    });
    let mut wall = BodyDesc::new(
        Shape::Box {
            half_extents: v(0.1, 1.0, 1.0),
        },
        Vec3::ZERO,
    );
    wall.kind = BodyKind::Kinematic;
    wall.velocity = v(2.0, 0.0, 0.0);
    scene.rigid = Some(RigidDesc {
        bodies: vec![wall],
        ..RigidDesc::default()
    });
    let mut world = scene.build().expect("builds");
    for _ in 0..scene.ticks {
        world.step(&TickInput::default());
        let (x, _) = particle(&world);
        let wall_x = world
            .rigid()
            .expect("rigid bodies")
            .position(Handle::new(0, 0))
            .expect("alive")
            .x;
        assert!(
            x.x >= wall_x + Fx::from_f64(0.1),
            "the wall overtook the particle"
        );
    }
    let (_, velocity) = particle(&world);
    let want = (1.0 + e) * 2.0;
    assert!(
        (velocity.x.to_f64() - want).abs() < 1e-3,
        "leaves at {velocity:?}, (1 + e) u = {want} m/s"
    );
}
