//! Characters against each other and against thrown bodies: two characters never pass
//! through each other nor jitter once they meet, a crowd never overlaps, and a dynamic body
//! thrown at a character or dropped on it is stopped by it.

use fixstep::character::CharacterDesc;
use fixstep::math::{Fx, Real};
use fixstep::rigid::{BodyDesc, EventKind, Shape};
use fixstep::world::{Command, Handle, PlayerInput, TickInput, World};

use super::character_support::*;

/// The capsules' radius and the skin (m).
const RADIUS: f64 = 0.3;
const SKIN: f64 = 0.01;

/// A character standing on the floor at (x, z).
fn standing(x: f64, z: f64) -> CharacterDesc<Fx> {
    CharacterDesc::new(capsule(), v(x, 0.81, z))
}

/// Steps `world` one tick, character k walking at `velocities[k]` (m/s).
fn walk_all(world: &mut World<Fx>, velocities: &[[f64; 3]]) {
    let commands = velocities
        .iter()
        .enumerate()
        .map(|(k, &[x, y, z])| Command::MoveCharacter {
            target: Handle::new(k as u32, 0),
            desired_velocity: v(x, y, z),
            jump: false,
        })
        .collect();
    let input = TickInput {
        tick: world.tick(),
        players: vec![PlayerInput {
            player: 0,
            commands,
        }],
    };
    world.step(&input);
}

/// The horizontal distance between the axes of characters `a` and `b`, m.
fn apart(world: &World<Fx>, a: usize, b: usize) -> f64 {
    let (p, q) = (pos(world, a), pos(world, b));
    (p[0] - q[0]).hypot(p[2] - q[2])
}

#[test]
fn two_characters_walking_into_each_other_stop_apart_and_do_not_jitter() {
    for speed in [2.0, 50.0] {
        let mut world = world(
            vec![floor(-20.0, 20.0)],
            vec![standing(-2.0, 0.0), standing(2.0, 0.0)],
        );
        let mut last = Vec::new();
        for tick in 0..120 {
            walk_all(&mut world, &[[speed, 0.0, 0.0], [-speed, 0.0, 0.0]]);
            let d = apart(&world, 0, 1);
            assert!(
                d >= 2.0 * RADIUS - 1e-6,
                "{speed} m/s, tick {tick}: axes {d} m apart, closer than two radii"
            );
            assert!(pos(&world, 0)[0] < pos(&world, 1)[0], "they swapped sides");
            if tick >= 90 {
                last.push((pos(&world, 0), pos(&world, 1)));
            }
        }
        let d = apart(&world, 0, 1);
        assert!(
            d <= 2.0 * RADIUS + 2.0 * SKIN + 1e-3,
            "{speed} m/s: they meet, a skin or two apart: {d}"
        );
        assert!(
            last.windows(2).all(|w| w[0] == w[1]),
            "{speed} m/s: once met, neither moves: {:?}",
            &last[..3]
        );
    }
}

#[test]
fn off_centre_they_slide_past_each_other() {
    let mut world = world(
        vec![floor(-20.0, 20.0)],
        vec![standing(-2.0, 0.0), standing(2.0, 0.2)],
    );
    for _ in 0..180 {
        walk_all(&mut world, &[[2.0, 0.0, 0.0], [-2.0, 0.0, 0.0]]);
        assert!(apart(&world, 0, 1) >= 2.0 * RADIUS - 1e-6);
    }
    assert!(
        pos(&world, 0)[0] > 2.0 && pos(&world, 1)[0] < -2.0,
        "they went round each other: {:?} {:?}",
        pos(&world, 0),
        pos(&world, 1)
    );
}

#[test]
fn a_crowd_walking_to_one_point_never_overlaps() {
    // 24 characters on a circle of 4 m, each walking to the centre at 3 m/s.
    let n = 24;
    let at = |k: usize| {
        let a = k as f64 * std::f64::consts::TAU / n as f64;
        (4.0 * a.cos(), 4.0 * a.sin())
    };
    let characters = (0..n).map(|k| standing(at(k).0, at(k).1)).collect();
    let mut world = world(vec![floor(-20.0, 20.0)], characters);
    let velocities: Vec<[f64; 3]> = (0..n)
        .map(|k| [-0.75 * at(k).0, 0.0, -0.75 * at(k).1])
        .collect();
    for tick in 0..150 {
        walk_all(&mut world, &velocities);
        for a in 0..n {
            for b in a + 1..n {
                let d = apart(&world, a, b);
                assert!(
                    d >= 2.0 * RADIUS - 1e-6,
                    "tick {tick}: characters {a} and {b} overlap ({d} m apart)"
                );
            }
            assert!(
                (pos(&world, a)[1] - 0.81).abs() < 0.05,
                "stays on the floor"
            );
        }
    }
}

