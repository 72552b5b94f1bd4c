//! The `debris` scene: particles colliding with rigid bodies. An emitter sprays 100 g pellets
//! at a stack of cardboard crates standing on the ground beside a static ledge; the pellets
//! bounce off the crates, the ledge and the ground (restitution 0.3, friction 0.4) and push
//! the crates back with every bounce, until the stack is knocked down.

use fixstep::math::{Real, Vec3};
use fixstep::particles::{
    CollisionDesc, EmitterDesc, ForceDesc, Integrator, Interval, ParticlesDesc, Spread,
};
use fixstep::rigid::{BodyDesc, Grid, RigidDesc, Shape};

use super::rigid::ground;

/// The bodies: the ground; a stack of six 40 cm cardboard crates of 50 kg/m³ (3.2 kg each) at the
/// origin; a static ledge 3 m long, 1 m high and 40 cm thick behind it, at x = 2 m.
pub fn debris_bodies<R: Real>() -> RigidDesc<R> {
    let crate_half = R::from_ratio(1, 5);
    let mut stack = BodyDesc::new(
        Shape::Box {
            half_extents: Vec3::splat(crate_half),
        },
        Vec3::new(R::ZERO, crate_half, R::ZERO),
    );
    stack.density = R::from_int(50);
    stack.grid = Some(Grid {
        count: (1, 6, 1),
        spacing: Vec3::new(R::ZERO, crate_half * R::TWO, R::ZERO),
    });
    let ledge = BodyDesc::new(
        Shape::Box {
            half_extents: Vec3::new(R::from_ratio(1, 5), R::HALF, R::from_ratio(3, 2)),
        },
        Vec3::new(R::TWO, R::HALF, R::ZERO),
    )
    .fixed();
    RigidDesc {
        bodies: vec![ground(), ledge, stack],
        ..RigidDesc::default()
    }
}

/// The pellets: one emitter at (−4, 1.2, 0) m spraying 250 pellets of 100 g a second along
/// +x (a 0.12 rad cone, 8–10 m/s, living 2–3 s), under gravity, velocity Verlet; group 0
/// collides with every body and pushes it.
pub fn debris_pellets<R: Real>() -> ParticlesDesc<R> {
    let mut collision = CollisionDesc::new(0);
    collision.restitution = R::from_ratio(3, 10);
    collision.friction = R::from_ratio(2, 5);
    collision.push = true;
    ParticlesDesc {
        integrator: Integrator::VelocityVerlet,
        capacity: 1024,
        emitters: vec![EmitterDesc {
            position: Vec3::new(-R::from_int(4), R::from_ratio(6, 5), R::ZERO),
            rate: R::from_int(250),
            spread: Spread::Cone {
                axis: Vec3::new(R::ONE, R::from_ratio(1, 10), R::ZERO),
                half_angle: R::from_ratio(12, 100),
            },
            speed: Interval::new(R::from_int(8), R::from_int(10)),
            lifetime: Interval::new(R::TWO, R::from_int(3)),
            mass: R::from_ratio(1, 10),
            group: 0,
            on: true,
        }],
        forces: vec![ForceDesc::Gravity {
            scale: R::ONE,
            group: None,
        }],
        collisions: vec![collision],
        contacts: None,
        ..ParticlesDesc::default()
    }
}
