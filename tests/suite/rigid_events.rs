//! Events, sensors, collision filters and spawning by input (issue [game-api]). Tolerances
//! come from the kinematics of free fall, not from this engine's output.

use fixstep::math::{Fx, Quat, Real, Vec3};
use fixstep::rigid::{
    BodyDesc, BodyKind, BodyTemplate, CollisionFilter, Event, EventKind, JointKind, JointTemplate,
    RigidDesc, Shape,
};
use fixstep::scene::Scene;
use fixstep::world::{Command, Handle, PlayerInput, TickInput, World};
use fixstep_scenes::builtin_scene;
use fixstep_scenes::rigid::ground;

const TICK_RATE: f64 = 60.0;
const G: f64 = 9.81;

fn v(x: f64, y: f64, z: f64) -> Vec3<Fx> {
    Vec3::new(Fx::from_f64(x), Fx::from_f64(y), Fx::from_f64(z))
}

fn ball(y: f64) -> BodyDesc<Fx> {
    BodyDesc::new(
        Shape::Sphere {
            radius: Fx::from_f64(0.25),
        },
        v(0.0, y, 0.0),
    )
}

fn scene_of(rigid: RigidDesc<Fx>) -> Scene<Fx> {
    let mut scene = Scene::empty("test");
    scene.rigid = Some(rigid);
    scene
}

/// Runs `ticks` ticks with the scene's script, returning every event.
fn events_of(world: &mut World<Fx>, scene: &Scene<Fx>, ticks: u64) -> Vec<Event> {
    let empty = TickInput::default();
    let mut events = Vec::new();
    for _ in 0..ticks {
        let input = scene.script_at(world.tick()).unwrap_or(&empty);
        events.extend(world.step(input).events);
    }
    events
}

fn count(events: &[Event], kind: EventKind) -> usize {
    events.iter().filter(|e| e.kind == kind).count()
}

#[test]
fn a_ball_resting_on_the_ground_begins_one_contact_and_never_ends_it() {
    let scene = scene_of(RigidDesc {
        bodies: vec![ground(), ball(1.0)],
        ..RigidDesc::default()
    });
    let mut world = scene.build().expect("builds");
    let events = events_of(&mut world, &scene, 300);
    assert_eq!(count(&events, EventKind::ContactBegin), 1, "{events:?}");
    assert_eq!(count(&events, EventKind::ContactEnd), 0, "{events:?}");
    let begin = events[0];
    assert_eq!(
        (begin.a, begin.b),
        (Handle::new(0, 0), Some(Handle::new(1, 0)))
    );
}

#[test]
fn a_ball_falls_through_a_sensor_plate_entering_at_the_free_fall_time() {
    let h = 2.0;
    let mut plate = BodyDesc::new(
        Shape::Box {
            half_extents: v(2.0, 0.05, 2.0),
        },
        v(0.0, -0.05, 0.0),
    )
    .fixed();
    plate.sensor = true;
    // The ball's lowest point starts h above the plate's top face (y = 0).
    let scene = scene_of(RigidDesc {
        bodies: vec![plate, ball(h + 0.25)],
        ..RigidDesc::default()
    });
    let mut world = scene.build().expect("builds");
    let events = events_of(&mut world, &scene, 120);
    let enters: Vec<&Event> = events
        .iter()
        .filter(|e| e.kind == EventKind::SensorEnter)
        .collect();
    assert_eq!(enters.len(), 1, "{events:?}");
    assert_eq!(count(&events, EventKind::SensorExit), 1, "{events:?}");
    assert_eq!(count(&events, EventKind::ContactBegin), 0, "{events:?}");
    let expected = (2.0 * h / G).sqrt() * TICK_RATE;
    let tick = enters[0].tick as f64;
    assert!(
        (tick - expected).abs() <= 1.0,
        "entered at tick {tick}, free fall says {expected:.2}"
    );
    // No contact impulse: the ball kept falling freely through the plate.
    let rigid = world.rigid().expect("rigid");
    let ball = Handle::new(1, 0);
    let vy = rigid.linear_velocity(ball).expect("live").y.to_f64();
    let t = 120.0 / TICK_RATE;
    assert!(
        (vy + G * t).abs() < 0.01 * G * t,
        "vy {vy}, free fall {}",
        -G * t
    );
}