/// A ball of radius 0.2 m thrown along +x at `speed` (m/s) from x = −3, 1 m up, at a
/// character standing at the origin; the ball's handle.
fn throw_ball(speed: f64, restitution: f64) -> (World<Fx>, Handle) {
    let mut ball = BodyDesc::new(Shape::Sphere { radius: fx(0.2) }, v(-3.0, 1.0, 0.0));
    ball.velocity = v(speed, 0.0, 0.0);
    ball.material.restitution = fx(restitution);
    let world = world(vec![floor(-20.0, 20.0), ball], vec![standing(0.0, 0.0)]);
    let handle = world
        .rigid()
        .expect("rigid")
        .handles()
        .nth(1)
        .expect("ball");
    (world, handle)
}

#[test]
fn a_ball_thrown_at_a_character_is_stopped_by_it() {
    for speed in [5.0, 20.0, 40.0] {
        let (mut world, ball) = throw_ball(speed, 0.0);
        let mut hits = Vec::new();
        for tick in 0..60 {
            idle(&mut world);
            hits.extend(
                world
                    .events()
                    .iter()
                    .filter(|e| e.kind == EventKind::CharacterHit && e.b == Some(ball))
                    .map(|e| e.a),
            );
            let [x, y, z] = world.rigid().unwrap().position(ball).unwrap().to_f64();
            // From the ball's centre to the capsule's axis, the segment y in [0.31, 1.31].
            let gap = (y.clamp(0.31, 1.31) - y).hypot(x.hypot(z));
            assert!(
                gap >= RADIUS + 0.2 - 1e-3 && x < 0.0,
                "{speed} m/s, tick {tick}: the ball at {x}, {y} is in the character"
            );
        }
        assert_eq!(hits, vec![Handle::new(0, 0)], "{speed} m/s: one hit event");
        let velocity = world.rigid().unwrap().linear_velocity(ball).unwrap();
        assert!(
            velocity.x.to_f64() <= 1e-3,
            "{speed} m/s: it lost its speed towards the character: {velocity:?}"
        );
        let p = pos(&world, 0);
        assert!(
            p[0].abs() < 1e-9 && (p[1] - 0.81).abs() < 1e-3,
            "the character is kinematic: not moved ({p:?})"
        );
    }
}

#[test]
fn a_bouncy_ball_bounces_back_off_a_character() {
    // It meets the character at about tick 15 and the floor at about tick 24.
    let (mut world, ball) = throw_ball(10.0, 0.8);
    for _ in 0..20 {
        idle(&mut world);
    }
    let vx = world
        .rigid()
        .unwrap()
        .linear_velocity(ball)
        .unwrap()
        .x
        .to_f64();
    // e = 0.8 of 10 m/s, the ball's spin taking none (the contact is on the line of its
    // centre).
    assert!((vx + 8.0).abs() < 0.1, "bounced back at 8 m/s: {vx}");
}

#[test]
fn a_crate_dropped_on_a_character_rests_on_its_head_and_falls_when_it_leaves() {
    let crate_box = BodyDesc::new(
        Shape::Box {
            half_extents: v(0.2, 0.2, 0.2),
        },
        v(0.0, 3.0, 0.0),
    );
    let mut world = world(
        vec![floor(-20.0, 20.0), crate_box],
        vec![standing(0.0, 0.0)],
    );
    let handle = world.rigid().unwrap().handles().nth(1).unwrap();
    for _ in 0..240 {
        idle(&mut world);
        let y = world.rigid().unwrap().position(handle).unwrap().y.to_f64();
        // The capsule's top is at 1.61 m; the crate's half height is 0.2 m.
        assert!(y >= 1.81 - 0.02, "the crate sank into the head: {y}");
    }
    let r = world.rigid().unwrap();
    let y = r.position(handle).unwrap().y.to_f64();
    let vy = r.linear_velocity(handle).unwrap().y.to_f64();
    assert!(y < 1.81 + 0.02 && vy.abs() < 0.2, "rests on it: {y} {vy}");
    // It has not fallen asleep there: the character walks away and it falls.
    for _ in 0..60 {
        walk(&mut world, v(3.0, 0.0, 0.0));
    }
    let y = world.rigid().unwrap().position(handle).unwrap().y.to_f64();
    assert!(y < 0.25, "fell to the floor once the head left: {y}");
}
