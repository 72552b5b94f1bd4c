//! The `parkour` scene: two scripted kinematic characters ([`fixstep::character`]) on a
//! course of static boxes. The runner (character 0) climbs stairs, jumps a gap between
//! two ledges, drops back to the ground and walks into a slope too steep to climb; the
//! mover (character 1) pushes two crates, then steps onto a kinematic platform shuttling
//! along x and rides it.

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

/// The slot of the shuttling platform among the bodies (the last one).
const PLATFORM: u32 = 10;

/// The course. The runner's lane (z = −2 m): four stairs of 0.25 m rise and 0.5 m run from
/// x = 2 m up to a ledge 1 m high (x = 4 to 6 m), a 1.2 m gap, a second ledge (x = 7.2 to
/// 10 m), a 55° slope from x = 13 m. The mover's lane (z = 2 m): two 0.5 m crates of 50 kg
/// at x = 2 and 3.2 m. Beyond it (z = 5 m) a kinematic platform 0.2 m thick, 2 m × 2 m,
/// starting at x = 1 m (its velocity is set by the script), body 10.
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
    RigidDesc {
        bodies,
        ..RigidDesc::default()
    }
}

/// The two characters: capsules 1.6 m tall, 0.3 m in radius, standing at x = 0 in their
/// lanes (z = −2 and 2 m); default settings (45°, 0.3 m steps and snap, 5 m/s jumps).
pub fn parkour_characters<R: Real>() -> Vec<CharacterDesc<R>> {
    let capsule = Shape::Capsule {
        radius: tenths(3),
        half_height: R::HALF,
    };
    [-20, 20]
        .into_iter()
        .map(|z| {
            CharacterDesc::new(
                capsule.clone(),
                Vec3::new(R::ZERO, R::from_ratio(81, 100), tenths(z)),
            )
        })
        .collect()
}

/// What the script does at a tick: which character (or the platform, `None`), the
/// velocity in tenths of m/s, and a jump.
type Cue = (u64, Option<u32>, [i64; 3], bool);

/// The script: the runner walks at 3 m/s, jumps at the ledge's end, walks off the far one
/// and on into the slope; the mover walks at 2 m/s into the crates, then turns to the
/// platform, which shuttles at 1.5 m/s along x, turning every 2 s.
const CUES: [Cue; 10] = [
    (0, Some(0), [30, 0, 0], false),
    (0, Some(1), [20, 0, 0], false),
    (0, None, [15, 0, 0], false),
    (112, Some(0), [30, 0, 0], true),
    (120, None, [-15, 0, 0], false),
    (200, Some(1), [-20, 0, 20], false),
    (240, None, [15, 0, 0], false),
    (270, Some(1), [0, 0, 20], false),
    (300, Some(1), [0, 0, 0], false),
    (360, None, [-15, 0, 0], false),
];

/// The script of the cues (`CUES`), one input per tick that has cues.
pub fn parkour_script<R: Real>() -> Vec<TickInput<R>> {
    let mut script: Vec<TickInput<R>> = Vec::new();
    for &(tick, who, [x, y, z], jump) in &CUES {
        let velocity = at(x, y, z);
        let command = match who {
            Some(index) => Command::MoveCharacter {
                target: Handle::new(index, 0),
                desired_velocity: velocity,
                jump,
            },
            None => Command::SetVelocity {
                target: Target::Body(Handle::new(PLATFORM, 0)),
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
