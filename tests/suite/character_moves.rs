//! The character's moves against analytic expectations: steps, slopes, stairs, platforms,
//! jumps, pushes, layers and events.

use fixstep::character::CharacterDesc;
use fixstep::math::{Fx, Real};
use fixstep::rigid::{BodyDesc, BodyKind, CollisionFilter, EventKind, Shape};

use super::character_support::*;

/// A character standing at x = 0 on the floor (feet 1 cm above it, the skin).
fn standing(x: f64, y: f64) -> CharacterDesc<Fx> {
    CharacterDesc::new(capsule(), v(x, y + 0.81, 0.0))
}

/// Walks a character with step height 0.35 m at 2 m/s towards a step of `height` (m)
/// whose face is at x = 1; its final position.
fn walk_to_step(height: f64) -> [f64; 3] {
    let mut c = standing(0.0, 0.0);
    c.settings.step_height = fx(0.35);
    let step = slab(v(6.0, height / 2.0, 0.0), v(5.0, height / 2.0, 5.0), 0.0);
    let mut world = world(vec![floor(-10.0, 20.0), step], vec![c]);
    for _ in 0..120 {
        walk(&mut world, v(2.0, 0.0, 0.0));
    }
    pos(&world, 0)
}

#[test]
fn a_step_below_the_step_height_is_climbed_and_one_above_it_stops() {
    let climbed = walk_to_step(0.3);
    assert!(climbed[0] > 3.5, "walked on over the step: {climbed:?}");
    assert!(
        (climbed[1] - 1.11).abs() < 0.02,
        "stands on the step: {climbed:?}"
    );
    let stopped = walk_to_step(0.4);
    assert!(
        stopped[0] < 0.71,
        "stopped before the face at x = 1: {stopped:?}"
    );
    assert!(
        (stopped[1] - 0.81).abs() < 0.02,
        "still on the floor: {stopped:?}"
    );
}

/// A slope of `degrees` rising along +x from the origin, with the floor before it; a
/// character walking into it at 2 m/s for 3 s from x = −1, its x at each tick.
fn walk_up_slope(degrees: f64) -> Vec<(f64, f64, bool)> {
    let a = degrees.to_radians();
    let (s, c) = a.sin_cos();
    // The slab's top face passes through the origin; its centre is half its thickness
    // below, along the face's normal (−sin a, cos a, 0); its near end is under the floor.
    let slope = slab(
        v(10.0 * c + 0.5 * s, 10.0 * s - 0.5 * c, 0.0),
        v(10.0, 0.5, 5.0),
        a,
    );
    let mut character = standing(-1.0, 0.0);
    character.settings.max_slope = fx(45f64.to_radians());
    let mut world = world(vec![floor(-20.0, 0.0), slope], vec![character]);
    (0..180)
        .map(|_| {
            walk(&mut world, v(2.0, 0.0, 0.0));
            let p = pos(&world, 0);
            (p[0], p[1], character_grounded(&world))
        })
        .collect()
}

fn character_grounded(world: &fixstep::world::World<Fx>) -> bool {
    character(world, 0).grounded
}

#[test]
fn a_slope_under_the_limit_is_walked_up_and_one_over_it_is_not() {
    let gentle = walk_up_slope(40.0);
    let (x, y, grounded) = *gentle.last().expect("ticks");
    assert!(x > 3.0 && grounded, "walked up the 40° slope: {x} {y}");
    // On the slope, its feet (0.8 m below the centre, the skin above) are on the surface.
    let surface = x * 40f64.to_radians().tan();
    assert!(
        y > surface + 0.5,
        "above the surface at x: {y} vs {surface}"
    );
    let steep = walk_up_slope(50.0);
    let furthest = steep.iter().map(|t| t.0).fold(f64::MIN, f64::max);
    assert!(
        furthest < 0.1,
        "no progress up the 50° slope: reached x = {furthest}"
    );
    let highest = steep.iter().map(|t| t.1).fold(f64::MIN, f64::max);
    assert!(highest < 0.81 + 0.1, "did not climb: {highest}");
}

#[test]
fn on_a_slope_over_the_limit_it_slides_down() {
    let a = 50f64.to_radians();
    let (s, c) = a.sin_cos();
    let slope = slab(
        v(10.0 * c + 0.5 * s, 10.0 * s - 0.5 * c, 0.0),
        v(10.0, 0.5, 5.0),
        a,
    );
    // Dropped just above the slope at x = 2 (surface at 2.38 m).
    let dropped = CharacterDesc::new(capsule(), v(2.0, 2.0 * a.tan() + 1.3, 0.0));
    let mut world = world(vec![floor(-20.0, 0.0), slope], vec![dropped]);
    for _ in 0..60 {
        idle(&mut world);
        assert!(!character(&world, 0).grounded || pos(&world, 0)[0] < 0.3);
    }
    let p = pos(&world, 0);
    assert!(p[0] < 1.0 && p[1] < 2.0, "slid down: {p:?}");
}