#[test]
fn a_body_on_a_layer_the_ground_masks_out_falls_through_it() {
    let mut floor = BodyDesc::new(
        Shape::Box {
            half_extents: v(5.0, 0.5, 5.0),
        },
        v(0.0, -0.5, 0.0),
    )
    .fixed();
    floor.filter = CollisionFilter::new(1, 1);
    let mut ghost = ball(1.0);
    ghost.filter = CollisionFilter::new(2, u32::MAX);
    let solid = {
        let mut b = ball(1.0);
        b.position = v(3.0, 1.0, 0.0);
        b
    };
    let scene = scene_of(RigidDesc {
        bodies: vec![floor, ghost, solid],
        ..RigidDesc::default()
    });
    let mut world = scene.build().expect("builds");
    let events = events_of(&mut world, &scene, 120);
    let rigid = world.rigid().expect("rigid");
    assert!(rigid.position(Handle::new(1, 0)).expect("live").y.to_f64() < -5.0);
    assert!(rigid.position(Handle::new(2, 0)).expect("live").y.to_f64() > 0.2);
    assert_eq!(count(&events, EventKind::ContactBegin), 1, "{events:?}");
}

fn spawn(template: u32, position: Vec3<Fx>, velocity: Vec3<Fx>) -> Command<Fx> {
    Command::SpawnBody {
        template,
        position,
        orientation: Quat::IDENTITY,
        velocity,
        angular_velocity: Vec3::ZERO,
    }
}

fn input(tick: u64, commands: Vec<Command<Fx>>) -> TickInput<Fx> {
    TickInput {
        tick,
        players: vec![PlayerInput {
            player: 0,
            commands,
        }],
    }
}

#[test]
fn spawned_bodies_take_the_lowest_free_slot_and_joints_join_them() {
    let mut template = BodyTemplate::new(Shape::Sphere {
        radius: Fx::from_f64(0.25),
    });
    template.filter = CollisionFilter::new(4, 1);
    let rigid = RigidDesc {
        bodies: vec![ground(), ball(3.0), ball(5.0)],
        templates: vec![template],
        joint_templates: vec![JointTemplate {
            kind: JointKind::Ball,
            collide: false,
            break_force: None,
            break_torque: None,
        }],
        ..RigidDesc::default()
    };
    let mut world = scene_of(rigid).build().expect("builds");
    let report = world.step(&input(
        0,
        vec![
            Command::Remove {
                target: fixstep::world::Target::Body(Handle::new(1, 0)),
            },
            spawn(0, v(0.0, 2.0, 0.0), v(1.0, 0.0, 0.0)),
            spawn(0, v(0.0, 4.0, 0.0), Vec3::ZERO),
        ],
    ));
    assert_eq!(report.ignored_commands, 0);
    let rigid = world.rigid().expect("rigid");
    assert_eq!(rigid.spawned(), &[Handle::new(1, 1), Handle::new(3, 0)]);
    assert_eq!(rigid.body_count(), 4);
    let joined = world.step(&input(
        1,
        vec![Command::SpawnJoint {
            template: 0,
            bodies: (Handle::new(1, 1), Handle::new(3, 0)),
            anchor: v(0.0, 3.0, 0.0),
            anchor_b: None,
            axis: Vec3::X,
        }],
    ));
    assert_eq!(joined.ignored_commands, 0);
    assert_eq!(
        world.rigid().expect("rigid").spawned_joints(),
        &[Handle::new(0, 0)]
    );
    // An unknown template and a stale body are ignored, not fatal.
    let bad = world.step(&input(
        2,
        vec![
            spawn(7, Vec3::ZERO, Vec3::ZERO),
            Command::SpawnJoint {
                template: 0,
                bodies: (Handle::new(1, 0), Handle::new(3, 0)),
                anchor: Vec3::ZERO,
                anchor_b: None,
                axis: Vec3::X,
            },
        ],
    ));
    assert_eq!(bad.ignored_commands, 2);
}

#[test]
fn a_removed_body_ends_its_contacts() {
    let scene = scene_of(RigidDesc {
        bodies: vec![ground(), ball(0.25)],
        ..RigidDesc::default()
    });
    let mut world = scene.build().expect("builds");
    events_of(&mut world, &scene, 10);
    let report = world.step(&input(
        10,
        vec![Command::Remove {
            target: fixstep::world::Target::Body(Handle::new(1, 0)),
        }],
    ));
    assert_eq!(
        report.events,
        vec![Event {
            tick: 10,
            kind: EventKind::ContactEnd,
            a: Handle::new(0, 0),
            b: Some(Handle::new(1, 0)),
        }]
    );
}

