//! The plugin in Bevy's `FixedUpdate` (no GGRS): startup entities become the scene, poses
//! reach `Transform`, events arrive as messages with their entities, queries answer with
//! entities, joints and characters are linked, and a run-time spawn and despawn become
//! commands that the replay holds.

use bevy::prelude::*;
use fixstep::character::CharacterDesc;
use fixstep::math::{Fx, Real, Vec3 as FxVec3};
use fixstep::replay::{VerifyOutcome, verify};
use fixstep::rigid::{EventKind, JointDesc, JointKind, QueryFilter, Shape};
use fixstep::scene::Scene;
use fixstep::world::Command;
use fixstep_bevy::box_game::{crate_body, crate_shape, scene};
use fixstep_bevy::prelude::*;

#[derive(Component)]
struct Ball;

#[derive(Resource, Default)]
struct Seen(Vec<PhysicsEvent>);

fn collect(mut reader: MessageReader<PhysicsEvent>, mut seen: ResMut<Seen>) {
    seen.0.extend(reader.read().copied());
}

fn fx(n: i64, d: i64) -> Fx {
    Fx::from_ratio(n, d)
}

fn level(mut commands: Commands) {
    commands.spawn((
        RigidBody::fixed(),
        Collider(Shape::Plane {
            normal: FxVec3::Y,
            offset: Fx::ZERO,
        }),
    ));
    let a = commands
        .spawn((
            Ball,
            RigidBody::dynamic(),
            Collider(Shape::Sphere { radius: fx(1, 4) }),
            FixedTransform::from_position(FxVec3::new(Fx::ZERO, fx(1, 1), Fx::ZERO)),
        ))
        .id();
    let b = commands
        .spawn((
            crate_body(),
            Collider(crate_shape()),
            FixedTransform::from_position(FxVec3::new(fx(3, 1), fx(3, 10), Fx::ZERO)),
        ))
        .id();
    commands.spawn(Joint {
        a,
        b,
        desc: JointDesc::new(
            JointKind::Ball,
            0,
            0,
            FxVec3::new(fx(3, 1), fx(1, 1), Fx::ZERO),
        ),
    });
    let mut character = CharacterDesc::new(
        Shape::Capsule {
            radius: fx(3, 10),
            half_height: fx(1, 2),
        },
        FxVec3::new(fx(-3, 1), fx(1, 1), Fx::ZERO),
    );
    character.position = FxVec3::new(fx(-3, 1), fx(1, 1), Fx::ZERO);
    commands.spawn(Character(character));
}

fn app(scene: Scene<Fx>) -> App {
    let mut app = App::new();
    app.add_plugins(MinimalPlugins)
        .add_plugins(FixstepPlugin::new(scene))
        .init_resource::<Seen>()
        .add_systems(Startup, level)
        .add_systems(FixedUpdate, collect.after(FixstepSystems::Step));
    app.update();
    app
}

fn step(app: &mut App, ticks: u32) {
    for _ in 0..ticks {
        app.world_mut().run_schedule(FixedUpdate);
    }
}

#[test]
fn startup_entities_become_the_scene_and_stay_linked() {
    let mut app = app(scene());
    let world = app.world().resource::<FixstepWorld>();
    assert_eq!(world.world().tick(), 0);
    let rigid = world.world().rigid().unwrap();
    assert_eq!(rigid.body_count(), 3);
    assert_eq!(world.scene().joints.as_ref().unwrap().list.len(), 1);
    assert_eq!(world.scene().characters.len(), 1);
    let links: Vec<BodyLink> = app
        .world_mut()
        .query::<&BodyLink>()
        .iter(app.world())
        .copied()
        .collect();
    assert_eq!(links.len(), 3);
    let joints = app
        .world_mut()
        .query::<&JointLink>()
        .iter(app.world())
        .count();
    let characters = app
        .world_mut()
        .query::<&CharacterLink>()
        .iter(app.world())
        .count();
    assert_eq!((joints, characters), (1, 1));
}

