//! The `pond` scene: height-field water. A pond 8 × 8 m, 0.5 m deep (64 × 64 cells of
//! 12.5 cm, waves at √(g · 0.5) ≈ 2.2 m/s, reflective banks, light damping); the script
//! drops four disturbances on it, whose rings spread, cross and bounce off the banks.
//! Sixteen corks (particles floating as columns) ring the centre; two boxes and two balls
//! lighter than water float and bob on the waves, tilted by them; a crate twice as dense
//! as water sinks to the pond's floor.

use fixstep::math::{Real, Vec3};
use fixstep::particles::{ForceDesc, ParticleDesc, ParticlesDesc};
use fixstep::rigid::{BodyDesc, RigidDesc, Shape};
use fixstep::types::{Command, PlayerInput, TickInput};
use fixstep::water::{WaterBodiesDesc, WaterBorder, WaterDesc, WaterParticleFloat};

/// `a/b` as a scalar.
fn ratio<R: Real>(a: i64, b: i64) -> R {
    R::from_ratio(a, b)
}

/// The corks' particle group.
const CORKS: u16 = 1;

/// The surface: rest level y = 0, from (−4, −4) to (4, 4) m in x and z, 0.5 m deep.
pub fn pond_water<R: Real>() -> WaterDesc<R> {
    WaterDesc {
        origin: Vec3::new(-R::from_int(4), R::ZERO, -R::from_int(4)),
        cells: (64, 64),
        cell_size: ratio(1, 8),
        depth: R::HALF,
        wave_speed: None,
        damping: ratio(1, 8),
        density: R::from_int(1000),
        border: WaterBorder::Reflective,
        particles: vec![WaterParticleFloat {
            group: CORKS,
            volume: ratio(1, 1000),
            height: ratio(1, 10),
            drag: R::ONE,
        }],
        bodies: Some(WaterBodiesDesc {
            filter: Default::default(),
            drag: R::ONE,
            angular_drag: R::ONE,
        }),
    }
}

/// Sixteen corks of 0.4 kg (columns 10 × 10 × 10 cm: 4 cm under at rest) on a ring of
/// radius 1.5 m, dropped from 5 cm above the water.
pub fn pond_corks<R: Real>() -> ParticlesDesc<R> {
    // The ring's points, written as exact ratios: (cos, sin) of k · 22.5° to 1/1000.
    const RING: [(i64, i64); 16] = [
        (1000, 0),
        (924, 383),
        (707, 707),
        (383, 924),
        (0, 1000),
        (-383, 924),
        (-707, 707),
        (-924, 383),
        (-1000, 0),
        (-924, -383),
        (-707, -707),
        (-383, -924),
        (0, -1000),
        (383, -924),
        (707, -707),
        (924, -383),
    ];
    let particles = RING
        .iter()
        .map(|&(c, s)| ParticleDesc {
            position: Vec3::new(ratio(3 * c, 2000), ratio(1, 10), ratio(3 * s, 2000)),
            velocity: Vec3::ZERO,
            mass: ratio(2, 5),
            group: CORKS,
            lifetime: R::ZERO,
        })
        .collect();
    ParticlesDesc {
        particles,
        forces: vec![ForceDesc::Gravity {
            scale: R::ONE,
            group: None,
        }],
        ..ParticlesDesc::default()
    }
}

/// The bodies: 0 the pond's floor (a plane 0.5 m below the surface); 1 and 2 boxes
/// 60 × 30 × 40 cm of 400 and 600 kg/m³; 3 and 4 balls 50 cm across of 300 and
/// 700 kg/m³; 5 a crate 40 cm on a side of 2000 kg/m³. Each starts just above the water.
pub fn pond_bodies<R: Real>() -> RigidDesc<R> {
    let floor = BodyDesc::new(
        Shape::Plane {
            normal: Vec3::Y,
            offset: -R::HALF,
        },
        Vec3::ZERO,
    )
    .fixed();
    let body = |shape: Shape<R>, x: i64, y: i64, z: i64, density: i32| {
        let mut body = BodyDesc::new(shape, Vec3::new(ratio(x, 10), ratio(y, 10), ratio(z, 10)));
        body.density = R::from_int(density);
        body
    };
    let slab = Shape::Box {
        half_extents: Vec3::new(ratio(3, 10), ratio(3, 20), ratio(1, 5)),
    };
    let ball = Shape::Sphere {
        radius: ratio(1, 4),
    };
    let crate_ = Shape::Box {
        half_extents: Vec3::splat(ratio(1, 5)),
    };
    RigidDesc {
        bodies: vec![
            floor,
            body(slab.clone(), -25, 3, 5, 400),
            body(slab, 20, 3, 20, 600),
            body(ball.clone(), 5, 4, -25, 300),
            body(ball, -15, 4, -20, 700),
            body(crate_, 25, 4, -15, 2000),
        ],
        ..RigidDesc::default()
    }
}

/// Four drops, 10 to 15 cm high and 60 cm across, one a second from tick 30.
pub fn pond_script<R: Real>() -> Vec<TickInput<R>> {
    let drops = [
        (30, 0, 0, 15),
        (90, -20, 15, 12),
        (150, 20, -5, 10),
        (210, -5, -25, 12),
    ];
    drops
        .iter()
        .map(|&(tick, x, z, height)| TickInput {
            tick,
            players: vec![PlayerInput {
                player: 0,
                commands: vec![Command::DisturbWater {
                    x: ratio(x, 10),
                    z: ratio(z, 10),
                    height: ratio(height, 100),
                    radius: ratio(3, 5),
                }],
            }],
        })
        .collect()
}
