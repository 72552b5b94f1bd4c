//! The README's "Limits" section, measured: each test pins one sentence of it, so a change
//! that lifts or moves a limit fails here and the README is updated with it.

use fixstep::prelude::*;

/// The height of body `index` after `ticks` ticks of the scene `ron`.
fn height_after(ron: &str, index: usize, ticks: u64) -> f64 {
    let scene = parse_scene::<Fx>(ron, "limit.ron").expect("the scene reads");
    let mut simulation = Simulation::new(&scene).expect("the scene builds");
    for _ in 0..ticks {
        simulation.step();
    }
    let rigid = simulation.world().rigid().expect("rigid bodies");
    let body = rigid.handles().nth(index).expect("the body exists");
    rigid.position(body).expect("alive").y.to_f64()
}

/// A 5 cm ball at `speed` m/s down onto a 2 cm slab of `kind` 2 m below it, without
/// gravity: the ball's height after two seconds.
fn ball_at_slab(kind: &str, speed: f64, bullet: bool) -> f64 {
    let ron = format!(
        "(name: \"tunnel\", gravity: (x: 0.0, y: 0.0, z: 0.0), rigid: (bodies: [
            (kind: {kind}, shape: Box(half_extents: (x: 1.0, y: 0.01, z: 1.0))),
            (shape: Sphere(radius: 0.025), position: (x: 0.0, y: 2.0, z: 0.0),
             velocity: (x: 0.0, y: {}, z: 0.0), bullet: {bullet}),
        ]))",
        -speed
    );
    height_after(&ron, 1, 120)
}

#[test]
fn a_small_fast_ball_stops_on_a_thin_static_slab() {
    // Dropped from 3 m: 7.7 m/s; and far faster.
    for speed in [7.7, 2000.0] {
        let y = ball_at_slab("Static", speed, false);
        assert!(
            (0.0..0.1).contains(&y),
            "{speed} m/s: the ball ends at {y} m"
        );
    }
}

#[test]
fn a_small_fast_ball_passes_through_a_thin_dynamic_slab_unless_it_is_a_bullet() {
    let y = ball_at_slab("Dynamic", 7.7, false);
    assert!(
        y < -1.0,
        "the ball ends at {y} m: has dynamic CCD landed? update the README"
    );
    let y = ball_at_slab("Dynamic", 7.7, true);
    assert!(y > -0.1, "the bullet ends at {y} m");
}

/// A unit box of `heavy` kg resting on a unit box of 1 kg on the ground: how far the top
/// box sank into the bottom one after ten seconds, m.
fn sinking(heavy: f64) -> f64 {
    let ron = format!(
        "(name: \"ratio\", rigid: (bodies: [
            (kind: Static, shape: Plane(normal: (x: 0.0, y: 1.0, z: 0.0), offset: 0.0)),
            (shape: Box(half_extents: (x: 0.5, y: 0.5, z: 0.5)), position: (x: 0.0, y: 0.5, z: 0.0),
             density: 1.0),
            (shape: Box(half_extents: (x: 0.5, y: 0.5, z: 0.5)), position: (x: 0.0, y: 1.5, z: 0.0),
             density: {heavy}),
        ]))"
    );
    let bottom = height_after(&ron, 1, 600);
    let top = height_after(&ron, 2, 600);
    1.0 - (top - bottom)
}

#[test]
fn a_heavy_box_sinks_into_a_light_one_and_passes_through_from_about_1_to_700() {
    let at_100 = sinking(100.0);
    assert!((0.005..0.02).contains(&at_100), "1:100 sinks {at_100} m");
    let at_500 = sinking(500.0);
    assert!((0.03..0.1).contains(&at_500), "1:500 sinks {at_500} m");
    let at_700 = sinking(700.0);
    assert!(
        at_700 > 0.9,
        "1:700 sinks {at_700} m: the heavy box should pass through"
    );
}

#[test]
fn the_broadphase_pair_cap_is_the_readmes() {
    let cap = fixstep::rigid::broadphase::MAX_PAIRS;
    assert_eq!(cap, 262_144);
    // About 725 bodies heaped on one spot: their n (n − 1) / 2 pairs pass the cap.
    let heap = (2..)
        .find(|n| n * (n - 1) / 2 > cap)
        .expect("some heap passes it");
    assert_eq!(heap, 725);
}

#[test]
fn the_scene_size_limits_are_the_readmes() {
    assert_eq!(fixstep::rigid::desc::MAX_BODIES, 262_144);
    assert_eq!(fixstep::rigid::joints::desc::MAX_JOINTS, 262_144);
    assert_eq!(fixstep::soft::desc::MAX_VERTICES, 262_144);
    assert_eq!(fixstep::fluid::desc::MAX_FLUID_PARTICLES, 1_048_576);
}
