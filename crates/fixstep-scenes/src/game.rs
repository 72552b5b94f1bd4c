//! The `shooter` scene: what a game asks of its physics, in one place. A scripted player
//! (a kinematic capsule) fires projectiles spawned by input at a wall of boxes; projectiles
//! are on their own layer, so they pass through the player and each other; a sensor plate
//! behind the wall counts what lands on it; the gun's line of sight is a ray query.

use fixstep::math::{Quat, Real, StateHasher, Vec3};
use fixstep::rigid::{
    BodyDesc, BodyKind, BodyTemplate, CollisionFilter, Grid, Material, QueryFilter, RayHit,
    RigidDesc, Shape,
};
use fixstep::scene::Scene;
use fixstep::world::{Command, PlayerInput, TickInput};

use super::rigid::ground;

/// Layer of the level: the ground, the wall's boxes and the plate.
pub const WORLD: u32 = 1;
/// Layer of the player.
pub const PLAYER: u32 = 2;
/// Layer of the projectiles.
pub const PROJECTILE: u32 = 4;

/// Where the gun's muzzle is, m.
pub fn muzzle<R: Real>() -> Vec3<R> {
    Vec3::new(R::ONE, R::from_ratio(3, 2), R::ZERO)
}

/// The player's shots: the tick it fires at (every second from 0.5 s) and the muzzle
/// velocity's horizontal and vertical components in tenths of m/s. Straight shots at
/// 20 m/s hit the wall low, then higher; lobs at (4.5, 10.2) m/s clear the wall (its top is
/// 4 m high) and land on the plate, 2.2 s later.
const SHOTS: [(u64, i64, i64); 8] = [
    (30, 200, 10),
    (90, 200, 30),
    (150, 45, 102),
    (210, 200, 45),
    (270, 200, 60),
    (330, 45, 102),
    (390, 200, 20),
    (450, 200, 50),
];

/// The bodies: the ground; the player, a kinematic capsule on [`PLAYER`] that only meets
/// the level; a wall of 3 × 4 unit boxes (300 kg each) on [`WORLD`], 8 m downrange; a
/// static sensor plate 2 m × 6 m behind the wall. One template: a steel ball of radius
/// 0.15 m (7800 kg/m³, 110 kg) on [`PROJECTILE`], meeting only [`WORLD`].
pub fn shooter<R: Real>() -> RigidDesc<R> {
    let mut player = BodyDesc::new(
        Shape::Capsule {
            radius: R::from_ratio(3, 10),
            half_height: R::from_ratio(6, 10),
        },
        Vec3::new(R::ZERO, R::from_ratio(9, 10), R::ZERO),
    );
    player.kind = BodyKind::Kinematic;
    player.filter = CollisionFilter::new(PLAYER, WORLD);

    let mut wall = BodyDesc::new(
        Shape::Box {
            half_extents: Vec3::splat(R::HALF),
        },
        Vec3::new(R::from_int(8), R::HALF, -R::ONE),
    );
    wall.grid = Some(Grid {
        count: (1, 4, 3),
        spacing: Vec3::new(R::ZERO, R::ONE, R::ONE),
    });
    wall.density = R::from_int(300);
    wall.filter = CollisionFilter::new(WORLD, u32::MAX);

    let mut plate = BodyDesc::new(
        Shape::Box {
            half_extents: Vec3::new(R::ONE, R::from_ratio(1, 20), R::from_int(3)),
        },
        Vec3::new(R::from_int(11), R::from_ratio(1, 20), R::ZERO),
    )
    .fixed();
    plate.sensor = true;
    plate.filter = CollisionFilter::new(WORLD, u32::MAX);

    let mut projectile = BodyTemplate::new(Shape::Sphere {
        radius: R::from_ratio(15, 100),
    });
    projectile.density = R::from_int(7800);
    projectile.material = Material {
        friction: R::HALF,
        restitution: R::from_ratio(1, 5),
    };
    projectile.filter = CollisionFilter::new(PROJECTILE, WORLD);

    RigidDesc {
        bodies: vec![ground(), player, wall, plate],
        templates: vec![projectile],
        ..RigidDesc::default()
    }
}

/// How far the gun's sight reaches, m.
pub const SIGHT_RANGE: i32 = 50;

/// The player's inputs: at each shot's tick, a [`Command::Payload`] with what the gun's
/// sight sees ([`sight_payload`]) and a projectile spawned at the muzzle flying downrange.
/// The sight is a ray query on the state before the tick, so the script is made by
/// simulating the scene up to each shot: a replay then carries the query results, and
/// re-simulating it checks them.
pub fn shooter_script<R: Real>() -> Vec<TickInput<R>> {
    let mut scene = Scene::empty("shooter");
    scene.rigid = Some(shooter());
    let mut world = scene.build().expect("the shooter scene builds");
    let mut script = Vec::with_capacity(SHOTS.len());
    for &(tick, along, up) in &SHOTS {
        let velocity = Vec3::new(R::from_ratio(along, 10), R::from_ratio(up, 10), R::ZERO);
        while world.tick() < tick {
            let input = script
                .last()
                .filter(|i: &&TickInput<R>| i.tick == world.tick());
            world.step(input.unwrap_or(&TickInput::default()));
        }
        let seen = world.cast_ray(
            muzzle(),
            velocity,
            R::from_int(SIGHT_RANGE),
            &QueryFilter::new().with_mask(WORLD),
        );
        let commands = vec![
            Command::Payload(sight_payload(seen.as_ref())),
            Command::SpawnBody {
                template: 0,
                position: muzzle(),
                orientation: Quat::IDENTITY,
                velocity,
                angular_velocity: Vec3::ZERO,
            },
        ];
        script.push(TickInput {
            tick,
            players: vec![PlayerInput {
                player: 0,
                commands,
            }],
        });
    }
    script
}

/// A sight's result as a payload: the low 32 bits of the state hash of the body's index and
/// generation and the distance's canonical bits; `u32::MAX` for a miss.
pub fn sight_payload<R: Real>(hit: Option<&RayHit<R>>) -> u32 {
    let Some(hit) = hit else {
        return u32::MAX;
    };
    let mut h = StateHasher::new();
    h.write_u32(hit.body.index);
    h.write_u32(hit.body.generation);
    h.write_real(hit.distance);
    h.finish() as u32
}
