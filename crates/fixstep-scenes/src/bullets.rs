//! The `bullets` scene: continuous collision at work. Steel balls of radius 5 cm fly at
//! 200 m/s (3.3 m per tick) at a static wall 5 cm thick, which they would pass in one tick
//! without the sweep; two bullets at 150 m/s knock a stack of boxes, which they would pass
//! through unless swept against dynamic bodies too.

use fixstep::math::{Real, Vec3};
use fixstep::rigid::{BodyDesc, Grid, RigidDesc, Shape};

use super::rigid::ground;

/// A steel ball (7800 kg/m³) of radius 5 cm at `position` (m) flying along x at `speed`
/// (m/s).
fn shot<R: Real>(position: Vec3<R>, speed: i32) -> BodyDesc<R> {
    let mut ball = BodyDesc::new(
        Shape::Sphere {
            radius: R::from_ratio(1, 20),
        },
        position,
    );
    ball.density = R::from_int(7800);
    ball.velocity = Vec3::new(R::from_int(speed), R::ZERO, R::ZERO);
    ball
}

/// The bodies: the ground; a static wall 5 cm thick, 2 m high and 2 m wide across x = 10 m;
/// a stack of four 50 cm boxes at x = 10 m, z = 3 m; three balls at 200 m/s at the wall
/// (heights 0.5, 1 and 1.5 m) and two bullets at 150 m/s at the stack (heights 0.25 and
/// 1.25 m), all starting at x = 0.
pub fn bullets<R: Real>() -> RigidDesc<R> {
    let wall = BodyDesc::new(
        Shape::Box {
            half_extents: Vec3::new(R::from_ratio(1, 40), R::ONE, R::ONE),
        },
        Vec3::new(R::from_int(10), R::ONE, R::ZERO),
    )
    .fixed();

    let mut stack = BodyDesc::new(
        Shape::Box {
            half_extents: Vec3::splat(R::from_ratio(1, 4)),
        },
        Vec3::new(R::from_int(10), R::from_ratio(1, 4), R::from_int(3)),
    );
    stack.grid = Some(Grid {
        count: (1, 4, 1),
        spacing: Vec3::new(R::ZERO, R::HALF, R::ZERO),
    });

    let mut bodies = vec![ground(), wall, stack];
    for tenths in [5, 10, 15] {
        bodies.push(shot(
            Vec3::new(R::ZERO, R::from_ratio(tenths, 10), R::ZERO),
            200,
        ));
    }
    for quarters in [1, 5] {
        let mut bullet = shot(
            Vec3::new(R::ZERO, R::from_ratio(quarters, 4), R::from_int(3)),
            150,
        );
        bullet.bullet = true;
        bodies.push(bullet);
    }
    RigidDesc {
        bodies,
        ..RigidDesc::default()
    }
}
