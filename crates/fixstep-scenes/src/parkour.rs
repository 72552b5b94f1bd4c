//! The `parkour` scene: three scripted kinematic characters ([`fixstep::character`]) on a
//! course of static boxes. The runner (character 0) climbs stairs, jumps a gap between
//! two ledges, drops back to the ground and walks into a slope too steep to climb; the
//! mover (character 1) pushes two crates, then steps onto a kinematic platform shuttling
//! along x and rides it. A third character, the crosser (character 2), walks across the
//! runner's lane into the runner where it stands against the slope, stops against it and
//! slides round it (characters collide with each other); a bouncy ball thrown at the runner there bounces off it (a
//! `character_hit` event).

use fixstep::character::CharacterDesc;
use fixstep::math::{Real, Vec3};
use fixstep::rigid::{BodyDesc, BodyKind, RigidDesc, Shape};
use fixstep::world::{Command, Handle, PlayerInput, Target, TickInput};

use super::rigid::ground;

/// A static box of half extents `half` (m) at `centre` (m).
fn block<R: Real>(centre: Vec3<R>, half: Vec3<R>) -> BodyDesc<R> {
    BodyDesc::new(Shape::Box { half_extents: half }, centre).fixed()
}

/// A length of `tenths` tenths of a metre.
fn tenths<R: Real>(tenths: i64) -> R {
    R::from_ratio(tenths, 10)
}

/// A vector in tenths of a metre.
fn at<R: Real>(x: i64, y: i64, z: i64) -> Vec3<R> {
    Vec3::new(tenths(x), tenths(y), tenths(z))
}

/// The slot of the shuttling platform among the bodies.
const PLATFORM: u32 = 10;

/// The slot of the ball thrown at the runner (the last body).
const BALL: u32 = 11;

/// Near where the runner stops against the slope, x in tenths of a metre (it stops at
/// x ≈ 12.84 m, where its capsule's lower sphere, centre 0.31 m up, radius 0.3 m and a 1 cm
/// skin, touches the 55° face).
const AT_SLOPE: i64 = 128;

/// The course. The runner's lane (z = −2 m): four stairs of 0.25 m rise and 0.5 m run from
/// x = 2 m up to a ledge 1 m high (x = 4 to 6 m), a 1.2 m gap, a second ledge (x = 7.2 to
/// 10 m), a 55° slope from x = 13 m. The mover's lane (z = 2 m): two 0.5 m crates of 50 kg
/// at x = 2 and 3.2 m. Beyond it (z = 5 m) a kinematic platform 0.2 m thick, 2 m × 2 m,
/// starting at x = 1 m (its velocity is set by the script), body 10. Last (body 11), a
/// ball of 0.2 m radius and restitution 0.8 resting on the ground at x = 12.8 m, z = −5 m,
/// beside where the runner stops against the slope, for the script to throw.
pub fn parkour_bodies<R: Real>() -> RigidDesc<R> {
    let mut bodies = vec![ground()];
    for k in 0..4 {
        let top = 25 * (k + 1);
        bodies.push(
            BodyDesc::new(
                Shape::Box {
                    half_extents: Vec3::new(
                        R::from_ratio(25, 100),
                        R::from_ratio(top, 200),
                        R::ONE,
                    ),
                },
                Vec3::new(
                    R::from_ratio(225 + 50 * k, 100),
                    R::from_ratio(top, 200),
                    -R::TWO,
                ),
            )
            .fixed(),
        );
    }
    bodies.push(block(at(50, 5, -20), at(10, 5, 10)));
    bodies.push(block(at(86, 5, -20), at(14, 5, 10)));
    for x in [20, 32] {
        let mut crate_box = BodyDesc::new(
            Shape::Box {
                half_extents: Vec3::splat(R::from_ratio(25, 100)),
            },
            Vec3::new(tenths(x), R::from_ratio(25, 100), R::TWO),
        );
        crate_box.density = R::from_int(400);
        bodies.push(crate_box);
    }
    // The slope: a slab whose top face rises at 55° from (13, 0, −2) along +x.
    let angle = R::from_ratio(55, 180) * R::PI;
    let (s, c) = angle.sin_cos();
    let mut slope = block(
        Vec3::new(
            R::from_int(13) + c * R::TWO + s * R::HALF,
            s * R::TWO - c * R::HALF,
            -R::TWO,
        ),
        Vec3::new(R::TWO, R::HALF, R::ONE),
    );
    slope.orientation = fixstep::math::Quat::from_axis_angle(Vec3::Z, angle);
    bodies.push(slope);
    let mut platform = BodyDesc::new(
        Shape::Box {
            half_extents: at(10, 1, 10),
        },
        at(10, 1, 50),
    );
    platform.kind = BodyKind::Kinematic;
    bodies.push(platform);
    let mut ball = BodyDesc::new(Shape::Sphere { radius: tenths(2) }, at(AT_SLOPE, 2, -50));
    ball.material.restitution = R::from_ratio(4, 5);
    bodies.push(ball);
    RigidDesc {
        bodies,
        ..RigidDesc::default()
    }
}