#[test]
fn a_script_spawning_an_unknown_template_or_past_the_limit_is_refused_by_field() {
    let mut scene = scene_of(RigidDesc {
        bodies: vec![ground()],
        templates: vec![BodyTemplate::new(Shape::Sphere { radius: Fx::ONE })],
        ..RigidDesc::default()
    });
    scene.script = vec![input(
        3,
        vec![
            spawn(0, Vec3::ZERO, Vec3::ZERO),
            spawn(2, Vec3::ZERO, Vec3::ZERO),
        ],
    )];
    let e = scene.build().expect_err("refused").to_string();
    assert!(
        e.contains("script[0].players[0].commands[1].template"),
        "{e}"
    );
    assert!(e.contains("template 2"), "{e}");

    let mut grid = ball(0.0);
    grid.kind = BodyKind::Static;
    grid.grid = Some(fixstep::rigid::Grid {
        count: (512, 512, 1),
        spacing: v(1.0, 0.0, 0.0),
    });
    let mut full = scene_of(RigidDesc {
        bodies: vec![grid],
        templates: vec![BodyTemplate::new(Shape::Sphere { radius: Fx::ONE })],
        ..RigidDesc::default()
    });
    full.script = vec![input(0, vec![spawn(0, Vec3::ZERO, Vec3::ZERO)])];
    let e = full.build().expect_err("refused").to_string();
    assert!(e.contains("script[0].players[0].commands[0]"), "{e}");
    assert!(e.contains("past the limit"), "{e}");
}

#[test]
fn a_negative_filter_in_a_scene_file_is_refused_by_field() {
    let text =
        "(name: \"x\", rigid: (bodies: [(shape: Sphere(radius: 1.0), filter: (layers: -1))]))";
    let e = fixstep::scene::parse_scene::<Fx>(text, "x.ron")
        .expect_err("refused")
        .to_string();
    assert!(e.contains("x.ron"), "{e}");
    assert!(e.contains("line 1"), "{e}");
}

/// The shooter's events and checksums over its run.
fn shooter_run(scene: &Scene<Fx>) -> (Vec<Event>, Vec<u64>) {
    let mut world = scene.build().expect("builds");
    let empty = TickInput::default();
    let mut events = Vec::new();
    let mut sums = Vec::new();
    for _ in 0..scene.ticks {
        let input = scene.script_at(world.tick()).unwrap_or(&empty);
        events.extend(world.step(input).events);
        sums.push(world.checksum().total);
    }
    (events, sums)
}

#[test]
fn the_shooter_hits_the_wall_and_the_plate_counts_arrivals() {
    let scene = builtin_scene::<Fx>("shooter").expect("built in");
    let (events, _) = shooter_run(&scene);
    assert!(count(&events, EventKind::ContactBegin) > 8, "{events:?}");
    assert!(count(&events, EventKind::SensorEnter) >= 1, "{events:?}");
    assert!(events.windows(2).all(|w| w[0] <= w[1]), "canonical order");
}

#[test]
fn restoring_at_every_tick_and_resimulating_gives_the_same_events_and_checksums() {
    let mut scene = builtin_scene::<Fx>("shooter").expect("built in");
    scene.ticks = 360;
    let (straight_events, straight_sums) = shooter_run(&scene);
    let mut world = scene.build().expect("builds");
    let empty = TickInput::default();
    let mut events = Vec::new();
    let mut sums = Vec::new();
    for _ in 0..scene.ticks {
        // Predict a tick with no input, roll it back, then simulate it for real.
        let saved = world.snapshot();
        world.step(&empty);
        world.restore(&saved);
        let input = scene.script_at(world.tick()).unwrap_or(&empty);
        events.extend(world.step(input).events);
        sums.push(world.checksum().total);
    }
    assert_eq!(sums, straight_sums);
    assert_eq!(events, straight_events);
}

#[test]
fn the_shooter_replay_carries_its_sight_queries() {
    use fixstep::replay::Replay;
    use fixstep::rigid::QueryFilter;
    use fixstep_scenes::game::{SIGHT_RANGE, WORLD, muzzle, sight_payload};
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("replays/shooter.replay");
    let replay = Replay::read(&path).unwrap_or_else(|e| panic!("{e}"));
    let mut world = replay.scene().build().expect("builds");
    let mut checked = 0;
    for input in replay.inputs() {
        while world.tick() < input.tick {
            world.step(&TickInput::default());
        }
        for command in input.players.iter().flat_map(|p| &p.commands) {
            let Command::Payload(recorded) = *command else {
                continue;
            };
            let velocity = input
                .players
                .iter()
                .flat_map(|p| &p.commands)
                .find_map(|c| match c {
                    Command::SpawnBody { velocity, .. } => Some(*velocity),
                    _ => None,
                })
                .expect("a shot with the sight");
            let seen = world.cast_ray(
                muzzle(),
                velocity,
                Fx::from_int(SIGHT_RANGE),
                &QueryFilter::new().with_mask(WORLD),
            );
            assert_eq!(
                sight_payload(seen.as_ref()),
                recorded,
                "tick {}",
                input.tick
            );
            checked += 1;
        }
        world.step(input);
    }
    assert_eq!(checked, 8);
}