#[test]
fn walking_down_stairs_at_5_m_s_it_is_never_airborne_two_ticks_running() {
    // Ten steps of 0.2 m rise and 0.4 m run going down along +x from x = 0.
    let mut bodies = vec![floor(-10.0, 0.0)];
    for k in 0..10 {
        let top = -0.2 * f64::from(k + 1);
        let bottom = -5.0;
        let x0 = 0.4 * f64::from(k);
        bodies.push(slab(
            v(x0 + 0.2, (top + bottom) / 2.0, 0.0),
            v(0.2, (top - bottom) / 2.0, 3.0),
            0.0,
        ));
    }
    bodies.push(slab(v(14.0, -2.5, 0.0), v(10.0, 0.5, 3.0), 0.0));
    let mut world = world(bodies, vec![standing(-1.0, 0.0)]);
    for _ in 0..10 {
        idle(&mut world);
    }
    let mut airborne_run = 0;
    let mut longest = 0;
    while pos(&world, 0)[0] < 5.0 {
        walk(&mut world, v(5.0, 0.0, 0.0));
        airborne_run = if character(&world, 0).grounded {
            0
        } else {
            airborne_run + 1
        };
        longest = longest.max(airborne_run);
        assert!(world.tick() < 200, "reached the bottom");
    }
    assert!(longest <= 1, "airborne {longest} ticks running");
    let p = pos(&world, 0);
    assert!(
        (p[1] - (-2.0 + 0.81)).abs() < 0.03,
        "on the bottom floor: {p:?}"
    );
}

#[test]
fn on_a_platform_at_2_m_s_it_keeps_its_place_within_a_centimetre_over_5_s() {
    let mut platform = BodyDesc::new(
        Shape::Box {
            half_extents: v(2.0, 0.25, 2.0),
        },
        v(0.0, 0.0, 0.0),
    );
    platform.kind = BodyKind::Kinematic;
    platform.velocity = v(2.0, 0.0, 0.0);
    let mut world = world(vec![platform], vec![standing(0.5, 0.25)]);
    idle(&mut world);
    let handle = world
        .rigid()
        .expect("rigid")
        .handles()
        .next()
        .expect("platform");
    let relative = |w: &fixstep::world::World<Fx>| {
        let p = w
            .rigid()
            .expect("rigid")
            .position(handle)
            .expect("live")
            .to_f64();
        let c = pos(w, 0);
        [c[0] - p[0], c[1] - p[1], c[2] - p[2]]
    };
    let start = relative(&world);
    for _ in 0..300 {
        idle(&mut world);
        let now = relative(&world);
        let drift = (0..3)
            .map(|i| (now[i] - start[i]).abs())
            .fold(0.0, f64::max);
        assert!(drift < 0.01, "tick {}: drifted {drift} m", world.tick());
        assert!(character(&world, 0).grounded);
    }
}

#[test]
fn a_jump_at_speed_v_rises_v_squared_over_2g() {
    let mut c = standing(0.0, 0.0);
    c.settings.jump_speed = fx(6.0);
    let mut world = world(vec![floor(-10.0, 10.0)], vec![c]);
    for _ in 0..5 {
        idle(&mut world);
    }
    assert!(character(&world, 0).grounded);
    let y0 = pos(&world, 0)[1];
    world.step(&move_input(world.tick(), 0, v(0.0, 0.0, 0.0), true));
    let mut peak = y0;
    for _ in 0..120 {
        peak = peak.max(pos(&world, 0)[1]);
        idle(&mut world);
    }
    let expected = 6.0 * 6.0 / (2.0 * 9.81);
    let rise = peak - y0;
    assert!(
        (rise - expected).abs() < 0.01 * expected,
        "rose {rise} m, expected {expected}"
    );
    assert!(character(&world, 0).grounded, "landed again");
    assert!((pos(&world, 0)[1] - y0).abs() < 0.01);
}

#[test]
fn it_pushes_a_crate_and_raises_hit_and_land_events() {
    let crate_box = BodyDesc::new(
        Shape::Box {
            half_extents: v(0.4, 0.4, 0.4),
        },
        v(2.0, 0.4, 0.0),
    );
    // Dropped from 0.5 m above the floor.
    let mut world = world(
        vec![floor(-10.0, 20.0), crate_box],
        vec![standing(0.0, 0.5)],
    );
    let mut events = Vec::new();
    for _ in 0..180 {
        walk(&mut world, v(2.0, 0.0, 0.0));
        events.extend(world.events().iter().copied());
    }
    let handles: Vec<_> = world.rigid().expect("rigid").handles().collect();
    let crate_x = world
        .rigid()
        .expect("rigid")
        .position(handles[1])
        .expect("live")
        .x
        .to_f64();
    assert!(crate_x > 3.0, "the crate was pushed along: x = {crate_x}");
    let lands: Vec<_> = events
        .iter()
        .filter(|e| e.kind == EventKind::CharacterLand)
        .collect();
    assert_eq!(lands.len(), 1, "{events:?}");
    assert_eq!(lands[0].b, Some(handles[0]));
    assert!(
        events
            .iter()
            .any(|e| e.kind == EventKind::CharacterHit && e.b == Some(handles[1])),
        "{events:?}"
    );
}

#[test]
fn a_wall_on_a_layer_it_does_not_collide_with_does_not_stop_it() {
    let mut wall = slab(v(1.5, 1.0, 0.0), v(0.1, 1.0, 5.0), 0.0);
    wall.filter = CollisionFilter::new(2, u32::MAX);
    let through = |mask: u32| {
        let mut c = standing(0.0, 0.0);
        c.settings.filter = CollisionFilter::new(1, mask);
        let mut world = world(vec![floor(-10.0, 20.0), wall.clone()], vec![c]);
        for _ in 0..90 {
            walk(&mut world, v(2.0, 0.0, 0.0));
        }
        pos(&world, 0)[0]
    };
    assert!(through(u32::MAX) < 1.2, "the wall stops it");
    assert!(through(!2) > 2.5, "it walks through the other layer");
}