/// The three characters: capsules 1.6 m tall, 0.3 m in radius; the runner and the mover
/// standing at x = 0 in their lanes (z = −2 and 2 m), the crosser at x = 12.8 m, z = 0,
/// beside the runner's lane where the runner will stop against the slope; default
/// settings (45°, 0.3 m steps and snap, 5 m/s jumps).
pub fn parkour_characters<R: Real>() -> Vec<CharacterDesc<R>> {
    let capsule = Shape::Capsule {
        radius: tenths(3),
        half_height: R::HALF,
    };
    [(0, -20), (0, 20), (AT_SLOPE, 0)]
        .into_iter()
        .map(|(x, z)| {
            CharacterDesc::new(
                capsule.clone(),
                Vec3::new(tenths(x), R::from_ratio(81, 100), tenths(z)),
            )
        })
        .collect()
}

/// Who a cue drives.
#[derive(Clone, Copy)]
enum Actor {
    /// A character, by index.
    Character(u32),
    /// A body, by slot: its velocity is set.
    Body(u32),
}

/// What the script does at a tick: who, the velocity in tenths of m/s, and a jump.
type Cue = (u64, Actor, [i64; 3], bool);

/// The script: the runner walks at 3 m/s, jumps at the ledge's end, walks off the far one
/// and on into the slope; the mover walks at 2 m/s into the crates, then turns to the
/// platform, which shuttles at 1.5 m/s along x, turning every 2 s. Once the runner stands
/// against the slope, the crosser walks at 2 m/s along −z into its side (4 cm off its
/// centre line), slides round it and stops beyond it; the ball is thrown at the runner's
/// other side (6 m/s along +z, 3 m/s up) and bounces back off it.
const CUES: [Cue; 13] = [
    (0, Actor::Character(0), [30, 0, 0], false),
    (0, Actor::Character(1), [20, 0, 0], false),
    (0, Actor::Body(PLATFORM), [15, 0, 0], false),
    (112, Actor::Character(0), [30, 0, 0], true),
    (120, Actor::Body(PLATFORM), [-15, 0, 0], false),
    (200, Actor::Character(1), [-20, 0, 20], false),
    (240, Actor::Body(PLATFORM), [15, 0, 0], false),
    (270, Actor::Character(1), [0, 0, 20], false),
    (270, Actor::Character(2), [0, 0, -20], false),
    (300, Actor::Character(1), [0, 0, 0], false),
    (330, Actor::Body(BALL), [0, 30, 60], false),
    (360, Actor::Body(PLATFORM), [-15, 0, 0], false),
    (390, Actor::Character(2), [0, 0, 0], false),
];

/// The script of the cues (`CUES`), one input per tick that has cues.
pub fn parkour_script<R: Real>() -> Vec<TickInput<R>> {
    let mut script: Vec<TickInput<R>> = Vec::new();
    for &(tick, who, [x, y, z], jump) in &CUES {
        let velocity = at(x, y, z);
        let command = match who {
            Actor::Character(index) => Command::MoveCharacter {
                target: Handle::new(index, 0),
                desired_velocity: velocity,
                jump,
            },
            Actor::Body(slot) => Command::SetVelocity {
                target: Target::Body(Handle::new(slot, 0)),
                velocity,
            },
        };
        match script.last_mut() {
            Some(last) if last.tick == tick => last.players[0].commands.push(command),
            _ => script.push(TickInput {
                tick,
                players: vec![PlayerInput {
                    player: 0,
                    commands: vec![command],
                }],
            }),
        }
    }
    script
}
