//! Helpers of the character tests: worlds of static boxes with characters, and driving them.

use fixstep::character::{Character, CharacterDesc};
use fixstep::math::{Fx, Quat, Real, Vec3};
use fixstep::rigid::{BodyDesc, RigidDesc, Shape};
use fixstep::scene::Scene;
use fixstep::world::{Command, Handle, PlayerInput, TickInput, World};

pub fn fx(x: f64) -> Fx {
    Fx::from_f64(x)
}

pub fn v(x: f64, y: f64, z: f64) -> Vec3<Fx> {
    Vec3::from_f64(x, y, z)
}

/// A capsule 1.6 m tall, 0.3 m in radius: its feet are 0.8 m below its centre.
pub fn capsule() -> Shape<Fx> {
    Shape::Capsule {
        radius: fx(0.3),
        half_height: fx(0.5),
    }
}

/// A static box of half extents `half` at `centre`, turned by `angle` rad about z.
pub fn slab(centre: Vec3<Fx>, half: Vec3<Fx>, angle: f64) -> BodyDesc<Fx> {
    let mut b = BodyDesc::new(Shape::Box { half_extents: half }, centre).fixed();
    b.orientation = Quat::from_axis_angle(Vec3::Z, fx(angle));
    b
}

/// The ground: the top of a large static slab at y = 0, spanning x in [x0, x1].
pub fn floor(x0: f64, x1: f64) -> BodyDesc<Fx> {
    slab(
        v((x0 + x1) / 2.0, -0.5, 0.0),
        v((x1 - x0) / 2.0, 0.5, 20.0),
        0.0,
    )
}

/// A world of `bodies` with `characters` (default gravity, 60 ticks/s).
pub fn world(bodies: Vec<BodyDesc<Fx>>, characters: Vec<CharacterDesc<Fx>>) -> World<Fx> {
    let mut scene = Scene::empty("character-test");
    scene.rigid = Some(RigidDesc {
        bodies,
        ..RigidDesc::default()
    });
    scene.characters = characters;
    scene.build().expect("the scene builds")
}

/// The tick input moving character `index` at `velocity` (m/s), jumping if `jump`.
pub fn move_input(tick: u64, index: u32, velocity: Vec3<Fx>, jump: bool) -> TickInput<Fx> {
    TickInput {
        tick,
        players: vec![PlayerInput {
            player: 0,
            commands: vec![Command::MoveCharacter {
                target: Handle::new(index, 0),
                desired_velocity: velocity,
                jump,
            }],
        }],
    }
}

/// Character `index` of `world`.
pub fn character(world: &World<Fx>, index: usize) -> &Character<Fx> {
    &world.characters().expect("characters").characters()[index]
}

/// Steps `world` one tick with character 0 walking at `velocity`.
pub fn walk(world: &mut World<Fx>, velocity: Vec3<Fx>) {
    let input = move_input(world.tick(), 0, velocity, false);
    world.step(&input);
}

/// Steps `world` one tick with no input.
pub fn idle(world: &mut World<Fx>) {
    world.step(&TickInput::default());
}

/// Position of character `index`, as f64.
pub fn pos(world: &World<Fx>, index: usize) -> [f64; 3] {
    character(world, index).position.to_f64()
}
