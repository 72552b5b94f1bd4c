//! `Simulation` feeds a scene's script tick by tick (also after a rollback), and reading
//! and building a scene fail with one error type that names the file, line and field.

use fixstep::prelude::*;

/// A ball on the ground that the script kicks sideways at tick 10 (player 0, 1 N·s).
const KICKED: &str = r#"(
    name: "kicked",
    gravity: (x: 0.0, y: 0.0, z: 0.0),
    rigid: (bodies: [(shape: Sphere(radius: 0.5))]),
    script: [(tick: 10, players: [(player: 0, commands: [
        ApplyImpulse(target: Body((index: 0, generation: 0)), impulse: (x: 1.0, y: 0.0, z: 0.0)),
    ])])],
)"#;

fn kicked() -> Scene<Fx> {
    parse_scene(KICKED, "kicked.ron").expect("the scene reads")
}

fn velocity_x(world: &World<Fx>) -> Fx {
    let rigid = world.rigid().expect("rigid bodies");
    let ball = rigid.handles().next().expect("the ball");
    rigid.linear_velocity(ball).expect("alive").x
}

#[test]
fn a_simulation_feeds_the_script_at_its_tick() {
    let scene = kicked();
    let mut simulation = Simulation::new(&scene).expect("builds");
    for _ in 0..10 {
        assert!(simulation.scripted().is_none());
        simulation.step();
    }
    assert_eq!(velocity_x(simulation.world()), Fx::ZERO);
    assert_eq!(simulation.scripted(), scene.script_at(10));
    simulation.step();
    assert!(velocity_x(simulation.world()) > Fx::ZERO);

    // The same as feeding `script_at` to the world by hand.
    let mut world = scene.build().expect("builds");
    for tick in 0..30 {
        let input = scene.script_at(tick).cloned().unwrap_or_default();
        world.step(&input);
    }
    for _ in 11..30 {
        simulation.step();
    }
    assert_eq!(world.checksum(), simulation.world().checksum());
}

#[test]
fn a_simulation_feeds_the_script_again_after_a_rollback() {
    let mut simulation = Simulation::new(&kicked()).expect("builds");
    for _ in 0..5 {
        simulation.step();
    }
    let saved = simulation.world().snapshot();
    for _ in 0..20 {
        simulation.step();
    }
    let first = simulation.world().checksum();
    simulation.world_mut().restore(&saved);
    for _ in 0..20 {
        simulation.step();
    }
    assert_eq!(simulation.world().checksum(), first);
}

#[test]
fn step_with_adds_the_games_commands_after_the_scripts() {
    let scene = kicked();
    let mut simulation = Simulation::new(&scene).expect("builds");
    let ball = simulation
        .world()
        .rigid()
        .expect("rigid")
        .handles()
        .next()
        .expect("ball");
    for _ in 0..10 {
        simulation.step();
    }
    // At tick 10 the script's 1 N·s and the game's 2 N·s both apply.
    let push = Command::ApplyImpulse {
        target: Target::Body(ball),
        impulse: Vec3::new(Fx::from_int(2), Fx::ZERO, Fx::ZERO),
        point: None,
    };
    simulation.step_with(&[PlayerInput {
        player: 0,
        commands: vec![push],
    }]);
    let with_both = velocity_x(simulation.world());

    let mut scripted_only = Simulation::new(&scene).expect("builds");
    for _ in 0..11 {
        scripted_only.step();
    }
    let script_alone = velocity_x(scripted_only.world());
    assert_eq!(with_both, script_alone * Fx::from_int(3));
}

#[test]
fn a_reading_error_names_the_file_and_line() {
    let error = parse_scene::<Fx>("(\n  name: \"x\",\n  tick_rate: \"fast\",\n)", "bad.ron")
        .expect_err("refused");
    assert_eq!(error.file.as_deref(), Some("bad.ron"));
    assert_eq!(error.line.map(|(line, _)| line), Some(3));
    let text = error.to_string();
    assert!(text.starts_with("bad.ron: line 3, column "), "{text}");
    assert!(!text.contains('\n'), "{text}");
}

#[test]
fn a_building_error_names_the_field_and_the_file_once_known() {
    let scene = parse_scene::<Fx>("(name: \"x\", tick_rate: 0)", "zero.ron").expect("reads");
    let error = scene.build().expect_err("a tick rate of 0 is refused");
    assert_eq!(
        error.to_string(),
        "field `tick_rate`: must be 1 to 10000 (got 0)"
    );
    assert_eq!(
        error.with_file("zero.ron").to_string(),
        "zero.ron: field `tick_rate`: must be 1 to 10000 (got 0)"
    );
    assert_eq!(
        SceneError::in_file("gone.ron", "cannot read: no such file").to_string(),
        "gone.ron: cannot read: no such file"
    );
}