#[test]
fn poses_reach_transform_and_the_ball_lands_with_an_event() {
    let mut app = app(scene());
    step(&mut app, 60);
    let (pose, transform, ball) = app
        .world_mut()
        .query_filtered::<(&FixedTransform, &Transform, Entity), With<Ball>>()
        .single(app.world())
        .map(|(p, t, e)| (*p, *t, e))
        .unwrap();
    // The ball (radius 1/4 m) fell 3/4 m onto the floor.
    let y = pose.position.y.to_f64();
    assert!((y - 0.25).abs() < 0.01, "ball at y = {y}");
    // `Update` has not run since: Transform holds the value of the last `update`; run one.
    app.update();
    let transform_after = *app.world().get::<Transform>(ball).unwrap();
    assert_ne!(transform, transform_after);
    assert!((f64::from(transform_after.translation.y) - 0.25).abs() < 0.02);
    let seen = &app.world().resource::<Seen>().0;
    let landing = seen
        .iter()
        .find(|e| e.kind == EventKind::ContactBegin && e.entity_b == Some(ball))
        .or_else(|| {
            seen.iter()
                .find(|e| e.kind == EventKind::ContactBegin && e.entity_a == Some(ball))
        });
    assert!(
        landing.is_some(),
        "no contact event with the ball: {seen:?}"
    );
}

#[test]
fn a_ray_query_names_the_entity() {
    let mut app = app(scene());
    step(&mut app, 1);
    let ball = app
        .world_mut()
        .query_filtered::<Entity, With<Ball>>()
        .single(app.world())
        .unwrap();
    let hit = app
        .world_mut()
        .run_system_cached(|query: PhysicsQuery| {
            query.cast_ray(
                FxVec3::new(Fx::ZERO, Fx::from_int(5), Fx::ZERO),
                FxVec3::new(Fx::ZERO, -Fx::ONE, Fx::ZERO),
                Fx::from_int(10),
                &QueryFilter::new(),
            )
        })
        .unwrap();
    assert_eq!(hit.and_then(|(_, e)| e), Some(ball));
}

#[test]
fn run_time_spawn_and_despawn_are_commands_in_the_replay() {
    let mut app = app(scene());
    step(&mut app, 5);
    let spawned = app
        .world_mut()
        .spawn((
            crate_body(),
            Collider(crate_shape()),
            FixedTransform::from_position(FxVec3::new(Fx::ZERO, fx(3, 1), fx(2, 1))),
        ))
        .id();
    step(&mut app, 1);
    let link = *app.world().get::<BodyLink>(spawned).expect("linked");
    let world = app.world().resource::<FixstepWorld>();
    assert!(world.world().rigid().unwrap().position(link.0).is_some());
    assert_eq!(world.world().rigid().unwrap().body_count(), 4);
    // A body that matches no template gets no body.
    let stray = app
        .world_mut()
        .spawn((
            RigidBody::dynamic(),
            Collider(Shape::Sphere { radius: fx(1, 8) }),
        ))
        .id();
    step(&mut app, 1);
    assert!(app.world().get::<BodyLink>(stray).is_none());
    app.world_mut().entity_mut(spawned).despawn();
    step(&mut app, 3);
    let world = app.world().resource::<FixstepWorld>();
    assert!(world.world().rigid().unwrap().position(link.0).is_none());
    let commands: Vec<&Command<Fx>> = world
        .history()
        .iter()
        .flat_map(|i| &i.players)
        .flat_map(|p| &p.commands)
        .collect();
    assert_eq!(commands.len(), 2, "{commands:?}");
    assert!(matches!(
        commands[0],
        Command::SpawnBody { template: 0, .. }
    ));
    assert!(matches!(commands[1], Command::Remove { .. }));
    let replay = world
        .replay(u64::MAX, core::num::NonZeroU32::new(5).unwrap())
        .unwrap();
    match verify(&replay).unwrap() {
        VerifyOutcome::Ok { checksum, ticks } => {
            assert_eq!(ticks, 10);
            assert_eq!(checksum, world.checksum());
        }
        other => panic!("{other:?}"),
    }
}
