//! The height-field water surface: waves travel at c = √(g·depth), the volume is kept to
//! the last bit, open borders let waves out, floating particles bob at their natural
//! frequency, floating bodies settle where Archimedes says, bad fields are named, and a
//! snapshot continues with the same checksums.

use fixstep::math::{Fx, Real};
use fixstep::replay::scene_id;
use fixstep::scene::{Scene, parse_scene};
use fixstep::types::{Command, PlayerInput};
use fixstep::world::{Part, TickInput, World, decode_snapshot, encode_snapshot};

fn scene(text: &str) -> Scene<Fx> {
    parse_scene::<Fx>(text, "water.ron").expect("the scene reads")
}

fn build(text: &str) -> World<Fx> {
    scene(text).build().expect("the scene builds")
}

fn fx(v: f64) -> Fx {
    Fx::from_f64(v)
}

fn disturb(x: f64, z: f64, height: f64, radius: f64) -> TickInput<Fx> {
    TickInput {
        tick: 0,
        players: vec![PlayerInput {
            player: 0,
            commands: vec![Command::DisturbWater {
                x: fx(x),
                z: fx(z),
                height: fx(height),
                radius: fx(radius),
            }],
        }],
    }
}

/// The x (m) of the highest surface point among cells whose centre lies beyond `from`
/// (m), refined by the parabola through the highest cell and its neighbours.
fn crest_beyond(world: &World<Fx>, from: f64) -> f64 {
    let water = world.water().expect("water");
    let s = water.settings();
    let size = s.cell_size.to_f64();
    let u: Vec<f64> = water.heights().iter().map(|h| h.to_f64()).collect();
    let first = ((from - s.origin.x.to_f64()) / size) as usize;
    let top = (first..u.len() - 1)
        .max_by(|&a, &b| u[a].total_cmp(&u[b]))
        .expect("cells");
    let (l, c, r) = (u[top - 1], u[top], u[top + 1]);
    let shift = 0.5 * (l - r) / (l - 2.0 * c + r);
    s.origin.x.to_f64() + (top as f64 + 0.5 + shift) * size
}

/// A channel 20 m long, 1 m deep: c = √(9.81 · 1) = 3.132 m/s.
const CHANNEL: &str = r#"(
    name: "channel",
    water_surface: Some((
        origin: (x: 0.0, y: 0.0, z: 0.0),
        cells: (400, 1),
        cell_size: 0.05,
        depth: 1.0,
    )),
)"#;

#[test]
fn a_wave_travels_at_the_shallow_water_speed() {
    let mut world = build(CHANNEL);
    let c = (9.81f64 * 1.0).sqrt();
    world.step(&disturb(5.0, 0.025, 0.02, 0.5));
    let empty = TickInput::default();
    // From 0.5 s to 1.5 s after the drop, the right-going half's crest.
    for _ in 1..30 {
        world.step(&empty);
    }
    let x1 = crest_beyond(&world, 5.5);
    for _ in 0..60 {
        world.step(&empty);
    }
    let x2 = crest_beyond(&world, 5.5);
    let speed = (x2 - x1) / 1.0;
    let error = (speed - c).abs() / c;
    eprintln!("crest speed {speed:.5} m/s, c = {c:.5} m/s");
    assert!(
        error < 0.02,
        "crest speed {speed:.4} m/s against c = {c:.4} m/s ({:.2} %)",
        100.0 * error
    );
}

#[test]
fn the_volume_is_conserved_to_the_last_bit() {
    let mut world = build(
        r#"(
        name: "basin",
        water_surface: Some((
            origin: (x: -2.0, y: 0.5, z: -1.5),
            cells: (32, 24),
            cell_size: 0.125,
            depth: 0.8,
            damping: 0.3,
        )),
    )"#,
    );
    world.step(&disturb(-0.7, 0.2, 0.05, 0.6));
    let water = world.water().expect("water");
    let after_drop = water.height_bits_sum();
    let first = water.heights().to_vec();
    assert_ne!(after_drop, 0, "the drop added water");
    let (input, empty) = (disturb(1.1, -0.4, -0.03, 0.4), TickInput::default());
    for tick in 1..600 {
        let report = world.step(if tick == 200 { &input } else { &empty });
        assert_eq!(report.saturations, 0);
        let sum = world.water().expect("water").height_bits_sum();
        if tick < 200 {
            assert_eq!(sum, after_drop, "tick {tick}");
        }
    }
    let water = world.water().expect("water");
    assert_ne!(water.heights(), &first[..], "the waves moved");
    let second = {
        let mut w = build(
            r#"(name: "b", water_surface: Some((origin: (x: -2.0, y: 0.5, z: -1.5),
            cells: (32, 24), cell_size: 0.125, depth: 0.8)))"#,
        );
        w.step(&disturb(1.1, -0.4, -0.03, 0.4));
        w.water().expect("water").height_bits_sum()
    };
    assert_eq!(
        water.height_bits_sum(),
        after_drop + second,
        "each drop adds its own volume and nothing else changes the sum"
    );
}

