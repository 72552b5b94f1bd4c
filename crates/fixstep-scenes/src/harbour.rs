//! The `harbour` scene: rigid bodies in water, two-way. A tank 0.6 × 0.3 × 0.25 m holds
//! water 12.5 cm deep (DFSPH, 2.5 cm spacing). A paddle, kinematic, turns at one end
//! and makes waves; two boxes and two balls lighter than water float and bob on them; a
//! crate four times as dense as the boxes is dropped in and sinks to the floor.

use fixstep::fluid::{FluidBlock, FluidBodiesDesc, FluidBox, FluidDesc, FluidSolver};
use fixstep::math::{Quat, Real, Vec3};
use fixstep::rigid::{BodyDesc, BodyKind, CollisionFilter, Part, RigidDesc, Shape};

use super::rigid::ground;

/// `a/b` as a scalar.
fn ratio<R: Real>(a: i64, b: i64) -> R {
    R::from_ratio(a, b)
}

/// The tank's inside (m), from the origin.
fn tank_size<R: Real>() -> Vec3<R> {
    Vec3::new(ratio(3, 5), ratio(3, 10), ratio(1, 4))
}

/// The layer of the bodies in the water; the tank's walls are on another, which the water
/// ignores (it has its own walls).
const AFLOAT: u32 = 1;

/// The bodies: 0 the floor (a plane); 1 the tank's walls, static; 2 the paddle, kinematic:
/// a blade 20 × 5 × 20 cm, level at first, turning at 2 rad/s about the z axis through
/// (0.12, 0.17, 0.125) m, its ends 5.5 cm into the water when upright; 3 and 4 boxes
/// 10 × 5 × 10 cm of 500 kg/m³; 5 and 6 balls 8 cm across of 400 kg/m³; 7 a crate 7.5 cm
/// on a side of 2000 kg/m³. Each starts just above the water.
pub fn harbour_bodies<R: Real>() -> RigidDesc<R> {
    // Each wall 10 cm thick, outside the tank's inside (0.6 × 0.3 × 0.25 m); the values
    // are written out so that the scene file reads them back to the bit.
    let wall = |centre: [(i64, i64); 3], half: [(i64, i64); 3]| Part {
        rotation: Quat::IDENTITY,
        translation: Vec3::new(
            ratio(centre[0].0, centre[0].1),
            ratio(centre[1].0, centre[1].1),
            ratio(centre[2].0, centre[2].1),
        ),
        shape: Shape::Box {
            half_extents: Vec3::new(
                ratio(half[0].0, half[0].1),
                ratio(half[1].0, half[1].1),
                ratio(half[2].0, half[2].1),
            ),
        },
    };
    let mut walls = BodyDesc::new(
        Shape::Compound {
            parts: vec![
                wall([(-1, 20), (3, 20), (1, 8)], [(1, 20), (3, 20), (9, 40)]),
                wall([(13, 20), (3, 20), (1, 8)], [(1, 20), (3, 20), (9, 40)]),
                wall([(3, 10), (3, 20), (-1, 20)], [(3, 10), (3, 20), (1, 20)]),
                wall([(3, 10), (3, 20), (3, 10)], [(3, 10), (3, 20), (1, 20)]),
            ],
        },
        Vec3::ZERO,
    )
    .fixed();
    walls.filter = CollisionFilter {
        layers: !AFLOAT,
        mask: u32::MAX,
    };
    let mut paddle = BodyDesc::new(
        Shape::Box {
            half_extents: Vec3::new(ratio(1, 10), ratio(1, 40), ratio(1, 10)),
        },
        Vec3::new(ratio(12, 100), ratio(17, 100), ratio(1, 8)),
    );
    paddle.kind = BodyKind::Kinematic;
    paddle.angular_velocity = Vec3::new(R::ZERO, R::ZERO, -R::TWO);
    let floater = |shape: Shape<R>, centre: Vec3<R>, density: i32| {
        let mut body = BodyDesc::new(shape, centre);
        body.density = R::from_int(density);
        body.filter = CollisionFilter {
            layers: AFLOAT,
            mask: u32::MAX,
        };
        body
    };
    let flat_box = Shape::Box {
        half_extents: Vec3::new(ratio(1, 20), ratio(1, 40), ratio(1, 20)),
    };
    let ball = Shape::Sphere {
        radius: ratio(1, 25),
    };
    let crate_box = Shape::Box {
        half_extents: Vec3::splat(ratio(3, 80)),
    };
    let bodies = vec![
        ground(),
        walls,
        paddle,
        floater(
            flat_box.clone(),
            Vec3::new(ratio(32, 100), ratio(155, 1000), ratio(7, 100)),
            500,
        ),
        floater(
            flat_box,
            Vec3::new(ratio(1, 2), ratio(155, 1000), ratio(17, 100)),
            500,
        ),
        floater(
            ball.clone(),
            Vec3::new(ratio(42, 100), ratio(17, 100), ratio(18, 100)),
            400,
        ),
        floater(
            ball,
            Vec3::new(ratio(54, 100), ratio(17, 100), ratio(6, 100)),
            400,
        ),
        floater(
            crate_box,
            Vec3::new(ratio(3, 10), ratio(17, 100), ratio(18, 100)),
            2000,
        ),
    ];
    RigidDesc {
        bodies,
        ..RigidDesc::default()
    }
}

/// The water: DFSPH, 2.5 cm spacing, 12.5 cm deep over the whole tank (1200 particles),
/// meeting the bodies on the floating layer. Its flow stays below 0.5 m/s, so the speed of
/// sound is 5 m/s (DFSPH's time-step limit takes a tenth of it as the fastest flow) and two
/// fluid substeps per step keep within that limit. The density tolerance is 0.2 % (at the
/// default 0.05 % a solve took about 28 iterations instead of 16).
pub fn harbour_water<R: Real>() -> FluidDesc<R> {
    let size = tank_size::<R>();
    let tank = FluidBox {
        min: Vec3::ZERO,
        max: size,
    };
    let mut desc = FluidDesc::new(FluidSolver::Dfsph, ratio(1, 40), tank);
    desc.substeps = 2;
    desc.speed_of_sound = R::from_int(5);
    desc.max_density_error = ratio(1, 500);
    desc.blocks.push(FluidBlock {
        region: FluidBox {
            min: Vec3::ZERO,
            max: Vec3::new(size.x, ratio(1, 8), size.z),
        },
        velocity: Vec3::ZERO,
    });
    desc.bodies = Some(FluidBodiesDesc {
        filter: CollisionFilter {
            layers: AFLOAT,
            mask: AFLOAT,
        },
    });
    desc
}
