//! What a world warns about: the broadphase's pair cap (named in the tick's report, and a
//! capped step still keeping the contacts with static bodies), where a tick's first
//! saturation happened, rigid bodies under the divergence check, and the scene builder's
//! mass-ratio warnings.

use fixstep::math::{Fx, Real, Vec3};
use fixstep::rigid::desc::BodyKind;
use fixstep::scene::{Scene, parse_scene};
use fixstep::world::{
    Command, DivergenceScale, Handle, Part, PlayerInput, SaturationSite, Stage, Target, TickInput,
    World,
};

/// 729 unit boxes (9 × 9 × 9, 1 cm apart) piled on one spot 2 m above a static ground box
/// whose top is at y = 0: 265,356 overlapping pairs, past the broadphase's cap.
pub const PILE: &str = "(name: \"pile\", rigid: (bodies: [
    (kind: Static, shape: Box(half_extents: (x: 20.0, y: 0.5, z: 20.0)),
     position: (x: 0.0, y: -0.5, z: 0.0)),
    (shape: Box(half_extents: (x: 0.5, y: 0.5, z: 0.5)), position: (x: 0.0, y: 2.0, z: 0.0),
     grid: Some((count: (9, 9, 9), spacing: (x: 0.01, y: 0.01, z: 0.01)))),
]))";

fn world(ron: &str) -> World<Fx> {
    let scene: Scene<Fx> = parse_scene(ron, "test.ron").expect("valid scene");
    scene.build().expect("builds")
}

/// The inputs of a tick without commands.
fn no_input(tick: u64) -> TickInput<Fx> {
    TickInput {
        tick,
        players: Vec::new(),
    }
}

/// Steps `world` `ticks` times without inputs.
fn run(world: &mut World<Fx>, ticks: u64) {
    for _ in 0..ticks {
        let tick = world.tick();
        world.step(&no_input(tick));
    }
}

/// The lowest centre of the world's dynamic bodies, m.
fn lowest_dynamic_centre(world: &World<Fx>) -> f64 {
    let rigid = world.rigid().expect("rigid bodies");
    rigid
        .handles()
        .filter(|&h| rigid.kind(h) == Some(BodyKind::Dynamic))
        .map(|h| rigid.position(h).expect("live").y.to_f64())
        .fold(f64::INFINITY, f64::min)
}

#[test]
fn a_capped_pile_is_reported_and_rests_on_the_ground() {
    let mut pile = world(PILE);
    let report = pile.step(&no_input(0));
    assert_eq!(report.capped_contact_steps, 1);
    // The cap is its own report, not a saturation.
    assert_eq!(report.saturations, 0);
    assert_eq!(report.first_saturation, None);
    // The boxes land after about 40 ticks; the ground holds them although they pass
    // through each other.
    run(&mut pile, 59);
    let health = pile.health();
    assert_eq!(health.first_capped_tick, Some(0));
    assert!(health.capped_ticks >= 40, "{health:?}");
    let lowest = lowest_dynamic_centre(&pile);
    assert!(lowest > 0.45, "a box fell to {lowest} m");
}

#[test]
fn a_capped_step_is_deterministic_across_a_restore() {
    let mut straight = world(PILE);
    run(&mut straight, 3);
    let snapshot = straight.snapshot();
    run(&mut straight, 3);
    // A fresh world, restored: its broadphase starts with another layout history.
    let mut restored = world(PILE);
    restored.restore(&snapshot);
    run(&mut restored, 3);
    assert_eq!(restored.checksum(), straight.checksum());
}

#[test]
fn a_saturation_names_the_stage_and_the_first_body_at_the_range_edge() {
    // A 1 kg box under 10⁹ m/s² of gravity: an intermediate saturates in the rigid stage of
    // the first tick, and the box's position reaches the range's edge about 124 ticks on.
    let mut world = world(
        "(name: \"edge\", gravity: (x: 0.0, y: -1000000000.0, z: 0.0), rigid: (bodies: [
            (shape: Box(half_extents: (x: 0.5, y: 0.5, z: 0.5)), density: 1.0),
        ]))",
    );
    let report = world.step(&no_input(0));
    assert!(report.saturations > 0, "{report:?}");
    assert_eq!(
        report.first_saturation,
        Some(SaturationSite {
            tick: 0,
            count: report.saturations,
            stage: Stage::Rigid,
            object: None,
        })
    );
    run(&mut world, 149);
    let health = world.health();
    assert_eq!(health.first_saturation, report.first_saturation);
    let (tick, part, handle) = health.first_saturated_object.expect("the box at the edge");
    assert!((110..140).contains(&tick), "{health:?}");
    assert_eq!((part, handle), (Part::Rigid, Handle::new(0, 0)));
    let y = world
        .rigid()
        .expect("rigid")
        .position(handle)
        .expect("live")
        .y;
    assert_eq!(y, Fx::MIN);
}

#[test]
fn the_divergence_check_covers_rigid_bodies() {
    // No particles and no soft bodies: the check watched nothing before it watched rigid
    // bodies. A box kicked from rest to 10 km/s: 5·10⁷ J/kg, far past 10⁴ times the floor.
    let mut world = world(
        "(name: \"kick\", rigid: (bodies: [
            (shape: Box(half_extents: (x: 0.5, y: 0.5, z: 0.5)), position: (x: 0.0, y: 0.5, z: 0.0)),
        ]))",
    );
    world.enable_divergence_check(1);
    run(&mut world, 2);
    assert_eq!(world.divergence(), None);
    let kick = TickInput {
        tick: world.tick(),
        players: vec![PlayerInput {
            player: 0,
            commands: vec![Command::SetVelocity {
                target: Target::Body(Handle::new(0, 0)),
                velocity: Vec3::new(Fx::from_int(10_000), Fx::ZERO, Fx::ZERO),
            }],
        }],
    };
    world.step(&kick);
    let divergence = world.divergence().expect("the kick counts as divergence");
    assert_eq!(divergence.tick, 3);
    assert_eq!(
        divergence.scale,
        DivergenceScale::RigidEnergyGainPerKilogram
    );
    assert!(world.health().divergence.is_some());
}