#[test]
fn an_open_border_lets_waves_out() {
    let open = CHANNEL.replace("depth: 1.0,", "depth: 1.0, border: Open,");
    let mut world = build(&open);
    world.step(&disturb(10.0, 0.025, 0.02, 0.5));
    let start = world.water().expect("water").volume().to_f64();
    let peak = 0.02f64;
    for _ in 0..240 {
        world.step(&TickInput::default());
    }
    let water = world.water().expect("water");
    let left = water
        .heights()
        .iter()
        .map(|u| u.to_f64().abs())
        .fold(0.0, f64::max);
    let kept = water.volume().to_f64();
    assert!(
        left < 0.03 * peak,
        "what is left is {left} m, against a peak of {peak} m"
    );
    assert!(kept.abs() < 0.03 * start, "{kept} m³ of {start} m³ left");
}

/// A 1 kg particle floating as a column of 0.1 × 0.1 m, 0.2 m tall: at rest half
/// submerged (depth d = m / (ρ A) = 0.1 m), at y = 0.
const BOBBER: &str = r#"(
    name: "bobber",
    particles: Some((
        particles: [(position: (x: 0.0, y: 0.03, z: 0.0), group: 3)],
        forces: [Gravity()],
    )),
    water_surface: Some((
        origin: (x: -1.0, y: 0.0, z: -1.0),
        cells: (8, 8),
        cell_size: 0.25,
        depth: 0.5,
        particles: [(group: 3, volume: 0.002, height: 0.2)],
    )),
)"#;

#[test]
fn a_floating_particle_bobs_at_its_natural_frequency() {
    // A column of cross-section A displaced by y from rest feels −ρ g A y more than its
    // weight: ω² = ρ g A / m.
    let (rho, g, area, mass) = (1000.0f64, 9.81, 0.01, 1.0);
    let omega = (rho * g * area / mass).sqrt();
    let mut world = build(BOBBER);
    let handle = world
        .particles()
        .expect("particles")
        .handles()
        .next()
        .expect("one");
    let mut ys = vec![
        world
            .particles()
            .unwrap()
            .position(handle)
            .unwrap()
            .y
            .to_f64(),
    ];
    for _ in 0..240 {
        world.step(&TickInput::default());
        ys.push(
            world
                .particles()
                .unwrap()
                .position(handle)
                .unwrap()
                .y
                .to_f64(),
        );
    }
    // Downward crossings of the rest height, interpolated.
    let dt = 1.0 / 60.0;
    let crossings: Vec<f64> = ys
        .windows(2)
        .enumerate()
        .filter(|(_, w)| w[0] > 0.0 && w[1] <= 0.0)
        .map(|(i, w)| (i as f64 + w[0] / (w[0] - w[1])) * dt)
        .collect();
    assert!(crossings.len() >= 5, "{crossings:?}");
    let periods = (crossings.len() - 1) as f64;
    let measured = std::f64::consts::TAU * periods / (crossings.last().unwrap() - crossings[0]);
    let error = (measured - omega).abs() / omega;
    eprintln!("bobbing: ω = {measured:.5} rad/s, √(ρgA/m) = {omega:.5} rad/s");
    assert!(
        error < 0.03,
        "ω = {measured:.4} rad/s against √(ρgA/m) = {omega:.4} ({:.2} %)",
        100.0 * error
    );
    let top = ys.iter().copied().fold(f64::MIN, f64::max);
    assert!(
        (top - 0.03).abs() < 0.003,
        "no drag, so the amplitude stays: {top}"
    );
}

#[test]
fn floating_bodies_settle_where_archimedes_says() {
    // A ball of density 500 floats half submerged (centre at the surface); a box of
    // density 250 and 0.4 m tall sinks 0.1 m (centre 0.1 m above the surface).
    let mut world = build(
        r#"(
        name: "floats",
        rigid: Some((bodies: [
            (shape: Sphere(radius: 0.25), position: (x: -1.0, y: 0.6, z: 0.0), density: 500.0),
            (shape: Box(half_extents: (x: 0.3, y: 0.2, z: 0.3)),
             position: (x: 1.0, y: 0.5, z: 0.0), density: 250.0),
        ])),
        water_surface: Some((
            origin: (x: -3.0, y: 0.0, z: -2.0),
            cells: (24, 16),
            cell_size: 0.25,
            depth: 1.0,
            bodies: Some((drag: 4.0, angular_drag: 4.0)),
        )),
    )"#,
    );
    for _ in 0..900 {
        world.step(&TickInput::default());
    }
    let rigid = world.rigid().expect("bodies");
    let handles: Vec<_> = rigid.handles().collect();
    let ball = rigid.position(handles[0]).expect("ball").y.to_f64();
    let block = rigid.position(handles[1]).expect("box").y.to_f64();
    eprintln!("floating: ball centre {ball:.5} m, box centre {block:.5} m");
    assert!(ball.abs() < 0.005, "the ball's centre is at {ball} m");
    assert!(
        (block - 0.1).abs() < 0.005,
        "the box's centre is at {block} m"
    );
}

#[test]
fn bad_fields_are_named() {
    let field = |text: &str| {
        scene(text)
            .build()
            .map(|_| ())
            .expect_err("the scene is refused")
            .field
    };
    let with = |extra: &str| {
        format!(
            r#"(name: "w", water_surface: Some((origin: (x: 0.0, y: 0.0, z: 0.0),
            cells: (4, 4), cell_size: 0.5, depth: 1.0, {extra})))"#
        )
    };
    assert_eq!(field(&with("damping: -1.0")), "water_surface.damping");
    assert_eq!(
        field(&with("wave_speed: Some(0.0)")),
        "water_surface.wave_speed"
    );
    assert_eq!(field(&with("density: 0.0")), "water_surface.density");
    assert_eq!(
        field(&with("particles: [(group: 0, volume: 0.0, height: 1.0)]")),
        "water_surface.particles[0].volume"
    );
    assert_eq!(
        field(&with(
            "particles: [(group: 0, volume: 1.0, height: 1.0), (group: 0, volume: 1.0, height: 1.0)]"
        )),
        "water_surface.particles[1].group"
    );
    assert_eq!(
        field(&with("bodies: Some((drag: -1.0))")),
        "water_surface.bodies.drag"
    );
    let text = with("").replace("cells: (4, 4)", "cells: (0, 4)");
    assert_eq!(field(&text), "water_surface.cells");
    let text = with("wave_speed: Some(900.0)").replace("cell_size: 0.5", "cell_size: 0.01");
    assert_eq!(field(&text), "water_surface.cell_size");
}

#[test]
fn a_disturbance_without_water_is_ignored() {
    let mut world = build(r#"(name: "dry")"#);
    let report = world.step(&disturb(0.0, 0.0, 1.0, 1.0));
    assert_eq!(report.ignored_commands, 1);
    assert!(
        world
            .checksum()
            .parts
            .iter()
            .all(|(part, _)| *part != Part::Water)
    );
}

#[test]
fn snapshot_mid_run_continues_with_the_same_checksums() {
    let scene = scene(BOBBER);
    let mut straight = scene.build().expect("builds");
    let mut resumed = scene.build().expect("builds");
    let drop = disturb(0.3, -0.2, 0.05, 0.5);
    straight.step(&drop);
    resumed.step(&drop);
    let empty = TickInput::default();
    for _ in 0..20 {
        straight.step(&empty);
        resumed.step(&empty);
    }
    let bytes =
        encode_snapshot(&resumed.snapshot(), &scene_id(&scene).expect("id")).expect("encodes");
    let state = decode_snapshot::<Fx>(&bytes).expect("decodes").state;
    let mut restored = World::from_state(state);
    for _ in 0..20 {
        straight.step(&empty);
        restored.step(&empty);
    }
    let a = straight.checksum();
    assert!(a.parts.iter().any(|(part, _)| *part == Part::Water));
    assert_eq!(a, restored.checksum());
}

#[test]
fn the_pond_floats_its_corks_and_boxes_and_sinks_its_crate() {
    let scene = fixstep_scenes::builtin_scene::<Fx>("pond").expect("built in");
    let mut world = scene.build().expect("builds");
    let mut simulation_ticks = 0;
    for tick in 0..scene.ticks {
        let input = scene.script_at(tick).cloned().unwrap_or_default();
        let report = world.step(&input);
        assert_eq!(report.saturations, 0, "tick {tick}");
        assert_eq!(report.ignored_commands, 0, "tick {tick}");
        simulation_ticks += 1;
    }
    assert_eq!(simulation_ticks, 300);
    let rigid = world.rigid().expect("bodies");
    let y: Vec<f64> = rigid
        .handles()
        .map(|h| rigid.position(h).expect("alive").y.to_f64())
        .collect();
    for (k, &height) in y.iter().enumerate().take(5).skip(1) {
        assert!(
            height.abs() < 0.3,
            "body {k} floats near the surface: {height} m"
        );
    }
    assert!(
        (y[5] + 0.3).abs() < 0.01,
        "the crate rests on the floor: {}",
        y[5]
    );
    let particles = world.particles().expect("corks");
    for h in particles.handles() {
        let cork = particles.position(h).expect("alive").y.to_f64();
        assert!(cork.abs() < 0.2, "a cork floats: {cork} m");
    }
}