/// A unit box of density `density` (kg/m³, so its mass in kg) centred at height `y`.
fn unit_box(density: &str, y: &str) -> String {
    format!(
        "(shape: Box(half_extents: (x: 0.5, y: 0.5, z: 0.5)), position: (x: 0.0, y: {y}, z: 0.0),
          density: {density})"
    )
}

/// A scene of a static ground and `bodies`, with `joints` when given.
fn stack(bodies: &[String], joints: &str) -> String {
    format!(
        "(name: \"stack\", rigid: (bodies: [
            (kind: Static, shape: Plane(normal: (x: 0.0, y: 1.0, z: 0.0), offset: 0.0)),
            {}]){joints})",
        bodies.join(",")
    )
}

#[test]
fn a_heavy_box_on_a_light_one_is_warned_about_with_both_indices() {
    let built = world(&stack(
        &[unit_box("1.0", "0.5"), unit_box("100000.0", "1.5")],
        "",
    ));
    let warnings = built.warnings();
    assert_eq!(warnings.len(), 1, "{warnings:?}");
    assert!(
        warnings[0].starts_with(
            "rigid.bodies: bodies 1 (1 kg) and 2 (100000 kg) can touch, a mass ratio of \
             1:100000, past 1:100"
        ),
        "{warnings:?}"
    );
}

#[test]
fn a_heavy_box_between_two_light_ones_names_both_pairs() {
    let built = world(&stack(
        &[
            unit_box("0.1", "0.5"),
            unit_box("100000.0", "1.5"),
            unit_box("0.1", "2.5"),
        ],
        "",
    ));
    let warnings = built.warnings();
    assert_eq!(warnings.len(), 2, "{warnings:?}");
    assert!(warnings[0].contains("bodies 1 (0.1 kg) and 2 (100000 kg)"));
    assert!(warnings[1].contains("bodies 3 (0.1 kg) and 2 (100000 kg)"));
}

#[test]
fn ratios_within_the_limit_or_between_bodies_that_cannot_touch_build_quietly() {
    let within = world(&stack(
        &[unit_box("1.0", "0.5"), unit_box("100.0", "1.5")],
        "",
    ));
    assert_eq!(within.warnings(), Vec::<String>::new());
    // The heavy box is on a layer the light one ignores, and the reverse.
    let apart = world(&stack(
        &[
            unit_box("1.0", "0.5")
                .replace("density: 1.0", "density: 1.0, filter: (layers: 1, mask: 1)"),
            unit_box("100000.0", "1.5").replace(
                "density: 100000.0",
                "density: 100000.0, filter: (layers: 2, mask: 2)",
            ),
        ],
        "",
    ));
    assert_eq!(apart.warnings(), Vec::<String>::new());
}

#[test]
fn a_joint_between_a_heavy_and_a_light_body_is_warned_about() {
    let jointed = world(&stack(
        &[
            unit_box("1.0", "0.5")
                .replace("density: 1.0", "density: 1.0, filter: (layers: 1, mask: 1)"),
            unit_box("5000.0", "3.0").replace(
                "density: 5000.0",
                "density: 5000.0, filter: (layers: 2, mask: 2)",
            ),
        ],
        ", joints: (list: [(kind: Ball, bodies: (1, 2), anchor: (x: 0.0, y: 1.75, z: 0.0))])",
    ));
    let warnings = jointed.warnings();
    assert_eq!(warnings.len(), 1, "{warnings:?}");
    assert!(
        warnings[0].starts_with(
            "joints: joint 0 ties bodies 1 (1 kg) and 2 (5000 kg), a mass ratio of 1:5000"
        ),
        "{warnings:?}"
    );
}

#[test]
fn many_heavy_pairs_are_listed_up_to_five_then_counted() {
    let mut bodies = vec![unit_box("100000.0", "10.0")];
    for k in 0..8 {
        bodies.push(unit_box("1.0", &format!("{}.5", k * 2)));
    }
    let warnings = world(&stack(&bodies, "")).warnings();
    assert_eq!(warnings.len(), 6, "{warnings:?}");
    for (warning, light) in warnings[..5].iter().zip(2..) {
        assert!(
            warning.contains(&format!("bodies {light} (1 kg) and 1 (100000 kg)")),
            "{warning}"
        );
    }
    assert_eq!(
        warnings[5],
        "rigid.bodies: 3 more pairs of bodies that can touch or are jointed have mass ratios \
         past 1:100"
    );
}

#[test]
fn builtin_scenes_have_no_mass_ratio_warnings() {
    for (name, _) in fixstep_scenes::BUILTIN_SCENES {
        let scene: Scene<Fx> = fixstep_scenes::builtin_scene(name).expect("built in");
        let warnings = scene.build().expect("builds").warnings();
        assert!(
            warnings.iter().all(|w| !w.contains("mass ratio")),
            "{name}: {warnings:?}"
        );
    }
}
